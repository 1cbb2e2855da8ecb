#include "curvsph/geometry/circle.hpp"

#include <fmt/format.h>

#include "curvsph/geometry/wall_yaml.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

CircleWall::CircleWall(const Vec2d& center, double radius, FluidSide side)
    : center_(center), radius_(radius), side_(side) {}

WallPoint<2> CircleWall::closest(const Vec2d& x, const ParamSeed&) const {
  WallPoint<2> p;
  const Vec2d r = x - center_;
  const double rho = r.norm();
  const Vec2d outward = rho > 0.0 ? Vec2d(r / rho) : Vec2d(1.0, 0.0);
  p.foot = center_ + radius_ * outward;
  apply_side(p, side_, outward, rho - radius_, 1.0 / radius_, 0.0);
  p.dir1 = perp(outward);
  p.param[0] = std::atan2(outward.y(), outward.x());
  p.param_count = 1;
  return p;
}

std::string CircleWall::describe() const {
  return fmt::format("circle center=({}, {}) r={} fluid {}", center_.x(), center_.y(), radius_,
                     to_string(side_));
}

WallPtr<2> make_circle_wall(const YAML::Node& node, const std::string& file,
                            const std::string& key) {
  check_wall_keys(node, {"center", "radius", "fluid"}, file, key);
  const Vec2d c = yaml::read_key(node, "center", file, key, yaml::read_vec<2>);
  const double r = yaml::read_key(node, "radius", file, key, yaml::read_positive);
  return std::make_shared<CircleWall>(c, r, read_fluid_side(node, file, key));
}

}  // namespace curvsph
