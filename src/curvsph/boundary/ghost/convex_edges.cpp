#include "curvsph/boundary/ghost/convex_edges.hpp"

#include <array>
#include <cmath>

#include "curvsph/boundary/ghost/facet_images.hpp"

namespace curvsph {

template <int D>
double edge_share(const MultiFace<D>& faces, const VecD<D>& y, const VecD<D>& n, double d,
                  double support, const std::function<bool(const VecD<D>&)>& in_fluid) {
  // No face recedes behind X's plane near y (a face's middle, a tank's concave edges): the
  // share is 1 without the faces' query.
  if (!faces.may_reach_behind(y, support, VecD<D>(y + d * n), n)) return 1.0;
  constexpr int kMaxFaces = 16;
  std::array<WallPoint<D>, kMaxFaces> fp;
  const int nf = faces.face_points_near(y, support, fp.data(), kMaxFaces);
  const double own = convex_share(d, support);
  double total = own;
  // X's own foot first: X and a second face of the same foot (a tangent junction) are not
  // counted again.
  std::array<VecD<D>, kMaxFaces + 1> feet;
  feet[0] = y + d * n;
  int nfeet = 1;
  for (int f = 0; f < nf; ++f) {
    const WallPoint<D>& z = fp[static_cast<std::size_t>(f)];
    const double dz = (y - z.foot).dot(z.normal);  // < 0: y behind Z (its tangent plane)
    if (!(std::abs(dz) < support)) continue;
    if ((y - z.foot - dz * z.normal).norm() > 1e-6 * std::abs(dz)) continue;  // y projects onto Z
    // Z recedes behind X's plane (a convex edge between them); a concave edge keeps its plain
    // images, cut or completed by flat_corners.hpp.
    if (!((z.foot - feet[0]).dot(n) < 0)) continue;
    // y in front of Z across a convex edge: in the fluid beyond Z (an acute solid's edge),
    // no share (x keeps it as a guard).
    if (dz > 0) return 0.0;
    if (!(dz < 0)) continue;
    bool dup = false;
    for (int q = 0; q < nfeet; ++q)
      dup |= (feet[static_cast<std::size_t>(q)] - z.foot).norm() <= 1e-7 * -dz;
    if (dup) continue;
    feet[static_cast<std::size_t>(nfeet++)] = z.foot;
    if (!in_fluid(VecD<D>(y - 2.0 * dz * z.normal))) continue;
    total += convex_share(-dz, support);
  }
  // A curved face's image deeper than the support (density_preserving beyond a convex face):
  // no face's f reaches it, and its own face's images alone cover it.
  return total > 0 ? own / total : 1.0;
}

template double edge_share<2>(const MultiFace<2>&, const Vec2d&, const Vec2d&, double, double,
                              const std::function<bool(const Vec2d&)>&);
template double edge_share<3>(const MultiFace<3>&, const Vec3d&, const Vec3d&, double, double,
                              const std::function<bool(const Vec3d&)>&);

}  // namespace curvsph
