#include "curvsph/analysis/droplet_wall.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "curvsph/analysis/contact_angle_fit.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/yaml_read.hpp"
#include "curvsph/physics/contact_angle.hpp"

namespace curvsph {
namespace {

class DropletWall final : public Analysis<2> {
 public:
  DropletWall(int drop, WallSet<2> walls, std::vector<std::optional<Real>> angles, double dx,
              double fit_radius)
      : drop_(drop),
        walls_(std::move(walls)),
        angles_(std::move(angles)),
        dx_(dx),
        fit_radius_(fit_radius) {}

  void observe(double t, const Particles<2>& P) override {
    const double mass = drop_mass(P);
    if (!started_) {
      mass0_ = mass;
      started_ = true;
    }
    for (std::size_t i = 0; i < P.size(); ++i)
      if (walls_.closest(P.x[i].cast<double>()).distance <= 0) ++crossings_;
    last_ = measure(P);
    history_.push_back({t, angle(last_.side[0]), angle(last_.side[1])});
  }

  void finish(double t, const Particles<2>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    observe(t, P);
    const double left = angle(last_.side[0]), right = angle(last_.side[1]);
    m["contact_angle_deg_left"] = left;
    m["contact_angle_deg_right"] = right;
    m["contact_angle_deg"] = (left + right) / 2;
    m["contact_angle_initial_deg"] = (history_.front()[1] + history_.front()[2]) / 2;
    double imposed = std::nan(""), err = 0;
    for (const auto& s : last_.side) {
      if (!s) {
        err = std::nan("");
        continue;
      }
      const WallPoint<2> wp = walls_.closest(s->contact);
      const auto& th = angles_.at(static_cast<std::size_t>(wp.wall));
      if (!th) continue;
      imposed = *th * 180 / std::numbers::pi;
      err = std::max(err, std::abs(s->theta_deg - imposed));
    }
    m["contact_angle_imposed_deg"] = imposed;
    m["contact_angle_error_deg"] = err;
    m["droplet_mass_change"] = std::abs(drop_mass(P) - mass0_) / mass0_;
    m["wall_crossings"] = crossings_;
    if (out_dir.empty()) return;
    std::ofstream h(out_dir / "contact_angle_history.csv");
    h << "time,left_deg,right_deg\n";
    for (const auto& r : history_) h << fmt::format("{:.6g},{:.4f},{:.4f}\n", r[0], r[1], r[2]);
    std::ofstream p(out_dir / "droplet_particles.csv");
    p << "x,y,drop\n";
    for (std::size_t i = 0; i < P.size(); ++i)
      p << fmt::format("{:.8g},{:.8g},{}\n", P.x[i].x(), P.x[i].y(), P.phase[i] == drop_ ? 1 : 0);
    std::ofstream f(out_dir / "droplet_fit.csv");
    f << "side,center_x,center_y,radius,contact_x,contact_y,theta_deg,points\n";
    for (int s = 0; s < 2; ++s)
      if (last_.side[s]) {
        const auto& a = *last_.side[s];
        f << fmt::format("{},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.4f},{}\n",
                         s == 0 ? "left" : "right", a.circle.center.x(), a.circle.center.y(),
                         a.circle.radius, a.contact.x(), a.contact.y(), a.theta_deg, a.points);
      }
  }

  // last_ is the latest observation's measurement: the run observes again before finish().
  nlohmann::json save_state() const override {
    return {
        {"started", started_}, {"mass0", mass0_}, {"crossings", crossings_}, {"history", history_}};
  }
  void load_state(const nlohmann::json& s) override {
    s.at("started").get_to(started_);
    s.at("mass0").get_to(mass0_);
    s.at("crossings").get_to(crossings_);
    s.at("history").get_to(history_);
  }

 private:
  static double angle(const std::optional<MeasuredAngle>& a) {
    return a ? a->theta_deg : std::nan("");
  }
  double drop_mass(const Particles<2>& P) const {
    double m = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.phase[i] == drop_) m += P.mass[i];
    return m;
  }
  DropContactAngles measure(const Particles<2>& P) const {
    std::vector<Vec2d> x(P.size());
    std::vector<int> is_drop(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) {
      x[i] = P.x[i].cast<double>();
      is_drop[i] = P.phase[i] == drop_;
    }
    // Nearest unlike neighbours of a lattice are dx apart, diagonal ones sqrt(2) dx.
    return measure_contact_angles(x, is_drop, walls_, 1.5 * dx_, 1.5 * dx_, fit_radius_);
  }

  int drop_;
  WallSet<2> walls_;
  std::vector<std::optional<Real>> angles_;
  double dx_, fit_radius_;
  bool started_ = false;
  double mass0_ = 0;
  long crossings_ = 0;
  DropContactAngles last_;
  std::vector<std::array<double, 3>> history_;
};

}  // namespace

template <int D>
std::unique_ptr<Analysis<D>> make_droplet_wall_analysis(const YAML::Node& params, const Case& c) {
  const std::string key = "analysis.droplet_wall";
  if constexpr (D != 2) {
    throw InputError(c.file_name(), key, "droplet_wall is 2-D");
  } else {
    double fit_dx = 0;  // 0: half the distance between the contact points
    if (params && params.IsMap()) {
      yaml::check_keys(params, {"fit_radius_dx"}, c.file_name(), key);
      if (params["fit_radius_dx"])
        fit_dx =
            yaml::read_nonnegative(params["fit_radius_dx"], c.file_name(), key + ".fit_radius_dx");
    }
    if (c.surface_tension.empty())
      throw InputError(c.file_name(), key,
                       "needs a surface_tension pair (the drop is its second fluid)");
    if (!c.root["walls"] || !c.root["walls"].IsSequence())
      throw InputError(c.file_name(), key, "needs walls");
    return std::make_unique<DropletWall>(
        c.surface_tension.front().fluid_b,
        parse_walls<2>(c.root["walls"], c.file_name(), c.file.parent_path()),
        parse_contact_angles<2>(c.root["walls"], c.file_name(), c.file.parent_path()), c.dx,
        fit_dx * c.dx);
  }
}

template std::unique_ptr<Analysis<2>> make_droplet_wall_analysis<2>(const YAML::Node&, const Case&);

}  // namespace curvsph
