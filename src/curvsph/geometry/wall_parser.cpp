#include "curvsph/geometry/wall_parser.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "curvsph/cad/cad_import.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/ellipse.hpp"
#include "curvsph/geometry/moving_wall.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/nurbs_surface_wall.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/torus.hpp"
#include "curvsph/io/quote.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {
namespace {

// Everything a factory may need about one `walls:` element.
struct WallSource {
  const YAML::Node& node;
  const std::string& file;
  const std::string& key;  // "walls.3"
  const std::filesystem::path& base_dir;
};

template <int D>
using WallFactory = std::vector<WallPtr<D>> (*)(const WallSource&);

// Adapts the common one-wall factory signature (node, file, key_prefix).
template <int D, WallPtr<D> (*Make)(const YAML::Node&, const std::string&, const std::string&)>
std::vector<WallPtr<D>> single(const WallSource& s) {
  return {Make(s.node, s.file, s.key)};
}

struct ShapeEntry {
  std::string_view name;
  WallFactory<2> make2;  // nullptr: not available in 2-D
  WallFactory<3> make3;  // nullptr: not available in 3-D
};

// The one dispatch table: shape name → factory per dimension.
const std::vector<ShapeEntry>& shape_table() {
  static const std::vector<ShapeEntry> table = {
      {"plane", single<2, &make_plane_wall<2>>, single<3, &make_plane_wall<3>>},
      {"box", single<2, &make_box_wall<2>>, single<3, &make_box_wall<3>>},
      {"circle", single<2, &make_circle_wall>, nullptr},
      {"ellipse", single<2, &make_ellipse_wall>, nullptr},
      {"cylinder", nullptr, single<3, &make_cylinder_wall>},
      {"sphere", nullptr, single<3, &make_sphere_wall>},
      {"torus", nullptr, single<3, &make_torus_wall>},
      {"nurbs_curve", single<2, &make_nurbs_curve_wall>, nullptr},
      {"nurbs_surface", nullptr, single<3, &make_nurbs_surface_wall>},
      {"cad", nullptr,
       [](const WallSource& s) {
         return make_cad_walls(s.node, s.file, s.key, s.base_dir.string());
       }},
  };
  return table;
}

template <int D>
WallFactory<D> factory_of(const ShapeEntry& e) {
  if constexpr (D == 2)
    return e.make2;
  else
    return e.make3;
}

std::string names_list(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

}  // namespace

template <int D>
std::vector<std::string> wall_shape_names() {
  std::vector<std::string> names;
  for (const auto& e : shape_table())
    if (factory_of<D>(e)) names.emplace_back(e.name);
  std::sort(names.begin(), names.end());
  return names;
}

template <int D>
WallMotion<D> parse_wall_motion(const YAML::Node& node, const std::string& file,
                                const std::string& key) {
  yaml::check_keys(node, {"rotate", "translate", "oscillate"}, file, key);
  if (node.size() != 1)
    throw InputError(file, key, "expected exactly one of rotate | translate | oscillate");
  WallMotion<D> m;
  if (yaml::has(node, "rotate")) {
    const std::string k = yaml::join(key, "rotate");
    const YAML::Node r = yaml::child(node, "rotate", file, key);
    if constexpr (D == 2)
      yaml::check_keys(r, {"omega", "center"}, file, k);
    else
      yaml::check_keys(r, {"omega", "center", "axis"}, file, k);
    m.kind = WallMotion<D>::Kind::rotate;
    m.omega = yaml::read_key(r, "omega", file, k, yaml::read_number);
    m.center = yaml::read_key(r, "center", file, k, yaml::read_vec<D>);
    // 3-D: the axis is required (a rotation about a guessed z would move the wall silently
    // the wrong way).
    if constexpr (D == 3) m.axis = yaml::read_key(r, "axis", file, k, yaml::read_direction<3>);
  } else if (yaml::has(node, "translate")) {
    const std::string k = yaml::join(key, "translate");
    const YAML::Node t = yaml::child(node, "translate", file, key);
    yaml::check_keys(t, {"velocity"}, file, k);
    m.kind = WallMotion<D>::Kind::translate;
    m.velocity = yaml::read_key(t, "velocity", file, k, yaml::read_vec<D>);
  } else {
    const std::string k = yaml::join(key, "oscillate");
    const YAML::Node o = yaml::child(node, "oscillate", file, key);
    yaml::check_keys(o, {"amplitude", "frequency", "phase"}, file, k);
    m.kind = WallMotion<D>::Kind::oscillate;
    m.amplitude = yaml::read_key(o, "amplitude", file, k, yaml::read_vec<D>);
    m.frequency = yaml::read_key(o, "frequency", file, k, yaml::read_number);
    if (!(m.frequency >= 0) || !std::isfinite(m.frequency))
      throw InputError(file, yaml::join(k, "frequency"),
                       fmt::format("must be a finite number >= 0 (got {})", m.frequency));
    if (yaml::has(o, "phase")) m.phase = yaml::read_key(o, "phase", file, k, yaml::read_number);
  }
  const auto finite = [](const auto& v) { return v.allFinite(); };
  if (!std::isfinite(m.omega) || !std::isfinite(m.phase) || !finite(m.center) ||
      !finite(m.velocity) || !finite(m.amplitude))
    throw InputError(file, key, "motion values must be finite");
  return m;
}

template <int D>
std::vector<WallPtr<D>> parse_wall(const YAML::Node& node, const std::string& file,
                                   const std::filesystem::path& base_dir, const std::string& key) {
  yaml::require_map(node, file, key);
  const std::string shape = yaml::read_key(node, "shape", file, key, yaml::read_string);
  const auto& table = shape_table();
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const ShapeEntry& e) { return e.name == shape; });
  const std::string shape_key = yaml::join(key, "shape");
  if (it == table.end())
    throw InputError(file, shape_key,
                     fmt::format("unknown shape {} (shapes in {}-D: {})", quote(shape), D,
                                 names_list(wall_shape_names<D>())));
  const WallFactory<D> make = factory_of<D>(*it);
  if (!make)
    throw InputError(file, shape_key,
                     fmt::format("shape '{}' is not available in {}-D (dimension: {}; shapes in "
                                 "{}-D: {})",
                                 shape, D, D, D, names_list(wall_shape_names<D>())));
  // `contact_angle` is a wetting property of any wall (read by physics/contact_angle.cpp),
  // not a shape key: the shape factory sees the element without it. Its value is checked here
  // (the schema's range), so that `geometry` and `shepard` refuse what `run` refuses.
  if (yaml::has(node, "contact_angle"))
    yaml::read_number(node["contact_angle"], file, yaml::join(key, "contact_angle"));
  // `name` and `moment_center` label it in the outputs (forces.csv, the walls output): none
  // is a shape key, and the shape factory sees the element without them.
  // (Copy-constructed, never assigned: assigning a YAML::Node rebinds the node it shares.)
  static constexpr const char* kCommon[] = {"contact_angle", "name", "moment_center"};
  const bool any_common = std::any_of(std::begin(kCommon), std::end(kCommon),
                                      [&](const char* k) { return yaml::has(node, k); });
  const YAML::Node shape_node = any_common ? [&] {
    YAML::Node copy = YAML::Clone(node);
    for (const char* k : kCommon) copy.remove(k);
    return copy;
  }()
                                           : node;
  std::vector<WallPtr<D>> walls = make(WallSource{shape_node, file, key, base_dir});
  if (yaml::has(node, "motion")) {
    const WallMotion<D> m = parse_wall_motion<D>(node["motion"], file, yaml::join(key, "motion"));
    // The geometry moves (geometry/moving_wall.hpp); static walls stay undecorated.
    for (auto& w : walls) w = std::make_shared<MovingWall<D>>(std::move(w), m);
  }
  std::string name;
  if (yaml::has(node, "name")) {
    const std::string k = yaml::join(key, "name");
    name = yaml::read_string(node["name"], file, k);
    if (name.empty() || name.find_first_of(",\"\n\r") != std::string::npos)
      throw InputError(file, k,
                       fmt::format("'{}' is not a usable name (non-empty, without commas, quotes "
                                   "or line breaks: it heads columns of forces.csv)",
                                   name));
  }
  VecD<D> centre = VecD<D>::Zero();
  if (yaml::has(node, "moment_center"))
    centre = yaml::read_key(node, "moment_center", file, key, yaml::read_vec<D>);
  for (const auto& w : walls) {
    auto& wall = const_cast<Wall<D>&>(*w);  // fresh, not yet shared (attach_motion)
    wall.name = name;
    wall.moment_center = centre;
  }
  return walls;
}

