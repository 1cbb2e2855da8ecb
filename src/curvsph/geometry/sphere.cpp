#include "curvsph/geometry/sphere.hpp"

#include <fmt/format.h>

#include "curvsph/geometry/wall_yaml.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

SphereWall::SphereWall(const Vec3d& center, double radius, FluidSide side)
    : center_(center), radius_(radius), side_(side) {}

WallPoint<3> SphereWall::closest(const Vec3d& x, const ParamSeed&) const {
  WallPoint<3> p;
  const Vec3d r = x - center_;
  const double rho = r.norm();
  const double theta = rho > 0.0 ? std::atan2(std::hypot(r.x(), r.y()), r.z()) : 0.0;
  const double phi = (r.x() != 0.0 || r.y() != 0.0) ? std::atan2(r.y(), r.x()) : 0.0;
  const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  const Vec3d outward = rho > 0.0 ? Vec3d(r / rho) : Vec3d(0.0, 0.0, 1.0);
  p.foot = center_ + radius_ * outward;
  apply_side(p, side_, outward, rho - radius_, 1.0 / radius_, 1.0 / radius_);
  p.dir1 = Vec3d(ct * cp, ct * sp, -st);
  p.dir2 = Vec3d(-sp, cp, 0.0);
  p.param = {theta, phi};
  p.param_count = 2;
  return p;
}

std::string SphereWall::describe() const {
  return fmt::format("sphere center=({}, {}, {}) r={} fluid {}", center_[0], center_[1], center_[2],
                     radius_, to_string(side_));
}

WallPtr<3> make_sphere_wall(const YAML::Node& node, const std::string& file,
                            const std::string& key) {
  check_wall_keys(node, {"center", "radius", "fluid"}, file, key);
  const Vec3d c = yaml::read_key(node, "center", file, key, yaml::read_vec<3>);
  const double r = yaml::read_key(node, "radius", file, key, yaml::read_positive);
  return std::make_shared<SphereWall>(c, r, read_fluid_side(node, file, key));
}

}  // namespace curvsph
