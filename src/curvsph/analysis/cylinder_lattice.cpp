#include "curvsph/analysis/cylinder_lattice.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <vector>

namespace curvsph {
namespace {

double mean_vx(const Particles<2>& P) {
  double vx = 0;
  for (const auto& v : P.v) vx += v.x();
  return P.size() ? vx / static_cast<double>(P.size()) : 0.0;
}

class CylinderLatticeAnalysis final : public Analysis<2> {
 public:
  // Mean x velocity at every output time: the history says whether Fig. 9's run reached a
  // steady state (the drive relaxes v_x towards v0 on the time scale tau, eq. 36).
  void observe(double t, const Particles<2>& P) override { history_.push_back({t, mean_vx(P)}); }

  bool absorb_instability(double t, const Particles<2>&, const InstabilityError& e) override {
    event_time_ = t;
    event_ = true;
    if (e.kind() == InstabilityError::Kind::penetration)
      penetrations_ = e.count();
    else
      blowup_ = true;
    return true;
  }

  void finish(double t, const Particles<2>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    m["t_max"] = event_ ? event_time_ : t;
    m["penetrations"] = penetrations_;
    m["blowup"] = blowup_ ? 1 : 0;
    m["mean_vx"] = mean_vx(P);
    // Steady-state indicator: relative change of the mean v_x over the last output interval.
    if (history_.size() >= 2) {
      const auto& a = history_[history_.size() - 2];
      const auto& b = history_.back();
      m["mean_vx_rel_change_last_interval"] =
          std::abs(b[1] - a[1]) / std::max(std::abs(b[1]), 1e-300);
      m["mean_vx_last_interval"] = b[0] - a[0];
    }
    if (out_dir.empty()) return;
    std::ofstream hist(out_dir / "history.csv");
    hist << "t,mean_vx\n";
    for (const auto& row : history_) hist << fmt::format("{:.6g},{:.8g}\n", row[0], row[1]);
    std::ofstream f(out_dir / "velocity.csv");
    f << "x,y,vx,vy\n";
    for (std::size_t i = 0; i < P.size(); ++i)
      f << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g}\n", P.x[i].x(), P.x[i].y(), P.v[i].x(),
                       P.v[i].y());
  }

  nlohmann::json save_state() const override { return {{"history", history_}}; }
  void load_state(const nlohmann::json& s) override { s.at("history").get_to(history_); }

 private:
  bool event_ = false, blowup_ = false;
  double event_time_ = 0;
  long penetrations_ = 0;
  std::vector<std::array<double, 2>> history_;  // (t, mean v_x) at output times
};

}  // namespace

std::unique_ptr<Analysis<2>> make_cylinder_lattice_analysis(const YAML::Node&, const Case&) {
  return std::make_unique<CylinderLatticeAnalysis>();
}

}  // namespace curvsph
