#pragma once
// `pressure_gradient: symmetric | difference` (physics/pressure_gradient.hpp). read_case
// resolves the default (difference for confined flows) and writes the choice into Case::root.
#include <string>

#include "curvsph/io/case_file.hpp"

namespace curvsph {

inline bool pressure_difference(const Case& c) {
  const YAML::Node n = c.root["pressure_gradient"];
  return n && n.IsScalar() && n.as<std::string>() == "difference";
}

}  // namespace curvsph
