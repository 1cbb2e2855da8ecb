#include "curvsph/analysis/poiseuille_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <vector>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/moving_wall.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/wall_parser.hpp"

namespace curvsph {

ChannelSetup channel_from_case(const Case& c, const std::string& key) {
  const std::string file = c.file_name();
  if (c.dimension != 2) throw InputError(file, key, "plane Poiseuille flow is implemented in 2-D");
  const YAML::Node wn = c.root["walls"];
  if (!wn || !wn.IsSequence())
    throw InputError(file, key, "needs two parallel plane walls in `walls:`");
  const WallSet<2> walls = parse_walls<2>(wn, file, c.file.parent_path());
  std::vector<std::pair<const PlaneWall<2>*, std::size_t>> planes;
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (const auto* p = dynamic_cast<const PlaneWall<2>*>(&walls[k].body()))
      planes.push_back({p, k});
  if (planes.size() != 2)
    throw InputError(file, key,
                     fmt::format("needs exactly two plane walls (the case has {})", planes.size()));
  const PlaneWall<2>& a = *planes[0].first;
  const PlaneWall<2>& b = *planes[1].first;
  if (a.normal().dot(b.normal()) > -1 + 1e-9)
    throw InputError(file, key, "the two plane walls must be parallel and face each other");
  ChannelSetup s;
  s.origin = a.point();
  s.normal = a.normal();
  s.flow.H = (b.point() - a.point()).dot(a.normal());
  if (!(s.flow.H > 0)) throw InputError(file, key, "the fluid between the plane walls is empty");
  s.along = Vec2d(-s.normal.y(), s.normal.x());
  if (s.along.x() < 0 || (s.along.x() == 0 && s.along.y() < 0)) s.along = -s.along;
  const auto& fl = c.fluids.at(0);
  s.flow.nu = fl.viscosity / fl.rho0;
  if (!(s.flow.nu > 0)) throw InputError(file, key, "needs a viscosity > 0 in fluids.0");
  s.flow.g = c.gravity.head<2>().dot(s.along);
  if (c.drive) {
    if (std::abs(s.along.x()) < 1 - 1e-12)
      throw InputError(file, key, "forcing.drive acts along x: the walls must be parallel to x");
    s.flow.drive = true;
    s.flow.v0 = c.drive_v0;
    s.flow.tau = c.drive_tau;
  }
  double* speeds[2] = {&s.flow.u0, &s.flow.u1};
  for (int w = 0; w < 2; ++w) {
    const Wall<2>& wall = walls[planes[w].second];  // the motion is the (moving) wall's
    if (wall.motion.kind == WallMotion<2>::Kind::rotate ||
        wall.motion.kind == WallMotion<2>::Kind::oscillate ||
        (wall.moves() && !motion_leaves_shape(wall.body(), wall.motion)))
      throw InputError(
          file, fmt::format("walls.{}.motion", planes[w].second),
          "a channel wall may translate along itself at a constant speed, not rotate or oscillate");
    *speeds[w] = wall.motion.velocity_at(a.point()).dot(s.along);
  }
  return s;
}

namespace {

class PoiseuilleAnalysis final : public Analysis<2> {
 public:
  explicit PoiseuilleAnalysis(ChannelSetup s) : s_(s) {}

  void observe(double t, const Particles<2>& P) override {
    times_.push_back(t);
    errors_.push_back(error(P));
  }

  void finish(double /*t*/, const Particles<2>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    m["velocity_l2_error"] = error(P);
    double vmax = 0, vref = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      vmax = std::max(vmax, static_cast<double>(P.v[i].cast<double>().dot(s_.along)));
      vref = std::max(vref, s_.flow.velocity(y_of(P, i)));
    }
    m["velocity_max"] = vmax;
    m["velocity_max_reference"] = vref;
    m["channel_height"] = s_.flow.H;
    if (out_dir.empty()) return;
    {
      std::ofstream csv(out_dir / "poiseuille_error.csv");
      csv << "time,velocity_l2_error\n";
      for (std::size_t k = 0; k < times_.size(); ++k)
        csv << fmt::format("{:.9g},{:.9g}\n", times_[k], errors_[k]);
    }
    std::ofstream csv(out_dir / "poiseuille_profile.csv");
    csv << "y,u,v,u_exact\n";
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Vec2d v = P.v[i].cast<double>();
      const double y = y_of(P, i);
      csv << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", y, v.dot(s_.along), v.dot(s_.normal),
                         s_.flow.velocity(y));
    }
  }

  nlohmann::json save_state() const override { return {{"times", times_}, {"errors", errors_}}; }
  void load_state(const nlohmann::json& s) override {
    s.at("times").get_to(times_);
    s.at("errors").get_to(errors_);
  }

 private:
  double y_of(const Particles<2>& P, std::size_t i) const {
    return (P.x[i].cast<double>() - s_.origin).dot(s_.normal);
  }

  double error(const Particles<2>& P) const {
    double e2 = 0, r2 = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Vec2d ue = s_.flow.velocity(y_of(P, i)) * s_.along;
      e2 += (P.v[i].cast<double>() - ue).squaredNorm();
      r2 += ue.squaredNorm();
    }
    return r2 > 0 ? std::sqrt(e2 / r2) : std::sqrt(e2 / std::max<std::size_t>(P.size(), 1));
  }

  ChannelSetup s_;
  std::vector<double> times_, errors_;
};

}  // namespace

std::unique_ptr<Analysis<2>> make_poiseuille_analysis(const YAML::Node& params, const Case& c) {
  if (params && !params.IsNull() && !(params.IsMap() && params.size() == 0))
    throw InputError(c.file_name(), "analysis.poiseuille",
                     "takes no parameters (the reference comes from the walls, gravity and "
                     "fluids.0); write {}");
  return std::make_unique<PoiseuilleAnalysis>(channel_from_case(c, "analysis.poiseuille"));
}

}  // namespace curvsph
