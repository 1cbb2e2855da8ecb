#include "curvsph/nurbs/yaml_input.hpp"

#include <fmt/format.h>

#include "curvsph/core/error.hpp"

namespace curvsph::nurbs::yaml {

const YAML::Node require(const YAML::Node& node, const std::string& key, const InputContext& ctx) {
  if (!node.IsMap()) throw InputError(ctx.file, ctx.prefix, "expected a map");
  const YAML::Node v = node[key];
  if (!v) throw InputError(ctx.file, ctx.key(key), "missing required key");
  return v;
}

double read_double(const YAML::Node& n, const std::string& key_path, const InputContext& ctx) {
  try {
    if (!n.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "");
    return n.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(ctx.file, ctx.key(key_path), "expected a number");
  }
}

int read_int(const YAML::Node& node, const std::string& key, const InputContext& ctx) {
  const YAML::Node n = require(node, key, ctx);
  try {
    if (!n.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "");
    return n.as<int>();
  } catch (const YAML::Exception&) {
    throw InputError(ctx.file, ctx.key(key), "expected an integer");
  }
}

std::vector<double> read_doubles(const YAML::Node& n, const std::string& key_path,
                                 const InputContext& ctx) {
  if (!n.IsSequence()) throw InputError(ctx.file, ctx.key(key_path), "expected a list of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < n.size(); ++i)
    out.push_back(read_double(n[i], fmt::format("{}.{}", key_path, i), ctx));
  return out;
}

template <int D>
VecD<D> read_point(const YAML::Node& n, const std::string& key_path, const InputContext& ctx) {
  const std::vector<double> v = read_doubles(n, key_path, ctx);
  if (static_cast<int>(v.size()) != D)
    throw InputError(ctx.file, ctx.key(key_path),
                     fmt::format("expected {} coordinates, got {}", D, v.size()));
  VecD<D> p;
  for (int i = 0; i < D; ++i) p[i] = v[i];
  return p;
}

std::string read_choice(const YAML::Node& node, const std::string& key,
                        std::initializer_list<const char*> choices, const InputContext& ctx) {
  const YAML::Node n = require(node, key, ctx);
  const std::string s = n.IsScalar() ? n.as<std::string>() : std::string();
  std::string all;
  for (const char* c : choices) {
    if (s == c) return s;
    all += all.empty() ? c : std::string(" | ") + c;
  }
  throw InputError(ctx.file, ctx.key(key), fmt::format("'{}' is not one of: {}", s, all));
}

void reject_unknown_keys(const YAML::Node& node, std::initializer_list<const char*> allowed,
                         const InputContext& ctx) {
  for (const auto& kv : node) {
    const std::string k = kv.first.as<std::string>();
    bool ok = false;
    for (const char* a : allowed) ok = ok || k == a;
    if (!ok) throw InputError(ctx.file, ctx.key(k), "unknown key");
  }
}

template VecD<2> read_point<2>(const YAML::Node&, const std::string&, const InputContext&);
template VecD<3> read_point<3>(const YAML::Node&, const std::string&, const InputContext&);

}  // namespace curvsph::nurbs::yaml
