#pragma once
// The `walls:` list of a case or geometry file → a WallSet (DESIGN.md §3 case files).
//
// Each element is a map with `shape` and the shape's own keys, plus an optional
//   motion: {rotate: {omega, center[, axis (3-D, required)]}} | {translate: {velocity}}
//           | {oscillate: {amplitude, frequency[, phase]}}
// which moves the wall's geometry (geometry/moving_wall.hpp).
// Shapes are dispatched through one table in wall_parser.cpp (name → factory per dimension);
// a new shape is one new file with its factory plus one line in that table.
// Every error is an InputError naming `file`, the key path (`walls.1.radius`) and the reason.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// `walls` is the list node; `key` its key path (for messages; "walls" in a case file);
// `base_dir` resolves relative file names (CAD walls), normally the YAML file's directory.
template <int D>
WallSet<D> parse_walls(const YAML::Node& walls, const std::string& file,
                       const std::filesystem::path& base_dir, const std::string& key = "walls");

// One wall element (`key` = "walls.3"); CAD elements may yield several walls.
template <int D>
std::vector<WallPtr<D>> parse_wall(const YAML::Node& node, const std::string& file,
                                   const std::filesystem::path& base_dir, const std::string& key);

// The `motion:` map of a wall (`key` = "walls.3.motion").
template <int D>
WallMotion<D> parse_wall_motion(const YAML::Node& node, const std::string& file,
                                const std::string& key);

// Shape names accepted in dimension D, sorted (for messages and --help).
template <int D>
std::vector<std::string> wall_shape_names();

extern template WallSet<2> parse_walls<2>(const YAML::Node&, const std::string&,
                                          const std::filesystem::path&, const std::string&);
extern template WallSet<3> parse_walls<3>(const YAML::Node&, const std::string&,
                                          const std::filesystem::path&, const std::string&);

}  // namespace curvsph
