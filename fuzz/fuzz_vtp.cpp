// The VTP reader (io/vtk_reader.cpp) a restart or a round-trip test reads snapshots with:
// not our format, truncated or corrupt data is a std::runtime_error naming the file.
#include <stdexcept>

#include "curvsph/io/vtk_reader.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = curvsph::fuzz::temp_input(data, size, ".vtp");
  try {
    const curvsph::io::VtkPolyData vtk = curvsph::io::read_vtp(path);
    curvsph::io::particles_from_vtk<2>(vtk);
    curvsph::io::particles_from_vtk<3>(vtk);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
