#include "curvsph/geometry/box.hpp"

#include <fmt/format.h>

#include <limits>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_yaml.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

template <int D>
BoxWall<D>::BoxWall(const VecD<D>& min, const VecD<D>& max, FluidSide side)
    : min_(min), max_(max), side_(side) {}

template <int D>
WallPoint<D> BoxWall<D>::closest(const VecD<D>& x, const ParamSeed&) const {
  WallPoint<D> p;
  const VecD<D> clamped = x.cwiseMax(min_).cwiseMin(max_);
  int clamped_axes = 0;
  for (int i = 0; i < D; ++i) clamped_axes += clamped[i] != x[i] ? 1 : 0;

  VecD<D> outward;
  double dist_outside;
  if (clamped_axes > 0) {
    p.foot = clamped;
    const VecD<D> r = x - clamped;
    dist_outside = r.norm();
    outward = r / dist_outside;
  } else {
    // Inside or on the boundary: the nearest face; ties go to the first face in order.
    int axis = 0;
    double best = std::numeric_limits<double>::infinity();
    double sign = -1.0;
    for (int i = 0; i < D; ++i) {
      if (x[i] - min_[i] < best) best = x[i] - min_[i], axis = i, sign = -1.0;
      if (max_[i] - x[i] < best) best = max_[i] - x[i], axis = i, sign = 1.0;
    }
    p.foot = x;
    p.foot[axis] = sign < 0 ? min_[axis] : max_[axis];
    outward = VecD<D>::Unit(axis) * sign;
    dist_outside = -best;
  }
  apply_side(p, side_, outward, dist_outside, 0.0, 0.0);
  if constexpr (D == 2) {
    p.dir1 = perp(p.normal);
  } else {
    // On an edge region the edge direction is the natural first tangent.
    int free_axis = -1;
    if (clamped_axes == 2)
      for (int i = 0; i < 3; ++i)
        if (clamped[i] == x[i]) free_axis = i;
    if (free_axis >= 0) {
      p.dir1 = Vec3d::Unit(free_axis);
      p.dir2 = p.normal.cross(p.dir1);
    } else {
      std::tie(p.dir1, p.dir2) = orthonormal_frame(p.normal);
    }
  }
  return p;
}

template <int D>
std::string BoxWall<D>::describe() const {
  std::string lo, hi;
  for (int i = 0; i < D; ++i) {
    lo += fmt::format("{}{}", i ? ", " : "", min_[i]);
    hi += fmt::format("{}{}", i ? ", " : "", max_[i]);
  }
  return fmt::format("box min=({}) max=({}) fluid {}", lo, hi, to_string(side_));
}

template <int D>
double BoxWall<D>::min_radius_of_curvature() const {
  return std::numeric_limits<double>::infinity();
}

template <int D>
WallPtr<D> make_box_wall(const YAML::Node& node, const std::string& file, const std::string& key) {
  check_wall_keys(node, {"min", "max", "fluid"}, file, key);
  const VecD<D> lo = yaml::read_key(node, "min", file, key, yaml::read_vec<D>);
  const VecD<D> hi = yaml::read_key(node, "max", file, key, yaml::read_vec<D>);
  for (int i = 0; i < D; ++i)
    if (!(lo[i] < hi[i]))
      throw InputError(file, yaml::join(key, "max"),
                       fmt::format("min must be < max in every axis (axis {}: min {} >= max {})", i,
                                   lo[i], hi[i]));
  return std::make_shared<BoxWall<D>>(lo, hi, read_fluid_side(node, file, key));
}

template class BoxWall<2>;
template class BoxWall<3>;
template WallPtr<2> make_box_wall<2>(const YAML::Node&, const std::string&, const std::string&);
template WallPtr<3> make_box_wall<3>(const YAML::Node&, const std::string&, const std::string&);

}  // namespace curvsph
