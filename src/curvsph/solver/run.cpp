#include "curvsph/solver/run.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <fstream>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/boundary/integrals/element_quadrature.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/core/stage_report.hpp"
#include "curvsph/core/threads.hpp"
#include "curvsph/io/forces_csv.hpp"
#include "curvsph/io/probes.hpp"
#include "curvsph/parallel/agree.hpp"
#include "curvsph/solver/progress.hpp"
#include "curvsph/solver/restart_state.hpp"
#include "curvsph/solver/run_guards.hpp"
#include "curvsph/solver/snapshot_writer.hpp"
#include "curvsph/solver/solver.hpp"
#include "curvsph/solver/stop_signal.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

// The restart state beside `snapshot` (solver/restart_state.hpp), checked against the case.
RestartState read_restart(const fs::path& snapshot, const Case& c) {
  const fs::path file = restart_state_path(snapshot);
  RestartState s = read_restart_state(file);
  check_case(s, c, snapshot.string());
  const auto it = s.header.find("snapshot");
  const std::string listed = it != s.header.end() && it->is_string() ? it->get<std::string>() : "";
  if (listed != snapshot.filename().string())
    throw InputError(
        file.string(), "snapshot",
        "belongs to the snapshot '" + listed + "', not to '" + snapshot.filename().string() + "'");
  const std::int64_t index = header_integer(s, "snapshot_index", file.string());
  if (index < 0 || index >= 999999)
    throw InputError(file.string(), "snapshot_index", "must be 0 to 999998");
  for (const char* key : {"output_counter", "probe_counter"})
    if (!(header_number(s, key, file.string()) >= 0))
      throw InputError(file.string(), key, "must be a number >= 0");
  return s;
}

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

// ranks, load_imbalance, halo_fraction and the communication counters (issue 8); on one
// rank: 1, 1, 0 and zeros.
template <int D>
void add_decomposition_metrics(const Decomposition<D>& dec, nlohmann::json& m) {
  const mpi::Comm& comm = dec.comm();
  const DecompositionStats& s = dec.stats();
  m["ranks"] = comm.size();
  // 1: the fluid passes ran under the midpoint rule (halo of h), 0: the owner rule (2h).
  m["halo_rule_midpoint"] = dec.midpoint() ? 1 : 0;
  // Max over mean owned count, averaged over the migrations (after each, before any
  // re-balance it triggers), and its largest value.
  m["load_imbalance"] = s.migrations ? s.imbalance_sum / static_cast<double>(s.migrations) : 1.0;
  m["load_imbalance_max"] = s.imbalance_max;
  m["rebalances"] = s.rebalances;
  // Halo copies per owned particle, summed over ranks and steps.
  const double halo = comm.sum(s.halo_sum), owned = comm.sum(s.owned_sum);
  m["halo_fraction"] = owned > 0 ? halo / owned : 0.0;
  m["seconds_communication"] = comm.max(comm.stats().seconds);
  m["seconds_decomposition"] = comm.max(s.seconds);
  m["messages"] = comm.sum(static_cast<std::int64_t>(comm.stats().messages));
  m["bytes_sent"] = comm.sum(comm.stats().bytes);
  if (s.conservation_checks > 0) {
    m["conservation_checks"] = s.conservation_checks;
    m["conservation_count_error_max"] = s.count_error_max;
    m["conservation_id_error_max"] = s.id_error_max;
    m["conservation_mass_rel_error_max"] = s.mass_rel_error_max;
  }
}

