// The restart state reader (solver/restart_state.cpp): a sidecar that is truncated, corrupt
// or of another case is an InputError naming the file and the key, never a crash, a huge
// allocation or another exception. (The solver's checks of a parsed state, Solver::load_state,
// are unit-tested in tests/solver/test_restart.cpp.)
#include <yaml-cpp/yaml.h>

#include "curvsph/core/error.hpp"
#include "curvsph/solver/restart_state.hpp"

namespace {
const char* kCase = R"(
name: fuzz
dimension: 2
resolution: {dx: 0.1, h_over_dx: 1.3}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids: [{rho0: 1000, viscosity: 0.01, region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {type: linear, c0: 10}
time: {end: 0.01}
)";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const curvsph::Case c = curvsph::read_case(YAML::Load(kCase), "fuzz.yaml");
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const curvsph::RestartState s = curvsph::parse_restart_state(bytes, "fuzz.restart");
    curvsph::check_case(s, c, "fuzz.vtp");
    for (const char* key : {"time", "dt", "output_counter"})
      curvsph::header_number(s, key, "fuzz.restart");
    curvsph::header_integer(s, "steps", "fuzz.restart");
    const auto& id = curvsph::int_array(s, "id", -1, "fuzz.restart");
    curvsph::real_array(s, "position", 2 * static_cast<std::int64_t>(id.size()), "fuzz.restart");
  } catch (const curvsph::InputError&) {
  }
  return 0;
}
