#pragma once
// `pressure_gradient: symmetric | difference` (physics/pressure_gradient.hpp), as read_case
// resolved it (default symmetric for every case).
#include "curvsph/io/case_file.hpp"

namespace curvsph {

inline bool pressure_difference(const Case& c) {
  return c.pressure_difference;
}

}  // namespace curvsph
