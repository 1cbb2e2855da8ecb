// The `curvsph` command line: dispatches to the registered sub-commands and maps errors to
// the exit codes of DESIGN.md §3 (2: bad input, 3: unstable run).
#include <algorithm>
#include <iostream>

#include "curvsph/app/command.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/parallel/communicator.hpp"
#include "curvsph/solver/stop_signal.hpp"

namespace curvsph::app {
std::vector<Command>& command_registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace curvsph::app

int main(int argc, char** argv) {
  using namespace curvsph;
  // MPI for the whole program (a no-op without MPI); under mpirun every rank runs main and
  // errors, which the ranks raise together (parallel/agree.hpp), are printed by rank 0.
  mpi::Session mpi_session(argc, argv);
  const bool speaker = mpi::Comm::world().root();
  CLI::App cli{
      "curvsph — SPH with accurate walls of curved shape (ghosts, density-preserving map, "
      "boundary integrals)"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "curvsph 0.1.0");
  auto& registry = app::command_registry();
  std::sort(registry.begin(), registry.end(),
            [](const app::Command& a, const app::Command& b) { return a.order < b.order; });
  std::function<int()> action;
  for (auto& cmd : registry) {
    CLI::App* sub = cli.add_subcommand(cmd.name, cmd.help);
    auto run = cmd.setup(*sub);
    sub->callback([&action, run] { action = run; });
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : kExitInputError;
  }
  try {
    return action ? action() : 0;
  } catch (const InputError& e) {
    if (speaker) std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const InstabilityError& e) {
    if (speaker) std::cerr << "unstable: " << e.what() << "\n";
    return kExitInstability;
  } catch (const Interrupted& e) {
    if (speaker) std::cerr << "interrupted by signal " << e.signal << "\n";
    return 128 + e.signal;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
