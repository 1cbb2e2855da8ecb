#include "curvsph/geometry/cylinder.hpp"

#include <fmt/format.h>

#include "curvsph/geometry/wall_yaml.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

CylinderWall::CylinderWall(const Vec3d& point, const Vec3d& axis, double radius, FluidSide side)
    : point_(point), axis_(axis.normalized()), radius_(radius), side_(side) {
  std::tie(e1_, e2_) = orthonormal_frame(axis_);
}

WallPoint<3> CylinderWall::closest(const Vec3d& x, const ParamSeed&) const {
  WallPoint<3> p;
  const Vec3d r = x - point_;
  const double along = axis_.dot(r);
  const double c1 = e1_.dot(r), c2 = e2_.dot(r);
  const double rho = std::hypot(c1, c2);
  const double phi = rho > 0.0 ? std::atan2(c2, c1) : 0.0;
  const Vec3d outward = rho > 0.0 ? Vec3d((c1 * e1_ + c2 * e2_) / rho) : e1_;
  p.foot = point_ + along * axis_ + radius_ * outward;
  // k_inside: 1/R around the circle (dir1), 0 along the axis (dir2).
  apply_side(p, side_, outward, rho - radius_, 1.0 / radius_, 0.0);
  p.dir1 = axis_.cross(outward);
  p.dir2 = axis_;
  sort_principal(p);
  p.param = {phi, along};
  p.param_count = 2;
  return p;
}

std::string CylinderWall::describe() const {
  return fmt::format("cylinder point=({}, {}, {}) axis=({}, {}, {}) r={} fluid {}", point_[0],
                     point_[1], point_[2], axis_[0], axis_[1], axis_[2], radius_, to_string(side_));
}

WallPtr<3> make_cylinder_wall(const YAML::Node& node, const std::string& file,
                              const std::string& key) {
  check_wall_keys(node, {"point", "axis", "radius", "fluid"}, file, key);
  const Vec3d point = yaml::read_key(node, "point", file, key, yaml::read_vec<3>);
  const Vec3d axis = yaml::read_key(node, "axis", file, key, yaml::read_direction<3>);
  const double r = yaml::read_key(node, "radius", file, key, yaml::read_positive);
  return std::make_shared<CylinderWall>(point, axis, r, read_fluid_side(node, file, key));
}

}  // namespace curvsph
