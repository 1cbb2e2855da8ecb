#pragma once
// Reading typed values out of YAML with errors that name the file, the dotted key path
// (list elements by index: `walls.1.radius`) and what is wrong (DESIGN.md §3 errors).
// Every helper takes the node itself, the file name and the node's own key path, so case
// files, geometry files and any other YAML input report errors the same way.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph::yaml {

// "walls" + "radius" -> "walls.radius"; "walls" + 1 -> "walls.1"; "" + "walls" -> "walls".
std::string join(const std::string& path, std::string_view key);
std::string join(const std::string& path, std::size_t index);

// Short description of a node's kind for messages ("a list", "the string 'abc'", ...).
std::string describe(const YAML::Node& node);

// `node` must be a map (a missing node is reported as a missing key).
void require_map(const YAML::Node& node, const std::string& file, const std::string& path);
// `node` must be a list; returns its length.
std::size_t require_list(const YAML::Node& node, const std::string& file, const std::string& path);

// Throws for the first key of the map `node` that is not in `allowed`, listing the allowed keys.
void check_keys(const YAML::Node& node, std::initializer_list<std::string_view> allowed,
                const std::string& file, const std::string& path);
void check_keys(const YAML::Node& node, const std::vector<std::string>& allowed,
                const std::string& file, const std::string& path);

// The child `key` of the map `node`; throws "missing key" when it is absent or null.
YAML::Node child(const YAML::Node& node, std::string_view key, const std::string& file,
                 const std::string& path);
// True when the map `node` has a non-null child `key`.
bool has(const YAML::Node& node, std::string_view key);

// Scalars. `path` is the key path of `node` itself.
double read_number(const YAML::Node& node, const std::string& file, const std::string& path);
double read_positive(const YAML::Node& node, const std::string& file, const std::string& path);
double read_nonnegative(const YAML::Node& node, const std::string& file, const std::string& path);
long read_integer(const YAML::Node& node, const std::string& file, const std::string& path);
bool read_bool(const YAML::Node& node, const std::string& file, const std::string& path);
std::string read_string(const YAML::Node& node, const std::string& file, const std::string& path);
// One of `choices`, e.g. read_choice(n, f, "walls.0.fluid", {"inside", "outside"}).
std::string read_choice(const YAML::Node& node, std::initializer_list<std::string_view> choices,
                        const std::string& file, const std::string& path);

// A list of numbers; `count` (when given) is the required length.
std::vector<double> read_numbers(const YAML::Node& node, const std::string& file,
                                 const std::string& path,
                                 std::optional<std::size_t> count = std::nullopt);

[[noreturn]] void throw_zero_vector(const std::string& file, const std::string& path);

// A list of exactly D numbers (a point or a vector in the case's dimension).
template <int D>
VecD<D> read_vec(const YAML::Node& node, const std::string& file, const std::string& path) {
  const std::vector<double> v = read_numbers(node, file, path, static_cast<std::size_t>(D));
  VecD<D> out;
  for (int i = 0; i < D; ++i) out[i] = v[static_cast<std::size_t>(i)];
  return out;
}

// A non-zero vector of D numbers, returned normalised (normals, axes).
template <int D>
VecD<D> read_direction(const YAML::Node& node, const std::string& file, const std::string& path) {
  const VecD<D> v = read_vec<D>(node, file, path);
  const double n = v.norm();
  if (!(n > 0.0)) throw_zero_vector(file, path);
  return v / n;
}

// Convenience for the common pattern `child` + `read_*` on a map.
template <typename F>
auto read_key(const YAML::Node& map, std::string_view key, const std::string& file,
              const std::string& path, F&& reader) {
  return reader(child(map, key, file, path), file, join(path, key));
}

// Loads a YAML file; a missing file, a syntax error or a key written twice in one map becomes an
// InputError naming the file (and the key).
YAML::Node load_file(const std::string& file);

// yaml-cpp keeps both entries of a key written twice in one map, and node[key] answers the
// first: the second value would be lost without a word. Throws an InputError naming `file`,
// the key path and (with `lines`: the tree was read from `file`) the line of the second entry.
void reject_duplicate_keys(const YAML::Node& root, const std::string& file, bool lines = true);

}  // namespace curvsph::yaml
