#include "curvsph/solver/run_guards.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <system_error>
#include <vector>

#include "curvsph/core/error.hpp"
#include "curvsph/setup/generate.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A file a run writes (run.cpp): log.txt is left out, as a shell may have redirected a run's
// output there before the run starts.
bool is_run_output(const std::string& name) {
  if (name == "series.pvd" || name == "metrics.json" || name == "metrics_unstable.json" ||
      name == "probes.csv" || name == "forces.csv")
    return true;
  const bool vtk = ends_with(name, ".vtp") || ends_with(name, ".pvtp") ||
                   ends_with(name, ".restart");  // the restart state (restart_state.hpp)
  return vtk && (name.starts_with("particles_") || name.starts_with("boundary_") ||
                 name.starts_with("walls_"));
}

// "819 kB", "205 GB", "2.05e+06 TB".
std::string bytes_text(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB"};
  int u = 0;
  while (u < 4 && bytes >= 1000) {
    bytes /= 1000;
    ++u;
  }
  return fmt::format("{:.3g} {}", bytes, units[u]);
}

// Outputs the schedule asks for: time.end / every (+ the first), at most max_steps + 2.
double output_count(const Case& c, double every) {
  double n = every > 0 ? c.t_end / every + 1 : 2;
  if (c.max_steps > 0) n = std::min(n, static_cast<double>(c.max_steps) + 2);
  return n;
}

}  // namespace

void prepare_output_dir(const fs::path& dir, bool overwrite, const fs::path& restart) {
  const std::string name = dir.string();
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st) && !fs::is_directory(st))
    throw InputError(name, "--out",
                     "exists and is not a directory (the output directory of the run)");
  std::vector<fs::path> old;
  if (fs::exists(st)) {
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (is_run_output(e.path().filename().string())) old.push_back(e.path());
    if (ec) throw InputError(name, "--out", "cannot read the directory: " + ec.message());
  }
  if (!old.empty() && !overwrite) {
    std::sort(old.begin(), old.end());
    throw InputError(name, "--out",
                     fmt::format("holds the files of another run ({} files: {}, ...); pass "
                                 "--overwrite to remove them first, or choose another directory",
                                 old.size(), old.front().filename().string()));
  }
  if (!old.empty() && !restart.empty()) {
    const fs::path snap = fs::weakly_canonical(restart, ec).parent_path();
    if (fs::equivalent(snap, dir, ec))
      throw InputError(name, "--overwrite",
                       "would remove the restart snapshot " + restart.string() +
                           " and its series; write the restarted run to another directory");
  }
  for (const fs::path& f : old) {
    fs::remove(f, ec);
    if (ec) throw InputError(f.string(), "--overwrite", "cannot remove: " + ec.message());
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError(name, "--out", "cannot create the directory: " + ec.message());
}

void check_output_count(const Case& c, bool probe_rows, bool force) {
  if (force) return;
  const double out_every = c.output_every > 0 ? c.output_every : c.t_end;
  const double snapshots = output_count(c, c.output_every);
  if (!(snapshots <= kMaxSnapshots))
    throw InputError(c.file_name(), "output.every",
                     fmt::format("time.end = {:g} / output.every = {:g} asks for {:.3g} "
                                 "snapshots, over the limit of {:.0e}; raise output.every or "
                                 "pass --force",
                                 c.t_end, c.output_every, snapshots, kMaxSnapshots));
  const double probe_every = c.probe_every > 0 ? c.probe_every : out_every;
  const double rows = output_count(c, probe_every);
  if (c.forces_every > 0 && !(output_count(c, c.forces_every) <= kMaxProbeRows))
    throw InputError(
        c.file_name(), "output.forces_every",
        fmt::format("time.end = {:g} / {:g} asks for {:.3g} rows of forces.csv, "
                    "over the limit of {:.0e}; raise it or pass --force",
                    c.t_end, c.forces_every, output_count(c, c.forces_every), kMaxProbeRows));
  if (probe_rows && !(rows <= kMaxProbeRows))
    throw InputError(c.file_name(), c.probe_every > 0 ? "output.probe_every" : "output.every",
                     fmt::format("time.end = {:g} / {:g} asks for {:.3g} probe rows, over the "
                                 "limit of {:.0e}; raise it or pass --force",
                                 c.t_end, probe_every, rows, kMaxProbeRows));
}

double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0;
}

void check_memory(const Case& c, double max_bytes) {
  const bool by_default = !(max_bytes > 0);
  if (by_default) max_bytes = 0.8 * physical_memory();
  if (!(max_bytes > 0)) return;  // memory unknown: nothing to compare with
  const double n = estimate_particle_count(c);
  const double bytes = n * kBytesPerParticle;
  if (!(bytes <= max_bytes))
    throw InputError(
        c.file_name(), "resolution.dx",
        fmt::format("dx = {:g} gives about {:.3g} particles, about {} at {:.0f} bytes per "
                    "particle, over the {} allowed ({}); raise dx or --max-memory",
                    c.dx, n, bytes_text(bytes), kBytesPerParticle, bytes_text(max_bytes),
                    by_default ? "80 % of the physical memory" : "--max-memory"));
}

OutputSchedule::OutputSchedule(double every, double t_start, double eps)
    : every_(every), eps_(eps), k_(first_after(t_start)) {}

double OutputSchedule::first_after(double t) const {
  return std::floor((t + eps_) / every_) + 1;
}

bool OutputSchedule::reached(double t) {
  if (t < next() - eps_) return false;
  k_ = std::max(k_ + 1, first_after(t));
  return true;
}

}  // namespace curvsph
