#include "curvsph/geometry/torus.hpp"

#include <fmt/format.h>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_yaml.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

TorusWall::TorusWall(const Vec3d& center, const Vec3d& axis, double major, double minor,
                     FluidSide side)
    : center_(center), axis_(axis.normalized()), major_(major), minor_(minor), side_(side) {
  std::tie(e1_, e2_) = orthonormal_frame(axis_);
}

WallPoint<3> TorusWall::closest(const Vec3d& x, const ParamSeed&) const {
  // The torus is the set of points at distance a from its centre circle, and distance to a
  // set is 1-Lipschitz, so the foot lies on the segment from x's nearest centre-circle
  // point through x: no iteration is needed.
  WallPoint<3> p;
  const Vec3d r = x - center_;
  const double h = axis_.dot(r);
  const double q1 = e1_.dot(r), q2 = e2_.dot(r);
  const double rho = std::hypot(q1, q2);
  // Directions from normalised vectors rather than cos/sin of atan2: exact to round-off.
  const Vec3d radial = rho > 0.0 ? Vec3d((q1 * e1_ + q2 * e2_) / rho) : e1_;
  const double delta = std::hypot(rho - major_, h);
  const double ct = delta > 0.0 ? (rho - major_) / delta : 1.0;
  const double st = delta > 0.0 ? h / delta : 0.0;
  const Vec3d outward = ct * radial + st * axis_;
  p.foot = center_ + major_ * radial + minor_ * outward;
  const double phi = rho > 0.0 ? std::atan2(q2, q1) : 0.0;
  const double theta = std::atan2(st, ct);
  apply_side(p, side_, outward, delta - minor_, 1.0 / minor_, ct / (major_ + minor_ * ct));
  p.dir1 = -st * radial + ct * axis_;  // along the tube's circle
  p.dir2 = axis_.cross(radial);        // along the major circle
  sort_principal(p);
  p.param = {theta, phi};
  p.param_count = 2;
  return p;
}

std::string TorusWall::describe() const {
  return fmt::format("torus center=({}, {}, {}) axis=({}, {}, {}) R={} a={} fluid {}", center_[0],
                     center_[1], center_[2], axis_[0], axis_[1], axis_[2], major_, minor_,
                     to_string(side_));
}

double TorusWall::min_radius_of_curvature() const {
  return std::min(minor_, major_ - minor_);
}

WallPtr<3> make_torus_wall(const YAML::Node& node, const std::string& file,
                           const std::string& key) {
  check_wall_keys(node, {"center", "axis", "major_radius", "minor_radius", "fluid"}, file, key);
  const Vec3d c = yaml::read_key(node, "center", file, key, yaml::read_vec<3>);
  const Vec3d axis = yaml::read_key(node, "axis", file, key, yaml::read_direction<3>);
  const double big = yaml::read_key(node, "major_radius", file, key, yaml::read_positive);
  const double small = yaml::read_key(node, "minor_radius", file, key, yaml::read_positive);
  if (!(small < big))
    throw InputError(file, yaml::join(key, "minor_radius"),
                     fmt::format("minor_radius {} >= major_radius {}: the torus self-intersects "
                                 "(a spindle/horn torus is not supported)",
                                 small, big));
  return std::make_shared<TorusWall>(c, axis, big, small, read_fluid_side(node, file, key));
}

}  // namespace curvsph