template <int D>
WallSet<D> parse_walls(const YAML::Node& walls, const std::string& file,
                       const std::filesystem::path& base_dir, const std::string& key) {
  const std::size_t n = yaml::require_list(walls, file, key);
  WallSet<D> set;
  std::vector<std::string> names;  // one per entry
  for (std::size_t i = 0; i < n; ++i) {
    const std::string entry = yaml::join(key, i);
    std::vector<WallPtr<D>> made = parse_wall<D>(walls[i], file, base_dir, entry);
    // Unnamed walls are wall0, wall1, ... after their entry (DESIGN.md §3); names are unique
    // across entries (a CAD entry's walls share theirs).
    std::string name =
        made.empty() || made.front()->name.empty() ? fmt::format("wall{}", i) : made.front()->name;
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw InputError(file, yaml::join(entry, "name"),
                       fmt::format("duplicate wall name '{}' (unnamed walls are wallN after "
                                   "their place in the list)",
                                   name));
    names.push_back(name);
    for (auto& w : made) {
      const_cast<Wall<D>&>(*w).name = name;
      set.add(std::move(w));
    }
  }
  return set;
}

template WallSet<2> parse_walls<2>(const YAML::Node&, const std::string&,
                                   const std::filesystem::path&, const std::string&);
template WallSet<3> parse_walls<3>(const YAML::Node&, const std::string&,
                                   const std::filesystem::path&, const std::string&);
template std::vector<WallPtr<2>> parse_wall<2>(const YAML::Node&, const std::string&,
                                               const std::filesystem::path&, const std::string&);
template std::vector<WallPtr<3>> parse_wall<3>(const YAML::Node&, const std::string&,
                                               const std::filesystem::path&, const std::string&);
template WallMotion<2> parse_wall_motion<2>(const YAML::Node&, const std::string&,
                                            const std::string&);
template WallMotion<3> parse_wall_motion<3>(const YAML::Node&, const std::string&,
                                            const std::string&);
template std::vector<std::string> wall_shape_names<2>();
template std::vector<std::string> wall_shape_names<3>();

}  // namespace curvsph
