// The points CSV reader (io/points_csv.cpp) of `geometry` and `shepard`, 2-D and 3-D.
#include "curvsph/core/error.hpp"
#include "curvsph/io/points_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    curvsph::parse_points_csv<2>(text, "points.csv");
  } catch (const curvsph::InputError&) {
  }
  try {
    curvsph::parse_points_csv<3>(text, "points.csv");
  } catch (const curvsph::InputError&) {
  }
  return 0;
}
