#pragma once
// A 3-D wall on a NURBS surface. The fluid is on the front (the side of dS/du x dS/dv) or
// the back. Beyond the surface's boundary the foot lies on the boundary; the normal is the
// surface normal there and the distance is |x - foot| signed by the side of that normal.
#include <yaml-cpp/yaml.h>

#include <limits>
#include <memory>
#include <string>

#include "curvsph/geometry/wall.hpp"
#include "curvsph/nurbs/projection.hpp"
#include "curvsph/nurbs/sampling.hpp"

namespace curvsph {

class NurbsSurfaceWall : public Wall<3> {
 public:
  enum class Side { front, back };
  NurbsSurfaceWall(nurbs::NurbsSurface surface, Side fluid, double tolerance = 0.0);

  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override { return min_radius_; }
  double distance_lower_bound(const Vec3d& x) const override {
    return proj_->lower_bound(x, std::numeric_limits<double>::infinity());
  }

  // Wall data at given parameters (also used by trimmed CAD faces).
  WallPoint<3> at(double u, double v, const Vec3d& x) const;
  nurbs::SurfaceSamples seeds(double dx) const { return nurbs::sample_surface(*surf_, dx); }
  const nurbs::NurbsSurface& surface() const { return *surf_; }
  const nurbs::SurfaceProjector& projector() const { return *proj_; }
  Side fluid() const { return side_; }
  double tolerance() const { return tol_; }
  void set_tolerance(double tol) { tol_ = tol > 0.0 ? tol : proj_->default_tolerance(); }
  void set_label(std::string label) { label_ = std::move(label); }

 private:
  std::unique_ptr<nurbs::NurbsSurface> surf_;
  std::unique_ptr<nurbs::SurfaceProjector> proj_;
  Side side_;
  double tol_;
  double min_radius_;
  std::string label_;
};

// {shape: nurbs_surface, degree: [p, q], control_points (rows along u, each a list along v),
//  weights (same nesting, optional), knots_u, knots_v, fluid: front|back}.
WallPtr<3> make_nurbs_surface_wall(const YAML::Node& node, const std::string& file,
                                   const std::string& key_prefix);

}  // namespace curvsph
