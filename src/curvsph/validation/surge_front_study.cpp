// `curvsph validate surge_front`: the classic 2-D dam break (cases/dam_break_2d.yaml, a column
// a wide and 2a high on a dry floor) against Martin & Moyce (1952, Fig. 3, n^2 = 2, a = 2.25 in):
// the surge front Z = x/a against T = t sqrt(2g/a) until it reaches the far wall (x = 16 a), and
// the height of the water on the far wall. Runs:
//  - resolution: ghost mirror_beta at dx = a/20, a/40 and a/80 (a/80 last, not with --quick);
//  - method: boundary integrals at a/40 (the three ghost maps are one map on a box's straight
//    walls: the free_surface study shows them bit for bit equal);
//  - sensitivity at a/20: a free-slip floor, c0 doubled, artificial viscosity alpha = 0.02.
// The front is the wet-floor front (analysis/floor_front.hpp); the largest x on the floor is
// reported beside it. The experiments' own spread (Martin & Moyce's two column sizes, Koshizuka
// & Oka 1996) is computed from data/martin_moyce/ for comparison. Finished runs are kept
// (run_cache.hpp): delete docs/validation/surge_front/runs/ to redo them with a new build.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/io/case_key.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/run_cache.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Run {
  std::string tag, label;
  int per_a;     // dx = a / per_a
  double t_end;  // 1.0 s: the front reaches the far wall at T ~ 9.5 (t ~ 0.96 s); 1.5 s: run-up
  std::vector<std::string> sets;
  bool in_quick;
};

const std::vector<Run>& runs() {
  static const std::vector<Run> r = {
      {"a20_mirror_beta", "ghost mirror_beta, a/20", 20, 1.0, {}, true},
      {"a40_mirror_beta", "ghost mirror_beta, a/40", 40, 1.5, {}, true},
      {"a40_integrals",
       "integrals geometric, a/40",
       40,
       1.5,
       {"boundary={method: integrals}"},
       true},
      {"a20_free_slip", "a/20, free-slip walls", 20, 1.0, {"boundary.velocity=free_slip"}, true},
      {"a20_c0_56", "a/20, c0 = 56 m/s (doubled)", 20, 1.0, {"eos.c0=56"}, true},
      {"a20_alpha_0.02",
       "a/20, artificial viscosity alpha = 0.02",
       20,
       1.0,
       {"artificial_viscosity={alpha: 0.02}"},
       true},
      {"a80_mirror_beta", "ghost mirror_beta, a/80", 80, 1.0, {"output.every=0.02"}, false},
  };
  return r;
}

using Table = std::map<std::string, std::vector<double>>;

// A CSV of numbers with a header line, by column; empty when the file is missing.
Table read_csv(const std::filesystem::path& path) {
  Table t;
  std::ifstream in(path);
  std::string line, cell;
  if (!std::getline(in, line)) return t;
  std::vector<std::string> names;
  for (std::istringstream s(line); std::getline(s, cell, ',');) names.push_back(cell);
  while (std::getline(in, line)) {
    std::istringstream s(line);
    for (const auto& n : names) {
      std::getline(s, cell, ',');
      t[n].push_back(cell.empty() ? kNaN : std::stod(cell));
    }
  }
  return t;
}

// y(x) linear between the samples of a curve increasing in x; NaN outside.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  for (std::size_t k = 1; k < x.size(); ++k)
    if (x[k - 1] <= at && at <= x[k])
      return y[k - 1] + (y[k] - y[k - 1]) * (at - x[k - 1]) / (x[k] - x[k - 1]);
  return kNaN;
}

double number_or_nan(const nlohmann::json& m, const char* k) {
  return m.contains(k) && m[k].is_number() ? m[k].get<double>() : kNaN;
}

