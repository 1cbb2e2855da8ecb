// `curvsph validate taylor_green`: the 2-D Taylor–Green vortex (Re = 100) at dx = 0.04, 0.02,
// 0.01 against the analytic solution: velocity error and energy decay rate vs dx, with the
// fitted order, and the kinetic energy history against exp(-16 pi^2 nu t).
#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {

StudyResult run_taylor_green_study(const StudyContext& ctx) {
  const auto case_path = ctx.source_dir / "cases" / "taylor_green_2d.yaml";
  const std::vector<double> dxs =
      ctx.quick ? std::vector<double>{0.04, 0.02} : std::vector<double>{0.04, 0.02, 0.01};
  const std::string t_end = ctx.quick ? "0.2" : "1.0";
  std::filesystem::create_directories(ctx.out_dir);
  std::ofstream csv(ctx.out_dir / "taylor_green.csv");
  csv << "dx,particles,steps,l2_velocity_error,decay_rate_rel_error,wall_seconds,"
         "tvf_l2_velocity_error,tvf_decay_rate_rel_error,tvf_wall_seconds\n";
  StudyResult r;
  std::vector<double> l2s;
  std::string table =
      "| dx | particles | steps | l2_velocity_error | decay_rate_rel_error | transport velocity: "
      "l2_velocity_error | decay_rate_rel_error |\n"
      "|---|---|---|---|---|---|---|\n";
  for (double dx : dxs) {
    const std::string tag = fmt::format("dx_{}", dx);
    const std::vector<std::string> sets = {fmt::format("resolution.dx={}", dx), "time.end=" + t_end,
                                           "output.vtk=false"};
    Case c = read_case(case_path, sets);
    RunOptions o;
    o.out_dir = ctx.out_dir / tag;
    o.overwrite = true;  // a study redoes its runs in its own folders
    o.threads = ctx.threads;
    o.progress = true;
    const auto m = run_case(c, o);
    // The comparison: summation density with the transport velocity (physics/
    // transport_velocity.hpp, p_b = rho0 c0^2) and no background pressure in the eos.
    std::vector<std::string> tvf_sets = sets;
    tvf_sets.insert(tvf_sets.end(),
                    {"density={method: summation}", "eos.p0=0", "transport_velocity={}"});
    RunOptions ot = o;
    ot.out_dir = ctx.out_dir / (tag + "_tvf");
    const auto mt = run_case(read_case(case_path, tvf_sets), ot);
    const double l2 = m["l2_velocity_error"], dr = m["decay_rate_rel_error"];
    const double tl2 = mt["l2_velocity_error"], tdr = mt["decay_rate_rel_error"];
    l2s.push_back(l2);
    csv << fmt::format("{},{},{},{:.6g},{:.6g},{:.3f},{:.6g},{:.6g},{:.3f}\n", dx,
                       m["particles"].get<long>(), m["steps"].get<long>(), l2, dr,
                       m["wall_seconds"].get<double>(), tl2, tdr, mt["wall_seconds"].get<double>());
    table += fmt::format("| {} | {} | {} | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n", dx,
                         m["particles"].get<long>(), m["steps"].get<long>(), l2, dr, tl2, tdr);
    r.metrics[tag + "_l2_velocity_error"] = l2;
    r.metrics[tag + "_decay_rate_rel_error"] = dr;
    r.metrics[tag + "_tvf_l2_velocity_error"] = tl2;
    r.metrics[tag + "_tvf_decay_rate_rel_error"] = tdr;
    if (dx == dxs.back()) {
      r.metrics["l2_velocity_error"] = l2;
      r.metrics["decay_rate_rel_error"] = dr;
      r.metrics["particle_steps_per_second"] = m["particle_steps_per_second"];
    }
  }
  csv.close();
  // Observed order of the velocity error between the two finest resolutions.
  const std::size_t n = dxs.size();
  const double order = std::log(l2s[n - 2] / l2s[n - 1]) / std::log(dxs[n - 2] / dxs[n - 1]);
  r.metrics["l2_velocity_error_order"] = order;
  const double finest = dxs.back();
  const double l2 = r.metrics["l2_velocity_error"], dr = r.metrics["decay_rate_rel_error"];
  const std::string ref = fmt::format("analytic, dx = {}, t = {}", finest, t_end);
  r.summary.push_back({"taylor_green.l2_velocity_error", l2, "<= 0.05", ref, l2 <= 0.05});
  r.summary.push_back({"taylor_green.decay_rate_rel_error", dr, "<= 0.05", ref, dr <= 0.05});
  run_plot_script(ctx, "plot_taylor_green.py", {ctx.out_dir.string()});
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Taylor–Green vortex, Re = 100\n\n"
     << "Case `cases/taylor_green_2d.yaml` (periodic unit square, U = 1, nu = 0.01, continuity "
        "density with delta-SPH, particle shifting), run to t = "
     << t_end
     << " at each dx. Beside it, the same case with the transport-velocity formulation "
        "(Adami, Hu & Adams 2013; `density: {method: summation}`, `eos.p0: 0`, "
        "`transport_velocity: {}`, i.e. p_b = rho0 c0^2; directories dx_*_tvf). Regenerate "
        "with `build/curvsph validate taylor_green`.\n\n"
     << table
     << "\nObserved order of the velocity error (two finest): " << fmt::format("{:.2f}", order)
     << "\n\n"
     << summary_markdown(r.summary)
     << "\n![error vs dx](error_vs_dx.png)\n\n![kinetic energy](kinetic_energy.png)\n";
  return r;
}

}  // namespace curvsph
