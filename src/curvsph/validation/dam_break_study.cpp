// `curvsph validate dam_break_3d`: SPHERIC benchmark test 2, the 3-D dam break against a box
// (Kleefsman et al. 2005; Calderon-Sanchez et al. §3.2), boundary integrals with the
// geometric Shepard factor, against the MARIN record (analysis/dam_break_analysis.hpp).
//
// A run takes hours on two cores, so a run directory that already holds metrics.json and
// the same `settings.txt` (the case overrides of that run) is reused rather than rerun;
// delete the directory to rerun it.
#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {
namespace {

struct DamBreakRun {
  int cells;     // particles across the water depth 0.55 m (dx = 0.55 / cells)
  double t_end;  // s
};

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

StudyResult run_dam_break_study(const StudyContext& ctx) {
  const auto case_path = ctx.source_dir / "cases" / "dam_break_3d.yaml";
  // The issue asks for 0.55/20 (its quick resolution) and 0.55/30 to t = 1.5 s at least (the
  // full study). The quick study runs 0.55/20 to 1.5 s and keeps the earlier 0.55/15 run
  // through the first impact (P1 peaks at 0.415 s in the experiment) beside it. A run cut
  // short by SIGINT/SIGTERM (solver/run.hpp) keeps its figures up to the time it reached.
  std::vector<DamBreakRun> runs;
  if (ctx.quick)
    runs = {{15, 0.45}, {20, 1.5}};
  else
    runs = {{20, 1.5}, {30, 1.5}};
  std::filesystem::create_directories(ctx.out_dir);
  StudyResult r;
  std::string table =
      "| run | particles | t reached | P1 impact (s) | first-impact P1 peak (Pa) | at (s) | "
      "P1 max (Pa) | at (s) | P2 max (Pa) | H2 at 1 s (m) | P1-P4 RMS / P1exp peak | "
      "lowest sensor (Pa) | H1-H4 RMS / 0.55 m | wall s |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  nlohmann::json exp_row;
  std::vector<std::string> tags;
  std::string notes;  // runs that ended before their time.end
  for (const auto& run : runs) {
    const std::string tag = fmt::format("dx{}", run.cells);
    const std::vector<std::string> settings = {
        fmt::format("resolution.dx={:.17g}", 0.55 / run.cells),
        fmt::format("time.end={:.17g}", run.t_end), "output.vtk=false"};
    std::string stamp;
    for (const auto& s : settings) stamp += s + "\n";
    const auto dir = ctx.out_dir / tag;
    nlohmann::json m;
    if (std::filesystem::exists(dir / "metrics.json") && read_text(dir / "settings.txt") == stamp) {
      std::cerr << tag << ": reusing the run in " << dir << "\n";
      m = nlohmann::json::parse(read_text(dir / "metrics.json"));
    } else {
      std::filesystem::create_directories(dir);
      std::ofstream(dir / "settings.txt") << stamp;
      const Case c = read_case(case_path, settings);
      RunOptions o;
      o.out_dir = dir;
      o.overwrite = true;  // a study redoes its runs in its own folders
      o.threads = ctx.threads;
      try {
        m = run_case(c, o);
      } catch (const InstabilityError& e) {
        std::cerr << tag << ": " << e.what() << "\n";
        m = nlohmann::json::parse(read_text(dir / "metrics_unstable.json"));
      }
    }
    tags.push_back(tag);
    auto num = [&](const char* k) {
      return m.contains(k) && m[k].is_number() ? m[k].get<double>() : std::nan("");
    };
    if (num("stopped") == 1)
      notes += fmt::format(
          "- `{}` was stopped by a signal at t = {:.3f} s of its {:.2f} s (out of time); its "
          "figures cover [0, {:.3f}] s.\n",
          tag, num("time_reached"), run.t_end, num("time_reached"));
    if (num("unstable") == 1)
      notes += fmt::format("- `{}` went unstable at t = {:.3f} s: {}\n", tag, num("time_reached"),
                           m.value("unstable_message", std::string()));
    for (const char* k :
         {"p1_peak", "p1_peak_time", "p1_first_peak", "p1_first_peak_time", "p1_impact_time",
          "p2_peak", "h2_at_1s", "p1_rms_error", "p2_rms_error", "p3_rms_error", "p4_rms_error",
          "h1_rms_error", "h2_rms_error", "h3_rms_error", "h4_rms_error", "sensor_min",
          "time_reached", "particles"})
      r.metrics[tag + "_" + k] = num(k);
    exp_row = m;
    table += fmt::format(
        "| `{}` | {:.0f} | {:.3f} | {:.4f} | {:.0f} | {:.4f} | {:.0f} | {:.4f} | {:.0f} | {:.3f} | "
        "{:.3f}, {:.3f}, {:.3f}, {:.3f} | {:.0f} | {:.3f}, {:.3f}, {:.3f}, {:.3f} | {:.0f} |\n",
        tag, num("particles"), num("time_reached"), num("p1_impact_time"), num("p1_first_peak"),
        num("p1_first_peak_time"), num("p1_peak"), num("p1_peak_time"), num("p2_peak"),
        num("h2_at_1s"), num("p1_rms_error"), num("p2_rms_error"), num("p3_rms_error"),
        num("p4_rms_error"), num("sensor_min"), num("h1_rms_error"), num("h2_rms_error"),
        num("h3_rms_error"), num("h4_rms_error"), num("wall_seconds"));
    const double pe = num("p1_peak_exp"), te = num("p1_impact_time_exp");
    const std::string ref =
        fmt::format("MARIN experiment (Kleefsman et al. 2005), 0.55/{}", run.cells);
    const bool reached = num("time_reached") >= num("p1_peak_time_exp") + 0.02;
    const double dt_impact = num("p1_impact_time") - te;
    r.summary.push_back({"dam_break_3d." + tag + ".p1_impact_time_error_s", dt_impact,
                         fmt::format("abs <= 0.05 (exp. {:.3f} s)", te), ref,
                         reached && std::abs(dt_impact) <= 0.05});
    // The "its peak" is the first impact's (dam_break_analysis.hpp); the maximum over
    // the run, later ringing included, is reported beside it.
    const double ratio = num("p1_first_peak") / pe;
    r.summary.push_back({"dam_break_3d." + tag + ".p1_first_peak_ratio", ratio,
                         fmt::format("0.75 .. 1.25 (exp. {:.0f} Pa)", pe), ref,
                         reached && ratio >= 0.75 && ratio <= 1.25});
    r.summary.push_back(
        {"dam_break_3d." + tag + ".p1_peak_ratio", num("p1_peak") / pe,
         fmt::format("reported (maximum over t <= {:.2f} s)", num("rms_window_end")), ref, true});
    // Issue 31 item 4: each of P1-P4 within 0.25 of the experimental P1 peak in RMS, no
    // sensor below -2 kPa, each gauge within 10 % of the 0.55 m depth in RMS.
    for (int k = 1; k <= 4; ++k) {
      const double e = num(fmt::format("p{}_rms_error", k).c_str());
      r.summary.push_back({fmt::format("dam_break_3d.{}.p{}_rms_error", tag, k), e,
                           fmt::format("<= 0.25 (t <= {:.2f} s)", num("rms_window_end")), ref,
                           e <= 0.25});
    }
    r.summary.push_back({"dam_break_3d." + tag + ".sensor_min_pa", num("sensor_min"),
                         fmt::format(">= -2000 Pa (P1-P8, t <= {:.2f} s)", num("rms_window_end")),
                         ref, num("sensor_min") >= -2000});
    for (int k = 1; k <= 4; ++k) {
      const double e = num(fmt::format("h{}_rms_error", k).c_str());
      r.summary.push_back({fmt::format("dam_break_3d.{}.h{}_rms_error", tag, k), e,
                           fmt::format("<= 0.10 (t <= {:.2f} s)", num("rms_window_end")), ref,
                           e <= 0.10});
    }
  }
  r.metrics["p1_peak_exp"] = exp_row.value("p1_peak_exp", 0.0);
  r.metrics["p1_peak_time_exp"] = exp_row.value("p1_peak_time_exp", 0.0);
  r.metrics["p1_impact_time_exp"] = exp_row.value("p1_impact_time_exp", 0.0);
  r.metrics["p2_peak_exp"] = exp_row.value("p2_peak_exp", 0.0);
  r.metrics["h2_at_1s_exp"] = exp_row.value("h2_at_1s_exp", 0.0);
  std::vector<std::string> args = {ctx.out_dir.string()};
  args.insert(args.end(), tags.begin(), tags.end());
  run_plot_script(ctx, "plot_dam_break.py", args);

  std::ofstream md(ctx.out_dir / "README.md");
  md << "# 3-D dam break against a box (SPHERIC test 2; Calderon et al. §3.2)\n\n"
        "Case `cases/dam_break_3d.yaml`: tank 3.22 x 1 x 1 m, water column 1.228 x 1 x 0.55 m "
        "at the right end, box 0.161 x 0.403 x 0.161 m on the floor (face toward the water at "
        "x = 0.8245 m); rho0 = 998, nu = 1e-6, linear EOS with c0 = 40 m/s, continuity density "
        "with delta-SPH (0.1), no artificial viscosity, h/dx = 2, walls by boundary integrals "
        "with the geometric Shepard factor, no-slip (BI viscous wall term), initial hydrostatic "
        "pressure. Experiment: `data/spheric2/test_case_2_exp_data.dat` (its height "
        "columns are H3, H2, H1, H4 in the benchmark's numbering; see the data README).\n\n"
        "**Pressure sensors.** P1-P4 sit on the box's face toward the water, P5-P8 on its top. "
        "A wall-mounted sensor reads the pressure at the wall surface, so the probes use the "
        "field `p_wall`: the fluid pressure extrapolated onto the fixed wall at the sensor "
        "point, sum_j (p_j + rho_j g.(x_s - x_j)) W V_j / sum_j W V_j (Adami, Hu & Adams 2012 "
        "eq. 27 with zero wall acceleration; the same formula as the boundary-integral wall "
        "pressure, so the sensor reads what the wall feels in the model). A plain Shepard "
        "average at the wall point (field `p`) is the pressure about 0.75 h inside the fluid, "
        "and a Shepard sum over fluid particles at a wall is incomplete (about 1/2), which the "
        "normalisation removes in both. A dry sensor (fluid fraction < 0.1) reads 0 in the "
        "figures. Height gauges: distance along +z to the last point where the fluid fraction "
        "sum_j V_j W_j >= 1/2.\n\n"
        "Impact time: first time P1 exceeds 20 % of the experimental P1 peak (same rule for "
        "the experiment). RMS errors over t in [0, min(1.5 s, end)], over the experimental P1 "
        "peak.\n\n"
        "**Runs.** `--quick`: 0.55/15 (13 365 particles) to t = 0.45 s, through the first "
        "impact, and 0.55/20 (31 680 particles, the issue's quick resolution) to t = 1.5 s; "
        "the full study: 0.55/20 and 0.55/30 (108 540 particles) to t = 1.5 s. This README "
        "comes from "
     << (ctx.quick ? "`--quick`" : "the full study")
     << ". Probes at 1 kHz, VTK snapshots off; the case as committed (boundary force of "
        "Calderon §3.2 off: `boundary.wall_force` false, the wall contact of "
        "`boundary.contact` at 0.1 dx).\n\n"
        "**P1's peak.** After the first impact a ringing of ~100 Hz (the box face's acoustic "
        "mode at c0 = 40 m/s; findings.md) grows at P1-P4 and sets the maximum over the run. "
        "The target figure is therefore the first impact's peak, `p1_first_peak`: P1's "
        "maximum within the experiment's impact-to-peak time (0.020 s) after the run's own "
        "impact (the same rule returns the experiment's peak); the maximum over the run, "
        "`p1_peak`, is reported beside it.\n\n"
        "## Runs\n\n"
     << table << (notes.empty() ? "" : "\n" + notes) << "\n## Summary\n\n"
     << summary_markdown(r.summary)
     << "\n## Figures\n\n![pressures P1-P8](pressures.png)\n\n![heights H1-H4](heights.png)\n\n"
        "Data: `RUN/probes.csv`, `RUN/dam_break_comparison.csv` (simulated and experimental "
        "side by side), `RUN/metrics.json`, `metrics.json`. Regenerate: `curvsph validate "
        "dam_break_3d [--quick]` (a run directory with the same `settings.txt` and a "
        "metrics.json is reused; delete it to rerun).\n";
  return r;
}

}  // namespace curvsph
