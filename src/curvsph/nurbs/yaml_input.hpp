#pragma once
// Reading NURBS data from YAML case files with errors that name the key (DESIGN.md §3).
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/nurbs/basis.hpp"

namespace curvsph::nurbs::yaml {

const YAML::Node require(const YAML::Node& node, const std::string& key, const InputContext& ctx);
int read_int(const YAML::Node& node, const std::string& key, const InputContext& ctx);
double read_double(const YAML::Node& n, const std::string& key_path, const InputContext& ctx);
std::vector<double> read_doubles(const YAML::Node& n, const std::string& key_path,
                                 const InputContext& ctx);
template <int D>
VecD<D> read_point(const YAML::Node& n, const std::string& key_path, const InputContext& ctx);
std::string read_choice(const YAML::Node& node, const std::string& key,
                        std::initializer_list<const char*> choices, const InputContext& ctx);
// Throws for keys of `node` outside `allowed`.
void reject_unknown_keys(const YAML::Node& node, std::initializer_list<const char*> allowed,
                         const InputContext& ctx);

}  // namespace curvsph::nurbs::yaml
