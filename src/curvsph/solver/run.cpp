#include "curvsph/solver/run.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <fstream>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/probes.hpp"
#include "curvsph/io/pvd_series.hpp"
#include "curvsph/io/vtk_writer.hpp"
#include "curvsph/solver/progress.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

// Writes to log.txt (when files are written) and nowhere else: stderr belongs to progress.
class RunLog {
 public:
  explicit RunLog(const fs::path& path, bool enabled) {
    if (enabled) out_.open(path);
  }
  template <class... A>
  void operator()(fmt::format_string<A...> f, A&&... a) {
    if (out_) {
      out_ << fmt::format(f, std::forward<A>(a)...) << '\n';
      out_.flush();
    }
  }

 private:
  std::ofstream out_;
};

template <int D>
nlohmann::json run_typed(const Case& c, const RunOptions& o) {
  if (o.threads > 0) omp_set_num_threads(o.threads);
  const auto wall_start = std::chrono::steady_clock::now();
  if (o.write_files) fs::create_directories(o.out_dir);
  RunLog log(o.out_dir / "log.txt", o.write_files);
  log("curvsph run: case '{}' from {}", c.name, c.file_name());

  Solver<D> solver(c);
  try {
    solver.initialize();
  } catch (const InstabilityError& e) {
    // The initial state is already bad (e.g. an initial pressure field the EOS maps outside
    // [0.5, 2] rho0): leave the snapshot DESIGN.md §3 promises, as for a later step.
    log("UNSTABLE: {}", e.what());
    if (o.write_files && c.write_vtk)
      io::write_vtp(o.out_dir / "particles_unstable.vtp", solver.particles());
    throw;
  }
  const auto& P = solver.particles();
  log("{} particles, dimension {}, dx = {}, h = {}, threads = {}", P.size(), D, c.dx, c.h(),
      omp_get_max_threads());
  if (const auto& rr = solver.relax_result())
    log("relaxation: {} steps in {:.2f} s, node-density spread {:.4g} -> {:.4g} (tolerance {})",
        rr->steps, rr->seconds, rr->spread_initial, rr->spread, c.relax.tolerance);

  std::vector<std::unique_ptr<Analysis<D>>> analyses;
  if (const YAML::Node an = c.root["analysis"]; an && an.IsMap())
    for (const auto& kv : an)
      analyses.push_back(make_analysis<D>(kv.first.as<std::string>(), kv.second, c));

  io::PvdSeries series(o.out_dir / "series.pvd");
  std::unique_ptr<ProbeWriter<D>> probes;
  if (o.write_files && !c.probes.empty())
    probes = std::make_unique<ProbeWriter<D>>(c.probes, (o.out_dir / "probes.csv").string(),
                                              static_cast<Real>(c.dx));
  int snapshot = 0;
  auto write_snapshot = [&](const std::string& name) {
    if (!o.write_files || !c.write_vtk) return;
    const auto t0 = std::chrono::steady_clock::now();
    const int index = snapshot;
    const std::string file = name.empty() ? fmt::format("particles_{:06d}.vtp", snapshot++) : name;
    io::write_vtp(o.out_dir / file, solver.particles());
    series.add(solver.time(), file);
    // Ghosts / wall elements as a second block of the series (kind: 1 ghost, 2 element).
    if (const auto* b = solver.boundary()) {
      std::vector<Vec<D>> bx;
      std::vector<int> kind;
      b->append_output(bx, kind);
      if (!bx.empty()) {
        io::VtkPolyData poly;
        poly.set_points(bx);
        poly.add_scalar("kind", std::vector<std::int32_t>(kind.begin(), kind.end()));
        const std::string bfile =
            name.empty() ? fmt::format("boundary_{:06d}.vtp", index) : "boundary_" + name;
        poly.write(o.out_dir / bfile);
        series.add(solver.time(), bfile, 1);
      }
    }
    solver.phase_times().output +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  double last_observed_time = -1;
  auto observe = [&] {
    for (auto& a : analyses) a->observe(solver.time(), solver.particles());
    last_observed_time = solver.time();
  };

  const double t_end = c.t_end;
  const double eps = 1e-9 * std::max(1.0, t_end);
  const double out_every = c.output_every > 0 ? c.output_every : t_end;
  const double probe_every = c.probe_every > 0 ? c.probe_every : out_every;
  double next_out = out_every, next_probe = probe_every;
  write_snapshot("");
  if (probes) probes->write_row(0, solver.particles(), solver.cells(), solver.kernel());
  observe();

  Progress progress(o.progress, t_end, P.size());
  const auto loop_start = std::chrono::steady_clock::now();
  bool unstable = false;
  try {
    while (solver.time() < t_end - eps && (c.max_steps == 0 || solver.steps() < c.max_steps)) {
      const double t = solver.time();
      const double cap = std::min({t_end - t, next_out - t, next_probe - t});
      solver.step(static_cast<Real>(cap));
      const double tn = solver.time();
      if (probes && tn >= next_probe - eps) {
        probes->write_row(tn, solver.particles(), solver.cells(), solver.kernel());
      }
      while (next_probe <= tn + eps) next_probe += probe_every;
      if (tn >= next_out - eps) {
        write_snapshot("");
        observe();
        log("t = {:.6g}, step {}, dt = {:.4g}", tn, solver.steps(), solver.dt());
      }
      while (next_out <= tn + eps) next_out += out_every;
      progress.update(solver.steps(), tn, solver.dt());
    }
  } catch (const InstabilityError& e) {
    progress.finish();
    log("UNSTABLE: {}", e.what());
    write_snapshot("particles_unstable.vtp");
    bool absorbed = false;
    for (auto& a : analyses)
      absorbed |= a->absorb_instability(solver.time(), solver.particles(), e);
    if (!absorbed) {
      // The analyses still report the state the run reached (a study plots a failed run up to
      // its failure): metrics_unstable.json (metrics.json stays the mark of a finished run),
      // then exit 3 as before.
      if (o.write_files) {
        nlohmann::json m;
        m["particles"] = P.size();
        m["steps"] = solver.steps();
        m["threads"] = omp_get_max_threads();
        m["time_reached"] = solver.time();
        m["wall_seconds"] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
        m["unstable"] = true;
        m["unstable_message"] = e.what();
        for (auto& a : analyses) a->finish(solver.time(), solver.particles(), m, o.out_dir);
        std::ofstream(o.out_dir / "metrics_unstable.json") << m.dump(2) << '\n';
      }
      throw;
    }
    unstable = true;
    log("the run stops at t = {:.6g}; the analyses record the event", solver.time());
  }
  if (!unstable) {
    progress.update(solver.steps(), solver.time(), solver.dt(), true);
    progress.finish();
  }
  // The last state is observed once: compare with the last observation, not the last
  // snapshot (with output.vtk = false no snapshot is ever written).
  if (!unstable && solver.time() != last_observed_time) {
    write_snapshot("");
    observe();
  }
  const double loop_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  nlohmann::json m;
  m["particles"] = P.size();
  m["steps"] = solver.steps();
  m["threads"] = omp_get_max_threads();
  m["wall_seconds"] = wall;
  m["particle_steps_per_second"] =
      loop_seconds > 0 ? static_cast<double>(P.size()) * solver.steps() / loop_seconds : 0.0;
  m["time_reached"] = solver.time();
  m["unstable"] = unstable ? 1 : 0;
  if (const auto& rr = solver.relax_result()) {
    m["relax_steps"] = rr->steps;
    m["relax_node_density_spread"] = rr->spread;
    m["relax_node_density_spread_initial"] = rr->spread_initial;
    m["relax_seconds"] = rr->seconds;
  }
  const auto& pt = solver.phase_times();
  m["seconds_neighbors"] = pt.neighbors;
  m["seconds_boundary"] = pt.boundary;
  m["seconds_boundary_prepass"] = pt.boundary_prepass;
  m["seconds_density"] = pt.density;
  m["seconds_forces"] = pt.forces;
  m["seconds_integrate"] = pt.integrate;
  m["seconds_output"] = pt.output;
  for (auto& a : analyses)
    a->finish(solver.time(), solver.particles(), m,
              o.write_files ? o.out_dir : std::filesystem::path());
  if (o.write_files) {
    std::ofstream(o.out_dir / "metrics.json") << m.dump(2) << '\n';
    log("done: {} steps in {:.2f} s", solver.steps(), wall);
  }
  return m;
}

}  // namespace

nlohmann::json run_case(const Case& c, const RunOptions& o) {
  return c.dimension == 2 ? run_typed<2>(c, o) : run_typed<3>(c, o);
}

}  // namespace curvsph
