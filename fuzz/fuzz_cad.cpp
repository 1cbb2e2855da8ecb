// STEP / IGES import (cad/cad_import.cpp through OpenCASCADE): the whole entry point of a
// `shape: cad` wall, read, converted to trimmed NURBS walls and, for a closed shell, the solid
// wall. The first byte picks the format (even: STEP, odd: IGES), the rest is the file.
#include <yaml-cpp/yaml.h>

#include "curvsph/cad/cad_import.hpp"
#include "curvsph/core/error.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string ext = data[0] % 2 == 0 ? ".step" : ".iges";
  const std::string path = curvsph::fuzz::temp_input(data + 1, size - 1, ext);
  YAML::Node node;
  node["shape"] = "cad";
  node["file"] = path;
  node["fluid"] = "inside";
  try {
    curvsph::make_cad_walls(node, "fuzz.yaml", "walls.0", "/");
  } catch (const curvsph::InputError&) {
  }
  return 0;
}
