// `curvsph run CASE.yaml [--out DIR] [--set key.path=value ...] [--threads N]
//  [--restart SNAPSHOT.vtp]`
#include <fmt/format.h>

#include <iostream>

#include "curvsph/app/command.hpp"
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
};

const CommandRegistration reg{Command{
    "run", "Run a case file; writes series.pvd, particles_*.vtp, probes.csv, log.txt, metrics.json",
    [](CLI::App& sub) -> std::function<int()> {
      auto args = std::make_shared<RunArgs>();
      sub.add_option("case", args->case_file, "case file (YAML)")->required();
      sub.add_option("--out,-o", args->out, "output directory")->capture_default_str();
      sub.add_option("--set,-s", args->sets,
                     "override a case key: key.path=value (list elements by index: "
                     "walls.1.radius=0.05); repeatable")
          ->allow_extra_args(false);
      sub.add_option("--threads,-t", args->threads, "OpenMP threads (0: all cores)")
          ->check(CLI::NonNegativeNumber);
      sub.add_flag("--quiet,-q", args->quiet, "no progress line");
      sub.add_option("--restart", args->restart,
                     "start from a snapshot (particles_NNNNNN.vtp) of an earlier run of the same "
                     "case, at its time in the series.pvd beside it")
          ->check(CLI::ExistingFile);
      return [args] {
        // [mpi] every rank reads the case; a failure on any stops all with its message.
        const mpi::Comm comm = mpi::Comm::world();
        Case c;
        mpi::agree_on_input(comm, [&] { c = read_case(args->case_file, args->sets); });
        RunOptions o;
        o.out_dir = args->out;
        o.threads = args->threads;
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
