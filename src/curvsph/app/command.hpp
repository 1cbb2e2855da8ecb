#pragma once
// Sub-commands of the `curvsph` command line register themselves here: a new command is
// one new file in app/ with one `const CommandRegistration reg{...}` line.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace curvsph::app {

// `setup` adds the sub-command's options to `sub` and returns the action run when the
// sub-command is chosen; the action returns the process exit code.
struct Command {
  std::string name;
  std::string help;
  std::function<std::function<int()>(CLI::App& sub)> setup;
  int order = 100;  // position in --help
};

std::vector<Command>& command_registry();

struct CommandRegistration {
  explicit CommandRegistration(Command c) { command_registry().push_back(std::move(c)); }
};

}  // namespace curvsph::app
