#pragma once
// A torus (3-D) with major radius R (centre to tube axis) and minor radius a (tube), R > a.
// fluid inside = flow in a toroidal pipe; fluid outside = a ring obstacle.
//
// Poloidal angle theta is 0 on the outer equator and pi on the inner one. Principal
// curvatures for fluid inside (negated for fluid outside; DESIGN.md §4, Vela Vela §4.3):
//   along the tube's circle   1/a
//   along the major circle    cos(theta) / (R + a cos(theta))
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph {

class TorusWall final : public Wall<3> {
 public:
  // `axis` need not be unit; it must be non-zero. Requires 0 < minor < major.
  TorusWall(const Vec3d& center, const Vec3d& axis, double major, double minor, FluidSide side);
  // u = poloidal angle theta in (-pi, pi] (positive towards +axis); v = toroidal angle phi
  // about the axis in the frame orthonormal_frame(axis). Ties are broken consistently: on
  // the axis phi = 0; on the tube's centre circle theta = 0.
  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  // min(a, R - a): the tube, or the major direction on the inner equator.
  double min_radius_of_curvature() const override;
  // Geometry, for discretisations (boundary elements): `axis` is unit.
  const Vec3d& center() const { return center_; }
  const Vec3d& axis() const { return axis_; }
  double major_radius() const { return major_; }
  double minor_radius() const { return minor_; }
  FluidSide side() const { return side_; }

 private:
  Vec3d center_, axis_, e1_, e2_;
  double major_, minor_;
  FluidSide side_;
};

// YAML: {shape: torus, center: [..], axis: [..], major_radius: R, minor_radius: a,
//        fluid: inside|outside}.
WallPtr<3> make_torus_wall(const YAML::Node& node, const std::string& file, const std::string& key);

}  // namespace curvsph
