#include "curvsph/geometry/nurbs_surface_wall.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "curvsph/core/error.hpp"
#include "curvsph/nurbs/yaml_input.hpp"

namespace curvsph {

NurbsSurfaceWall::NurbsSurfaceWall(nurbs::NurbsSurface surface, Side fluid, double tolerance)
    : surf_(std::make_unique<nurbs::NurbsSurface>(std::move(surface))),
      proj_(std::make_unique<nurbs::SurfaceProjector>(*surf_)),
      side_(fluid) {
  set_tolerance(tolerance);
  // Smallest radius of curvature: |kappa| on a grid of 16 x 16 points per knot-span pair.
  double kmax = 0.0;
  const auto& U = surf_->knots_u();
  const auto& V = surf_->knots_v();
  for (std::size_t a = 0; a + 1 < U.size(); ++a) {
    if (!(U[a + 1] > U[a]) || U[a + 1] <= surf_->u0() || U[a] >= surf_->u1()) continue;
    for (std::size_t b = 0; b + 1 < V.size(); ++b) {
      if (!(V[b + 1] > V[b]) || V[b + 1] <= surf_->v0() || V[b] >= surf_->v1()) continue;
      for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 16; ++j) {
          const double u = U[a] + (U[a + 1] - U[a]) * i / 16.0;
          const double v = V[b] + (V[b + 1] - V[b]) * j / 16.0;
          const nurbs::SurfaceDerivs d = surf_->eval(u, v);
          const Vec3d n = d.su.cross(d.sv);
          if (n.norm() <= 1e-12 * d.su.norm() * d.sv.norm() || !n.allFinite()) continue;
          const nurbs::PrincipalCurvatures c = nurbs::principal_curvatures(d, n.normalized());
          kmax = std::max({kmax, std::abs(c.k1), std::abs(c.k2)});
        }
    }
  }
  min_radius_ = kmax > 0.0 ? 1.0 / kmax : std::numeric_limits<double>::infinity();
}

WallPoint<3> NurbsSurfaceWall::at(double u, double v, const Vec3d& x) const {
  const nurbs::SurfaceDerivs d = surf_->eval(u, v);
  const double s = side_ == Side::front ? 1.0 : -1.0;
  Vec3d n = s * d.su.cross(d.sv);
  WallPoint<3> w;
  w.foot = d.s;
  const Vec3d r = x - d.s;
  if (n.norm() <= 1e-12 * d.su.norm() * d.sv.norm() || !n.allFinite()) {
    // Degenerate parametrisation (a pole): the normal is the direction to x, oriented by
    // a nearby regular point.
    const nurbs::SurfaceDerivs e =
        surf_->eval(0.999 * u + 0.001 * 0.5 * (surf_->u0() + surf_->u1()),
                    0.999 * v + 0.001 * 0.5 * (surf_->v0() + surf_->v1()));
    const Vec3d ne = s * e.su.cross(e.sv);
    n = r.norm() > 0.0 ? Vec3d(r * (r.dot(ne) >= 0.0 ? 1.0 : -1.0)) : ne;
  }
  w.normal = n.normalized();
  w.distance = std::copysign(r.norm(), r.dot(w.normal));
  const nurbs::PrincipalCurvatures c = nurbs::principal_curvatures(d, w.normal);
  w.k1 = c.k1;
  w.k2 = c.k2;
  w.dir1 = c.dir1;
  w.dir2 = c.dir2;
  w.param = {u, v};
  w.param_count = 2;
  return w;
}

WallPoint<3> NurbsSurfaceWall::closest(const Vec3d& x, const ParamSeed& seed) const {
  const nurbs::Projection pr = proj_->project(x, seed.valid ? seed.param.data() : nullptr, tol_);
  WallPoint<3> w = at(pr.param[0], pr.param[1], x);
  w.iterations = pr.iterations;
  return w;
}

std::string NurbsSurfaceWall::describe() const {
  return fmt::format("nurbs_surface{} degree=[{}, {}] control_points={}x{} fluid={}",
                     label_.empty() ? "" : " " + label_, surf_->degree_u(), surf_->degree_v(),
                     surf_->count_u(), surf_->count_v(), side_ == Side::front ? "front" : "back");
}

WallPtr<3> make_nurbs_surface_wall(const YAML::Node& node, const std::string& file,
                                   const std::string& key_prefix) {
  using namespace nurbs::yaml;
  const nurbs::InputContext ctx{file, key_prefix};
  reject_unknown_keys(node,
                      {"shape", "degree", "control_points", "weights", "knots_u", "knots_v",
                       "fluid", "motion", "name", "tolerance"},
                      ctx);
  const YAML::Node deg = require(node, "degree", ctx);
  const std::vector<double> dg = read_doubles(deg, "degree", ctx);
  if (dg.size() != 2 || dg[0] != std::floor(dg[0]) || dg[1] != std::floor(dg[1]))
    throw InputError(file, ctx.key("degree"), "expected two integers [p, q]");
  const YAML::Node cp = require(node, "control_points", ctx);
  if (!cp.IsSequence()) throw InputError(file, ctx.key("control_points"), "expected a list");
  std::vector<std::vector<Vec3d>> ctrl(cp.size());
  for (std::size_t i = 0; i < cp.size(); ++i) {
    if (!cp[i].IsSequence())
      throw InputError(file, ctx.key(fmt::format("control_points.{}", i)),
                       "expected a list of points (one row along v)");
    for (std::size_t j = 0; j < cp[i].size(); ++j)
      ctrl[i].push_back(read_point<3>(cp[i][j], fmt::format("control_points.{}.{}", i, j), ctx));
  }
  if (ctrl.empty()) throw InputError(file, ctx.key("control_points"), "no control points");
  std::vector<std::vector<double>> weights;
  if (const YAML::Node w = node["weights"]) {
    if (!w.IsSequence()) throw InputError(file, ctx.key("weights"), "expected a list of rows");
    for (std::size_t i = 0; i < w.size(); ++i)
      weights.push_back(read_doubles(w[i], fmt::format("weights.{}", i), ctx));
  }
  const std::vector<double> ku = read_doubles(require(node, "knots_u", ctx), "knots_u", ctx);
  const std::vector<double> kv = read_doubles(require(node, "knots_v", ctx), "knots_v", ctx);
  const std::string side = read_choice(node, "fluid", {"front", "back"}, ctx);
  double tol = 0.0;
  if (node["tolerance"]) tol = read_double(node["tolerance"], "tolerance", ctx);
  nurbs::NurbsSurface s(static_cast<int>(dg[0]), static_cast<int>(dg[1]), ctrl, weights, ku, kv,
                        ctx);
  return std::make_shared<NurbsSurfaceWall>(
      std::move(s), side == "front" ? NurbsSurfaceWall::Side::front : NurbsSurfaceWall::Side::back,
      tol);
}

}  // namespace curvsph
