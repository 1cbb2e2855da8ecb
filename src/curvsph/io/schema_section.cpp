#include "curvsph/io/schema_section.hpp"

#include <algorithm>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_schema.hpp"
#include "curvsph/io/quote.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph::schema {
namespace {

// One value against its row; the yaml:: readers check type, finiteness and the row's range.
void check_value(const YAML::Node& n, const Key& k, const std::string& file,
                 const std::string& path) {
  switch (k.type) {
    case Type::number:
      yaml::read_number(n, file, path);
      break;
    case Type::integer:
      yaml::read_integer(n, file, path);
      break;
    case Type::boolean:
      yaml::read_bool(n, file, path);
      break;
    case Type::string:
      yaml::read_string(n, file, path);
      break;
    case Type::choice: {
      const std::string v = yaml::read_string(n, file, path);
      if (std::find(k.choices.begin(), k.choices.end(), v) != k.choices.end()) break;
      std::string list;
      for (const auto& c : k.choices) list += (list.empty() ? "" : " | ") + c;
      throw InputError(file, path, "expected one of " + list + ", got " + quote(v));
    }
    case Type::map:
      check_section(n, file, path);
      break;
    case Type::vector:
      for (std::size_t i = 0, m = yaml::require_list(n, file, path); i < m; ++i)
        yaml::read_number(n[i], file, yaml::join(path, i));
      break;
    case Type::list:
      yaml::require_list(n, file, path);
      break;
  }
}

}  // namespace

void check_section(const YAML::Node& node, const std::string& file, const std::string& path) {
  const std::vector<std::string> names = children(path);
  const bool given = node && !node.IsNull();
  if (given) {
    if (!node.IsMap()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError(file, path,
                       "expected a map (" + (list.empty() ? "no parameters" : "keys: " + list) +
                           "), got " + yaml::describe(node));
    }
    yaml::check_keys(node, names, file, path);
  }
  for (const auto& name : names) {
    const std::string key = yaml::join(path, name);
    const Key* k = find(key);
    if (given && yaml::has(node, name))
      check_value(node[name], *k, file, key);
    else if (k->fallback == "required")
      throw InputError(file, key, "missing key");
  }
}

}  // namespace curvsph::schema
