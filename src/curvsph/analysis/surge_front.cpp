#include "curvsph/analysis/surge_front.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "curvsph/analysis/floor_front.hpp"
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
                     std::optional<double> far_wall, std::vector<Sample> exp, double g, double dx,
                     double h)
      : wall_(wall), width_(width), far_(far_wall), exp_(std::move(exp)), g_(g), dx_(dx), h_(h) {}

  void observe(double t, const Particles<2>& P) override {
    if (P.size() == 0) return;
    if (!wall_ || !width_ || !floor_) {  // from the initial particles
      double lo = std::numeric_limits<double>::infinity(), hi = -lo, low = lo;
      for (const auto& x : P.x) {
        lo = std::min(lo, static_cast<double>(x.x()));
        hi = std::max(hi, static_cast<double>(x.x()));
        low = std::min(low, static_cast<double>(x.y()));
      }
      if (!wall_) wall_ = lo - dx_ / 2;
      if (!width_) width_ = hi - lo + dx_;
      if (!floor_) floor_ = low - dx_ / 2;
    }
    volume_.resize(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) volume_[i] = P.mass[i] / P.rho[i];
    const double a = *width_;
    const FloorFront f = floor_front(P.x, volume_, *floor_, *wall_ + a / 2, dx_, h_);
    double runup = 0;
    if (far_)
      for (const auto& x : P.x)
        if (std::abs(x.x() - *far_) < 2 * dx_) runup = std::max(runup, x.y() - *floor_);
    history_.push_back({t * std::sqrt(2 * g_ / a), (f.wet_x - *wall_) / a,
                        (f.largest_x - *wall_) / a, runup / (2 * a)});
  }

  void finish(double, const Particles<2>&, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    if (history_.empty() || !width_) return;
    const double a = *width_;
    // Front at the far wall: from then on the surge is a run-up, not a front.
    double T_far = nan;
    if (far_)
      for (const auto& h : history_)
        if (h.Z * a + *wall_ >= *far_ - 2 * dx_) {
          T_far = h.T;
          break;
        }
    const double T_last = std::isnan(T_far) ? history_.back().T : T_far;
    std::vector<Compared> cmp;
    for (const Sample& e : exp_)
      if (e.T >= history_.front().T && e.T <= T_last)
        cmp.push_back({e, at(e.T, &Row::Z), at(e.T, &Row::Zmax), first_reached(e.Z)});
    const auto errors = [&](double Compared::*z, const char* max_key, const char* rms_key) {
      double max_err = 0, sum2 = 0;
      for (const Compared& c : cmp) {
        const double err = std::abs(c.*z - c.exp.Z) / c.exp.Z;
        max_err = std::isnan(err) || std::isnan(max_err) ? nan : std::max(max_err, err);
        sum2 += err * err;
      }
      m[max_key] = cmp.empty() ? nan : max_err;
      m[rms_key] = cmp.empty() ? nan : std::sqrt(sum2 / static_cast<double>(cmp.size()));
    };
    m["surge_front_points"] = cmp.size();
    errors(&Compared::Z, "surge_front_max_rel_error", "surge_front_rms_rel_error");
    errors(&Compared::Zmax, "surge_front_largest_x_max_rel_error",
           "surge_front_largest_x_rms_rel_error");
    // The lag T_exp - T_sim(Z_exp) at the first and last compared points, and the front speeds
    // dZ/dT (least squares) over the compared points in the second half of the front's run,
    // Z_exp >= Z_exp,last / 2: a start delay shows as a constant lag, a slower front as a lag
    // that grows (Ritter's shallow-water front: dZ/dT = 2 sqrt(g 2a) / sqrt(2 g a) = 2).
    m["surge_front_lag_first"] = cmp.empty() ? nan : cmp.front().exp.T - cmp.front().T_sim;
    m["surge_front_lag_last"] = cmp.empty() ? nan : cmp.back().exp.T - cmp.back().T_sim;
    std::vector<double> T, Zs, Ze;
    for (const Compared& c : cmp)
      if (c.exp.Z >= cmp.back().exp.Z / 2) {
        T.push_back(c.exp.T);
        Zs.push_back(c.Z);
        Ze.push_back(c.exp.Z);
      }
    m["surge_front_speed"] = slope(T, Zs);
    m["surge_front_speed_experiment"] = slope(T, Ze);
    m["surge_front_t_far_wall"] = T_far;
    double runup = 0;
    for (const auto& h : history_) runup = std::max(runup, h.H);
    if (far_) m["far_wall_runup_max"] = runup;
    if (out_dir.empty()) return;
    std::ofstream out(out_dir / "surge_front.csv");
    out << "T,Z,Z_largest_x,far_wall_height\n";
    for (const auto& h : history_)
      out << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g}\n", h.T, h.Z, h.Zmax, h.H);
    std::ofstream cout_(out_dir / "surge_front_compare.csv");
    cout_ << "T_exp,Z_exp,Z,Z_largest_x,T_sim_at_Z_exp,lag\n";
    for (const Compared& c : cmp)
      cout_ << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", c.exp.T, c.exp.Z, c.Z,
                           c.Zmax, c.T_sim, c.exp.T - c.T_sim);
  }

  nlohmann::json save_state() const override {
    nlohmann::json rows = nlohmann::json::array();
    for (const Row& r : history_) rows.push_back({r.T, r.Z, r.Zmax, r.H});
    const auto opt = [](const std::optional<double>& v) {
      return v ? nlohmann::json(*v) : nullptr;
    };
    return {{"wall", opt(wall_)},
            {"width", opt(width_)},
            {"far", opt(far_)},
            {"floor", opt(floor_)},
            {"history", rows}};
  }
  void load_state(const nlohmann::json& s) override {
    const auto opt = [&](const char* k) {
      return !s.contains(k) || s.at(k).is_null() ? std::optional<double>() : s.at(k).get<double>();
    };
    wall_ = opt("wall");
    width_ = opt("width");
    far_ = opt("far");
    floor_ = opt("floor");
    history_.clear();
    for (const auto& r : s.at("history")) {
      // A state written before the wet-floor front had T, Z (largest x), H: Z stands for both.
      const bool old = r.size() == 3;
      history_.push_back({r.at(0).get<double>(), r.at(1).get<double>(),
                          r.at(old ? 1 : 2).get<double>(), r.at(old ? 2 : 3).get<double>()});
    }
  }

 private:
  struct Row {
    double T, Z, Zmax, H;  // Z: wet front, Zmax: largest x on the floor (floor_front.hpp)
  };
  struct Compared {
    Sample exp;
    double Z, Zmax, T_sim;  // the fronts at exp.T; the time the wet front first reached exp.Z
  };
  // A column of the history at T, linear between outputs.
  double at(double T, double Row::*z) const {
    auto it = std::lower_bound(history_.begin(), history_.end(), T,
                               [](const Row& r, double T) { return r.T < T; });
    if (it == history_.end()) return std::numeric_limits<double>::quiet_NaN();
    if (it == history_.begin() || !(it->T > T)) return (*it).*z;
    const Row& p = *(it - 1);
    return p.*z + ((*it).*z - p.*z) * (T - p.T) / (it->T - p.T);
  }
  // The first T at which the wet front reaches Z, linear between outputs; NaN if never.
  double first_reached(double Z) const {
    for (std::size_t k = 1; k < history_.size(); ++k)
      if (history_[k].Z >= Z) {
        const Row &p = history_[k - 1], &q = history_[k];
        return p.Z >= Z ? p.T : p.T + (q.T - p.T) * (Z - p.Z) / (q.Z - p.Z);
      }
    return std::numeric_limits<double>::quiet_NaN();
  }
  static double slope(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = static_cast<double>(x.size());
    if (x.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t k = 0; k < x.size(); ++k) {
      sx += x[k];
      sy += y[k];
      sxx += x[k] * x[k];
      sxy += x[k] * y[k];
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  }
  std::optional<double> wall_, width_, far_, floor_;
  std::vector<Sample> exp_;
  double g_, dx_, h_;
  std::vector<Row> history_;
  std::vector<Real> volume_;
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
  return std::make_unique<SurgeFrontAnalysis>(wall, width, far, std::move(exp), g, c.dx, c.h());
}

}  // namespace curvsph
