#include "curvsph/nurbs/curve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "curvsph/core/error.hpp"

namespace curvsph::nurbs {

template <int D>
NurbsCurve<D>::NurbsCurve(int degree, std::vector<Point> ctrl, std::vector<double> weights,
                          std::vector<double> knots, const InputContext& ctx)
    : p_(degree), ctrl_(std::move(ctrl)), w_(std::move(weights)), U_(std::move(knots)) {
  const int n = static_cast<int>(ctrl_.size());
  if (w_.empty()) w_.assign(ctrl_.size(), 1.0);
  if (w_.size() != ctrl_.size())
    throw InputError(ctx.file, ctx.key("weights"),
                     fmt::format("{} weights for {} control points", w_.size(), n));
  for (std::size_t i = 0; i < w_.size(); ++i)
    if (!(w_[i] > 0.0) || !std::isfinite(w_[i]))
      throw InputError(ctx.file, ctx.key("weights"),
                       fmt::format("weight {} is {}, weights must be > 0", i, w_[i]));
  for (std::size_t i = 0; i < ctrl_.size(); ++i)
    if (!ctrl_[i].allFinite())
      throw InputError(ctx.file, ctx.key("control_points"),
                       fmt::format("control point {} is not finite", i));
  // Weights are defined up to a common factor; beyond a ratio of 1e12 the curve collapses
  // onto the heaviest control point in double precision.
  const auto [wmin, wmax] = std::minmax_element(w_.begin(), w_.end());
  if (*wmax > kMaxWeightRatio * *wmin)
    throw InputError(ctx.file, ctx.key("weights"),
                     fmt::format("largest / smallest weight is {:.3g}, at most {:.0g}",
                                 *wmax / *wmin, kMaxWeightRatio));
  validate_knots(U_, p_, n, ctx, "knots");
  pw_.resize(ctrl_.size());
  Point lo = ctrl_[0], hi = ctrl_[0];
  for (std::size_t i = 0; i < ctrl_.size(); ++i) {
    pw_[i].template head<D>() = w_[i] * ctrl_[i];
    pw_[i][D] = w_[i];
    lo = lo.cwiseMin(ctrl_[i]);
    hi = hi.cwiseMax(ctrl_[i]);
  }
  size_ = (hi - lo).norm();
  // All control points equal: the curve is a point, with no normal or curvature.
  if (!(size_ > kMinRelativeExtent * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff())))
    throw InputError(ctx.file, ctx.key("control_points"),
                     "all control points coincide: the curve is a point");
  closed_ = (point(t0()) - point(t1())).norm() <= 1e-12 * size_;
}

template <int D>
CurveDerivs<D> NurbsCurve<D>::eval(double t) const {
  const int n = static_cast<int>(ctrl_.size()) - 1;
  const int span = find_span(n, p_, t, U_.data());
  double ders[3][kMaxOrder];
  ders_basis_funs(span, t, p_, 2, U_.data(), ders);
  HPoint a[3] = {HPoint::Zero(), HPoint::Zero(), HPoint::Zero()};
  for (int j = 0; j <= p_; ++j) {
    const HPoint& pw = pw_[span - p_ + j];
    a[0] += ders[0][j] * pw;
    a[1] += ders[1][j] * pw;
    a[2] += ders[2][j] * pw;
  }
  // A4.2 with k <= 2: C^(k) = (A^(k) - sum_i binom(k,i) w^(i) C^(k-i)) / w.
  CurveDerivs<D> r;
  const double w = a[0][D], w1 = a[1][D], w2 = a[2][D];
  r.c = a[0].template head<D>() / w;
  r.d1 = (a[1].template head<D>() - w1 * r.c) / w;
  r.d2 = (a[2].template head<D>() - 2.0 * w1 * r.d1 - w2 * r.c) / w;
  return r;
}

template <int D>
typename NurbsCurve<D>::Point NurbsCurve<D>::point(double t) const {
  const int n = static_cast<int>(ctrl_.size()) - 1;
  const int span = find_span(n, p_, t, U_.data());
  double N[kMaxOrder];
  basis_funs(span, t, p_, U_.data(), N);
  HPoint a = HPoint::Zero();
  for (int j = 0; j <= p_; ++j) a += N[j] * pw_[span - p_ + j];
  return a.template head<D>() / a[D];
}

double signed_curvature(const CurveDerivs<2>& d) {
  const double cross = d.d1.x() * d.d2.y() - d.d1.y() * d.d2.x();
  return cross / std::pow(d.d1.norm(), 3);
}

template <int D>
double curvature(const CurveDerivs<D>& d) {
  const double s = d.d1.norm();
  if constexpr (D == 2) {
    return std::abs(signed_curvature(d));
  } else {
    return d.d1.cross(d.d2).norm() / (s * s * s);
  }
}

template class NurbsCurve<2>;
template class NurbsCurve<3>;
template double curvature<2>(const CurveDerivs<2>&);
template double curvature<3>(const CurveDerivs<3>&);

}  // namespace curvsph::nurbs
