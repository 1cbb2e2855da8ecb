#include "curvsph/analysis/cylinder_lattice.hpp"

#include <fmt/format.h>

#include <fstream>

namespace curvsph {
namespace {

class CylinderLatticeAnalysis final : public Analysis<2> {
 public:
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
    double vx = 0;
    for (const auto& v : P.v) vx += v.x();
    m["mean_vx"] = P.size() ? vx / static_cast<double>(P.size()) : 0.0;
    if (out_dir.empty()) return;
    std::ofstream f(out_dir / "velocity.csv");
    f << "x,y,vx,vy\n";
    for (std::size_t i = 0; i < P.size(); ++i)
      f << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g}\n", P.x[i].x(), P.x[i].y(), P.v[i].x(),
                       P.v[i].y());
  }

 private:
  bool event_ = false, blowup_ = false;
  double event_time_ = 0;
  long penetrations_ = 0;
};

}  // namespace

std::unique_ptr<Analysis<2>> make_cylinder_lattice_analysis(const YAML::Node&, const Case&) {
  return std::make_unique<CylinderLatticeAnalysis>();
}

}  // namespace curvsph
