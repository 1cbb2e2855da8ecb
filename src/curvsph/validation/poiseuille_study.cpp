// `curvsph validate poiseuille`: the plane Poiseuille case at its own resolution (32
// particles across the channel), started from rest and run for three viscous times; the
// velocity profile against the parabola and the error history.
#include <fmt/format.h>

#include <fstream>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {

StudyResult run_poiseuille_study(const StudyContext& ctx) {
  const auto case_path = ctx.source_dir / "cases" / "poiseuille_2d.yaml";
  std::vector<std::string> overrides = {"output.vtk=false"};
  if (ctx.quick) overrides.push_back("time.end=1.0");
  const Case c = read_case(case_path, overrides);
  std::filesystem::create_directories(ctx.out_dir);
  RunOptions o;
  o.out_dir = ctx.out_dir / "run";
  o.overwrite = true;  // a study redoes its runs in its own folders
  o.threads = ctx.threads;
  o.progress = true;
  const auto m = run_case(c, o);
  StudyResult r;
  const double l2 = m["velocity_l2_error"];
  for (const char* k : {"velocity_l2_error", "velocity_max", "velocity_max_reference", "particles",
                        "steps", "wall_seconds"})
    r.metrics[k] = m[k];
  const std::string ref =
      fmt::format("parabola g/(2 nu) y (H - y); dx = H/32, t = {} H^2/nu", c.t_end);
  r.summary.push_back({"poiseuille.velocity_l2_error", l2, "<= 0.01", ref, l2 <= 0.01});
  run_plot_script(ctx, "plot_poiseuille.py", {ctx.out_dir.string()});
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Plane Poiseuille flow\n\n"
     << "Case `cases/poiseuille_2d.yaml`: channel H = 1 mm, periodic along x, nu = 1e-6 m^2/s, "
        "g = 8e-3 m/s^2 along x (u_max = 1 mm/s, Re = 1), no-slip mirror ghosts on two plane "
        "walls, 32 particles across, started from rest and run to t = "
     << c.t_end << " s (" << c.t_end
     << " viscous times H^2/nu). Regenerate with `build/curvsph validate poiseuille`.\n\n"
     << fmt::format("{} particles, {} steps, {:.1f} s wall.\n\n", m["particles"].get<long>(),
                    m["steps"].get<long>(), m["wall_seconds"].get<double>())
     << summary_markdown(r.summary)
     << "\n![profile](profile.png)\n\n![error vs time](error_vs_time.png)\n";
  return r;
}

}  // namespace curvsph
