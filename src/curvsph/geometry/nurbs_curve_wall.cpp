#include "curvsph/geometry/nurbs_curve_wall.hpp"

#include <fmt/format.h>

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
  return w;
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
