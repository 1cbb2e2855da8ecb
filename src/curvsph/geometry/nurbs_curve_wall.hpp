#pragma once
// A 2-D wall along a NURBS curve (DESIGN.md §4, Barker §3). The fluid is on the left or the
// right of the direction of increasing parameter.
//
// Beyond an open end the foot is the end point; the normal there is the curve's own normal
// at the end (so ghost maps see a smooth continuation of the wall), and the distance is
// the true Euclidean distance |x - foot| signed by the side of that normal.
#include <yaml-cpp/yaml.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "curvsph/geometry/faceted.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/nurbs/projection.hpp"
#include "curvsph/nurbs/sampling.hpp"

namespace curvsph {

class NurbsCurveWall : public Wall<2>, public Faceted<2> {
 public:
  enum class Side { left, right };
  // tolerance: closest-point distance tolerance (<= 0: 1e-10 of the curve's size).
  NurbsCurveWall(nurbs::NurbsCurve<2> curve, Side fluid, double tolerance = 0.0);

  WallPoint<2> closest(const Vec2d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override { return min_radius_; }
  double distance_lower_bound(const Vec2d& x) const override {
    return proj_->lower_bound(x, std::numeric_limits<double>::infinity());
  }

  // A degree-1 curve is a polyline: its segments are its faces (faceted.hpp); -1 otherwise.
  int facets_near(const Vec2d& x, double reach, WallFacet<2>* out, int max) const override;

  // Boundary particles at arc-length spacing about dx, with their parameters (the seeds).
  nurbs::CurveSamples<2> boundary_particles(double dx) const {
    return nurbs::sample_arc_length(*curve_, dx);
  }
  const nurbs::NurbsCurve<2>& curve() const { return *curve_; }
  const nurbs::CurveProjector<2>& projector() const { return *proj_; }
  Side fluid() const { return side_; }
  double tolerance() const { return tol_; }
  void set_tolerance(double tol) { tol_ = tol > 0.0 ? tol : proj_->default_tolerance(); }

 private:
  std::unique_ptr<nurbs::NurbsCurve<2>> curve_;  // stable address for the projector
  std::unique_ptr<nurbs::CurveProjector<2>> proj_;
  Side side_;
  double tol_;
  double min_radius_;
  std::vector<WallFacet<2>> facets_;  // degree 1 only: the segments, in curve order
  void polygon_vertex(const Vec2d& x, WallPoint<2>& w) const;
};

// {shape: nurbs_curve, degree, control_points, weights (optional, default 1), knots,
//  fluid: left|right, motion (read by the wall-set parser)}; errors name e.g. walls.2.knots.
WallPtr<2> make_nurbs_curve_wall(const YAML::Node& node, const std::string& file,
                                 const std::string& key_prefix);

}  // namespace curvsph
