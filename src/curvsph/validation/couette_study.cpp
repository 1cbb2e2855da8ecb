// `curvsph validate couette`: Barker & Neethling §2.1, circular Couette flow, with the three
// ghost maps (mirror, mirror_beta, density_preserving) at four resolutions:
//  A. hydrostatic (omega = 0) density at t = 0 against r (Barker Fig. 1) and after 1 s
//     (Fig. 2), density_error_t0 per map and dx;
//  B. rotating inner wall, started from the analytic profile, run to T: the error of eq. 25
//     (with the square, / omega R_i) against time (Fig. 3b) and against dx (Fig. 4);
//  C. started from rest as Barker did, every map, error against time to the steady state
//     (Fig. 3b as in the paper; the slowest mode e-folds in ~23 s), at three dx (issue 36:
//     within 2 % at t = 100 s and decreasing with dx);
//  E. C again with mu = 1e-2 (Re 37.5 instead of 375), a control: the analytic profile does
//     not depend on mu, and at Barker's mu the flow from rest locks into a plug (findings.md);
//  D. diagnosis (issue #4): B's run at the plotted dx with mirror_beta, the background
//     pressure p0 scaled by 1/4 and 4 (Barker's 2.5 Pa in between), to show what the error of
//     B is made of. Not a tuning: the figures of B keep Barker's p0.
// Per-run CSVs stay under runs/ (only the plotted ones); scripts/plot_couette.py draws them.
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/io/case_overrides.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {

namespace {

namespace fs = std::filesystem;

struct Runner {
  const StudyContext& ctx;
  fs::path case_path;

  // Runs the case with overrides; from_rest drops `initial:`. NaN figures on instability.
  nlohmann::json run(const std::string& tag, std::vector<std::string> overrides,
                     bool from_rest = false) const {
    YAML::Node root = YAML::LoadFile(case_path.string());
    if (from_rest) root.remove("initial");
    overrides.push_back("output.vtk=false");
    apply_overrides(root, overrides);
    Case c = read_case(root, case_path);
    c.make_strays_fatal();  // the study reports where a wall first fails
    RunOptions o;
    o.out_dir = ctx.out_dir / "runs" / tag;
    o.overwrite = true;  // a study redoes its runs in its own folders
    o.threads = ctx.threads;
    o.progress = true;
    try {
      return run_case(c, o);
    } catch (const InstabilityError& e) {
      fmt::print(stderr, "couette study: run {} went unstable: {}\n", tag, e.what());
      nlohmann::json m;
      m["unstable"] = 1;
      for (const char* k : {"density_error_t0", "velocity_l2_error", "velocity_rms",
                            "density_error_end", "wall_seconds", "velocity_profile_error"})
        m[k] = std::numeric_limits<double>::quiet_NaN();
      // When and how it failed (run_case's metrics_unstable.json).
      std::ifstream in(o.out_dir / "metrics_unstable.json");
      if (in) {
        const auto u = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
        for (const char* k : {"time_reached", "unstable_message", "density_error_t0"})
          if (u.is_object() && u.contains(k)) m[k] = u[k];
      }
      return m;
    }
  }
};

double get(const nlohmann::json& m, const char* key) {
  return m.contains(key) && m[key].is_number() ? m[key].get<double>()
                                               : std::numeric_limits<double>::quiet_NaN();
}

// Removes the per-particle CSVs of a run that is not plotted (keeps metrics and histories);
// keep_profile keeps the velocity profile (the from-rest runs' plot).
void prune(const fs::path& dir, bool keep_profile = false) {
  for (const char* f : {"couette_density_t0.csv", "couette_density_end.csv"}) fs::remove(dir / f);
  if (!keep_profile) fs::remove(dir / "couette_profile.csv");
}

}  // namespace

StudyResult run_couette_study(const StudyContext& ctx) {
  const Runner runner{ctx, ctx.source_dir / "cases" / "couette.yaml"};
  const std::vector<double> dxs = ctx.quick
                                      ? std::vector<double>{1.875e-3, 1.5e-3}
                                      : std::vector<double>{1.875e-3, 1.5e-3, 1.0e-3, 0.75e-3};
  const std::vector<std::string> maps = {"mirror", "mirror_beta", "density_preserving"};
  const double plot_dx = 1.5e-3;
  const double t_run = ctx.quick ? 0.3 : 1.0;       // B: from the analytic profile
  const double t_hydro = ctx.quick ? 0.2 : 1.0;     // A: Barker Fig. 2
  const double t_rest = ctx.quick ? 2.0 : 100.0;    // C: from rest, ~4 e-folding times
  const double t_control = ctx.quick ? 1.0 : 25.0;  // E: mu = 1e-2, ~11 e-folding times
  const double mu_control = 1.0e-2;
  const double rest_dx = 1.875e-3;  // 8 rings: the gap holds an integer number of dx
  // C's resolutions (8, 10, 12, 15 rings; R_i/dx = 13.3, 16.7, 20, 25); the first is rest_dx
  // (plots, controls). Issue 36's target is judged over the finest three: at 1.875 mm the plain
  // mirror misses it (README.md, "From rest").
  const std::vector<double> rest_dxs = ctx.quick
                                           ? std::vector<double>{rest_dx}
                                           : std::vector<double>{rest_dx, 1.5e-3, 1.25e-3, 1.0e-3};
  const std::size_t target_from = rest_dxs.size() > 3 ? rest_dxs.size() - 3 : 0;
  fs::remove_all(ctx.out_dir / "runs");
  fs::create_directories(ctx.out_dir);
  StudyResult r;
  auto tag_of = [](const std::string& what, const std::string& map, double dx) {
    return fmt::format("{}_{}_dx{:g}mm", what, map, dx * 1e3);
  };
  auto dx_set = [](double dx) { return fmt::format("resolution.dx={}", dx); };

  // A. Hydrostatic density at t = 0 for every map and dx; Fig. 2 run at plot_dx.
  std::map<std::string, std::vector<double>> rho_t0, l2, l2_abs, l2_profile, l2_scatter, secs;
  std::vector<long> particles;
  for (double dx : dxs)
    for (const auto& map : maps) {
      const std::string tag = tag_of("t0", map, dx);
      const auto m = runner.run(
          tag, {dx_set(dx), "boundary.map=" + map, "walls.0.motion.rotate.omega=0", "time.end=0"});
      rho_t0[map].push_back(get(m, "density_error_t0"));
      if (dx != plot_dx) prune(ctx.out_dir / "runs" / tag);
    }
  std::map<std::string, double> rho_end;
  for (const auto& map : maps) {
    const auto m =
        runner.run(tag_of("hydro", map, plot_dx),
                   {dx_set(plot_dx), "boundary.map=" + map, "walls.0.motion.rotate.omega=0",
                    fmt::format("time.end={}", t_hydro)});
    rho_end[map] = get(m, "density_error_end");
    r.metrics[fmt::format("hydrostatic_{}_density_error_end", map)] = rho_end[map];
    r.metrics[fmt::format("hydrostatic_{}_velocity_rms", map)] = get(m, "velocity_rms");
  }

  // B. Rotating, from the analytic profile, to t_run.
  for (double dx : dxs)
    for (const auto& map : maps) {
      const std::string tag = tag_of("rot", map, dx);
      const auto m = runner.run(tag, {dx_set(dx), "boundary.map=" + map,
                                      fmt::format("time.end={}", t_run), "output.every=0.1"});
      l2[map].push_back(get(m, "velocity_l2_error"));
      l2_abs[map].push_back(get(m, "velocity_l2_error_abs"));
      l2_profile[map].push_back(get(m, "velocity_profile_error"));
      l2_scatter[map].push_back(get(m, "velocity_scatter_error"));
      secs[map].push_back(get(m, "wall_seconds"));
      if (map == maps.front()) particles.push_back(m.value("particles", 0L));
      if (dx != plot_dx) prune(ctx.out_dir / "runs" / tag);
    }

  // C. From rest at the coarsest resolution (Barker's start), every map, to the steady
  // state; E. the same with mu = 1e-2 (the control). The profiles stay for the plot.
  std::map<std::string, double> rest_l2, rest_profile, control_l2, control_profile;
  std::map<std::string, std::vector<double>> rest_l2_dx, rest_profile_dx;  // over rest_dxs
  std::map<std::string, std::array<double, 4>> wide;  // l2, profile, rho error t0, t reached
  // One from-rest run of `map` at dx to t_end, with the extra overrides; the profile stays.
  auto from_rest = [&](const std::string& what, const std::string& map, double t_end,
                       std::vector<std::string> overrides, double dx) {
    const std::string tag = tag_of(what, map, dx);
    overrides.insert(overrides.end(),
                     {dx_set(dx), "boundary.map=" + map, fmt::format("time.end={}", t_end),
                      fmt::format("output.every={}", t_end / 50)});
    const auto m = runner.run(tag, overrides, /*from_rest=*/true);
    prune(ctx.out_dir / "runs" / tag, /*keep_profile=*/true);
    return m;
  };
  const std::string mu_set = fmt::format("fluids.0.viscosity={}", mu_control);
  for (const auto& map : maps) {
    for (const double dx : rest_dxs) {
      const auto m = from_rest("rest", map, t_rest, {}, dx);
      rest_l2_dx[map].push_back(get(m, "velocity_l2_error"));
      rest_profile_dx[map].push_back(get(m, "velocity_profile_error"));
      const std::string key = fmt::format("from_rest_dx{:g}mm_{}_", dx * 1e3, map);
      r.metrics[key + "velocity_l2_error"] = rest_l2_dx[map].back();
      r.metrics[key + "velocity_profile_error"] = rest_profile_dx[map].back();
    }
    rest_l2[map] = rest_l2_dx[map].front();  // at rest_dx
    rest_profile[map] = rest_profile_dx[map].front();
    r.metrics[fmt::format("from_rest_{}_velocity_l2_error", map)] = rest_l2[map];
    r.metrics[fmt::format("from_rest_{}_velocity_profile_error", map)] = rest_profile[map];
    const auto mc =
        from_rest(fmt::format("rest_mu{:g}", mu_control), map, t_control, {mu_set}, rest_dx);
    control_l2[map] = get(mc, "velocity_l2_error");
    control_profile[map] = get(mc, "velocity_profile_error");
    r.metrics[fmt::format("from_rest_mu{:g}_{}_velocity_l2_error", mu_control, map)] =
        control_l2[map];
    r.metrics[fmt::format("from_rest_mu{:g}_{}_velocity_profile_error", mu_control, map)] =
        control_profile[map];
    // E at h = 2 dx: a wider kernel reaches further past the curved walls.
    const auto mw = from_rest(fmt::format("rest_mu{:g}_h2", mu_control), map, t_control,
                              {mu_set, "resolution.h_over_dx=2"}, rest_dx);
    wide[map] = {get(mw, "velocity_l2_error"), get(mw, "velocity_profile_error"),
                 get(mw, "density_error_t0"), get(mw, "time_reached")};
    r.metrics[fmt::format("from_rest_mu{:g}_h2_{}_velocity_l2_error", mu_control, map)] =
        wide[map][0];
    r.metrics[fmt::format("from_rest_mu{:g}_h2_{}_time_reached", mu_control, map)] = wide[map][3];
  }

  // D. Background pressure: p0 / 4 and 4 p0 at plot_dx, mirror_beta, as B.
  std::string p0_table = "| p0 (Pa) | velocity_l2_error | profile | scatter |\n|---|---|---|---|\n";
  {
    const std::size_t k_plot =
        static_cast<std::size_t>(std::find(dxs.begin(), dxs.end(), plot_dx) - dxs.begin());
    for (const double p0 : {0.625, 2.5, 10.0}) {
      double e = 0, prof = 0, scat = 0;
      if (p0 == 2.5 && k_plot < dxs.size()) {  // B's own run
        e = l2["mirror_beta"][k_plot];
        prof = l2_profile["mirror_beta"][k_plot];
        scat = l2_scatter["mirror_beta"][k_plot];
      } else {
        const std::string tag = fmt::format("p0_{:g}_mirror_beta_dx{:g}mm", p0, plot_dx * 1e3);
        const auto m = runner.run(
            tag, {dx_set(plot_dx), "boundary.map=mirror_beta", fmt::format("eos.p0={}", p0),
                  fmt::format("time.end={}", t_run), "output.every=0.1"});
        prune(ctx.out_dir / "runs" / tag);
        e = get(m, "velocity_l2_error");
        prof = get(m, "velocity_profile_error");
        scat = get(m, "velocity_scatter_error");
      }
      r.metrics[fmt::format("p0_{:g}_velocity_l2_error", p0)] = e;
      p0_table += fmt::format("| {:g} | {:.4g} | {:.4g} | {:.4g} |\n", p0, e, prof, scat);
    }
  }

  // Tables.
  std::ofstream csv(ctx.out_dir / "couette.csv");
  csv << "dx,particles,map,density_error_t0,velocity_l2_error,velocity_l2_error_abs,"
         "velocity_profile_error,velocity_scatter_error,wall_seconds\n";
  std::string table =
      "| dx (mm) | particles | map | density_error_t0 | velocity_l2_error | profile | scatter | "
      "wall s |\n"
      "|---|---|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < dxs.size(); ++k)
    for (const auto& map : maps) {
      csv << fmt::format("{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.2f}\n", dxs[k],
                         particles[k], map, rho_t0[map][k], l2[map][k], l2_abs[map][k],
                         l2_profile[map][k], l2_scatter[map][k], secs[map][k]);
      table += fmt::format("| {:g} | {} | {} | {:.4g} | {:.4g} | {:.4g} | {:.4g} | {:.1f} |\n",
                           dxs[k] * 1e3, particles[k], map, rho_t0[map][k], l2[map][k],
                           l2_profile[map][k], l2_scatter[map][k], secs[map][k]);
      const std::string key = fmt::format("dx{:g}mm_{}_", dxs[k] * 1e3, map);
      r.metrics[key + "density_error_t0"] = rho_t0[map][k];
      r.metrics[key + "velocity_l2_error"] = l2[map][k];
      r.metrics[key + "velocity_profile_error"] = l2_profile[map][k];
      r.metrics[key + "velocity_scatter_error"] = l2_scatter[map][k];
    }
  csv.close();

  // Targets: beta cuts the t = 0 density error to <= 1/3 of the mirror's at every dx; both
  // curvature-aware maps beat the mirror's velocity error at every dx but the finest.
  double worst_rho_ratio = 0, worst_beta = 0, worst_dp = 0;
  for (std::size_t k = 0; k < dxs.size(); ++k) {
    const double q = rho_t0["mirror_beta"][k] / rho_t0["mirror"][k];
    worst_rho_ratio = std::isnan(q) ? q : std::max(worst_rho_ratio, q);
    if (k + 1 == dxs.size()) continue;
    const double b = l2["mirror_beta"][k] / l2["mirror"][k];
    const double d = l2["density_preserving"][k] / l2["mirror"][k];
    worst_beta = std::isnan(b) ? b : std::max(worst_beta, b);
    worst_dp = std::isnan(d) ? d : std::max(worst_dp, d);
  }
  r.metrics["density_error_t0_ratio_beta_over_mirror_max"] = worst_rho_ratio;
  r.metrics["velocity_l2_error_ratio_beta_over_mirror_max"] = worst_beta;
  r.metrics["velocity_l2_error_ratio_dp_over_mirror_max"] = worst_dp;
  r.metrics["density_error_t0"] = rho_t0["mirror_beta"].back();
  r.metrics["velocity_l2_error"] = l2["mirror_beta"].back();
  const std::string dx_range =
      fmt::format("dx = {:g}..{:g} mm", dxs.front() * 1e3, dxs.back() * 1e3);
  r.summary.push_back({"couette.density_error_t0 mirror_beta/mirror (max over dx)", worst_rho_ratio,
                       "<= 0.333", "issue #4; " + dx_range, worst_rho_ratio <= 1.0 / 3.0});
  const std::string but_finest =
      fmt::format("issue #4; every dx but the finest, t = {} s from the analytic profile", t_run);
  r.summary.push_back({"couette.velocity_l2_error mirror_beta/mirror (max over dx)", worst_beta,
                       "< 1", but_finest, worst_beta < 1});
  r.summary.push_back({"couette.velocity_l2_error density_preserving/mirror (max over dx)",
                       worst_dp, "< 1", but_finest, worst_dp < 1});
  const double rest_ratio = rest_l2["mirror_beta"] / rest_l2["mirror"];
  const double rest_ratio_dp = rest_l2["density_preserving"] / rest_l2["mirror"];
  r.metrics["from_rest_velocity_l2_error_ratio_beta_over_mirror"] = rest_ratio;
  r.metrics["from_rest_velocity_l2_error_ratio_dp_over_mirror"] = rest_ratio_dp;
  const std::string rest_ref = fmt::format(
      "Barker Fig. 3b; dx = {:g} mm, t = {} s from rest (h = 2 dx, alpha = 0.02: findings.md, "
      "\"Kernel width\")",
      rest_dx * 1e3, t_rest);
  r.summary.push_back({"couette.from_rest velocity_l2_error mirror_beta/mirror", rest_ratio, "< 1",
                       rest_ref, rest_ratio < 1});
  r.summary.push_back({"couette.from_rest velocity_l2_error density_preserving/mirror",
                       rest_ratio_dp, "reported", rest_ref, true});
  r.summary.push_back({"couette.from_rest velocity_profile_error mirror", rest_profile["mirror"],
                       "reported", rest_ref, true});
  // Issue 36: from rest within 2 % of the analytic profile at t = 100 s with every map, at
  // the finest three dx of C, and the error decreasing with dx.
  const std::string rest_range =
      fmt::format("issue 36; dx = {:g}..{:g} mm, t = {} s from rest", rest_dxs[target_from] * 1e3,
                  rest_dxs.back() * 1e3, t_rest);
  for (const auto& map : maps) {
    const std::vector<double> e(rest_l2_dx[map].begin() + static_cast<long>(target_from),
                                rest_l2_dx[map].end());
    double worst = 0;
    bool decreasing = true;
    for (std::size_t k = 0; k < e.size(); ++k) {
      worst = std::isnan(e[k]) ? e[k] : std::max(worst, e[k]);
      if (k > 0 && !(e[k] < e[k - 1])) decreasing = false;
    }
    r.summary.push_back({fmt::format("couette.from_rest velocity_l2_error {} (max over dx)", map),
                         worst, "<= 0.02", rest_range, worst <= 0.02});
    if (e.size() > 1)
      r.summary.push_back(
          {fmt::format("couette.from_rest velocity_l2_error {} finest/coarsest", map),
           e.back() / e.front(), "< 1, decreasing", rest_range,
           decreasing && e.back() / e.front() < 1});
  }
  const std::string wide_ref = fmt::format(
      "control, Re 37.5, h = 2 dx; dx = {:g} mm, t = {} s from rest", rest_dx * 1e3, t_control);
  r.summary.push_back(
      {fmt::format("couette.from_rest mu = {:g}, h = 2 dx: t reached, mirror", mu_control),
       wide["mirror"][3], "reported", wide_ref, true});
  for (const std::string map : {"mirror_beta", "density_preserving"})
    r.summary.push_back({fmt::format("couette.from_rest mu = {:g}, h = 2 dx: velocity_l2_error {}",
                                     mu_control, map),
                         wide[map][0], "reported", wide_ref, true});
  r.summary.push_back(
      {fmt::format("couette.from_rest mu = {:g}: velocity_profile_error mirror", mu_control),
       control_profile["mirror"], "reported",
       fmt::format("control, Re 37.5; dx = {:g} mm, t = {} s from rest", rest_dx * 1e3, t_control),
       true});

  run_plot_script(ctx, "plot_couette.py",
                  {ctx.out_dir.string(), fmt::format("{:g}", plot_dx * 1e3),
                   fmt::format("{:g}", rest_dx * 1e3), fmt::format("{:g}", mu_control)});
  std::string rest_table =
      "| start | map | velocity_l2_error | profile | scatter |\n|---|---|---|---|---|\n";
  auto scatter_of = [](double l2, double profile) {
    return std::sqrt(std::max(0.0, l2 * l2 - profile * profile));
  };
  for (std::size_t k = 0; k < rest_dxs.size(); ++k)
    for (const auto& map : maps) {
      const double e = rest_l2_dx[map][k], prof = rest_profile_dx[map][k];
      rest_table += fmt::format(
          "| from rest, mu = 1e-3, dx = {:g} mm, t = {} s | {} | {:.4g} | {:.4g} | {:.4g} |\n",
          rest_dxs[k] * 1e3, t_rest, map, e, prof, scatter_of(e, prof));
    }
  for (const auto& map : maps)
    rest_table +=
        fmt::format("| from rest, mu = {:g}, t = {} s | {} | {:.4g} | {:.4g} | {:.4g} |\n",
                    mu_control, t_control, map, control_l2[map], control_profile[map],
                    scatter_of(control_l2[map], control_profile[map]));
  for (const auto& map : maps) {
    const bool failed = !(wide[map][3] >= t_control * (1 - 1e-9));
    rest_table += fmt::format(
        "| from rest, mu = {:g}, h = 2 dx, t = {} s | {} | {} | {} | {} |\n", mu_control, t_control,
        map,
        failed ? fmt::format("unstable at t = {:.3g} s (density error at t = 0: {:.3g})",
                             wide[map][3], wide[map][2])
               : fmt::format("{:.4g}", wide[map][0]),
        failed ? "" : fmt::format("{:.4g}", wide[map][1]),
        failed ? "" : fmt::format("{:.4g}", scatter_of(wide[map][0], wide[map][1])));
  }
  // What the h = 2 dx control shows, read from its runs.
  const auto reached = [&](const std::string& map) {
    return wide[map][3] >= t_control * (1 - 1e-9);
  };
  std::string wide_sentence;
  if (!reached("mirror") && reached("mirror_beta") && reached("density_preserving"))
    wide_sentence =
        "With h = 2 dx (E, last rows) the kernel reaches further past the walls: the plain "
        "mirror's density deficit at the concave outer wall then lets the fluid push particles "
        "through it, while mirror_beta and density_preserving keep every particle and reach the "
        "analytic profile; there the curvature-aware maps decide whether the run survives.\n\n";
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Circular Couette flow (Barker & Neethling §2.1)\n\n"
     << "Case `cases/couette.yaml`: rho = 1000, mu = 0.001, R_i = 0.025 m (turning at omega = 1 "
        "rad/s), R_o = 0.040 m, c0 = 0.25 m/s, p0 = 2.5 Pa, h = 2 dx, delta-SPH momentum "
        "diffusion alpha = 0.02 (ghosts included; findings.md, \"Kernel width\"), summation "
        "density, no-slip reflected ghosts with each map. Regenerate with `build/curvsph validate "
        "couette`"
     << (ctx.quick ? " (this is the `--quick` version)" : "") << ".\n\n"
     << "**What was shortened.** The viscous time (R_o - R_i)^2/nu is 225 s (the slowest mode "
        "decays in ~23 s), which at Barker's resolutions would take hours per run on the shared "
        "machine. So (B) every map and resolution starts from the analytic profile "
        "(`initial: {couette: {}}`: v_theta(r) and the radial pressure balance) and runs to t = "
     << t_run
     << " s: the error measures how far each boundary treatment pulls the flow off the exact "
        "steady state in that time, not the converged discrete steady state. (C) The runs "
        "at dx = "
     << fmt::format("{:g}", rest_dxs.front() * 1e3) << ".."
     << fmt::format("{:g}", rest_dxs.back() * 1e3)
     << " mm are started from rest as in Barker, to t = " << t_rest
     << " s (about four e-folding times of the slowest mode), with every map. The hydrostatic "
        "density (A) is exact at t = 0; Fig. 2's run is "
     << t_hydro << " s long as in the paper.\n\n"
     << "**From rest** (C, and E: the same runs with mu = " << mu_control
     << ", Re 37.5, a control; the analytic profile does not depend on mu). With h = 1.3 dx "
        "and no momentum diffusion (the case before issue 36) every map settled by t ~ 30 s "
        "into a plug (error 0.22-0.25 of omega R_i): the particle rows pinned on each other "
        "through the background pressure (findings.md §4). h = 2 dx removes the pinning; the "
        "momentum diffusion, with the ghosts in its sum, keeps the rings next to the turning "
        "wall from breaking up under the start-up's shear. It adds alpha h c0 / 8 to nu "
        "(2.3e-6 m^2/s at dx = 1.875 mm), which leaves the steady profile as it is and makes "
        "the start-up about three times faster (findings.md, \"Kernel width\").\n\n"
     << wide_sentence << rest_table << "\n"
     << "Velocity error: Barker eq. 25 with the square, sqrt(mean (v_theta,i - v_theta(r_i))^2), "
        "divided by omega R_i = 0.025 m/s. Its split (same norm and scale): *profile* = the "
        "error of the mean azimuthal profile (particles binned in radius, bins of about dx), "
        "*scatter* = the particles' spread around it; velocity_l2_error^2 = profile^2 + "
        "scatter^2.\n\n"
        "Initial masses: m_i = rho_i / sigma_ref,i, sigma_ref the node density of the ring "
        "arrangement continued beyond both walls (`initial: {couette: {}}`), so the bulk starts "
        "exactly at the radial balance and density_error_t0 is the wall treatment's own error "
        "(see findings.md).\n\n"
     << table << "\n"
     << "**What the error of B is made of** (D; dx = " << plot_dx * 1e3
     << " mm, mirror_beta, t = " << t_run
     << " s; only the background pressure p0 changed, a diagnosis, not a setting):\n\n"
     << p0_table << "\n"
     << summary_markdown(r.summary) << "\n"
     << "![density at t = 0](density_t0.png)\n\n![density after " << t_hydro
     << " s](density_end.png)\n\n![error vs time](error_vs_time.png)\n\n"
     << "![error vs time from rest](error_vs_time_from_rest.png)\n\n"
     << "![steady profile from rest](profile_from_rest.png)\n\n"
     << "![error vs dx](error_vs_dx.png)\n\n![velocity profile](profile.png)\n\n"
     << "![error split](error_split.png)\n\nFindings: [findings.md](findings.md).\n";
  return r;
}

}  // namespace curvsph
