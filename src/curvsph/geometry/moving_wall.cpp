#include "curvsph/geometry/moving_wall.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/sphere.hpp"

namespace curvsph {
namespace {

// Relative tolerance of the invariance tests: a motion given to round-off in the case file.
constexpr double kSame = 1e-12;

bool same_point(const VecD<2>& a, const VecD<2>& b, double scale) {
  return (a - b).norm() <= kSame * (1.0 + scale);
}
bool same_point(const VecD<3>& a, const VecD<3>& b, double scale) {
  return (a - b).norm() <= kSame * (1.0 + scale);
}
// Unit vectors parallel or antiparallel.
bool parallel(const Vec3d& a, const Vec3d& b) {
  return a.cross(b).norm() <= kSame;
}

}  // namespace

template <int D>
Eigen::Matrix<double, D, D> motion_rotation(const WallMotion<D>& m, double t) {
  if (m.kind != WallMotion<D>::Kind::rotate) return Eigen::Matrix<double, D, D>::Identity();
  const double angle = m.omega * t;
  if constexpr (D == 2) {
    return Eigen::Rotation2D<double>(angle).toRotationMatrix();
  } else {
    return Eigen::AngleAxisd(angle, m.axis.normalized()).toRotationMatrix();
  }
}

template <int D>
bool motion_leaves_shape(const Wall<D>& wall, const WallMotion<D>& m) {
  using K = typename WallMotion<D>::Kind;
  if (m.kind == K::none) return true;
  // Sliding along a plane (translation or oscillation tangential to it).
  if (const auto* p = dynamic_cast<const PlaneWall<D>*>(&wall)) {
    const VecD<D> dir = m.kind == K::translate ? m.velocity : m.amplitude;
    return m.kind != K::rotate && std::abs(dir.dot(p->normal())) <= kSame * dir.norm();
  }
  if constexpr (D == 2) {
    if (const auto* c = dynamic_cast<const CircleWall*>(&wall))
      return m.kind == K::rotate && same_point(m.center, c->center(), c->center().norm());
  } else {
    if (const auto* s = dynamic_cast<const SphereWall*>(&wall))
      return m.kind == K::rotate && same_point(m.center, s->center(), s->center().norm());
    if (const auto* c = dynamic_cast<const CylinderWall*>(&wall)) {
      const Vec3d a = c->axis().normalized();
      if (m.kind == K::rotate) {
        const Vec3d r = m.center - c->point();
        const bool on_axis = (r - r.dot(a) * a).norm() <= kSame * (1.0 + c->point().norm());
        return on_axis && parallel(m.axis.normalized(), a);
      }
      const Vec3d dir = m.kind == K::translate ? m.velocity : m.amplitude;
      return (dir - dir.dot(a) * a).norm() <= kSame * dir.norm();
    }
  }
  return false;
}

template <int D>
MovingWall<D>::MovingWall(WallPtr<D> inner, const WallMotion<D>& motion)
    : inner_(std::move(inner)), geometry_moves_(!motion_leaves_shape(*inner_, motion)) {
  this->motion = motion;
  set_time(0.0);
}

template <int D>
void MovingWall<D>::set_time(double t) {
  t_ = t;
  if (!geometry_moves_) return;  // R = I, s = 0 for ever
  R_ = motion_rotation(this->motion, t);
  if (this->motion.kind == WallMotion<D>::Kind::rotate)
    s_ = this->motion.center - R_ * this->motion.center;
  else
    s_ = this->motion.displacement(t);
}

template <int D>
WallPoint<D> MovingWall<D>::closest(const VecD<D>& x, const ParamSeed& seed) const {
  if (!geometry_moves_) return inner_->closest(x, seed);
  WallPoint<D> p = inner_->closest(to_body(x), seed);
  p.foot = to_world(p.foot);
  p.normal = R_ * p.normal;
  p.dir1 = R_ * p.dir1;
  p.dir2 = R_ * p.dir2;
  return p;
}

template <int D>
std::string MovingWall<D>::describe() const {
  using K = typename WallMotion<D>::Kind;
  const char* what = this->motion.kind == K::rotate      ? "rotating"
                     : this->motion.kind == K::translate ? "translating"
                                                         : "oscillating";
  return inner_->describe() + " (" + what + ")";
}

template class MovingWall<2>;
template class MovingWall<3>;
template Eigen::Matrix<double, 2, 2> motion_rotation<2>(const WallMotion<2>&, double);
template Eigen::Matrix<double, 3, 3> motion_rotation<3>(const WallMotion<3>&, double);
template bool motion_leaves_shape<2>(const Wall<2>&, const WallMotion<2>&);
template bool motion_leaves_shape<3>(const Wall<3>&, const WallMotion<3>&);

}  // namespace curvsph
