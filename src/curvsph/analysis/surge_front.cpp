#include "curvsph/analysis/surge_front.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "curvsph/io/data_file.hpp"

namespace curvsph {
namespace {

struct Sample {
  double T, Z;
};

std::vector<Sample> read_front_csv(const std::filesystem::path& path, const std::string& file,
                                   const std::string& key) {
  std::ifstream in(path);
  if (!in) throw InputError(file, key, "cannot read the experiment file " + path.string());
  std::vector<Sample> out;
  std::string line;
  std::getline(in, line);  // header T,Z
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream s(line);
    Sample v{};
    char comma = 0;
    if (!(s >> v.T >> comma >> v.Z) || comma != ',' || !std::isfinite(v.T) || !std::isfinite(v.Z))
      throw InputError(
          file, key, fmt::format("{}: line '{}' is not 'T,Z'", path.string(), line.substr(0, 80)));
    out.push_back(v);
  }
  if (out.empty()) throw InputError(file, key, path.string() + ": no data rows");
  return out;
}

class SurgeFrontAnalysis final : public Analysis<2> {
 public:
  SurgeFrontAnalysis(std::optional<double> wall, std::optional<double> width,
                     std::optional<double> far_wall, std::vector<Sample> exp, double g, double dx)
      : wall_(wall), width_(width), far_(far_wall), exp_(std::move(exp)), g_(g), dx_(dx) {}

  void observe(double t, const Particles<2>& P) override {
    if (P.size() == 0) return;
    if (!wall_ || !width_) {  // from the initial particles
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const auto& x : P.x) {
        lo = std::min(lo, static_cast<double>(x.x()));
        hi = std::max(hi, static_cast<double>(x.x()));
      }
      if (!wall_) wall_ = lo - dx_ / 2;
      if (!width_) width_ = hi - lo + dx_;
    }
    double floor = std::numeric_limits<double>::infinity();
    for (const auto& x : P.x) floor = std::min(floor, static_cast<double>(x.y()));
    double front = -std::numeric_limits<double>::infinity(), runup = 0;
    for (const auto& x : P.x) {
      if (x.y() <= floor + 2 * dx_) front = std::max(front, static_cast<double>(x.x()));
      if (far_ && std::abs(x.x() - *far_) < 2 * dx_) runup = std::max(runup, x.y() - floor);
    }
    const double a = *width_;
    history_.push_back({t * std::sqrt(2 * g_ / a), (front - *wall_) / a, runup / (2 * a)});
  }

  void finish(double, const Particles<2>&, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    if (history_.empty() || !width_) return;
    const double a = *width_;
    // Front at the far wall: from then on the surge is a run-up, not a front.
    double T_far = std::numeric_limits<double>::quiet_NaN();
    if (far_)
      for (const auto& h : history_)
        if (h.Z * a + *wall_ >= *far_ - 2 * dx_) {
          T_far = h.T;
          break;
        }
    const double T_last = std::isnan(T_far) ? history_.back().T : T_far;
    double max_err = 0, sum2 = 0;
    long n = 0;
    for (const Sample& e : exp_) {
      if (e.T < history_.front().T || e.T > T_last) continue;
      auto it = std::lower_bound(history_.begin(), history_.end(), e.T,
                                 [](const Row& r, double T) { return r.T < T; });
      double Z = it->Z;
      if (it != history_.begin() && it->T > e.T) {
        const Row& p = *(it - 1);
        Z = p.Z + (it->Z - p.Z) * (e.T - p.T) / (it->T - p.T);
      }
      const double err = std::abs(Z - e.Z) / e.Z;
      max_err = std::max(max_err, err);
      sum2 += err * err;
      ++n;
    }
    m["surge_front_points"] = n;
    m["surge_front_max_rel_error"] = n ? max_err : std::numeric_limits<double>::quiet_NaN();
    m["surge_front_rms_rel_error"] =
        n ? std::sqrt(sum2 / static_cast<double>(n)) : std::numeric_limits<double>::quiet_NaN();
    m["surge_front_t_far_wall"] = T_far;
    double runup = 0;
    for (const auto& h : history_) runup = std::max(runup, h.H);
    if (far_) m["far_wall_runup_max"] = runup;
    if (out_dir.empty()) return;
    std::ofstream out(out_dir / "surge_front.csv");
    out << "T,Z,far_wall_height\n";
    for (const auto& h : history_) out << fmt::format("{:.6g},{:.6g},{:.6g}\n", h.T, h.Z, h.H);
  }

  nlohmann::json save_state() const override {
    nlohmann::json rows = nlohmann::json::array();
    for (const Row& r : history_) rows.push_back({r.T, r.Z, r.H});
    const auto opt = [](const std::optional<double>& v) {
      return v ? nlohmann::json(*v) : nullptr;
    };
    return {{"wall", opt(wall_)}, {"width", opt(width_)}, {"far", opt(far_)}, {"history", rows}};
  }
  void load_state(const nlohmann::json& s) override {
    const auto opt = [&](const char* k) {
      return s.at(k).is_null() ? std::optional<double>() : s.at(k).get<double>();
    };
    wall_ = opt("wall");
    width_ = opt("width");
    far_ = opt("far");
    history_.clear();
    for (const auto& r : s.at("history"))
      history_.push_back({r.at(0).get<double>(), r.at(1).get<double>(), r.at(2).get<double>()});
  }

 private:
  struct Row {
    double T, Z, H;
  };
  std::optional<double> wall_, width_, far_;
  std::vector<Sample> exp_;
  double g_, dx_;
  std::vector<Row> history_;
};

}  // namespace

std::unique_ptr<Analysis<2>> make_surge_front_analysis(const YAML::Node& params, const Case& c) {
  const std::string file = c.file_name(), key = "analysis.surge_front";
  if (c.dimension != 2) throw InputError(file, key, "the surge-front analysis is 2-D");
  const double g = c.gravity.norm();
  if (!(g > 0)) throw InputError(file, key, "needs gravity");
  if (params && !params.IsNull() && !params.IsMap())
    throw InputError(file, key, "must be a mapping ({wall, width, far_wall, experiment})");
  std::optional<double> wall, width, far;
  std::vector<Sample> exp;
  if (params && params.IsMap())
    for (const auto& kv : params) {
      const std::string k = kv.first.as<std::string>();
      const std::string kk = key + "." + k;
      if (k == "experiment") {
        exp = read_front_csv(
            resolve_data_file(kv.second.as<std::string>(), c.file.parent_path(), file, kk), file,
            kk);
        continue;
      }
      double v = 0;
      if (!kv.second.IsScalar() || !YAML::convert<double>::decode(kv.second, v) ||
          !std::isfinite(v))
        throw InputError(file, kk, "must be a number");
      if (k == "wall")
        wall = v;
      else if (k == "width") {
        if (!(v > 0)) throw InputError(file, kk, "must be > 0");
        width = v;
      } else if (k == "far_wall")
        far = v;
      else
        throw InputError(file, kk, "unknown key (allowed here: wall, width, far_wall, experiment)");
    }
  return std::make_unique<SurgeFrontAnalysis>(wall, width, far, std::move(exp), g, c.dx);
}

}  // namespace curvsph
