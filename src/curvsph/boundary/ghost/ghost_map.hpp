#pragma once
// Ghost maps (DESIGN.md §4): where a fluid particle at depth d in front of a wall puts its
// ghost behind the wall, and with which volume weight beta.
//
// Conventions (wall.hpp): zeta is the normal offset measured INTO the wall (zeta > 0 behind
// the wall, the fluid particle sits at zeta = -d), k1, k2 the principal curvatures with
// k > 0 where the wall is concave seen from the fluid (2-D: k2 = 0). The area / volume
// element at offset zeta scales as J(zeta) = (1 + k1 zeta)(1 + k2 zeta), and
//   G(zeta) = int_0^zeta J = zeta + (k1 + k2) zeta^2 / 2 + k1 k2 zeta^3 / 3.
//
// | map                 | ghost depth zeta'              | beta                          |
// | mirror              | d                              | 1                             |
// | mirror_beta         | d                              | J(d)/J(-d) (Barker eqs. 17-19) |
// | density_preserving  | root of G(zeta') = -G(-d)      | 1 (Vela Vela eq. 13)          |
//
// Region the wall allows. Behind the wall J must stay positive: zeta < zeta_max =
// min over k_i < 0 of 1/|k_i| (the centre of curvature of a convex obstacle, the torus axis
// behind the inner equator); +inf when no k_i < 0. In front of the wall the closest-point
// depth never exceeds d_max = min over k_i > 0 of 1/k_i. Since G is increasing on
// [0, zeta_max) and -G(-d) is increasing on [0, d_max), the density-preserving ghost exists
// and is unique iff -G(-d) < G(zeta_max); the mirror maps need d < zeta_max (otherwise the
// ghost lies beyond the centre of curvature and mirror_beta's beta is <= 0). Where there is
// no root the map returns ok = false; it never returns a garbage depth. Depths the wall
// does not allow in front (d <= 0, or 1 - k_i d <= 0) also give ok = false.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace curvsph {

enum class GhostMapKind { mirror, mirror_beta, density_preserving };

const char* to_string(GhostMapKind m);
// "mirror" | "mirror_beta" | "density_preserving"; anything else: InputError(file, key, ...).
GhostMapKind parse_ghost_map(const std::string& name, const std::string& file = {},
                             const std::string& key = {});

struct GhostDepth {
  double depth = 0.0;  // zeta' > 0, behind the wall
  double beta = 1.0;   // volume weight of the ghost
  bool ok = false;     // false: no ghost inside the region the wall allows
};

inline double ghost_jacobian(double k1, double k2, double zeta) {
  return (1.0 + k1 * zeta) * (1.0 + k2 * zeta);
}

inline double ghost_volume_g(double k1, double k2, double zeta) {
  return zeta * (1.0 + zeta * (0.5 * (k1 + k2) + zeta * (k1 * k2 / 3.0)));
}

// zeta_max above (+inf when the wall is nowhere convex here).
inline double ghost_zeta_limit(double k1, double k2) {
  double z = std::numeric_limits<double>::infinity();
  if (k1 < 0) z = std::min(z, -1.0 / k1);
  if (k2 < 0) z = std::min(z, -1.0 / k2);
  return z;
}

// d_max above (+inf when the wall is nowhere concave here).
inline double ghost_fluid_depth_limit(double k1, double k2) {
  double d = std::numeric_limits<double>::infinity();
  if (k1 > 0) d = std::min(d, 1.0 / k1);
  if (k2 > 0) d = std::min(d, 1.0 / k2);
  return d;
}

inline bool ghost_depth_allowed(double d, double k1, double k2) {
  return d > 0 && 1.0 - k1 * d > 0 && 1.0 - k2 * d > 0;
}

inline GhostDepth ghost_mirror(double d, double k1, double k2) {
  GhostDepth g;
  g.depth = d;
  g.ok = ghost_depth_allowed(d, k1, k2) && d < ghost_zeta_limit(k1, k2);
  return g;
}

