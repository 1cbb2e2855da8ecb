#pragma once
// `--set a.b=value` overrides on a YAML tree (DESIGN.md §3). List elements are addressed by
// index (`walls.1.radius=0.05`); the value is parsed as YAML, so numbers, strings and lists
// (`domain.periodic=[true,false]`) all work. Unknown keys are created here and rejected later
// by the case validation, so a typo in an override gets the same message as one in the file.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace curvsph {

// Applies "path=value" to root (in place). Throws InputError naming the override.
void apply_override(YAML::Node& root, const std::string& assignment);
void apply_overrides(YAML::Node& root, const std::vector<std::string>& assignments);

}  // namespace curvsph
