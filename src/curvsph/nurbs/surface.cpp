#include "curvsph/nurbs/surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "curvsph/core/error.hpp"

namespace curvsph::nurbs {

NurbsSurface::NurbsSurface(int degree_u, int degree_v, const std::vector<std::vector<Vec3d>>& ctrl,
                           const std::vector<std::vector<double>>& weights,
                           std::vector<double> knots_u, std::vector<double> knots_v,
                           const InputContext& ctx)
    : p_(degree_u), q_(degree_v), U_(std::move(knots_u)), V_(std::move(knots_v)) {
  nu_ = static_cast<int>(ctrl.size());
  nv_ = nu_ > 0 ? static_cast<int>(ctrl[0].size()) : 0;
  for (int i = 0; i < nu_; ++i)
    if (static_cast<int>(ctrl[i].size()) != nv_)
      throw InputError(ctx.file, ctx.key(fmt::format("control_points.{}", i)),
                       fmt::format("row has {} points, row 0 has {}", ctrl[i].size(), nv_));
  if (!weights.empty()) {
    if (static_cast<int>(weights.size()) != nu_)
      throw InputError(
          ctx.file, ctx.key("weights"),
          fmt::format("{} weight rows for {} control-point rows", weights.size(), nu_));
    for (int i = 0; i < nu_; ++i) {
      if (static_cast<int>(weights[i].size()) != nv_)
        throw InputError(ctx.file, ctx.key(fmt::format("weights.{}", i)),
                         fmt::format("{} weights for {} control points", weights[i].size(), nv_));
      for (int j = 0; j < nv_; ++j)
        if (!(weights[i][j] > 0.0) || !std::isfinite(weights[i][j]))
          throw InputError(ctx.file, ctx.key(fmt::format("weights.{}.{}", i, j)),
                           fmt::format("weight is {}, weights must be > 0", weights[i][j]));
    }
  }
  if (!weights.empty()) {
    double wmin = weights[0][0], wmax = wmin;
    for (const auto& row : weights)
      for (double w : row) wmin = std::min(wmin, w), wmax = std::max(wmax, w);
    // As for curves: beyond a ratio of 1e12 the surface collapses onto one control point.
    if (wmax > kMaxWeightRatio * wmin)
      throw InputError(ctx.file, ctx.key("weights"),
                       fmt::format("largest / smallest weight is {:.3g}, at most {:.0g}",
                                   wmax / wmin, kMaxWeightRatio));
  }
  validate_knots(U_, p_, nu_, ctx, "knots_u");
  validate_knots(V_, q_, nv_, ctx, "knots_v");
  pw_.resize(static_cast<std::size_t>(nu_ * nv_));
  Vec3d lo = ctrl[0][0], hi = ctrl[0][0];
  for (int i = 0; i < nu_; ++i)
    for (int j = 0; j < nv_; ++j) {
      const Vec3d& c = ctrl[i][j];
      if (!c.allFinite())
        throw InputError(ctx.file, ctx.key(fmt::format("control_points.{}.{}", i, j)),
                         "control point is not finite");
      const double w = weights.empty() ? 1.0 : weights[i][j];
      pw_[i * nv_ + j] << w * c, w;
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
  size_ = (hi - lo).norm();
  if (!(size_ > kMinRelativeExtent * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff())))
    throw InputError(ctx.file, ctx.key("control_points"),
                     "all control points coincide: the surface is a point");
  const double tol = 1e-12 * size_;
  closed_u_ = closed_v_ = true;
  for (int k = 0; k <= 4; ++k) {
    const double a = u0() + (u1() - u0()) * k / 4.0, b = v0() + (v1() - v0()) * k / 4.0;
    if ((point(u0(), b) - point(u1(), b)).norm() > tol) closed_u_ = false;
    if ((point(a, v0()) - point(a, v1())).norm() > tol) closed_v_ = false;
  }
}

SurfaceDerivs NurbsSurface::eval(double u, double v) const {
  const int su = find_span(nu_ - 1, p_, u, U_.data());
  const int sv = find_span(nv_ - 1, q_, v, V_.data());
  double Nu[3][kMaxOrder], Nv[3][kMaxOrder];
  ders_basis_funs(su, u, p_, 2, U_.data(), Nu);
  ders_basis_funs(sv, v, q_, 2, V_.data(), Nv);
  // A[k][l] = d^{k+l} Sw / du^k dv^l for k + l <= 2 (P&T A3.6 on homogeneous points).
  HPoint A[3][3];
  for (auto& row : A)
    for (auto& a : row) a.setZero();
  for (int i = 0; i <= p_; ++i) {
    HPoint t[3] = {HPoint::Zero(), HPoint::Zero(), HPoint::Zero()};
    const HPoint* row = &pw_[(su - p_ + i) * nv_ + (sv - q_)];
    for (int j = 0; j <= q_; ++j) {
      t[0] += Nv[0][j] * row[j];
      t[1] += Nv[1][j] * row[j];
      t[2] += Nv[2][j] * row[j];
    }
    A[0][0] += Nu[0][i] * t[0];
    A[0][1] += Nu[0][i] * t[1];
    A[0][2] += Nu[0][i] * t[2];
    A[1][0] += Nu[1][i] * t[0];
    A[1][1] += Nu[1][i] * t[1];
    A[2][0] += Nu[2][i] * t[0];
  }
  // A4.4 (quotient rule) written out for k + l <= 2.
  const double w = A[0][0][3], wu = A[1][0][3], wv = A[0][1][3];
  const double wuu = A[2][0][3], wuv = A[1][1][3], wvv = A[0][2][3];
  SurfaceDerivs d;
  d.s = A[0][0].head<3>() / w;
  d.su = (A[1][0].head<3>() - wu * d.s) / w;
  d.sv = (A[0][1].head<3>() - wv * d.s) / w;
  d.suu = (A[2][0].head<3>() - 2.0 * wu * d.su - wuu * d.s) / w;
  d.svv = (A[0][2].head<3>() - 2.0 * wv * d.sv - wvv * d.s) / w;
  d.suv = (A[1][1].head<3>() - wu * d.sv - wv * d.su - wuv * d.s) / w;
  return d;
}

Vec3d NurbsSurface::point(double u, double v) const {
  const int su = find_span(nu_ - 1, p_, u, U_.data());
  const int sv = find_span(nv_ - 1, q_, v, V_.data());
  double Nu[kMaxOrder], Nv[kMaxOrder];
  basis_funs(su, u, p_, U_.data(), Nu);
  basis_funs(sv, v, q_, V_.data(), Nv);
  HPoint a = HPoint::Zero();
  for (int i = 0; i <= p_; ++i) {
    HPoint t = HPoint::Zero();
    const HPoint* row = &pw_[(su - p_ + i) * nv_ + (sv - q_)];
    for (int j = 0; j <= q_; ++j) t += Nv[j] * row[j];
    a += Nu[i] * t;
  }
  return a.head<3>() / a[3];
}

PrincipalCurvatures principal_curvatures(const SurfaceDerivs& d, const Vec3d& n) {
  const double E = d.su.dot(d.su), F = d.su.dot(d.sv), G = d.sv.dot(d.sv);
  const double L = d.suu.dot(n), M = d.suv.dot(n), N = d.svv.dot(n);
  const double det = E * G - F * F;
  const double H = (E * N - 2.0 * F * M + G * L) / (2.0 * det);  // mean curvature
  const double K = (L * N - M * M) / det;                        // Gauss curvature
  const double disc = std::sqrt(std::max(0.0, H * H - K));
  PrincipalCurvatures c;
  c.k1 = H + disc;
  c.k2 = H - disc;
  // Principal direction a*Su + b*Sv solves (II - k1 I)(a, b) = 0; take the better row.
  const double r1a = L - c.k1 * E, r1b = M - c.k1 * F;
  const double r2a = M - c.k1 * F, r2b = N - c.k1 * G;
  double a, b;
  if (r1a * r1a + r1b * r1b >= r2a * r2a + r2b * r2b) {
    a = -r1b;
    b = r1a;
  } else {
    a = r2b;
    b = -r2a;
  }
  Vec3d t = a * d.su + b * d.sv;
  // Umbilic (k1 == k2, planes and spheres): every tangent direction is principal.
  if (disc <= 1e-10 * std::abs(H) || t.squaredNorm() == 0.0) t = d.su;
  c.dir1 = t.normalized();
  c.dir2 = n.cross(c.dir1).normalized();
  return c;
}

}  // namespace curvsph::nurbs
