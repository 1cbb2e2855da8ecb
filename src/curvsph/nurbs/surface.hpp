#pragma once
// NURBS surface (3-D) of any degrees (<= kMaxDegree) with non-uniform knots and rational
// weights. Derivatives: homogeneous ones from DersBasisFuns in u and v (P&T A3.6), then the
// rational quotient rule (A4.4). Principal curvatures from the first and second
// fundamental forms (do Carmo §3-3; P&T eq. 2.x not needed).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/nurbs/basis.hpp"

namespace curvsph::nurbs {

struct SurfaceDerivs {
  Vec3d s = Vec3d::Zero();
  Vec3d su = Vec3d::Zero(), sv = Vec3d::Zero();
  Vec3d suu = Vec3d::Zero(), suv = Vec3d::Zero(), svv = Vec3d::Zero();
};

struct PrincipalCurvatures {
  double k1 = 0.0, k2 = 0.0;  // k1 >= k2
  Vec3d dir1 = Vec3d::Zero(), dir2 = Vec3d::Zero();
};

// Principal curvatures with respect to the unit normal n: kappa > 0 where the surface bends
// toward n (so with n pointing into the fluid this is the DESIGN.md §4 convention: fluid
// inside a sphere gives +1/R). Eigen-pairs of I^{-1} II with II measured along n.
PrincipalCurvatures principal_curvatures(const SurfaceDerivs& d, const Vec3d& n);

class NurbsSurface {
 public:
  using HPoint = Eigen::Vector4d;  // (w P, w)

  // ctrl[i][j]: i along u (rows), j along v. Empty weights mean all 1.
  NurbsSurface(int degree_u, int degree_v, const std::vector<std::vector<Vec3d>>& ctrl,
               const std::vector<std::vector<double>>& weights, std::vector<double> knots_u,
               std::vector<double> knots_v, const InputContext& ctx = {});

  SurfaceDerivs eval(double u, double v) const;  // S and derivatives up to order 2 (A4.4)
  Vec3d point(double u, double v) const;

  int degree_u() const { return p_; }
  int degree_v() const { return q_; }
  int count_u() const { return nu_; }
  int count_v() const { return nv_; }
  const std::vector<double>& knots_u() const { return U_; }
  const std::vector<double>& knots_v() const { return V_; }
  // Row-major homogeneous control net: index i * count_v() + j.
  const std::vector<HPoint>& homogeneous() const { return pw_; }
  Vec3d control_point(int i, int j) const {
    const HPoint& h = pw_[i * nv_ + j];
    return h.head<3>() / h[3];
  }
  double weight(int i, int j) const { return pw_[i * nv_ + j][3]; }
  double u0() const { return U_[p_]; }
  double u1() const { return U_[nu_]; }
  double v0() const { return V_[q_]; }
  double v1() const { return V_[nv_]; }
  // Seams: S(u0, v) == S(u1, v) (closed_u) or S(u, v0) == S(u, v1) (closed_v) at sample
  // parameters within 1e-12 of the size; projections then wrap.
  bool closed_u() const { return closed_u_; }
  bool closed_v() const { return closed_v_; }
  double size() const { return size_; }

 private:
  int p_, q_, nu_, nv_;
  std::vector<double> U_, V_;
  std::vector<HPoint> pw_;
  bool closed_u_ = false, closed_v_ = false;
  double size_ = 1.0;
};

}  // namespace curvsph::nurbs
