#include "curvsph/geometry/plane.hpp"

#include <fmt/format.h>

#include <limits>

#include "curvsph/geometry/shape_util.hpp"
#include "curvsph/geometry/wall_yaml.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

template <int D>
PlaneWall<D>::PlaneWall(const VecD<D>& point, const VecD<D>& normal)
    : point_(point), normal_(normal.normalized()) {
  if constexpr (D == 2) {
    t1_ = perp(normal_);
    t2_.setZero();
  } else {
    std::tie(t1_, t2_) = orthonormal_frame(normal_);
  }
}

template <int D>
WallPoint<D> PlaneWall<D>::closest(const VecD<D>& x, const ParamSeed&) const {
  WallPoint<D> p;
  const VecD<D> r = x - point_;
  p.distance = normal_.dot(r);
  p.foot = x - p.distance * normal_;
  p.normal = normal_;
  p.dir1 = t1_;
  p.dir2 = t2_;
  p.param[0] = t1_.dot(r);
  p.param[1] = D == 3 ? t2_.dot(r) : 0.0;
  p.param_count = D == 3 ? 2 : 1;
  return p;
}

template <int D>
std::string PlaneWall<D>::describe() const {
  if constexpr (D == 2)
    return fmt::format("plane point=({}, {}) normal=({}, {})", point_[0], point_[1], normal_[0],
                       normal_[1]);
  else
    return fmt::format("plane point=({}, {}, {}) normal=({}, {}, {})", point_[0], point_[1],
                       point_[2], normal_[0], normal_[1], normal_[2]);
}

template <int D>
double PlaneWall<D>::min_radius_of_curvature() const {
  return std::numeric_limits<double>::infinity();
}

template <int D>
WallPtr<D> make_plane_wall(const YAML::Node& node, const std::string& file,
                           const std::string& key) {
  check_wall_keys(node, {"point", "normal"}, file, key);
  const VecD<D> point = yaml::read_key(node, "point", file, key, yaml::read_vec<D>);
  const VecD<D> normal = yaml::read_key(node, "normal", file, key, yaml::read_direction<D>);
  return std::make_shared<PlaneWall<D>>(point, normal);
}

template class PlaneWall<2>;
template class PlaneWall<3>;
template WallPtr<2> make_plane_wall<2>(const YAML::Node&, const std::string&, const std::string&);
template WallPtr<3> make_plane_wall<3>(const YAML::Node&, const std::string&, const std::string&);

}  // namespace curvsph
