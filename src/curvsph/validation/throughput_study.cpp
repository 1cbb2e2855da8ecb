// Validation study `throughput` (issue 7): particle-steps per second of
//  (a) the SPHERIC test 2 dam break (cases/dam_break_3d.yaml) at dx = 0.018 m with the kernel
//      support matched to DualSPHysics' reference run (h/dx = 1.732), c0 = 45, CFL 0.2, for
//      each boundary treatment (boundary integrals with geometric gamma, mirror ghosts, none);
//      and with the Fourtakas density diffusion term (`_fourtakas`, no gradient pass);
//  (b) the same at h/dx = 2 (boundary integrals);
//  (c) a 3-D periodic box of 10^6 particles (cases/periodic_box_3d.yaml at dx = 0.01);
//  (d) Couette flow (cases/couette.yaml) with density-preserving ghosts: the share of a step
//      spent in the ghost pre-pass.
// Each configuration runs at 1 and 2 threads back to back in this process, after warm-up
// steps that are not timed. Particle-steps count every particle that takes part in the
// interaction: fluid plus ghosts or boundary elements (BoundaryModel::append_output), averaged
// over the timed steps. Memory: bytes held by the particle fields, the cell list and the
// solver's scratch (Solver::bytes_held), and the process's peak RSS (getrusage).
// Writes throughput.csv, the plot of scripts/plot_throughput.py and README.md.
#include <fmt/format.h>
#include <omp.h>
#include <strings.h>
#include <sys/resource.h>
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cstdlib>
#include <fstream>

#include "curvsph/io/case_file.hpp"
#include "curvsph/io/case_overrides.hpp"
#include "curvsph/solver/solver.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {
namespace {

struct Config {
  std::string name;       // row label
  std::string case_file;  // under cases/
  std::vector<std::string> overrides;
  bool drop_walls = false;  // fluid only: `boundary.method: none` refuses a case with walls
  int warmup = 0, steps = 0;
  std::vector<int> threads;
};

struct Measurement {
  std::string name;
  int threads = 0;
  double fluid = 0, interacting = 0;  // particles; interacting = fluid + ghosts/elements
  int steps = 0;
  double seconds = 0;  // timed steps only
  double particle_steps_per_second = 0;
  PhaseTimes phases;
  double bytes_held = 0;
  double peak_rss_bytes = 0;
};

double peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) * 1024.0;  // Linux reports kilobytes
}

template <int D>
Measurement measure(const Case& c, const std::string& name, int threads, int warmup, int steps) {
  omp_set_num_threads(threads);
  Solver<D> solver(c);
  solver.initialize();
  for (int k = 0; k < warmup; ++k) solver.step();
  solver.phase_times() = PhaseTimes{};
  Measurement m;
  m.name = name;
  m.threads = threads;
  m.steps = steps;
  m.fluid = static_cast<double>(solver.particles().size());
  std::vector<Vec<D>> bx;
  std::vector<int> kind;
  double boundary_sum = 0;
  for (int k = 0; k < steps; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    solver.step();
    m.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (const auto* b = solver.boundary()) {  // counted outside the timed region
      bx.clear();
      kind.clear();
      b->append_output(bx, kind);
      boundary_sum += static_cast<double>(bx.size());
    }
  }
  m.interacting = m.fluid + boundary_sum / std::max(steps, 1);
  m.particle_steps_per_second = m.seconds > 0 ? m.interacting * steps / m.seconds : 0;
  m.phases = solver.phase_times();
  m.bytes_held = static_cast<double>(solver.bytes_held());
  m.peak_rss_bytes = peak_rss_bytes();
  return m;
}

// How idle OpenMP threads wait (OMP_WAIT_POLICY, and libgomp's GOMP_SPINCOUNT): read by the
// runtime before main(), so the study can only record it. It matters for thread scaling: a
// dam-break step has 22 parallel regions and more barriers, and a thread that sleeps at them
// (passive) must be woken by the kernel each time, ~0.5 ms for a halted vCPU on the VM the
// figures were taken on (docs/performance.md).
const char* wait_policy_env() {
  return std::getenv("OMP_WAIT_POLICY");
}

bool wait_policy_is(const char* want) {
  const char* v = wait_policy_env();
  return v != nullptr && strcasecmp(v, want) == 0;
}

