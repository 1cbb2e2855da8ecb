#include "curvsph/geometry/nurbs_curve_wall.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "curvsph/core/error.hpp"
#include "curvsph/nurbs/yaml_input.hpp"

namespace curvsph {

NurbsCurveWall::NurbsCurveWall(nurbs::NurbsCurve<2> curve, Side fluid, double tolerance)
    : curve_(std::make_unique<nurbs::NurbsCurve<2>>(std::move(curve))),
      proj_(std::make_unique<nurbs::CurveProjector<2>>(*curve_)),
      side_(fluid) {
  set_tolerance(tolerance);
  // Smallest radius of curvature: dense sampling of |kappa| per knot span.
  double kmax = 0.0;
  const auto& U = curve_->knots();
  for (std::size_t k = 0; k + 1 < U.size(); ++k) {
    if (!(U[k + 1] > U[k]) || U[k + 1] <= curve_->t0() || U[k] >= curve_->t1()) continue;
    for (int i = 0; i <= 64; ++i)
      kmax = std::max(kmax, nurbs::curvature(curve_->eval(U[k] + (U[k + 1] - U[k]) * i / 64.0)));
  }
  min_radius_ = kmax > 0.0 ? 1.0 / kmax : std::numeric_limits<double>::infinity();
  // Degree 1: the curve passes through every control point (the Greville abscissae of degree
  // 1 are knots) and is straight between them, whatever the weights.
  if (curve_->degree() == 1) {
    const auto& P = curve_->control_points();
    const double s = side_ == Side::left ? 1.0 : -1.0;
    for (std::size_t k = 0; k + 1 < P.size(); ++k) {
      const Vec2d t = P[k + 1] - P[k];
      if (!(t.norm() > 0.0)) continue;
      facets_.push_back({P[k], P[k + 1], s * Vec2d(-t.y(), t.x()).normalized()});
    }
  }
}

int NurbsCurveWall::facets_near(const Vec2d& x, double reach, WallFacet<2>* out, int max) const {
  if (facets_.empty()) return -1;
  int n = 0;
  for (const WallFacet<2>& f : facets_) {
    const Vec2d t = f.b - f.a;
    const double u = std::clamp((x - f.a).dot(t) / t.squaredNorm(), 0.0, 1.0);
    if ((x - (f.a + u * t)).norm() < reach && n < max) out[n++] = f;
  }
  return n;
}

WallPoint<2> NurbsCurveWall::closest(const Vec2d& x, const ParamSeed& seed) const {
  const nurbs::Projection pr = proj_->project(x, seed.valid ? &seed.param[0] : nullptr, tol_);
  const nurbs::CurveDerivs<2> d = curve_->eval(pr.param[0]);
  const double s = side_ == Side::left ? 1.0 : -1.0;
  WallPoint<2> w;
  w.foot = d.c;
  w.normal = s * Vec2d(-d.d1.y(), d.d1.x()).normalized();  // left normal, Barker eq. 37
  const double r_n = (x - d.c).dot(w.normal);
  w.distance = std::copysign((x - d.c).norm(), r_n);
  w.k1 = s * nurbs::signed_curvature(d);
  w.k2 = 0.0;
  w.param = {pr.param[0], 0.0};
  w.param_count = 1;
  w.iterations = pr.iterations;
  if (!facets_.empty()) polygon_vertex(x, w);
  return w;
}

// A polygon's kink: one side's normal can put a point on the wrong side there (outside an acute
// corner, beside the vertex, the floor's normal sees it above the floor). The angle-weighted
// pseudo-normal, here the sum of the two faces' normals, decides (Baerentzen & Aanaes 2005, in
// 2-D), and the normal is along foot -> point, flat, as box corners give.
void NurbsCurveWall::polygon_vertex(const Vec2d& x, WallPoint<2>& w) const {
  const double tie = 1e-9 * curve_->size();
  for (std::size_t k = 0; k + 1 < facets_.size(); ++k) {
    const Vec2d& v = facets_[k].b;
    if ((w.foot - v).norm() > tie || (facets_[k + 1].a - v).norm() > tie) continue;
    const Vec2d pseudo = facets_[k].normal + facets_[k + 1].normal;
    if (facets_[k].normal.dot(facets_[k + 1].normal) > 1.0 - 1e-12) return;  // collinear
    const Vec2d d = x - v;
    const double len = d.norm();
    const double sign = d.dot(pseudo) >= 0 ? 1.0 : -1.0;
    w.foot = v;
    w.distance = sign * len;
    if (len > tie) w.normal = sign * d / len;
    w.k1 = 0.0;
    return;
  }
}

std::string NurbsCurveWall::describe() const {
  return fmt::format("nurbs_curve degree={} control_points={} fluid={}", curve_->degree(),
                     curve_->control_points().size(), side_ == Side::left ? "left" : "right");
}

WallPtr<2> make_nurbs_curve_wall(const YAML::Node& node, const std::string& file,
                                 const std::string& key_prefix) {
  using namespace nurbs::yaml;
  const nurbs::InputContext ctx{file, key_prefix};
  reject_unknown_keys(node,
                      {"shape", "degree", "control_points", "weights", "knots", "fluid", "motion",
                       "name", "tolerance"},
                      ctx);
  const int degree = read_int(node, "degree", ctx);
  const YAML::Node cp = require(node, "control_points", ctx);
  if (!cp.IsSequence()) throw InputError(file, ctx.key("control_points"), "expected a list");
  std::vector<Vec2d> ctrl;
  for (std::size_t i = 0; i < cp.size(); ++i)
    ctrl.push_back(read_point<2>(cp[i], fmt::format("control_points.{}", i), ctx));
  std::vector<double> weights;
  if (node["weights"]) weights = read_doubles(node["weights"], "weights", ctx);
  const std::vector<double> knots = read_doubles(require(node, "knots", ctx), "knots", ctx);
  const std::string side = read_choice(node, "fluid", {"left", "right"}, ctx);
  double tol = 0.0;
  if (node["tolerance"]) tol = read_double(node["tolerance"], "tolerance", ctx);
  nurbs::NurbsCurve<2> curve(degree, std::move(ctrl), std::move(weights), knots, ctx);
  return std::make_shared<NurbsCurveWall>(
      std::move(curve), side == "left" ? NurbsCurveWall::Side::left : NurbsCurveWall::Side::right,
      tol);
}

}  // namespace curvsph
