#include "curvsph/boundary/ghost/convex_box.hpp"

#include <algorithm>
#include <cmath>

namespace curvsph {

template <int D>
int box_outside_images(const VecD<D>& x, const VecD<D>& lo, const VecD<D>& hi, double support,
                       const std::function<bool(const VecD<D>&)>& in_fluid, FacetImage<D>* out,
                       int max) {
  using Mat = Eigen::Matrix<double, D, D>;
  int n = 0;
  // The faces' partition of unity at a point y of the box (convex_box.hpp): the raw shares of
  // the faces whose reflection of y is a fluid point, each at y's distance to its plane (face
  // (a0, s0), y's own source's, counted without asking).
  const auto total_share = [&](const VecD<D>& y, int a0, int s0) {
    double total = 0;
    for (int a = 0; a < D; ++a)
      for (int s = 0; s < 2; ++s) {
        const double plane = s == 0 ? lo[a] : hi[a];
        const double f = convex_share(std::abs(y[a] - plane), support);
        if (!(f > 0)) continue;
        if (a != a0 || s != s0) {
          VecD<D> r = y;
          r[a] = 2.0 * plane - y[a];
          if (!in_fluid(r)) continue;
        }
        total += f;
      }
    return total;
  };
  const VecD<D> clamped = x.cwiseMax(lo).cwiseMin(hi);
  int clamped_axes = 0;
  for (int a = 0; a < D; ++a) clamped_axes += clamped[a] != x[a];
  for (int a = 0; a < D; ++a)
    for (int s = 0; s < 2; ++s) {
      // x on the fluid side of face (a, s), within the support of its plane.
      const double d = s == 0 ? lo[a] - x[a] : x[a] - hi[a];
      if (!(d > 0 && d < support)) continue;
      const VecD<D> nrm = VecD<D>::Unit(a) * (s == 0 ? -1.0 : 1.0);
      VecD<D> y = x;
      y[a] -= 2.0 * d * nrm[a];
      bool in_box = true;
      for (int b = 0; b < D; ++b) in_box &= y[b] > lo[b] && y[b] < hi[b];
      double weight = 0;
      if (in_box) {
        const double total = total_share(y, a, s);
        weight = total > 0 ? convex_share(d, support) / total : 0.0;
      }
      // No share: a guard of no volume if x projects onto the face (its only single image).
      if (!(weight > 0) && clamped_axes != 1) continue;
      if (n >= max) return n;
      FacetImage<D> im;
      im.x = y;
      im.M = Mat::Identity() - 2.0 * nrm * nrm.transpose();
      im.foot = x - d * nrm;
      im.normal = nrm;
      im.depth = im.source_depth = d;
      im.reflections = 1;
      im.weight = weight;
      out[n++] = im;
    }
  // Beyond two or more faces (an edge's or a vertex's region): the closest-point image, a
  // guard (at 90 degrees the faces' reflections fill the solid alone).
  const double dist = (x - clamped).norm();
  if (clamped_axes >= 2 && dist > 0 && dist < support && n < max) {
    FacetImage<D> im;
    im.x = 2.0 * clamped - x;
    im.M = Mat::Identity();
    for (int a = 0; a < D; ++a)
      if (clamped[a] != x[a]) im.M(a, a) = -1;
    im.foot = clamped;
    im.normal = (x - clamped) / dist;
    im.depth = im.source_depth = dist;
    im.reflections = 1;
    im.weight = 0;
    out[n++] = im;
  }
  return n;
}

template int box_outside_images<2>(const Vec2d&, const Vec2d&, const Vec2d&, double,
                                   const std::function<bool(const Vec2d&)>&, FacetImage<2>*, int);
template int box_outside_images<3>(const Vec3d&, const Vec3d&, const Vec3d&, double,
                                   const std::function<bool(const Vec3d&)>&, FacetImage<3>*, int);

}  // namespace curvsph
