// `curvsph validate shepard_cost`: Calderon-Sanchez et al. Table 1 — time per step of the 3-D
// dam break (cases/dam_break_3d.yaml, dx = 0.55/20, h/dx = 2) with gamma = 1
// (`shepard: none`), the volume factor and the geometric factor; the cost of each factor in %
// over gamma = 1. Modes back to back in each repeat, the median of the per-repeat ratios.
#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <vector>

#include "curvsph/analysis/median.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {

StudyResult run_shepard_cost_study(const StudyContext& ctx) {
  const auto case_path = ctx.source_dir / "cases" / "dam_break_3d.yaml";
  const int steps = ctx.quick ? 4 : 12;
  const int repeats = ctx.quick ? 1 : 9;
  const char* modes[] = {"none", "volume", "geometric"};
  double best[3], boundary[3];
  std::fill(std::begin(best), std::end(best), std::numeric_limits<double>::infinity());
  std::fill(std::begin(boundary), std::end(boundary), std::numeric_limits<double>::infinity());
  long particles = 0;
  std::filesystem::create_directories(ctx.out_dir);
  // Percentages: the median over the repeats of each mode's step time over gamma = 1's in the
  // same repeat (modes run back to back), which cancels the machine's drift between repeats;
  // the ratio of best times mixes moments and moved the figure by ~10 points between runs.
  std::vector<double> ratio[3];
  for (int rep = 0; rep < repeats; ++rep) {
    double this_rep[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      const Case c =
          read_case(case_path, {fmt::format("time.max_steps={}", steps),
                                std::string("boundary.shepard=") + modes[k], "output.vtk=false"});
      RunOptions o;
      o.threads = ctx.threads;
      o.progress = false;
      o.write_files = false;
      const nlohmann::json m = run_case(c, o);
      particles = m["particles"];
      const long n = m["steps"];
      // Loop time per step (set-up excluded): particles * steps / (particle steps per s).
      const double per_step =
          static_cast<double>(particles) / m["particle_steps_per_second"].get<double>();
      best[k] = std::min(best[k], per_step);
      boundary[k] =
          std::min(boundary[k], m["seconds_boundary"].get<double>() / static_cast<double>(n));
      this_rep[k] = per_step;
    }
    for (int k = 1; k < 3; ++k) ratio[k].push_back(this_rep[k] / this_rep[0]);
  }
  StudyResult r;
  const double pct_volume = 100 * (median(ratio[1]) - 1);
  const double pct_geometric = 100 * (median(ratio[2]) - 1);
  r.metrics["particles"] = particles;
  r.metrics["steps_per_run"] = steps;
  r.metrics["repeats"] = repeats;
  for (int k = 0; k < 3; ++k) {
    r.metrics[fmt::format("seconds_per_step_{}", modes[k])] = best[k];
    r.metrics[fmt::format("seconds_boundary_per_step_{}", modes[k])] = boundary[k];
  }
  r.metrics["shepard_cost_pct_volume"] = pct_volume;
  r.metrics["shepard_cost_pct_geometric"] = pct_geometric;
  const std::string ref = "Calderon Table 1, 0.55/45, h/dr = 2: volume +16 %, geometric +12 %";
  r.summary.push_back(
      {"shepard_cost.shepard_cost_pct_geometric", pct_geometric, "<= 5", ref, pct_geometric <= 5});
  r.summary.push_back({"shepard_cost.geometric_below_volume", pct_geometric - pct_volume,
                       "< 0 (geometric - volume, % points)", ref, pct_geometric < pct_volume});
  r.summary.push_back({"shepard_cost.shepard_cost_pct_volume", pct_volume, "reported", ref, true});
  // The factor's own cost, where it is spent: the boundary phase's increase over gamma = 1, as
  // a share of the gamma = 1 step. The fluid passes are the same code in every mode, so this
  // is the load-robust figure on a shared machine (the whole-step ratio above moves by
  // several points between identical runs there).
  for (int k : {1, 2}) {
    const double phase = 100 * (boundary[k] - boundary[0]) / best[0];
    r.metrics[fmt::format("boundary_phase_pct_{}", modes[k])] = phase;
    r.summary.push_back({fmt::format("shepard_cost.boundary_phase_pct_{}", modes[k]), phase,
                         "reported (boundary phase over gamma = 1, % of a step)", ref, true});
  }
  std::ofstream csv(ctx.out_dir / "shepard_cost.csv");
  csv << "shepard,seconds_per_step,seconds_boundary_per_step,increase_pct\n";
  std::string table =
      "| Shepard factor | s / step | boundary s / step | over gamma = 1 (%) | paper, 0.55/45, "
      "h/dr = 2 (s / step) |\n|---|---|---|---|---|\n";
  const char* paper[] = {"0.43", "0.50 (former)", "0.48 (new)"};
  const double pct[3] = {0.0, pct_volume, pct_geometric};
  for (int k = 0; k < 3; ++k) {
    csv << fmt::format("{},{:.6f},{:.6f},{:.3f}\n", modes[k], best[k], boundary[k], pct[k]);
    table += fmt::format("| {} | {:.4f} | {:.4f} | {:+.1f} | {} |\n", modes[k], best[k],
                         boundary[k], pct[k], paper[k]);
  }
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Cost of the Shepard factor (Calderon et al. Table 1)\n\n"
     << "The 3-D dam break (`cases/dam_break_3d.yaml`, dx = 0.55/20, h/dx = 2, " << particles
     << " particles, boundary integrals) run for " << steps
     << " steps with gamma = 1 (`boundary.shepard: none`), the volume factor sum_j W_ij V_j "
        "and the geometric factor; loop time per step (set-up excluded), modes run back to back "
        "in each of "
     << repeats
     << " repeat(s); s / step is the best of the repeats, the increase over gamma = 1 the "
        "median over the repeats of the step-time ratio within a repeat; "
     << (ctx.threads > 0 ? std::to_string(ctx.threads) : "default")
     << " thread(s). The geometric factor is computed only for particles with a wall "
        "element within 2h plus the element size (a cell list over element centres): a flat "
        "face that covers the particle's whole support disc gives the half-space value in "
        "closed form, other faces are integrated along the rim of their patch near the "
        "particle, edges beyond 2h in closed form (boundary/integrals/shepard.hpp). Timings on a "
        "machine shared by several users: "
        "compare the ratios, not the seconds. The paper's times are on a GPU at 0.55/45 (Table "
        "1). Regenerate with `build/curvsph validate shepard_cost`.\n\n"
     << table << "\n## Summary\n\n"
     << summary_markdown(r.summary);
  return r;
}

}  // namespace curvsph
