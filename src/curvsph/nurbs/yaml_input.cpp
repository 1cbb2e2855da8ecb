#include "curvsph/nurbs/yaml_input.hpp"

#include <fmt/format.h>

#include <cmath>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_schema.hpp"
#include "curvsph/io/quote.hpp"

namespace curvsph::nurbs::yaml {

const YAML::Node require(const YAML::Node& node, const std::string& key, const InputContext& ctx) {
  if (!node.IsMap()) throw InputError(ctx.file, ctx.prefix, "expected a map");
  const YAML::Node v = node[key];
  if (!v) throw InputError(ctx.file, ctx.key(key), "missing required key");
  return v;
}

double read_double(const YAML::Node& n, const std::string& key_path, const InputContext& ctx) {
  double v = 0.0;
  // yaml-cpp's conversion accepts .nan and .inf; a geometric input must be finite.
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v))
    throw InputError(
        ctx.file, ctx.key(key_path),
        "expected a finite number" + (n.IsScalar() ? ", got " + quote(n.Scalar()) : std::string()));
  schema::check_number(ctx.file, ctx.key(key_path), v);
  return v;
}

int read_int(const YAML::Node& node, const std::string& key, const InputContext& ctx) {
  const YAML::Node n = require(node, key, ctx);
  int v = 0;
  if (!n.IsScalar() || !YAML::convert<int>::decode(n, v))
    throw InputError(ctx.file, ctx.key(key), "expected an integer");
  schema::check_number(ctx.file, ctx.key(key), v);
  return v;
}

std::vector<double> read_doubles(const YAML::Node& n, const std::string& key_path,
                                 const InputContext& ctx) {
  schema::lookup(ctx.key(key_path));
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
    schema::check_option(ctx.key(key), c);  // the reader's options are the table's
    if (s == c) return s;
    all += all.empty() ? c : std::string(" | ") + c;
  }
  throw InputError(ctx.file, ctx.key(key), fmt::format("{} is not one of: {}", quote(s), all));
}

void reject_unknown_keys(const YAML::Node& node, std::initializer_list<const char*> allowed,
                         const InputContext& ctx) {
  if (schema::strict())
    for (const char* a : allowed) schema::lookup(ctx.key(a));
  for (const auto& kv : node) {
    const std::string k = kv.first.as<std::string>();
    bool ok = false;
    std::string list;
    for (const char* a : allowed) {
      ok = ok || k == a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (!ok)
      throw InputError(ctx.file, ctx.key(clip(k)), "unknown key (allowed here: " + list + ")");
  }
}

template VecD<2> read_point<2>(const YAML::Node&, const std::string&, const InputContext&);
template VecD<3> read_point<3>(const YAML::Node&, const std::string&, const InputContext&);

}  // namespace curvsph::nurbs::yaml