inline GhostDepth ghost_mirror_beta(double d, double k1, double k2) {
  GhostDepth g;
  g.depth = d;
  g.ok = ghost_depth_allowed(d, k1, k2) && d < ghost_zeta_limit(k1, k2);
  if (g.ok) g.beta = ghost_jacobian(k1, k2, d) / ghost_jacobian(k1, k2, -d);
  return g;
}

// Root of G(zeta') = -G(-d), safeguarded: closed form where k1 k2 = 0, otherwise Newton
// from the quadratic estimate with a bisection fallback inside the bracket [0, hi]
// (hi = zeta_max, or -G(-d) itself when every k >= 0 since then G(zeta) >= zeta). Reports
// ok = false exactly when there is no root in the region the wall allows.
GhostDepth ghost_density_preserving_safe(double d, double k1, double k2);

// Same root, fast path for the common case (the hot loop of ghost placement): with the cubic
// term moved to the right-hand side at a cheap estimate w of the root, the quadratic gives
// a start within O(k^3 d^4) of the root; a Halley step (and, for deep particles, chord\n// steps)
// then reach round-off. No convergence within five steps, or a result outside the region, hands
// over to the safeguarded solver, so the answer is the same either way.
inline GhostDepth ghost_density_preserving(double d, double k1, double k2) {
  const double H = k1 + k2, K = k1 * k2;
  const double target = d * (1.0 - d * (0.5 * H - d * (K / 3.0)));  // -G(-d)
  // Depths the wall allows in front: 1 - k_i d > 0 (closest points never lie deeper).
  if (!(d > 0 && 1.0 - k1 * d > 0 && 1.0 - k2 * d > 0)) return GhostDepth{};
  if (K == 0.0) {
    // Quadratic H z^2/2 + z - target = 0 in the cancellation-free form.
    GhostDepth g;
    const double disc = 1.0 + 2.0 * H * target;
    const double z = 2.0 * target / (1.0 + std::sqrt(std::max(disc, 0.0)));
    g.depth = z;
    g.ok = disc >= 0 && z > 0 && 1.0 + k1 * z > 0 && 1.0 + k2 * z > 0;
    return g;
  }
  if (k1 == k2) {
    // Umbilic point (sphere): G = ((1 + k z)^3 - 1)/(3k), so z = ((1 + 3u)^(1/3) - 1)/k with
    // u = k target (Vela Vela eq. 25). Near the wall (|u| <= 0.1, the common case) the
    // binomial series z/target = 1 - u + 5u^2/3 - 10u^3/3 + 22u^4/3 - 154u^5/9 + 374u^6/9
    // (relative error < 104 u^7 <= 1e-5) and one Halley step on the cubic (error
    // (2/3) u^2 e^3 < 1e-17 relative) replace the cube root.
    GhostDepth g;
    const double u = k1 * target;
    if (std::abs(u) <= 0.1) {
      double z =
          target *
          (1.0 + u * (-1.0 + u * (5.0 / 3.0 +
                                  u * (-10.0 / 3.0 + u * (22.0 / 3.0 + u * (-154.0 / 9.0 +
                                                                            u * (374.0 / 9.0)))))));
      const double j1 = 1.0 + k1 * z;  // J = j1^2, J' = 2 k j1
      const double f = z * (1.0 + k1 * z * (1.0 + k1 * z * (1.0 / 3.0))) - target;
      z -= f * j1 / (j1 * j1 * j1 - f * k1);  // Halley: 2 f J / (2 J^2 - f J')
      g.depth = z;
      g.ok = z > 0 && 1.0 + k1 * z > 0;
      return g;
    }
    // Otherwise the closed form with c = cbrt(1 + 3u): z = 3 target/(c^2 + c + 1)
    // (cancellation-free).
    const double c = std::cbrt(1.0 + 3.0 * k1 * target);
    g.depth = 3.0 * target / (c * c + c + 1.0);
    g.ok = 1.0 + 3.0 * k1 * target > 0 && 1.0 + k1 * g.depth > 0;
    return g;
  }
  const double hd = H * d;
  const double w = d * (1.0 - hd * (1.0 - hd));  // d - H d^2 + H^2 d^3
  const double tq = target - (K / 3.0) * w * w * w;
  const double disc = 1.0 + 2.0 * H * tq;
  double z = 2.0 * tq / (1.0 + std::sqrt(std::max(disc, 0.0)));
  // One Halley step (cubic convergence): the error left after a step s is about C s^3 with
  // C = (J'/2J)^2 + |K|/3 (J'' = 2K). Most particles stop here; the rest continue with chord
  // steps, whose error after a step s is about (|J'|/J) |z - z0| |s| (z0: where J was taken).
  const double z0 = z;
  const double j = ghost_jacobian(k1, k2, z), jp = H + 2.0 * K * z;
  const double f = ghost_volume_g(k1, k2, z) - target;
  double step = 2.0 * f * j / (2.0 * j * j - f * jp);
  z -= step;
  const double c = 0.25 * (jp * jp) / (j * j) + std::abs(K) / 3.0;
  bool converged = std::abs(step) <= 1e-3 * z && c * std::abs(step * step * step) <= 1e-16 * z;
  const double inv_j = 1.0 / j, rate = std::abs(jp) * inv_j;
  for (int it = 0; it < 5 && !converged; ++it) {
    step = (ghost_volume_g(k1, k2, z) - target) * inv_j;
    z -= step;
    converged = step == 0.0 || rate * std::abs((z - z0) * step) <= 1e-16 * z;
  }
  if (converged && disc >= 0 && z > 0 && 1.0 + k1 * z > 0 && 1.0 + k2 * z > 0) {
    GhostDepth g;
    g.depth = z;
    g.ok = true;
    return g;
  }
  return ghost_density_preserving_safe(d, k1, k2);
}

