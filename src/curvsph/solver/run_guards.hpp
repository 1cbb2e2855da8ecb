#pragma once
// What a run checks before it allocates or writes anything (DESIGN.md §3: bad input is exit 2
// within seconds, never a hang, a crash or lost output), and the output schedule by integer
// counters.
#include <filesystem>

#include "curvsph/io/case_file.hpp"

namespace curvsph {

// Snapshots (time.end / output.every) and probe rows (time.end / output.probe_every) a run may
// ask for without `run --force`: output.every = 1e-12 wrote a snapshot every step (about 1 GB
// a minute) and time.end = 1e300 asked for 2e301. The cases of cases/ ask for at most 120
// snapshots and 6000 probe rows.
inline constexpr double kMaxSnapshots = 1e5;
inline constexpr double kMaxProbeRows = 1e7;

// Bytes per particle of the up-front memory estimate. Measured (docs/validation/throughput):
// Solver::bytes_held is 220 to 365 bytes per fluid particle and the peak resident size of a
// whole run 350 bytes per particle (10^6-particle periodic box) to 1.5 kB (the 3-D dam break
// at 116 000 particles with its boundary elements and start-up); 2 kB keeps the estimate above
// both.
inline constexpr double kBytesPerParticle = 2048;

// Checks the output directory and clears it on `overwrite`; creates it. Throws InputError
// (key --out) when `dir` exists and is not a directory (a regular file, /dev/null), cannot be
// created, or holds another run's files (series.pvd, metrics.json, metrics_unstable.json,
// probes.csv, forces.csv, particles_*, boundary_* and walls_* .vtp/.pvtp) and `overwrite` is off;
// with `overwrite` those files are removed (others, log.txt included, are left). `restart`: the
// snapshot a run starts from, which `overwrite` must not remove.
void prepare_output_dir(const std::filesystem::path& dir, bool overwrite,
                        const std::filesystem::path& restart);

// Refuses (InputError naming output.every / output.probe_every) a schedule of more than
// kMaxSnapshots snapshots, or of more than kMaxProbeRows probe rows when `probe_rows`,
// unless `force`. time.max_steps bounds both.
void check_output_count(const Case& c, bool probe_rows, bool force);

// Physical memory in bytes (sysconf), 0 when unknown.
double physical_memory();

// The particle count the case's fluid regions will generate (setup/generate.hpp) and the
// bytes at kBytesPerParticle; refuses (InputError naming resolution.dx) above `max_bytes`
// (0: 80 % of physical_memory()), before any particle exists.
void check_memory(const Case& c, double max_bytes);

// Output (or probe) times k * every, k = 1, 2, ..., counted by k: no `next += every` loop,
// which never caught up with t when every was tiny against t's round-off (time.end = 1e300
// hung there). Times within eps of t count as reached.
class OutputSchedule {
 public:
  OutputSchedule(double every, double t_start, double eps);
  double next() const { return k_ * every_; }
  // The counter k, for the restart state (solver/restart_state.hpp).
  double counter() const { return k_; }
  void set_counter(double k) { k_ = k; }
  // Whether t reached next(); if so the counter moves to the first time after t.
  bool reached(double t);

 private:
  double first_after(double t) const;
  double every_, eps_;
  double k_;  // an integer, in a double (exact to 2^53; past that a run was --force'd)
};

}  // namespace curvsph