std::string wait_policy() {
  const char* policy = wait_policy_env();
  const char* spin = std::getenv("GOMP_SPINCOUNT");
  std::string s = policy ? policy : "unset (runtime default)";
  if (spin) s += fmt::format(", GOMP_SPINCOUNT={}", spin);
  return s;
}

double share(const Measurement& m, double seconds) {
  return m.seconds > 0 ? seconds / m.seconds : 0;
}

}  // namespace

StudyResult run_throughput_study(const StudyContext& ctx) {
  std::filesystem::create_directories(ctx.out_dir);
  const int dam_warmup = ctx.quick ? 2 : 20, dam_steps = ctx.quick ? 5 : 200;
  // The dam break as DualSPHysics' reference ran it (issue 7); probes and VTK off: output is
  // not part of the interaction being compared.
  const std::vector<std::string> dam = {"resolution.dx=0.018", "eos.c0=45", "time.cfl=0.2",
                                        "output.vtk=false"};
  auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<Config> configs = {
      {"dam_break",
       "dam_break_3d.yaml",
       with(dam, {"resolution.h_over_dx=1.732"}),
       false,
       dam_warmup,
       dam_steps,
       {2, 1}},
      {"dam_break_fourtakas",
       "dam_break_3d.yaml",
       with(dam, {"resolution.h_over_dx=1.732", "density.diffusion_term=fourtakas"}),
       false,
       dam_warmup,
       dam_steps,
       {2, 1}},
      {"dam_break_ghost",
       "dam_break_3d.yaml",
       with(dam, {"resolution.h_over_dx=1.732", "boundary.method=ghost", "boundary.map=mirror",
                  "boundary.velocity=no_slip"}),
       false,
       dam_warmup,
       dam_steps,
       {2, 1}},
      {"dam_break_fluid_only",
       "dam_break_3d.yaml",
       with(dam, {"resolution.h_over_dx=1.732", "boundary.method=none"}),
       true,
       dam_warmup,
       dam_steps,
       {2, 1}},
      {"dam_break_h2",
       "dam_break_3d.yaml",
       with(dam, {"resolution.h_over_dx=2"}),
       false,
       dam_warmup,
       dam_steps,
       {2, 1}},
      {"periodic_box_1e6",
       "periodic_box_3d.yaml",
       {"resolution.dx=0.01"},
       false,
       ctx.quick ? 1 : 2,
       ctx.quick ? 2 : 10,
       {2, 1}},
      {"couette_density_preserving",
       "couette.yaml",
       {"boundary.map=density_preserving", "output.vtk=false"},
       false,
       ctx.quick ? 5 : 20,
       ctx.quick ? 20 : 200,
       {2, 1}},
  };

  std::vector<Measurement> rows;
  for (const auto& cfg : configs) {
    const auto path = ctx.source_dir / "cases" / cfg.case_file;
    YAML::Node root = YAML::LoadFile(path.string());
    root.remove("probes");
    if (cfg.drop_walls) root.remove("walls");
    apply_overrides(root, cfg.overrides);
    const Case c = read_case(root, path);
    for (int t : cfg.threads) {
      fmt::print(stderr, "throughput: {} at {} thread(s)\n", cfg.name, t);
      rows.push_back(c.dimension == 2 ? measure<2>(c, cfg.name, t, cfg.warmup, cfg.steps)
                                      : measure<3>(c, cfg.name, t, cfg.warmup, cfg.steps));
    }
  }
  if (ctx.threads > 0) omp_set_num_threads(ctx.threads);

  auto find = [&](const std::string& name, int threads) -> const Measurement& {
    for (const auto& m : rows)
      if (m.name == name && m.threads == threads) return m;
    throw std::logic_error("throughput: no row " + name);
  };

  {
    std::ofstream csv(ctx.out_dir / "throughput.csv");
    csv << "config,threads,fluid_particles,interacting_particles,steps,seconds,"
           "particle_steps_per_second,neighbors,boundary_prepass,boundary_terms,density,forces,"
           "integrate,bytes_held_per_fluid_particle,peak_rss_bytes\n";
    for (const auto& m : rows) {
      const auto& p = m.phases;
      csv << fmt::format(
          "{},{},{},{:.1f},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},"
          "{:.1f},{:.0f}\n",
          m.name, m.threads, m.fluid, m.interacting, m.steps, m.seconds,
          m.particle_steps_per_second, p.neighbors, p.boundary_prepass,
          p.boundary - p.boundary_prepass, p.density, p.forces, p.integrate, m.bytes_held / m.fluid,
          m.peak_rss_bytes);
    }
  }

  StudyResult r;
  for (const auto& m : rows) {
    const std::string k = fmt::format("{}_{}t", m.name, m.threads);
    r.metrics[k + "_particle_steps_per_second"] = m.particle_steps_per_second;
    r.metrics[k + "_interacting_particles"] = m.interacting;
    r.metrics[k + "_boundary_prepass_share"] = share(m, m.phases.boundary_prepass);
    r.metrics[k + "_shepard_share"] = share(m, m.phases.shepard);
    r.metrics[k + "_boundary_share"] = share(m, m.phases.boundary);
    r.metrics[k + "_density_share"] = share(m, m.phases.density);
    r.metrics[k + "_forces_share"] = share(m, m.phases.forces);
    r.metrics[k + "_neighbors_share"] = share(m, m.phases.neighbors);
    r.metrics[k + "_integrate_share"] = share(m, m.phases.integrate);
    r.metrics[k + "_bytes_held_per_particle"] = m.bytes_held / m.fluid;
  }
  const auto& d2 = find("dam_break", 2);
  const auto& d1 = find("dam_break", 1);
  const auto& box = find("periodic_box_1e6", 2);
  const auto& couette = find("couette_density_preserving", 2);
  r.metrics["dam_break_particle_steps_per_second_2t"] = d2.particle_steps_per_second;
  r.metrics["dam_break_particle_steps_per_second_1t"] = d1.particle_steps_per_second;
  r.metrics["thread_scaling"] = d2.particle_steps_per_second / d1.particle_steps_per_second;
  r.metrics["bytes_per_particle"] = box.bytes_held / box.fluid;
  r.metrics["peak_rss_bytes"] = peak_rss_bytes();
  r.metrics["boundary_prepass_share"] = share(couette, couette.phases.boundary_prepass);
  // The geometric Shepard factor's own time (timed inside the boundary-integral pre-pass);
  // the whole pre-pass also holds the particle-element pair search and the closest-point
  // projections, which every Shepard mode pays (gamma = 1 included): reported beside it.
  r.metrics["shepard_share"] = share(d2, d2.phases.shepard);
  r.metrics["bi_prepass_share"] = share(d2, d2.phases.boundary_prepass);
  // The same run with DualSPHysics' kind of density diffusion (no gradient pass; see
  // density.hpp, DensityDiffusion): the like-for-like comparison with the reference, beside
  // figure (a), which keeps the dam-break case's own (Antuono) term.
  const auto& f2 = find("dam_break_fourtakas", 2);
  const auto& f1 = find("dam_break_fourtakas", 1);
  r.metrics["dam_break_fourtakas_particle_steps_per_second_2t"] = f2.particle_steps_per_second;
  r.metrics["dam_break_fourtakas_particle_steps_per_second_1t"] = f1.particle_steps_per_second;
  r.metrics["dam_break_fourtakas_thread_scaling"] =
      f2.particle_steps_per_second / f1.particle_steps_per_second;
  r.metrics["quick"] = ctx.quick ? 1 : 0;
  // metrics.json holds numbers only (DESIGN.md): the policy as two flags, the text in README.
  r.metrics["omp_wait_policy_active"] = wait_policy_is("active") ? 1 : 0;
  r.metrics["omp_wait_policy_passive"] = wait_policy_is("passive") ? 1 : 0;

  const std::string ref = "issue 7 (DualSPHysics 5.4 on this machine kind: 3.2-3.6e5 on 2 threads)";
  auto row = [&](const std::string& k, const std::string& target, bool pass) {
    r.summary.push_back({k, r.metrics[k].get<double>(), target, ref, pass});
  };
  const double pss2 = r.metrics["dam_break_particle_steps_per_second_2t"];
  const double scaling = r.metrics["thread_scaling"];
  const double bpp = r.metrics["bytes_per_particle"];
  const double prepass = r.metrics["boundary_prepass_share"];
  const double shepard = r.metrics["shepard_share"];
  row("dam_break_particle_steps_per_second_2t", ">= 5e5", pss2 >= 5e5);
  row("dam_break_particle_steps_per_second_1t", "reported", true);
  row("thread_scaling", ">= 1.8", scaling >= 1.8);
  row("bytes_per_particle", "<= 300 (10^6 particles)", bpp <= 300);
  row("boundary_prepass_share", "<= 0.15 (Couette, density_preserving)", prepass <= 0.15);
  row("shepard_share", "<= 0.05 (dam break, geometric)", shepard <= 0.05);
  row("bi_prepass_share", "reported (dam break: gamma + element pair search)", true);
  row("dam_break_fourtakas_particle_steps_per_second_2t",
      "reported (Fourtakas density diffusion, no gradient pass, as DualSPHysics' DDT)", true);

  run_plot_script(ctx, "plot_throughput.py", {ctx.out_dir.string()});

  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Throughput (issue 7)\n\n"
        "Particle-steps per second, counting every particle in the interaction (fluid plus "
        "ghosts or boundary elements, averaged over the timed steps), and the time split by "
        "phase. Dam break: cases/dam_break_3d.yaml at dx = 0.018 m, c0 = 45, CFL 0.2, probes "
        "and VTK off, h/dx = 1.732 (support matched to DualSPHysics' reference run) unless "
        "named `_h2`; `_fourtakas` replaces the case's delta-SPH term (Antuono et al.: "
        "renormalised density gradient, a pass of its own) by Fourtakas et al.'s (2019), which "
        "needs none, like DualSPHysics' density diffusion terms; `_ghost` swaps the boundary "
        "integrals for mirror ghosts, `_fluid_only` "
        "drops the walls (fluid cost alone). `periodic_box_1e6`: cases/periodic_box_3d.yaml at "
        "dx = 0.01. `couette_density_preserving`: cases/couette.yaml with "
        "boundary.map=density_preserving.\n\n"
     << fmt::format(
            "Timed steps: {} after {} warm-up steps (dam break){}. OpenMP wait policy: "
            "{}.\n\n",
            dam_steps, dam_warmup, ctx.quick ? " — a `--quick` run" : "", wait_policy())
     << "Absolute rates depend on the machine and its load: the runs of this directory were "
        "taken on a shared 2-core machine (see docs/performance.md for the load at the time). "
        "Compare rows with each other, not with other machines.\n\n"
        "## Summary\n\n"
     << summary_markdown(r.summary)
     << "\n## All configurations\n\n"
        "| config | threads | interacting particles | p-steps/s | neighbours | pre-pass | "
        "of it gamma | wall terms | density | forces | integrate | bytes held / particle |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& m : rows) {
    const auto& p = m.phases;
    md << fmt::format(
        "| {} | {} | {:.0f} | {:.3g} | {:.0f} % | {:.0f} % | {:.1f} % | {:.0f} % | {:.0f} % | "
        "{:.0f} % | {:.0f} % | {:.0f} |\n",
        m.name, m.threads, m.interacting, m.particle_steps_per_second, 100 * share(m, p.neighbors),
        100 * share(m, p.boundary_prepass), 100 * share(m, p.shepard),
        100 * share(m, p.boundary - p.boundary_prepass), 100 * share(m, p.density),
        100 * share(m, p.forces), 100 * share(m, p.integrate), m.bytes_held / m.fluid);
  }
  md << "\nPhases: `pre-pass` is BoundaryModel::prepare (ghost generation, or gamma and the "
        "element lists of boundary integrals); `of it gamma` the Shepard factor's own time "
        "inside the pre-pass (timed per particle, thread-seconds over the team size: "
        "`shepard_share`); `wall terms` the wall accelerations; the wall contributions to the "
        "density (rate) are inside `density`.\n";
  md << "\nBytes held: particle fields (capacity) + fluid cell list + the solver's scratch + "
        "the re-sort buffers; boundary models' own arrays are not included (peak RSS of the "
        "whole study process: "
     << fmt::format("{:.0f} MB", peak_rss_bytes() / 1e6) << ").\n\n![throughput](throughput.png)\n";
  return r;
}

}  // namespace curvsph