inline GhostDepth ghost_map(GhostMapKind map, double d, double k1, double k2) {
  switch (map) {
    case GhostMapKind::mirror_beta:
      return ghost_mirror_beta(d, k1, k2);
    case GhostMapKind::density_preserving:
      return ghost_density_preserving(d, k1, k2);
    case GhostMapKind::mirror:
    default:
      return ghost_mirror(d, k1, k2);
  }
}

// Largest fluid depth D such that every depth d in (0, D) has a ghost under `map` where the
// wall has curvatures (k1, k2); +inf when every depth the wall allows has one. A kernel
// support 2h works there iff 2h < D (every fluid particle within 2h has its ghost).
double ghost_max_depth(GhostMapKind map, double k1, double k2);

// Same, knowing only the smallest radius of curvature of a wall (the sign unknown): assumes
// the worst case, a convex wall of that radius in every direction (2-D circle obstacle,
// 3-D sphere obstacle). Conservative: a concave wall of that radius needs no limit.
double ghost_max_depth_convex(GhostMapKind map, int dim, double min_radius);

// Set-up refusal (DESIGN.md §3, §4): throws InputError(file, key, reason) when a support 2h
// leaves ghosts without a root where the wall has curvatures (k1, k2). The reason names the
// wall (`wall_description`), its smallest radius of curvature, the curvatures, and the
// largest h that would work.
void check_ghost_support(GhostMapKind map, double k1, double k2, double support, double min_radius,
                         const std::string& wall_description, const std::string& file,
                         const std::string& key);

// Set-up refusal for a wall that is concave seen from the fluid (k > 0) with a radius of
// curvature 1/k below the kernel support 2h, where a fluid particle lies within 2h of it (a
// fillet or a pipe too narrow for the kernel). Every ghost map has a root there (the depths
// the wall allows in front are below 1/k), but the construction is not well defined: a
// particle next to the wall has the centre of curvature inside its support, where the closest
// point, and with it the ghost of a particle, is not unique (the fluid around it folds onto
// the whole arc), mirror_beta's weight (1 + k d)/(1 - k d) grows without bound as d nears
// 1/k (a CAD cylinder of radius 1.75 h blew up, docs/geometry.md), and the ghost layer, the
// image of the band 0 < d < 1/k, is at most 1/k deep (the mirror maps; less for
// density_preserving), so the 2h-deep support behind the wall is left short. Throws
// InputError(file, key, reason) with the radius, 2h and the largest h.
void check_concave_support(double k1, double k2, double support,
                           const std::string& wall_description, const std::string& file,
                           const std::string& key);

}  // namespace curvsph
