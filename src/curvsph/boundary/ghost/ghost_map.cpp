#include "curvsph/boundary/ghost/ghost_map.hpp"

#include <fmt/format.h>

#include "curvsph/core/error.hpp"

namespace curvsph {

const char* to_string(GhostMapKind m) {
  switch (m) {
    case GhostMapKind::mirror_beta:
      return "mirror_beta";
    case GhostMapKind::density_preserving:
      return "density_preserving";
    case GhostMapKind::mirror:
    default:
      return "mirror";
  }
}

GhostMapKind parse_ghost_map(const std::string& name, const std::string& file,
                             const std::string& key) {
  if (name == "mirror") return GhostMapKind::mirror;
  if (name == "mirror_beta") return GhostMapKind::mirror_beta;
  if (name == "density_preserving") return GhostMapKind::density_preserving;
  throw InputError(file, key,
                   fmt::format("unknown ghost map '{}' (expected mirror, mirror_beta or "
                               "density_preserving)",
                               name));
}

GhostDepth ghost_density_preserving_safe(double d, double k1, double k2) {
  GhostDepth g;
  if (!ghost_depth_allowed(d, k1, k2)) return g;
  const double H = k1 + k2, K = k1 * k2;
  const double target = -ghost_volume_g(k1, k2, -d);
  const double zmax = ghost_zeta_limit(k1, k2);
  const bool bounded = zmax < std::numeric_limits<double>::infinity();
  if (bounded && !(target < ghost_volume_g(k1, k2, zmax))) return g;
  const double disc = 1.0 + 2.0 * H * target;
  double z = disc >= 0 ? 2.0 * target / (1.0 + std::sqrt(disc)) : 0.5 * zmax;
  if (K == 0.0) {
    g.depth = z;
    g.ok = disc >= 0 && z > 0 && z < zmax;
    return g;
  }
  double lo = 0.0, hi = bounded ? zmax : target;
  if (!(z > lo && z < hi)) z = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const double f = ghost_volume_g(k1, k2, z) - target;
    if (f < 0)
      lo = z;
    else
      hi = z;
    const double step = f / ghost_jacobian(k1, k2, z);
    double zn = z - step;
    // Once the step is below 1e-8 z, Newton's quadratic convergence puts zn at round-off.
    if (std::abs(step) <= 1e-8 * z) {
      z = zn;
      break;
    }
    if (!(zn > lo && zn < hi)) zn = 0.5 * (lo + hi);
    if (zn == z) break;
    z = zn;
  }
  g.depth = z;
  g.ok = z > 0 && z < zmax;
  return g;
}

double ghost_max_depth(GhostMapKind map, double k1, double k2) {
  const double inf = std::numeric_limits<double>::infinity();
  const double zmax = ghost_zeta_limit(k1, k2);
  const double dmax = ghost_fluid_depth_limit(k1, k2);
  if (zmax == inf) return inf;
  if (map != GhostMapKind::density_preserving) return zmax < dmax ? zmax : inf;
  // -G(-d) increases on [0, dmax); find where it reaches G(zmax).
  const double gmax = ghost_volume_g(k1, k2, zmax);
  auto lhs = [&](double d) { return -ghost_volume_g(k1, k2, -d); };
  double hi;
  if (dmax < inf) {
    if (lhs(dmax) <= gmax) return inf;
    hi = dmax;
  } else {
    hi = zmax;
    while (lhs(hi) <= gmax) hi *= 2.0;
  }
  double lo = 0.0;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (lhs(mid) < gmax ? lo : hi) = mid;
  }
  return lo;
}

double ghost_max_depth_convex(GhostMapKind map, int dim, double min_radius) {
  if (!(min_radius < std::numeric_limits<double>::infinity()))
    return std::numeric_limits<double>::infinity();
  const double k = -1.0 / min_radius;
  return ghost_max_depth(map, k, dim == 3 ? k : 0.0);
}

void check_ghost_support(GhostMapKind map, double k1, double k2, double support, double min_radius,
                         const std::string& wall_description, const std::string& file,
                         const std::string& key) {
  const double dmax = ghost_max_depth(map, k1, k2);
  if (support < dmax) return;
  throw InputError(
      file, key,
      fmt::format("{}: the {} ghost map has no ghost inside the wall for fluid particles "
                  "deeper than {:.6g} where the wall has curvatures k1 = {:.6g}, k2 = {:.6g} "
                  "(smallest radius of curvature {:.6g}), but the kernel support 2h = {:.6g} "
                  "reaches deeper; the largest h that works is h < {:.6g}",
                  wall_description, to_string(map), dmax, k1, k2, min_radius, support, 0.5 * dmax));
}

void check_concave_support(double k1, double k2, double support,
                           const std::string& wall_description, const std::string& file,
                           const std::string& key) {
  const double k = std::max(k1, k2);
  if (!(k > 0) || 1.0 / k >= support) return;
  throw InputError(
      file, key,
      fmt::format("{}: concave seen from the fluid with radius of curvature {:.6g} (curvatures "
                  "k1 = {:.6g}, k2 = {:.6g}) where fluid particles lie within the kernel support "
                  "2h = {:.6g} of it; below 2h the centre of curvature lies inside the support of "
                  "a particle next to the wall, where the closest point and the ghost are not "
                  "unique, and the ghosts (at most that radius deep) cannot fill the support "
                  "behind the wall; the largest h that works is h < {:.6g} (or round the wall "
                  "with a radius of at least 2h)",
                  wall_description, 1.0 / k, k1, k2, support, 0.5 / k));
}

}  // namespace curvsph