// Largest |Z_other(T) - Z_ref(T)| / Z_ref(T) over the reference points within the other
// curve's range: the distance between two experiments, or between two resolutions.
double max_rel_diff(const Table& ref, const Table& other, const char* ref_T, const char* ref_Z,
                    const char* other_T, const char* other_Z) {
  double d = 0;
  int n = 0;
  const auto& T = ref.at(ref_T);
  for (std::size_t k = 0; k < T.size(); ++k) {
    const double z = interpolate(other.at(other_T), other.at(other_Z), T[k]);
    if (std::isnan(z)) continue;
    d = std::max(d, std::abs(z - ref.at(ref_Z)[k]) / ref.at(ref_Z)[k]);
    ++n;
  }
  return n ? d : kNaN;
}

}  // namespace

StudyResult run_surge_front_study(const StudyContext& ctx) {
  const auto case_path = ctx.source_dir / "cases" / "dam_break_2d.yaml";
  const auto data = ctx.source_dir / "data" / "martin_moyce";
  const double a = 0.2;  // the case's column width
  const std::string fingerprint = case_key(case_path);
  std::filesystem::create_directories(ctx.out_dir);
  StudyResult r;
  std::string table =
      "| run | particles | t reached | front points | max rel. error | RMS rel. error | max rel. "
      "error, largest x | lag T_exp - T_sim first / last | dZ/dT sim / exp. | T at far wall | "
      "far wall / 2a: highest particle, gauge max (T), gauge at 1.5 s | put back / removed / "
      "clamped | wall s |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, Table> compare;
  for (const Run& run : runs()) {
    if (ctx.quick && !run.in_quick) continue;
    std::vector<std::string> sets = {fmt::format("resolution.dx={:.17g}", a / run.per_a),
                                     fmt::format("time.end={}", run.t_end), "output.vtk=false"};
    sets.insert(sets.end(), run.sets.begin(), run.sets.end());
    RunOptions o;
    o.out_dir = ctx.out_dir / "runs" / run.tag;
    o.threads = ctx.threads;
    o.progress = true;
    o.overwrite = true;  // the study's own directory, rerun
    nlohmann::json m = cached_run(o.out_dir, fingerprint, sets);
    if (m.is_null()) {
      try {
        m = run_case(read_case(case_path, sets), o);
      } catch (const InstabilityError& e) {
        std::cerr << "surge_front: " << run.tag << ": " << e.what() << "\n";
        std::ifstream in(o.out_dir / "metrics_unstable.json");
        m = nlohmann::json::parse(in);
      }
      store_run(o.out_dir, fingerprint, sets, m);
    } else {
      std::cerr << "surge_front: " << run.tag << ": reusing the finished run\n";
    }
    compare[run.tag] = read_csv(o.out_dir / "surge_front_compare.csv");
    // The case's gauge H_far, 0.01 m before the far wall: the height of the water there.
    const Table probes = read_csv(o.out_dir / "probes.csv");
    double gauge_max = kNaN, gauge_T = kNaN, gauge_end = kNaN;
    if (probes.count("H_far.height") && !probes.at("H_far.height").empty()) {
      const auto& H = probes.at("H_far.height");
      const auto k = static_cast<std::size_t>(std::max_element(H.begin(), H.end()) - H.begin());
      gauge_max = H[k] / (2 * a);
      gauge_T = probes.at("time")[k] * std::sqrt(2 * 9.81 / a);
      gauge_end = H.back() / (2 * a);
    }
    const double e = number_or_nan(m, "surge_front_max_rel_error");
    const double reached = number_or_nan(m, "time_reached");
    const double n0 = number_or_nan(m, "particles_initial");
    const double proj = number_or_nan(m, "particles_projected");
    table += fmt::format(
        "| {} | {:.0f} | {:.3f} / {} | {:.0f} | {:.3f} | {:.3f} | {:.3f} | {:.2f} / {:.2f} | "
        "{:.2f} / {:.2f} | {:.2f} | {} | {:.0f} / {:.0f} / {:.0f} | {:.0f} |\n",
        run.label, n0, reached, run.t_end, number_or_nan(m, "surge_front_points"), e,
        number_or_nan(m, "surge_front_rms_rel_error"),
        number_or_nan(m, "surge_front_largest_x_max_rel_error"),
        number_or_nan(m, "surge_front_lag_first"), number_or_nan(m, "surge_front_lag_last"),
        number_or_nan(m, "surge_front_speed"), number_or_nan(m, "surge_front_speed_experiment"),
        number_or_nan(m, "surge_front_t_far_wall"),
        // Runs to t = 1 s stop as the front reaches the far wall: no run-up yet.
        run.t_end > 1.2
            ? fmt::format("{:.2f}, {:.2f} ({:.1f}), {:.2f}", number_or_nan(m, "far_wall_runup_max"),
                          gauge_max, gauge_T, gauge_end)
            : "-",
        proj, number_or_nan(m, "particles_removed"), number_or_nan(m, "density_clamped"),
        number_or_nan(m, "wall_seconds"));
    const std::string key = "surge_front." + run.tag;
    for (const char* k :
         {"surge_front_max_rel_error", "surge_front_rms_rel_error",
          "surge_front_largest_x_max_rel_error", "surge_front_lag_first", "surge_front_lag_last",
          "surge_front_speed", "surge_front_speed_experiment", "surge_front_t_far_wall",
          "far_wall_runup_max", "time_reached", "particles_projected", "particles_removed",
          "density_clamped"})
      r.metrics[key + "." + k] = number_or_nan(m, k);
    if (run.per_a >= 40) {  // the study's resolutions; a/20 is under-resolved (README)
      r.summary.push_back({key + ".max_rel_error", e, "<= 0.05",
                           "Martin & Moyce (1952) Fig. 3, n^2 = 2, a = 2.25 in, T <= 9.24",
                           e <= 0.05});
      r.summary.push_back({key + ".rms_rel_error", number_or_nan(m, "surge_front_rms_rel_error"),
                           "reported", "same points", true});
      r.summary.push_back({key + ".lag_last", number_or_nan(m, "surge_front_lag_last"), "reported",
                           fmt::format("T_exp - T_sim at Z = 13.97; at Z = 1.22: {:.3f}",
                                       number_or_nan(m, "surge_front_lag_first")),
                           true});
      r.summary.push_back({key + ".front_speed", number_or_nan(m, "surge_front_speed"), "reported",
                           fmt::format("dZ/dT, experiment {:.3f}, Ritter's shallow-water front 2",
                                       number_or_nan(m, "surge_front_speed_experiment")),
                           true});
      r.summary.push_back({key + ".projected_fraction", proj / n0, "<= 0.001",
                           "particles put back from past a wall (issue 31 item 1)",
                           proj / n0 <= 0.001});
      if (run.t_end > 1.2) {
        r.metrics[key + ".far_wall_gauge_max"] = gauge_max;
        r.metrics[key + ".far_wall_gauge_end"] = gauge_end;
        r.summary.push_back({key + ".far_wall_runup_max", number_or_nan(m, "far_wall_runup_max"),
                             "reported", "highest particle on the far wall over 2a, t <= 1.5 s",
                             true});
        r.summary.push_back({key + ".far_wall_gauge_max", gauge_max, "reported",
                             fmt::format("water height on the far wall (gauge H_far) over 2a, "
                                         "largest at T = {:.1f}; {:.2f} at t = 1.5 s",
                                         gauge_T, gauge_end),
                             true});
      }
    }
  }
  // Figures without a target are rows with pass = true and target "reported" (study.cpp).
  // Resolution: how far the front moves between resolutions, against how far the experiments
  // lie from each other.
  const auto change = [&](const std::string& coarse, const std::string& fine) {
    if (!compare.count(coarse) || !compare.count(fine) || compare[coarse].empty() ||
        compare[fine].empty())
      return kNaN;
    return max_rel_diff(compare[fine], compare[coarse], "T_exp", "Z", "T_exp", "Z");
  };
  const double c20_40 = change("a20_mirror_beta", "a40_mirror_beta");
  const double c40_80 = change("a40_mirror_beta", "a80_mirror_beta");
  const Table mm = read_csv(data / "front_a_2.25in.csv");
  const Table mm_small = read_csv(data / "front_a_1.125in.csv");
  const Table ko = read_csv(data / "front_koshizuka_oka_1996.csv");
  const double spread_small = max_rel_diff(mm, mm_small, "T", "Z", "T", "Z");
  const double spread_ko = max_rel_diff(mm, ko, "T", "Z", "T", "Z");
  r.metrics["surge_front.resolution_change_a20_a40"] = c20_40;
  r.metrics["surge_front.resolution_change_a40_a80"] = c40_80;
  r.metrics["surge_front.experiments.mm_1.125in_vs_2.25in"] = spread_small;
  r.metrics["surge_front.experiments.koshizuka_oka_vs_mm_2.25in"] = spread_ko;
  r.summary.push_back({"surge_front.resolution_change_a20_a40", c20_40, "reported",
                       "largest abs(Z(a/20) - Z(a/40)) / Z(a/40) at the experiment's times", true});
  if (!ctx.quick)
    r.summary.push_back({"surge_front.resolution_change_a40_a80", c40_80, "reported",
                         "largest abs(Z(a/40) - Z(a/80)) / Z(a/80) at the experiment's times",
                         true});
  r.summary.push_back({"surge_front.experiments.mm_1.125in_vs_2.25in", spread_small, "reported",
                       "Martin & Moyce's two column sizes, max rel. difference (T <= 5.3)", true});
  r.summary.push_back({"surge_front.experiments.koshizuka_oka_vs_mm_2.25in", spread_ko, "reported",
                       "Koshizuka & Oka (1996) against Martin & Moyce (T <= 3.1)", true});

  run_plot_script(ctx, "plot_surge_front.py", {ctx.out_dir.string()});
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Surge front of the 2-D dam break (Martin & Moyce 1952)\n\n"
     << "Case `cases/dam_break_2d.yaml`: a water column a = 0.2 m wide and 2a high collapses "
        "onto a dry floor and runs to the far wall at x = 16 a, with the case's free-surface "
        "defaults (no wall force). Front Z = x/a against T = t sqrt(2g/a) (Martin & Moyce's "
        "T = n t sqrt(g/a) with n^2 = 2), compared with `data/martin_moyce/front_a_2.25in.csv` "
        "up to the far wall. The front is where the water on the floor ends: the SPH "
        "interpolant of the fluid's indicator, completed by the floor's images, falls below 1/2 "
        "along the first particle row (analysis/floor_front.hpp); the largest x of a particle "
        "on the floor is listed beside it. Regenerate with `build/curvsph validate "
        "surge_front`"
     << (ctx.quick ? " (these figures: `--quick`, without the a/80 run)" : "")
     << "; finished runs are reused (delete `runs/` after a code change).\n\n"
     << "The study's resolution is a/40 (3200 particles); a/20 is listed for the resolution "
        "series and the sensitivity runs. The front moves by "
     << fmt::format("{:.3f}", c20_40) << " (max relative change) from a/20 to a/40"
     << (ctx.quick ? "" : fmt::format(" and by {:.3f} from a/40 to a/80", c40_80))
     << "; Martin & Moyce's two column sizes differ by " << fmt::format("{:.3f}", spread_small)
     << " and Koshizuka & Oka's experiment differs from Martin & Moyce's by "
     << fmt::format("{:.3f}", spread_ko)
     << " over their common range: under Froude scaling an inviscid front does not depend on "
        "the column's size, so that spread is what the experiments carry beyond inviscid "
        "flow (release of the column, floor friction, surface tension).\n\n"
     << "Lag: T_exp - T_sim(Z_exp), the reduced time by which the experiment reaches a front "
        "position later than the simulation, at the first (Z = 1.22) and last (Z = 13.97) "
        "point; dZ/dT: least-squares front speed over the points with Z >= 7 (Ritter's "
        "shallow-water front: 2). A lag that stays constant is a delay at the start; a lag "
        "that grows is a slower front.\n\n"
     << table << "\n![surge front](surge_front.png)\n\n"
     << summary_markdown(r.summary);
  return r;
}

}  // namespace curvsph
