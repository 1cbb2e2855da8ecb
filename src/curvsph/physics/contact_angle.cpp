#include "curvsph/physics/contact_angle.hpp"

#include <fmt/format.h>

#include <numbers>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

template <int D>
std::vector<std::optional<Real>> parse_contact_angles(const YAML::Node& walls,
                                                      const std::string& file,
                                                      const std::filesystem::path& base_dir) {
  std::vector<std::optional<Real>> out;
  if (!walls || !walls.IsSequence()) return out;
  bool any = false;
  for (std::size_t i = 0; i < walls.size(); ++i) any = any || yaml::has(walls[i], "contact_angle");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const std::string key = yaml::join("walls", i);
    std::optional<Real> theta;
    if (yaml::has(walls[i], "contact_angle")) {
      const std::string k = yaml::join(key, "contact_angle");
      const double deg = yaml::read_number(walls[i]["contact_angle"], file, k);
      if (!(deg > 0 && deg < 180))
        throw InputError(file, k, fmt::format("{} is not an angle in (0, 180) degrees", deg));
      theta = static_cast<Real>(deg * std::numbers::pi / 180);
    }
    const std::size_t count = any ? parse_wall<D>(walls[i], file, base_dir, key).size() : 1;
    out.insert(out.end(), count, theta);
  }
  return out;
}

template std::vector<std::optional<Real>> parse_contact_angles<2>(const YAML::Node&,
                                                                  const std::string&,
                                                                  const std::filesystem::path&);
template std::vector<std::optional<Real>> parse_contact_angles<3>(const YAML::Node&,
                                                                  const std::string&,
                                                                  const std::filesystem::path&);

}  // namespace curvsph
