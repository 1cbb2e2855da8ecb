#pragma once
// Small pieces shared by the analytic walls: which side holds the fluid, orthonormal frames,
// and turning an "outward" answer (normal away from the solid's interior) into the wall
// convention of wall.hpp.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// `inside`: the fluid fills the shape's interior (a pipe, a tank); `outside`: the shape is
// an obstacle in the fluid.
enum class FluidSide { inside, outside };

inline const char* to_string(FluidSide s) {
  return s == FluidSide::inside ? "inside" : "outside";
}

// Unit vectors (e1, e2) with (e1, e2, n) right-handed and orthonormal; n must be unit.
// The choice is a fixed function of n, so angles measured in this frame are reproducible.
inline std::pair<Vec3d, Vec3d> orthonormal_frame(const Vec3d& n) {
  // Start from the coordinate axis least aligned with n: well conditioned for every n.
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[k])) k = i;
  Vec3d a = Vec3d::Zero();
  a[k] = 1.0;
  const Vec3d e1 = (a - a.dot(n) * n).normalized();
  return {e1, n.cross(e1)};
}

// 2-D unit tangent: the normal turned by +90 degrees.
inline Vec2d perp(const Vec2d& n) {
  return Vec2d(-n.y(), n.x());
}

// Given the outward normal of a solid interior (pointing away from the region the shape
// encloses), the unsigned distance with its sign relative to the interior (> 0 outside),
// and the curvatures measured for fluid INSIDE (positive where the interior is concave),
// fills the normal, distance and curvatures for the chosen side.
template <int D>
void apply_side(WallPoint<D>& p, FluidSide side, const VecD<D>& outward, double dist_outside,
                double k_inside_1, double k_inside_2) {
  const double s = side == FluidSide::inside ? -1.0 : 1.0;
  p.normal = s * outward;
  p.distance = s * dist_outside;
  // `+ 0.0` turns -0 into 0 so flat walls print k = 0 on both sides.
  p.k1 = (side == FluidSide::inside ? k_inside_1 : -k_inside_1) + 0.0;
  p.k2 = (side == FluidSide::inside ? k_inside_2 : -k_inside_2) + 0.0;
}

// Orders (k1, dir1), (k2, dir2) so that k1 >= k2.
template <int D>
void sort_principal(WallPoint<D>& p) {
  if (p.k1 < p.k2) {
    std::swap(p.k1, p.k2);
    std::swap(p.dir1, p.dir2);
  }
}

}  // namespace curvsph
