#pragma once
// The InputError message with which a case is refused, by read_case or the Solver's set-up
// (the checks that need the walls and the boundary model); "" when it is accepted.
#include <yaml-cpp/yaml.h>

#include <string>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph::test {

template <int D>
std::string solver_refusal(const YAML::Node& root) {
  try {
    const Case c = read_case(root, "case.yaml");
    Solver<D> s(c);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace curvsph::test
