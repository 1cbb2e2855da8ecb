// The case reader (io/case_file.cpp, io/yaml_read, nurbs/yaml_input) on arbitrary YAML text:
// a bad case is an InputError (exit 2), never a crash or another exception.
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = curvsph::fuzz::temp_input(data, size, ".yaml");
  try {
    curvsph::read_case(path);
  } catch (const curvsph::InputError&) {
  }
  return 0;
}
