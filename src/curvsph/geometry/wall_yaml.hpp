#pragma once
// YAML pieces every wall factory shares: the keys all walls accept and the `fluid` key.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph {

// Checks that the wall map `node` (key path `key`, e.g. "walls.2") holds only `own` keys
// plus the keys every wall accepts (`shape`, `motion`).
void check_wall_keys(const YAML::Node& node, std::initializer_list<std::string_view> own,
                     const std::string& file, const std::string& key);

// The required `fluid: inside | outside` key.
FluidSide read_fluid_side(const YAML::Node& node, const std::string& file, const std::string& key);

}  // namespace curvsph
