#pragma once
// A wall that moves rigidly (DESIGN.md §3 `motion:`): a decorator around any wall (analytic,
// NURBS, CAD face or solid, STL) that holds the inner wall in its body frame — the shape as
// the case file gives it — and places it in the world at time t:
//
//   x_world = R(t) x_body + s(t)
//   translate {velocity v}:                    R = I,          s = v t
//   oscillate {amplitude A, frequency F, phi}: R = I,          s = A sin(2 pi F t + phi)
//   rotate {omega, center c[, axis a]}:        R = R_a(omega t), s = c - R c
//
// so the wall at t = 0 is the given shape (moved by A sin(phi) for an oscillation with a phase).
// Queries go through the body frame: the query point is taken to the body frame, the inner wall
// answers, and foot, normal and principal directions are taken back (normals rotate; distance,
// curvatures and surface parameters are invariant under a rigid motion). The velocity of the
// wall point x is v(t) + omega x (x - c) (WallMotion::velocity_at).
//
// Motions that leave the shape onto itself (a circle, sphere or cylinder turning about its own
// centre or axis; a plane or cylinder sliding along itself) keep the geometry in place
// (geometry_moves() is false): the wall is then exactly the static shape with a surface velocity,
// as the Couette cases want, and boundary elements need not be moved.
//
// set_time is called by the solver between passes (WallSet::set_time); queries are const and
// may run concurrently between two set_time calls.
#include <Eigen/Core>

#include "curvsph/geometry/wall.hpp"

namespace curvsph {

template <int D>
class MovingWall final : public Wall<D> {
 public:
  using Rotation = Eigen::Matrix<double, D, D>;

  // Placed at t = 0.
  MovingWall(WallPtr<D> inner, const WallMotion<D>& motion);

  WallPoint<D> closest(const VecD<D>& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override { return inner_->min_radius_of_curvature(); }
  double distance_lower_bound(const VecD<D>& x) const override {
    return inner_->distance_lower_bound(to_body(x));
  }
  bool closed_surface() const override { return inner_->closed_surface(); }
  bool moves() const override { return true; }
  void set_time(double t) override;
  VecD<D> velocity(const VecD<D>& x) const override { return this->motion.velocity_at(x, t_); }
  const Wall<D>& body() const override { return *inner_; }

  // False when the motion maps the shape onto itself (then R = I and s = 0 at every t).
  bool geometry_moves() const { return geometry_moves_; }
  double time() const { return t_; }
  const Rotation& rotation() const { return R_; }
  const VecD<D>& shift() const { return s_; }
  VecD<D> to_world(const VecD<D>& xb) const { return R_ * xb + s_; }
  VecD<D> to_body(const VecD<D>& x) const { return R_.transpose() * (x - s_); }

 private:
  WallPtr<D> inner_;
  bool geometry_moves_ = true;
  double t_ = 0.0;
  Rotation R_ = Rotation::Identity();
  VecD<D> s_ = VecD<D>::Zero();
};

// The rotation R_a(angle) of a rigid motion (2-D: about z; 3-D: about the unit axis a).
template <int D>
Eigen::Matrix<double, D, D> motion_rotation(const WallMotion<D>& m, double t);

// Whether the motion maps the wall onto itself (see above); shapes it does not know: false.
template <int D>
bool motion_leaves_shape(const Wall<D>& wall, const WallMotion<D>& m);

}  // namespace curvsph