template <int D>
nlohmann::json run_typed(const Case& c, const RunOptions& o) {
  // Capped at the processors available (core/threads.hpp; `run` warns).
  if (const int threads = cap_threads(o.threads).threads; threads > 0) omp_set_num_threads(threads);
  const auto wall_start = std::chrono::steady_clock::now();
  const mpi::Comm comm = mpi::Comm::world();
  const bool parallel = comm.size() > 1;
  // [mpi] Rank 0 writes the shared files (log, series, probes, metrics); every rank writes
  // its own piece of each snapshot.
  const bool writer = o.write_files && comm.root();
  // Refusals before anything is allocated or written (run_guards.hpp); rank 0 checks and
  // clears the output directory.
  mpi::agree_on_input(comm, [&] {
    check_output_count(c, o.write_files && !c.probes.empty(), o.force);
    check_memory(c, o.max_memory);
    if (writer) prepare_output_dir(o.out_dir, o.overwrite, o.restart);
  });
  if (o.write_files) fs::create_directories(o.out_dir);
  RunLog log(o.out_dir / "log.txt", writer);
  log("curvsph run: case '{}' from {}", c.name, c.file_name());

  // Set-up reads the rest of the case (walls, analyses, probes): an error found on any rank
  // stops every rank with the same message before the first collective step.
  std::unique_ptr<Solver<D>> solver_ptr;
  std::vector<std::unique_ptr<Analysis<D>>> analyses;
  // Set-up stages longer than ~2 s say so (core/stage_report.hpp), as the progress line does.
  struct StageReports {
    explicit StageReports(bool on) { set_stage_reports(on); }
    ~StageReports() { set_stage_reports(false); }
  } stage_reports_on(o.progress && comm.root());
  mpi::agree_on_input(comm, [&] {
    solver_ptr = std::make_unique<Solver<D>>(c);
    if (const YAML::Node an = c.root["analysis"]; an && an.IsMap())
      for (const auto& kv : an)
        analyses.push_back(make_analysis<D>(kv.first.as<std::string>(), kv.second, c));
  });
  Solver<D>& solver = *solver_ptr;
  // A restart continues the stopped run's state (solver/restart_state.hpp): the solver's, the
  // analyses' series and the output schedule; its snapshots are numbered after the one it
  // starts from.
  std::optional<RestartState> restored;
  if (!o.restart.empty()) {
    const std::string file = restart_state_path(o.restart).string();
    mpi::agree_on_input(comm, [&] {
      restored = read_restart(o.restart, c);
      solver.load_state(*restored, file);
      const nlohmann::json& states = restored->header["analyses"];
      if (comm.root())
        for (std::size_t k = 0; k < analyses.size(); ++k) {
          const std::string key = "analyses." + std::to_string(k);
          if (!states.is_array() || k >= states.size())
            throw InputError(file, key, "missing: the snapshot's run had other analyses");
          try {
            analyses[k]->load_state(states[k]);
          } catch (const nlohmann::json::exception& e) {
            throw InputError(file, key, std::string("does not fit the analysis: ") + e.what());
          }
        }
    });
    log("restart from {} at t = {:.17g}, step {}", o.restart.string(), solver.time(),
        solver.steps());
  }

  // A named snapshot (the state of an unstable run) is written even with output.vtk off:
  // DESIGN.md §3 promises an unstable run's last VTK snapshot, and studies that turn the
  // periodic output off are where a blow-up is otherwise left without one.
  SnapshotWriter<D> snapshots(c, o.out_dir, comm);
  if (restored)
    snapshots.continue_after(static_cast<int>(
        header_integer(*restored, "snapshot_index", restart_state_path(o.restart).string())));
  auto write_snapshot = [&](const std::string& name) {
    if (!o.write_files || (!c.write_vtk && name.empty())) return;
    const auto t0 = std::chrono::steady_clock::now();
    snapshots.write(solver, name);
    solver.phase_times().output +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };

  // Wall loads (io/forces_csv.hpp): at the forces times, and in metrics.json; computed by the
  // boundary model's wall pass of the steps that land on those times (Solver::wall_loads).
  const bool has_loads = solver.boundary() && !solver.walls().empty() && c.forces_every != 0;
  if (has_loads) solver.want_wall_loads_from(solver.time());
  try {
    solver.initialize();
  } catch (const InstabilityError& e) {
    // The initial state is already bad (e.g. an initial pressure field the EOS maps outside
    // [0.5, 2] rho0): leave the snapshot DESIGN.md §3 promises, as for a later step.
    log("UNSTABLE: {}", e.what());
    write_snapshot("particles_unstable.vtp");
    throw;
  }
  // [mpi] Totals over the ranks.
  const auto n_particles = static_cast<std::size_t>(solver.decomposition().global_count());
  log("{} particles, dimension {}, dx = {}, h = {}, threads = {}, ranks = {}", n_particles, D, c.dx,
      c.h(), omp_get_max_threads(), comm.size());
  // Which wall-term quadrature a boundary-integral run used (element_quadrature.hpp), in
  // metrics.json and metrics_unstable.json alike: stored runs from before it (W at the element
  // centres) lack the key, and studies say so.
  const auto label_quadrature = [&](nlohmann::json& m) {
    if (c.boundary.method == "integrals")
      m["bi_element_quadrature_points"] = ElementQuadrature<D>::kPoints;
  };
  // The stray-particle counters (solver/stray_particles.hpp), summed over the ranks.
  const auto add_stray_metrics = [&](nlohmann::json& m) {
    const auto& sc = solver.stray_counts();
    m["particles_initial"] = solver.initial_count();
    m["particles_removed"] = comm.sum(static_cast<std::int64_t>(sc.removed));
    m["particles_projected"] = comm.sum(static_cast<std::int64_t>(sc.projected));
    m["density_clamped"] = comm.sum(static_cast<std::int64_t>(sc.density_clamped));
    m["wall_contacts"] = comm.sum(static_cast<std::int64_t>(sc.contacts));
    // [mpi] a particle stopped on two ranks (it migrated between) counts twice.
    m["wall_contact_particles"] = comm.sum(static_cast<std::int64_t>(solver.contact_particles()));
    if (const auto& ob = solver.open_boundaries(); ob.active()) {
      // Open boundaries (solver/open_boundaries.hpp): what crossed them, and the fluid's mass
      // (buffer particles not counted), which changes by mass_inflow - mass_outflow.
      m["particles_inflow"] = comm.sum(ob.inflow_count());
      m["particles_outflow"] = comm.sum(ob.outflow_count());
      m["mass_inflow"] = comm.sum(ob.inflow_mass());
      m["mass_outflow"] = comm.sum(ob.outflow_mass());
      m["mass_fluid_initial"] = solver.fluid_mass_initial();
      m["mass_fluid"] = solver.fluid_mass();
    }
  };
  const char* relax_figure =
      c.relax.map == "integrals" ? "BI residual max h|R|" : "node-density spread";
  if (const auto& rr = solver.relax_result())
    log("relaxation: {} steps in {:.2f} s, {} {:.4g} -> {:.4g} (tolerance {})", rr->steps,
        rr->seconds, relax_figure, rr->spread_initial, rr->spread, c.relax.tolerance);
  if (const auto& rr = solver.relax_result(); rr && c.relax.max_steps > 0 &&
                                              rr->spread > c.relax.tolerance && o.warnings &&
                                              comm.root() && o.restart.empty()) {
    // (max_steps = 0 asks for no packing: a case switching its packing off says so.)
    // An unconverged packing starts the run off the scheme's equilibrium where it stopped
    // (with boundary integrals, at the corners and walls: the forces 2 p_i R_i of
    // integrals_boundary.cpp item 2b), so say it rather than leave it in the log.
    fmt::print(stderr,
               "warning: {}: setup.relax stopped at max_steps = {} with {} {:.3g}, above its "
               "tolerance {:.3g}; raise setup.relax.max_steps or the tolerance\n",
               c.file_name(), rr->steps, relax_figure, rr->spread, c.relax.tolerance);
  }
  if (const auto& de = solver.initial_density_error()) {
    log("first density sum against the set-up density: max |rho/rho_set - 1| = {:.3g}; about "
        "its mean, max {:.3g} with {} particles above 1 %",
        de->max, de->local, de->local_above_1pct);
    // A local error above 2 % starts the run with pressure waves of a few per cent of
    // rho0 c0^2, as large as the flow's own (c0 is chosen for ~1 % density variation).
    if (de->local > 0.02 && o.warnings && comm.root() && o.restart.empty()) {
      // The plain mirror at a curved wall is the usual cause (Barker §2: its ghosts stand for
      // the wrong volume); say so where it applies.
      const bool mirror = c.boundary.method == "ghost" && c.boundary.map == "mirror";
      fmt::print(stderr,
                 "warning: {}: the first density sum departs from the set-up density by up to "
                 "{:.2g} % ({} particles above 1 %){}\n",
                 c.file_name(), 100 * de->local, de->local_above_1pct,
                 mirror ? "; the mirror map miscounts the ghosts' volume at curved walls "
                          "(boundary.map mirror_beta or density_preserving corrects it), and an "
                          "arrangement cut by a wall leaves gaps or overlaps there"
                        : "; the arrangement is uneven where it meets the walls (a lattice cut "
                          "by a wall leaves gaps or overlaps there; setup.relax packs a fluid "
                          "region)");
    }
  }

  std::unique_ptr<ProbeWriter<D>> probes;
  if (writer && !c.probes.empty())
    probes = std::make_unique<ProbeWriter<D>>(c.probes, (o.out_dir / "probes.csv").string(),
                                              static_cast<Real>(c.dx),
                                              c.gravity.head<D>().template cast<Real>());
  const bool any_probes = o.write_files && !c.probes.empty();
  // [mpi] Probes and analyses see every particle: with MPI the owned particles are gathered
  // on rank 0 at probe and output times (not scalable beyond one node's memory; fine for
  // the sizes these figures are computed at).
  CellList<D> gathered_cells;
  gathered_cells.configure(solver.cells().support(), c.domain_min, c.domain_max, c.periodic);
  double last_probe_time = -1;
  auto write_probes = [&](double t) {
    last_probe_time = t;
    if (!parallel) {
      if (probes) probes->write_row(t, solver.particles(), solver.cells(), solver.kernel());
      return;
    }
    const Particles<D> all = solver.decomposition().gather(solver.particles());
    if (!probes) return;
    gathered_cells.build(all.x);
    probes->write_row(t, all, gathered_cells, solver.kernel());
  };
  // Runs f(particles) on the view of every particle: this rank's on one rank, the gathered
  // set on rank 0 with MPI (the other ranks only take part in the gather).
  auto with_all = [&](auto&& f) {
    if (!parallel) return f(solver.particles());
    const Particles<D> all = solver.decomposition().gather(solver.particles());
    if (comm.root()) return f(all);
    return decltype(f(all))();
  };
  double last_observed_time = -1;
  auto observe = [&] {
    if (!analyses.empty())
      with_all([&](const Particles<D>& all) {
        for (auto& a : analyses) a->observe(solver.time(), all);
      });
    last_observed_time = solver.time();
  };

  const double t_end = c.t_end;
  const double eps = 1e-9 * std::max(1.0, t_end);
  const double out_every = c.output_every > 0 ? c.output_every : t_end;
  const double probe_every = c.probe_every > 0 ? c.probe_every : out_every;
  // Output and probe times after the start (t = 0, or a restart's time), multiples of every.
  OutputSchedule out_times(out_every, solver.time(), eps);
  OutputSchedule probe_times(probe_every, solver.time(), eps);
  const double forces_every = c.forces_every > 0 ? c.forces_every : probe_every;
  OutputSchedule force_times(forces_every, solver.time(), eps);
  const WallGroups wall_groups = WallGroups::of(solver.walls());
  std::unique_ptr<ForcesCsv> forces;
  if (writer && has_loads)
    forces = std::make_unique<ForcesCsv>((o.out_dir / "forces.csv").string(), wall_groups, D);
  std::vector<WallLoad> loads_last, loads_sum(wall_groups.names.size());
  long load_rows = 0;
  double last_load_time = -1;
  auto record_loads = [&] {
    if (!has_loads || solver.wall_loads_time() != solver.time()) return;
    last_load_time = solver.time();
    loads_last = wall_groups.sum(solver.wall_loads());
    for (std::size_t k = 0; k < loads_last.size(); ++k)
      for (std::size_t a = 0; a < 3; ++a) {
        loads_sum[k].force[a] += loads_last[k].force[a];
        loads_sum[k].moment[a] += loads_last[k].moment[a];
      }
    ++load_rows;
    if (forces) forces->write_row(solver.time(), solver.wall_loads());
  };
  // The restart state beside each numbered snapshot (output.restart), after the analyses
  // observed its time; with `last` the previous one is removed once the new one is written.
  fs::path last_restart_file;
  auto analysis_states = [&] {
    nlohmann::json states = nlohmann::json::array();
    for (const auto& a : analyses) states.push_back(a->save_state());
    return states;
  };
  auto write_restart = [&](nlohmann::json states) {
    if (!o.write_files || !c.write_vtk || c.output_restart == Case::RestartFiles::none) return;
    const auto t0 = std::chrono::steady_clock::now();
    RestartState s;
    solver.save_state(s);  // [mpi] collective: gathers on rank 0
    if (!writer) return;
    stamp_case(s, c);
    s.header["snapshot"] = snapshots.last_file();
    s.header["snapshot_index"] = snapshots.last_index();
    s.header["output_counter"] = out_times.counter();
    s.header["probe_counter"] = probe_times.counter();
    s.header["threads"] = omp_get_max_threads();
    s.header["analyses"] = std::move(states);
    const fs::path file = restart_state_path(o.out_dir / snapshots.last_file());
    write_restart_state(file, s);
    if (c.output_restart == Case::RestartFiles::last && !last_restart_file.empty() &&
        last_restart_file != file)
      fs::remove(last_restart_file);
    last_restart_file = file;
    solver.phase_times().output +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  if (restored) {
    // The first run wrote this time's snapshot, probe row and observation: go on after them,
    // on its schedule's counters.
    const std::string file = restart_state_path(o.restart).string();
    out_times.set_counter(header_number(*restored, "output_counter", file));
    probe_times.set_counter(header_number(*restored, "probe_counter", file));
    last_probe_time = last_observed_time = solver.time();
  } else {
    write_snapshot("");
    if (any_probes) write_probes(solver.time());
    record_loads();
    observe();
    write_restart(analysis_states());
  }

  Progress progress(o.progress && comm.root(), t_end, n_particles);
  const auto loop_start = std::chrono::steady_clock::now();
  bool unstable = false;
  bool stopped = false;
  const StopOnSignal stop_on_signal;
  try {
    while (solver.time() < t_end - eps && (c.max_steps == 0 || solver.steps() < c.max_steps)) {
      // [mpi] every rank stops at the same step when any was signalled.
      stopped = stop_signal() != 0;
      if (parallel) stopped = comm.max(static_cast<std::int64_t>(stopped)) > 0;
      if (stopped) {
        log("stopped by a signal at t = {:.6g}, step {}", solver.time(), solver.steps());
        break;
      }
      const double t = solver.time();
      double cap = std::min({t_end - t, out_times.next() - t, probe_times.next() - t});
      if (has_loads) {
        cap = std::min(cap, force_times.next() - t);
        solver.want_wall_loads_from(std::min(force_times.next(), t_end) - eps);
      }
      solver.step(static_cast<Real>(cap));
      const double tn = solver.time();
      if (probe_times.reached(tn) && any_probes) write_probes(tn);
      if (force_times.reached(tn) || tn >= t_end - eps) record_loads();
      if (out_times.reached(tn)) {
        write_snapshot("");
        observe();
        write_restart(analysis_states());
        log("t = {:.6g}, step {}, dt = {:.4g}", tn, solver.steps(), solver.dt());
      }
      progress.update(solver.steps(), tn, solver.stable_step());
    }
  } catch (const InstabilityError& e) {
    progress.finish();
    log("UNSTABLE: {}", e.what());
    write_snapshot("particles_unstable.vtp");
    bool absorbed = false;
    if (!analyses.empty())
      with_all([&](const Particles<D>& all) {
        for (auto& a : analyses) absorbed |= a->absorb_instability(solver.time(), all, e);
      });
    // [mpi] rank 0 decides for every rank (only it ran the analyses).
    if (parallel) absorbed = comm.max(static_cast<std::int64_t>(absorbed)) > 0;
    if (!absorbed) {
      // The analyses still report the state the run reached (a study plots a failed run up to
      // its failure): metrics_unstable.json (metrics.json stays the mark of a finished run),
      // then exit 3 as before.
      nlohmann::json m;
      m["particles"] = n_particles;
      m["steps"] = solver.steps();
      m["threads"] = omp_get_max_threads();
      m["ranks"] = comm.size();
      m["time_reached"] = solver.time();
      m["wall_seconds"] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      m["unstable"] = 1;  // 0/1 as in metrics.json
      m["unstable_message"] = e.what();
      label_quadrature(m);
      add_stray_metrics(m);
      with_all([&](const Particles<D>& all) {
        for (auto& a : analyses) a->finish(solver.time(), all, m, writer ? o.out_dir : fs::path());
      });
      if (writer) std::ofstream(o.out_dir / "metrics_unstable.json") << m.dump(2) << '\n';
      throw;
    }
    unstable = true;
    log("the run stops at t = {:.6g}; the analyses record the event", solver.time());
  }
  if (!unstable) {
    progress.update(solver.steps(), solver.time(), solver.stable_step(), true);
    progress.finish();
  }
  // The last state is observed once: compare with the last observation, not the last
  // snapshot (with output.vtk = false no snapshot is ever written).
  if (!unstable && solver.time() != last_observed_time) {
    write_snapshot("");
    // The analyses' state before this extra observation (the time a cut or a signal stopped
    // at, off the output schedule): a restart from here observes the scheduled times only,
    // as the straight run does.
    nlohmann::json states = analysis_states();
    observe();
    write_restart(std::move(states));
  }
  // Likewise the probes: a run cut by time.max_steps or a signal ends its probe series with
  // the state it stopped at, as its snapshots.
  if (!unstable && any_probes && solver.time() != last_probe_time) write_probes(solver.time());
  const double loop_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  nlohmann::json m;
  m["particles"] = n_particles;
  m["steps"] = solver.steps();
  m["threads"] = omp_get_max_threads();
  m["wall_seconds"] = wall;
  m["particle_steps_per_second"] =
      loop_seconds > 0 ? static_cast<double>(n_particles) * solver.steps() / loop_seconds : 0.0;
  add_decomposition_metrics(solver.decomposition(), m);
  m["time_reached"] = solver.time();
  m["unstable"] = unstable ? 1 : 0;
  m["stopped"] = stopped ? 1 : 0;  // ended by SIGINT / SIGTERM before time.end
  add_stray_metrics(m);
  if (const auto& de = solver.initial_density_error()) {
    m["density_error_initial"] = de->max;
    m["density_error_initial_local"] = de->local;
    m["density_error_initial_local_above_1pct"] = de->local_above_1pct;
  }
  label_quadrature(m);
  if (const auto& rr = solver.relax_result()) {
    m["relax_steps"] = rr->steps;
    m["relax_node_density_spread"] = rr->spread;
    m["relax_node_density_spread_initial"] = rr->spread_initial;
    m["relax_seconds"] = rr->seconds;
  }
  // [mpi] Phase times of the slowest rank (the others wait for it).
  const auto& pt = solver.phase_times();
  m["seconds_neighbors"] = comm.max(pt.neighbors);
  m["seconds_boundary"] = comm.max(pt.boundary);
  m["seconds_boundary_prepass"] = comm.max(pt.boundary_prepass);
  m["seconds_shepard"] = comm.max(pt.shepard);
  m["seconds_density"] = comm.max(pt.density);
  m["seconds_forces"] = comm.max(pt.forces);
  m["seconds_integrate"] = comm.max(pt.integrate);
  m["seconds_output"] = comm.max(pt.output);
  // The wall loads: at the last forces time (forces.NAME.fx, ...) and their mean over the
  // forces times (forces_mean.NAME.fx, ...), the start included.
  if (load_rows > 0) {
    for (std::size_t k = 0; k < wall_groups.names.size(); ++k) {
      const auto names = load_components(D);
      const auto last = load_values(loads_last[k], D), sum = load_values(loads_sum[k], D);
      for (std::size_t a = 0; a < names.size(); ++a) {
        m["forces." + wall_groups.names[k] + "." + names[a]] = last[a];
        m["forces_mean." + wall_groups.names[k] + "." + names[a]] =
            sum[a] / static_cast<double>(load_rows);
      }
    }
    m["forces_time"] = last_load_time;
  }
  with_all([&](const Particles<D>& all) {
    for (auto& a : analyses) a->finish(solver.time(), all, m, writer ? o.out_dir : fs::path());
  });
  if (writer) {
    std::ofstream(o.out_dir / "metrics.json") << m.dump(2) << '\n';
    log("done: {} steps in {:.2f} s", solver.steps(), wall);
  }
  return m;
}

}  // namespace

nlohmann::json run_case(const Case& c, const RunOptions& o) {
  // Where a stop ends the program (stop_signal.hpp), no run starts after one, and a stopped
  // run ends it once its outputs are written.
  if (stop_ends_program() && stop_signal() != 0) throw Interrupted{stop_signal()};
  nlohmann::json m = c.dimension == 2 ? run_typed<2>(c, o) : run_typed<3>(c, o);
  if (stop_ends_program() && m.value("stopped", 0) != 0) throw Interrupted{stop_signal()};
  return m;
}

}  // namespace curvsph
