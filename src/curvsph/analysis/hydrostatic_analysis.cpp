#include "curvsph/analysis/hydrostatic_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <vector>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/physics/compressible_column.hpp"

namespace curvsph {

Hydrostatic hydrostatic_from_case(const Case& c, const YAML::Node& params, const std::string& key) {
  const std::string file = c.file_name();
  Hydrostatic hs;
  if (!params || !params.IsMap()) throw InputError(file, key, "must be a mapping ({depth: 0.5})");
  for (const auto& kv : params) {
    const auto k = kv.first.as<std::string>();
    if (k != "depth" && k != "bottom")
      throw InputError(file, key + "." + k, "unknown key (allowed here: depth, bottom)");
  }
  if (!params["depth"] || !YAML::convert<double>::decode(params["depth"], hs.depth) ||
      !(hs.depth > 0))
    throw InputError(file, key + ".depth", "must be a number > 0");
  if (params["bottom"] && !YAML::convert<double>::decode(params["bottom"], hs.bottom))
    throw InputError(file, key + ".bottom", "must be a number");
  // Gravity along the last axis: -y in 2-D, -z in 3-D.
  const Vec3d g = c.gravity;
  const int up = c.dimension == 3 ? 2 : 1;
  bool along = g[up] < 0;
  for (int d = 0; d < c.dimension; ++d)
    if (d != up && std::abs(g[d]) > 1e-12 * std::abs(g[up])) along = false;
  if (!along)
    throw InputError(file, key,
                     c.dimension == 3 ? "needs gravity along -z" : "needs gravity along -y");
  hs.g = -g[up];
  hs.rho0 = c.fluids.at(0).rho0;
  return hs;
}

namespace {

// y is the last axis (z in 3-D).
template <int D>
class HydrostaticAnalysis final : public Analysis<D> {
 public:
  HydrostaticAnalysis(Hydrostatic hs, WallSet<D> walls, double support)
      : hs_(hs), walls_(std::move(walls)), support_(support) {}

  void observe(double t, const Particles<D>& P) override {
    double ke = 0, mass = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      ke += 0.5 * P.mass[i] * P.v[i].squaredNorm();
      mass += P.mass[i];
    }
    times_.push_back(t);
    ke_.push_back(ke / (mass * hs_.g * hs_.depth));
    perr_.push_back(pressure_error(P, -1));
  }

  void finish(double t, const Particles<D>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    if (times_.empty() || times_.back() != t) observe(t, P);
    const double tau = std::sqrt(hs_.g / hs_.depth);
    if (!out_dir.empty()) {
      std::ofstream csv(out_dir / "hydrostatic_history.csv");
      csv << "time,reduced_time,kinetic_energy,pressure_l2_error\n";
      for (std::size_t k = 0; k < times_.size(); ++k)
        csv << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", times_[k], times_[k] * tau, ke_[k],
                           perr_[k]);
      std::ofstream prof(out_dir / "hydrostatic_profile.csv");
      prof << "x,y,p,p_exact\n";
      for (std::size_t i = 0; i < P.size(); ++i)
        prof << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", P.x[i][0], P.x[i][D - 1], P.p[i],
                            exact(P.x[i][D - 1]));
    }
    long escaped = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (!walls_.empty() && walls_.closest(P.x[i].template cast<double>()).distance <= 0)
        ++escaped;
    m["kinetic_energy_max"] = *std::max_element(ke_.begin(), ke_.end());
    m["kinetic_energy_final"] = ke_.back();
    m["pressure_l2_error"] = perr_.back();
    m["pressure_l2_error_deep"] = pressure_error(P, support_);
    m["escaped_particles"] = escaped;
    m["t_end_reached"] = t * tau;
  }

  nlohmann::json save_state() const override {
    return {{"times", times_}, {"ke", ke_}, {"perr", perr_}};
  }
  void load_state(const nlohmann::json& s) override {
    s.at("times").get_to(times_);
    s.at("ke").get_to(ke_);
    s.at("perr").get_to(perr_);
  }

 private:
  double exact(double y) const { return std::max(0.0, hs_.pressure(y)); }
  // RMS over the particles at least `below` under the surface (all: below < 0).
  double pressure_error(const Particles<D>& P, double below) const {
    double e2 = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (below >= 0 && hs_.surface() - P.x[i][D - 1] < below) continue;
      const double d = P.p[i] - exact(P.x[i][D - 1]);
      e2 += d * d;
      ++n;
    }
    if (n == 0) return std::numeric_limits<double>::quiet_NaN();  // none that deep
    return std::sqrt(e2 / static_cast<double>(n)) / (hs_.rho0 * hs_.g * hs_.depth);
  }

  Hydrostatic hs_;
  WallSet<D> walls_;
  double support_;  // 2h: "deep" is at least this far below the surface
  std::vector<double> times_, ke_, perr_;
};

}  // namespace

template <int D>
std::unique_ptr<Analysis<D>> make_hydrostatic_analysis(const YAML::Node& params, const Case& c) {
  WallSet<D> walls;
  if (c.root["walls"] && c.root["walls"].IsSequence())
    walls = parse_walls<D>(c.root["walls"], c.file_name(), c.file.parent_path());
  return std::make_unique<HydrostaticAnalysis<D>>(
      hydrostatic_from_case(c, params, "analysis.hydrostatic"), std::move(walls), 2 * c.h());
}

template std::unique_ptr<Analysis<2>> make_hydrostatic_analysis<2>(const YAML::Node&, const Case&);
template std::unique_ptr<Analysis<3>> make_hydrostatic_analysis<3>(const YAML::Node&, const Case&);

template <int D>
void hydrostatic_initial(const Case& c, const YAML::Node& params, const Eos& eos,
                         const std::vector<Real>& rho0, Particles<D>& P) {
  const Hydrostatic hs = hydrostatic_from_case(c, params, "initial.hydrostatic");
  std::vector<CompressibleColumn> column;
  for (const Real r0 : rho0) column.emplace_back(eos, r0, hs.g, hs.depth);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Real p = static_cast<Real>(column[P.phase[i]](hs.surface() - P.x[i][D - 1]) + eos.p0);
    // Mass follows the density (taylor_green_initial explains why).
    const Real volume = P.mass[i] / rho0[P.phase[i]];
    P.rho[i] = eos.density(p, rho0[P.phase[i]]);
    P.mass[i] = P.rho[i] * volume;
    P.p[i] = p;
    P.v[i].setZero();
  }
}

template void hydrostatic_initial<2>(const Case&, const YAML::Node&, const Eos&,
                                     const std::vector<Real>&, Particles<2>&);
template void hydrostatic_initial<3>(const Case&, const YAML::Node&, const Eos&,
                                     const std::vector<Real>&, Particles<3>&);

}  // namespace curvsph
