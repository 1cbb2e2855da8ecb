// `curvsph run CASE.yaml [--out DIR] [--set key.path=value ...] [--threads N]
//  [--restart SNAPSHOT.vtp] [--overwrite] [--force] [--max-memory BYTES]`
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <utility>

#include "curvsph/app/command.hpp"
#include "curvsph/app/thread_option.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/parallel/agree.hpp"
#include "curvsph/solver/run.hpp"

namespace curvsph::app {
namespace {

struct RunArgs {
  std::string case_file;
  std::string out = "out";
  std::vector<std::string> sets;
  int threads = 0;
  bool quiet = false;
  std::string restart;
  bool overwrite = false;
  bool force = false;
  double max_memory = 0;
};

// BYTES: a number (1e9, 8589934592) with an optional unit kB, MB, GB, TB (powers of 1000) or
// KiB, MiB, GiB, TiB (powers of 1024); replaced by the plain number of bytes, > 0.
CLI::Validator bytes_value() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const char* begin = s.c_str();
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        const std::string unit(end);
        static const std::pair<const char*, double> units[] = {
            {"", 1},         {"B", 1},        {"kB", 1e3},    {"KB", 1e3},
            {"MB", 1e6},     {"GB", 1e9},     {"TB", 1e12},   {"KiB", 1024.0},
            {"MiB", 0x1p20}, {"GiB", 0x1p30}, {"TiB", 0x1p40}};
        for (const auto& [name, factor] : units)
          if (end != begin && unit == name && std::isfinite(v * factor) && v * factor > 0) {
            s = fmt::format("{:.17g}", v * factor);
            return "";
          }
        return "must be a positive number of bytes (e.g. 8e9, 8GB, 16GiB), got '" + s + "'";
      },
      "BYTES");
}

const CommandRegistration reg{Command{
    "run",
    "Run a case file; writes series.pvd, particles_*.vtp, boundary_*.vtp, probes.csv (with "
    "probes), log.txt, metrics.json",
    [](CLI::App& sub) -> std::function<int()> {
      auto args = std::make_shared<RunArgs>();
      sub.add_option("case", args->case_file, "case file (YAML)")->required();
      sub.add_option("--out,-o", args->out, "output directory")->capture_default_str();
      sub.add_option("--set,-s", args->sets,
                     "override a case key: key.path=value (list elements by index: "
                     "walls.1.radius=0.05); repeatable")
          ->allow_extra_args(false);
      add_threads_option(sub, args->threads);
      sub.add_flag("--quiet,-q", args->quiet,
                   "no progress line and no set-up stage lines (warnings are still printed)");
      sub.add_option("--restart", args->restart,
                     "continue an earlier run of the same case from a snapshot "
                     "(particles_NNNNNN.vtp) and the restart state beside it "
                     "(particles_NNNNNN.restart, output.restart), bit for bit; write to a new "
                     "--out: the snapshots are numbered after it")
          ->check(CLI::ExistingFile);
      sub.add_flag("--overwrite", args->overwrite,
                   "write into an output directory that holds another run's files, removing "
                   "them first (series.pvd, particles_*.vtp, boundary_*.vtp, probes.csv, "
                   "metrics*.json); without it such a directory is refused");
      sub.add_flag("--force", args->force,
                   "run a schedule of more than 1e5 snapshots (time.end / output.every) or 1e7 "
                   "probe rows, refused without it");
      sub.add_option("--max-memory", args->max_memory,
                     "refuse a run whose estimated memory (2048 bytes per particle) exceeds "
                     "BYTES (e.g. 8e9, 8GB, 16GiB; default 80 % of the physical "
                     "memory)")
          ->transform(bytes_value());
      return [args] {
        // [mpi] every rank reads the case; a failure on any stops all with its message.
        const mpi::Comm comm = mpi::Comm::world();
        Case c;
        mpi::agree_on_input(comm, [&] { c = read_case(args->case_file, args->sets); });
        RunOptions o;
        o.out_dir = args->out;
        o.threads = checked_threads(args->threads, comm.root());
        o.overwrite = args->overwrite;
        o.force = args->force;
        o.max_memory = args->max_memory;
        o.progress = !args->quiet;
        o.restart = args->restart;
        const auto m = run_case(c, o);
        if (comm.root()) std::cout << m.dump(2) << std::endl;
        return 0;
      };
    },
    10}};

}  // namespace
}  // namespace curvsph::app
