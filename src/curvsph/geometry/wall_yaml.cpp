#include "curvsph/geometry/wall_yaml.hpp"

#include <vector>

#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

void check_wall_keys(const YAML::Node& node, std::initializer_list<std::string_view> own,
                     const std::string& file, const std::string& key) {
  std::vector<std::string> allowed{"shape"};
  for (auto k : own) allowed.emplace_back(k);
  allowed.emplace_back("motion");
  yaml::check_keys(node, allowed, file, key);
}

FluidSide read_fluid_side(const YAML::Node& node, const std::string& file, const std::string& key) {
  const std::string s = yaml::read_choice(yaml::child(node, "fluid", file, key),
                                          {"inside", "outside"}, file, yaml::join(key, "fluid"));
  return s == "inside" ? FluidSide::inside : FluidSide::outside;
}

}  // namespace curvsph
