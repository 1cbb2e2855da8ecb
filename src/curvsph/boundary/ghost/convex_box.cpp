#include "curvsph/boundary/ghost/convex_box.hpp"

#include <algorithm>
#include <cmath>

namespace curvsph {

template <int D>
int box_outside_images(const VecD<D>& x, const VecD<D>& lo, const VecD<D>& hi, double support,
                       FacetImage<D>* out, int max) {
  using Mat = Eigen::Matrix<double, D, D>;
  int n = 0;
  // The faces' partition of unity at a point y of the box (convex_box.hpp): the sum of the
  // raw shares of all 2D faces, each at y's distance to its plane.
  const auto total_share = [&](const VecD<D>& y) {
    double s = 0;
    for (int a = 0; a < D; ++a)
      s += convex_share(y[a] - lo[a], support) + convex_share(hi[a] - y[a], support);
    return s;
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
        const double total = total_share(y);
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

template int box_outside_images<2>(const Vec2d&, const Vec2d&, const Vec2d&, double, FacetImage<2>*,
                                   int);
template int box_outside_images<3>(const Vec3d&, const Vec3d&, const Vec3d&, double, FacetImage<3>*,
                                   int);

}  // namespace curvsph
