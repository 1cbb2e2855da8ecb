#pragma once
// An axis-aligned ellipse (2-D) with semi-axes a (along x) and b (along y).
//
// Closest point: the foot x satisfies x_i = e_i^2 y_i / (t + e_i^2) for the Lagrange
// multiplier t, the unique root of a convex decreasing function on the admissible interval
// (Eberly, "Distance from a point to an ellipse"). We solve in u = t + e_min^2 to avoid the
// cancellation near the centre, bracket the root in closed form and run Newton from the left
// end — monotone for a convex decreasing function — with a bisection fallback, so it never
// fails. The centre and the axes are handled in closed form.
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph {

class EllipseWall final : public Wall<2> {
 public:
  EllipseWall(const Vec2d& center, double a, double b, FluidSide side);
  // u = eccentric angle of the foot, foot = center + (a cos u, b sin u), u in (-pi, pi].
  // Where two feet are equally close (the centre, the segment between the centres of
  // curvature of the major-axis tips) the one on the positive side of the minor axis wins.
  WallPoint<2> closest(const Vec2d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  // min(b^2/a, a^2/b), reached at the tips of the major axis.
  double min_radius_of_curvature() const override;
  // Geometry, for discretisations (boundary elements): semi-axes a (along x), b (along y).
  const Vec2d& center() const { return center_; }
  double semi_axis_a() const { return a_; }
  double semi_axis_b() const { return b_; }
  FluidSide side() const { return side_; }

 private:
  Vec2d center_;
  double a_, b_;
  FluidSide side_;
};

// Closest point to (y0, y1), y0, y1 >= 0, on the ellipse (x0/e0)^2 + (x1/e1)^2 = 1 with
// e0 >= e1 > 0, in the first quadrant; `iterations` receives the Newton steps spent.
Vec2d ellipse_foot_first_quadrant(double e0, double e1, double y0, double y1, int& iterations);

// YAML: {shape: ellipse, center: [x, y], semi_axes: [a, b], fluid: inside|outside}.
WallPtr<2> make_ellipse_wall(const YAML::Node& node, const std::string& file,
                             const std::string& key);

}  // namespace curvsph
