#pragma once
// NURBS curve of any degree (<= kMaxDegree) in 2-D or 3-D with non-uniform knots and
// rational weights. Points and derivatives follow Piegl & Tiller: homogeneous derivatives
// from DersBasisFuns (A2.3, A3.2), then the quotient rule for rational curves (A4.2).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/nurbs/basis.hpp"

namespace curvsph::nurbs {

template <int D>
struct CurveDerivs {
  VecD<D> c = VecD<D>::Zero();   // C(t)
  VecD<D> d1 = VecD<D>::Zero();  // C'(t)
  VecD<D> d2 = VecD<D>::Zero();  // C''(t)
};

template <int D>
class NurbsCurve {
 public:
  static_assert(D == 2 || D == 3);
  using Point = VecD<D>;
  using HPoint = Eigen::Matrix<double, D + 1, 1>;  // (w P, w)

  // Validates the data (throws InputError naming ctx.key("knots") etc.). Empty weights
  // mean all 1 (a non-rational B-spline).
  NurbsCurve(int degree, std::vector<Point> ctrl, std::vector<double> weights,
             std::vector<double> knots, const InputContext& ctx = {});

  CurveDerivs<D> eval(double t) const;  // C, C', C'' (A4.2)
  Point point(double t) const;          // C only (A4.1)

  int degree() const { return p_; }
  const std::vector<Point>& control_points() const { return ctrl_; }
  const std::vector<double>& weights() const { return w_; }
  const std::vector<double>& knots() const { return U_; }
  const std::vector<HPoint>& homogeneous() const { return pw_; }
  double t0() const { return U_[p_]; }
  double t1() const { return U_[ctrl_.size()]; }
  // C(t0) == C(t1) within 1e-12 of the size: projections then wrap across the seam.
  bool closed() const { return closed_; }
  // Diagonal of the control points' bounding box: the length scale for tolerances.
  double size() const { return size_; }

 private:
  int p_;
  std::vector<Point> ctrl_;
  std::vector<double> w_;
  std::vector<double> U_;
  std::vector<HPoint> pw_;
  bool closed_ = false;
  double size_ = 0.0;
};

// 2-D signed curvature (C' x C'')/|C'|^3: > 0 where the curve turns left (counter-clockwise)
// with increasing parameter. As a wall with the fluid on the left this is the DESIGN.md §4
// curvature (fluid inside a counter-clockwise circle: +1/R); fluid on the right flips it.
double signed_curvature(const CurveDerivs<2>& d);
// Unsigned curvature |C' x C''|/|C'|^3 (any dimension).
template <int D>
double curvature(const CurveDerivs<D>& d);

extern template class NurbsCurve<2>;
extern template class NurbsCurve<3>;

}  // namespace curvsph::nurbs
