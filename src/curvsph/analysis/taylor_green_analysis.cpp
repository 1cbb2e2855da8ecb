#include "curvsph/analysis/taylor_green_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <vector>

#include "curvsph/core/error.hpp"

namespace curvsph {

TaylorGreen taylor_green_from_case(const Case& c, const YAML::Node& params,
                                   const std::string& key) {
  const std::string file = c.file_name();
  if (c.dimension != 2) throw InputError(file, key, "the Taylor–Green vortex is 2-D");
  if (!c.has_domain || !c.periodic[0] || !c.periodic[1])
    throw InputError(file, key, "needs a domain periodic on both axes");
  const double lx = c.domain_max[0] - c.domain_min[0], ly = c.domain_max[1] - c.domain_min[1];
  if (std::abs(lx - ly) > 1e-12 * lx) throw InputError(file, key, "needs a square domain");
  TaylorGreen tg;
  if (params && params.IsMap()) {
    for (const auto& kv : params) {
      const auto k = kv.first.as<std::string>();
      if (k != "U") throw InputError(file, key + "." + k, "unknown key (allowed here: U)");
    }
    if (params["U"]) {
      double u = 0;
      if (!YAML::convert<double>::decode(params["U"], u) || !(u > 0))
        throw InputError(file, key + ".U", "must be a number > 0");
      tg.U = u;
    }
  } else if (params && !params.IsNull()) {
    throw InputError(file, key, "must be a mapping ({U: 1})");
  }
  tg.L = lx;
  tg.origin_x = c.domain_min[0];
  tg.origin_y = c.domain_min[1];
  tg.rho = c.fluids.at(0).rho0;
  tg.nu = c.fluids.at(0).viscosity / c.fluids.at(0).rho0;
  return tg;
}

namespace {

class TaylorGreenAnalysis final : public Analysis<2> {
 public:
  explicit TaylorGreenAnalysis(TaylorGreen tg) : tg_(tg) {}

  void observe(double t, const Particles<2>& P) override {
    double ke = 0;
    for (std::size_t i = 0; i < P.size(); ++i) ke += 0.5 * P.mass[i] * P.v[i].squaredNorm();
    times_.push_back(t);
    energies_.push_back(ke);
  }

  void finish(double t, const Particles<2>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    if (!out_dir.empty()) {
      std::ofstream csv(out_dir / "taylor_green_energy.csv");
      csv << "time,kinetic_energy,kinetic_energy_exact\n";
      for (std::size_t k = 0; k < times_.size(); ++k)
        csv << fmt::format("{:.9g},{:.9g},{:.9g}\n", times_[k], energies_[k],
                           energies_.front() * std::exp(-tg_.energy_decay_rate() * times_[k]));
    }
    double err2 = 0, ref2 = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Vec2d ue = tg_.velocity(P.x[i][0], P.x[i][1], t);
      err2 += (P.v[i].cast<double>() - ue).squaredNorm();
      ref2 += ue.squaredNorm();
    }
    m["l2_velocity_error"] = std::sqrt(err2 / ref2);
    // Least-squares slope of log(KE) against t over every observation.
    double st = 0, sy = 0, stt = 0, sty = 0;
    const double n = static_cast<double>(times_.size());
    for (std::size_t k = 0; k < times_.size(); ++k) {
      const double y = std::log(energies_[k]);
      st += times_[k];
      sy += y;
      stt += times_[k] * times_[k];
      sty += times_[k] * y;
    }
    const double rate = n >= 2 ? -(n * sty - st * sy) / (n * stt - st * st) : 0.0;
    const double ref = tg_.energy_decay_rate();
    m["decay_rate"] = rate;
    m["decay_rate_reference"] = ref;
    m["decay_rate_rel_error"] = std::abs(rate - ref) / ref;
    m["kinetic_energy_ratio"] = energies_.empty() ? 0.0 : energies_.back() / energies_.front();
    m["kinetic_energy_ratio_reference"] = std::exp(-ref * t);
  }

  // The series since t = 0: kinetic_energy_ratio and decay_rate measure from there.
  nlohmann::json save_state() const override {
    return {{"times", times_}, {"energies", energies_}};
  }
  void load_state(const nlohmann::json& s) override {
    s.at("times").get_to(times_);
    s.at("energies").get_to(energies_);
  }

 private:
  TaylorGreen tg_;
  std::vector<double> times_, energies_;
};

}  // namespace

std::unique_ptr<Analysis<2>> make_taylor_green_analysis(const YAML::Node& params, const Case& c) {
  return std::make_unique<TaylorGreenAnalysis>(
      taylor_green_from_case(c, params, "analysis.taylor_green"));
}

void taylor_green_initial(const Case& c, const YAML::Node& params, const Eos& eos,
                          const std::vector<Real>& rho0, Particles<2>& P) {
  const TaylorGreen tg = taylor_green_from_case(c, params, "initial.taylor_green");
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.x[i][0], y = P.x[i][1];
    P.v[i] = tg.velocity(x, y, 0).cast<Real>();
    const Real p = static_cast<Real>(tg.pressure(x, y, 0) + eos.p0);
    // Mass follows the density so that rho/m stays the lattice's number density: the
    // sigma-form pressure gradient is consistent only when sigma = rho/m matches the
    // particle arrangement (a p0-sized spurious force otherwise).
    const Real volume = P.mass[i] / rho0[P.phase[i]];
    P.rho[i] = eos.density(p, rho0[P.phase[i]]);
    P.mass[i] = P.rho[i] * volume;
    P.p[i] = p;
  }
}

}  // namespace curvsph
