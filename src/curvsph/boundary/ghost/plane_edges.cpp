#include "curvsph/boundary/ghost/plane_edges.hpp"

#include <cmath>

namespace curvsph {

template <int D>
std::optional<PlaneEdgeImage<D>> plane_edge_image(const Wall<D>& w, const VecD<D>& x,
                                                  const WallPoint<D>& p, const VecD<D>& ghost,
                                                  const FlatFace<D>& A, double support) {
  const auto reflect = [&](const VecD<D>& y) -> VecD<D> {
    return y - 2.0 * (y - A.foot).dot(A.normal) * A.normal;
  };
  const double da = (ghost - A.foot).dot(A.normal);
  if (!(da > 0 && da < support)) return std::nullopt;  // behind the plane already, or too far
  // Mirror symmetry of the wall about A near x: x_A's closest point is x's reflected.
  const WallPoint<D> q = w.closest(reflect(x));
  const double tol = 1e-9 * support;
  const VecD<D> n_ref = p.normal - 2.0 * p.normal.dot(A.normal) * A.normal;
  if ((q.foot - reflect(p.foot)).norm() > tol || (q.normal - n_ref).norm() > 1e-9 ||
      std::abs(q.distance - p.distance) > tol ||
      std::abs(q.k1 - p.k1) > 1e-9 * std::abs(p.k1) + 1e-12 ||
      std::abs(q.k2 - p.k2) > 1e-9 * std::abs(p.k2) + 1e-12)
    return std::nullopt;
  const VecD<D> foot = ghost - da * A.normal;
  return PlaneEdgeImage<D>{foot - da * A.normal, foot, da};
}

template std::optional<PlaneEdgeImage<2>> plane_edge_image<2>(const Wall<2>&, const VecD<2>&,
                                                              const WallPoint<2>&, const VecD<2>&,
                                                              const FlatFace<2>&, double);
template std::optional<PlaneEdgeImage<3>> plane_edge_image<3>(const Wall<3>&, const VecD<3>&,
                                                              const WallPoint<3>&, const VecD<3>&,
                                                              const FlatFace<3>&, double);

}  // namespace curvsph
