// The STL reader (cad/stl_reader.cpp), ASCII and binary, and the closed-surface check.
#include "curvsph/cad/stl_reader.hpp"
#include "curvsph/core/error.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = curvsph::fuzz::temp_input(data, size, ".stl");
  try {
    const auto mesh = curvsph::cad::read_stl(path, "fuzz.yaml", "walls.0.file");
    curvsph::cad::require_closed(mesh, path, "fuzz.yaml", "walls.0.file");
  } catch (const curvsph::InputError&) {
  }
  return 0;
}
