#include "curvsph/io/yaml_read.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_schema.hpp"
#include "curvsph/io/quote.hpp"

namespace curvsph::yaml {

namespace {
// A case or geometry file is a few kB (meshes and CAD sit in files of their own); reading
// stops here rather than filling the memory from a device or a huge file.
constexpr std::size_t kMaxYamlBytes = std::size_t{64} << 20;
// Nodes visited by the duplicate-key walk: aliases of aliases expand exponentially.
constexpr long kMaxYamlNodes = 10'000'000;

void reject_duplicates(const YAML::Node& node, const std::string& file, const std::string& path,
                       bool lines, long& budget) {
  if (--budget < 0) throw InputError(file, path, "too many YAML nodes (nested aliases?)");
  if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : node) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
      if (kv.first.IsScalar() && !seen.insert(key).second)
        throw InputError(
            file, join(path, clip(key)),
            lines && kv.first.Mark().line >= 0
                ? "duplicate key (again on line " + std::to_string(kv.first.Mark().line + 1) + ")"
                : std::string("duplicate key"));
      reject_duplicates(kv.second, file, join(path, key), lines, budget);
    }
  } else if (node.IsSequence()) {
    std::size_t i = 0;
    for (const auto& item : node) reject_duplicates(item, file, join(path, i++), lines, budget);
  }
}
}  // namespace

void reject_duplicate_keys(const YAML::Node& root, const std::string& file, bool lines) {
  long budget = kMaxYamlNodes;
  reject_duplicates(root, file, "", lines, budget);
}

std::string join(const std::string& path, std::string_view key) {
  if (path.empty()) return std::string(key);
  return path + "." + std::string(key);
}

std::string join(const std::string& path, std::size_t index) {
  return join(path, std::to_string(index));
}

std::string describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list of " + std::to_string(node.size());
  if (node.IsMap()) return "a map";
  return quote(node.Scalar());
}

void require_map(const YAML::Node& node, const std::string& file, const std::string& path) {
  if (!node.IsDefined() || node.IsNull()) throw InputError(file, path, "missing key");
  if (!node.IsMap()) throw InputError(file, path, "expected a map, got " + describe(node));
}

std::size_t require_list(const YAML::Node& node, const std::string& file, const std::string& path) {
  if (!node.IsDefined() || node.IsNull()) throw InputError(file, path, "missing key");
  if (!node.IsSequence()) throw InputError(file, path, "expected a list, got " + describe(node));
  return node.size();
}

namespace {
template <typename Range>
void check_keys_impl(const YAML::Node& node, const Range& allowed, const std::string& file,
                     const std::string& path) {
  require_map(node, file, path);
  // The per-shape lists of the walls are narrower than the schema's walls.* (a circle takes
  // no normal): the list given here decides, and each of its names must be declared.
  if (schema::strict())
    for (const auto& a : allowed) schema::lookup(join(path, a));
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) throw InputError(file, path, "map keys must be plain names");
    const std::string key = kv.first.Scalar();
    bool ok = false;
    for (const auto& a : allowed) ok = ok || key == a;
    if (ok) continue;
    std::string list;
    for (const auto& a : allowed) {
      if (!list.empty()) list += ", ";
      list += a;
    }
    throw InputError(file, join(path, clip(key)), "unknown key (allowed here: " + list + ")");
  }
}
}  // namespace

void check_keys(const YAML::Node& node, std::initializer_list<std::string_view> allowed,
                const std::string& file, const std::string& path) {
  check_keys_impl(node, allowed, file, path);
}

void check_keys(const YAML::Node& node, const std::vector<std::string>& allowed,
                const std::string& file, const std::string& path) {
  check_keys_impl(node, allowed, file, path);
}

bool has(const YAML::Node& node, std::string_view key) {
  if (!node.IsMap()) return false;
  const YAML::Node c = node[std::string(key)];
  return c.IsDefined() && !c.IsNull();
}

YAML::Node child(const YAML::Node& node, std::string_view key, const std::string& file,
                 const std::string& path) {
  require_map(node, file, path);
  if (!has(node, key)) throw InputError(file, join(path, key), "missing key");
  return node[std::string(key)];
}

double read_number(const YAML::Node& node, const std::string& file, const std::string& path) {
  if (!node.IsDefined() || node.IsNull()) throw InputError(file, path, "missing key");
  if (!node.IsScalar()) throw InputError(file, path, "expected a number, got " + describe(node));
  double v = 0.0;
  // yaml-cpp's conversion accepts ".inf"/".nan"; a physical input must be finite.
  if (!YAML::convert<double>::decode(node, v) || !std::isfinite(v))
    throw InputError(file, path, "expected a finite number, got " + describe(node));
  schema::check_number(file, path, v);
  return v;
}

double read_positive(const YAML::Node& node, const std::string& file, const std::string& path) {
  const double v = read_number(node, file, path);
  if (!(v > 0.0)) throw InputError(file, path, "must be > 0, got " + quote(node.Scalar()));
  return v;
}

double read_nonnegative(const YAML::Node& node, const std::string& file, const std::string& path) {
  const double v = read_number(node, file, path);
  if (v < 0.0) throw InputError(file, path, "must be >= 0, got " + quote(node.Scalar()));
  return v;
}

long read_integer(const YAML::Node& node, const std::string& file, const std::string& path) {
  if (!node.IsDefined() || node.IsNull()) throw InputError(file, path, "missing key");
  long v = 0;
  if (!node.IsScalar() || !YAML::convert<long>::decode(node, v))
    throw InputError(file, path, "expected an integer, got " + describe(node));
  schema::check_number(file, path, static_cast<double>(v));
  return v;
}

bool read_bool(const YAML::Node& node, const std::string& file, const std::string& path) {
  schema::lookup(path);
  if (!node.IsDefined() || node.IsNull()) throw InputError(file, path, "missing key");
  bool v = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, v))
    throw InputError(file, path, "expected true or false, got " + describe(node));
  return v;
}

std::string read_string(const YAML::Node& node, const std::string& file, const std::string& path) {
  schema::lookup(path);
  if (!node.IsDefined() || node.IsNull()) throw InputError(file, path, "missing key");
  if (!node.IsScalar()) throw InputError(file, path, "expected a string, got " + describe(node));
  return node.Scalar();
}

std::string read_choice(const YAML::Node& node, std::initializer_list<std::string_view> choices,
                        const std::string& file, const std::string& path) {
  const std::string v = read_string(node, file, path);
  std::string list;
  for (const auto& c : choices) {
    schema::check_option(path, c);  // the reader's options are the table's
    if (v == c) return v;
    if (!list.empty()) list += " | ";
    list += c;
  }
  throw InputError(file, path, "expected one of " + list + ", got " + quote(v));
}

std::vector<double> read_numbers(const YAML::Node& node, const std::string& file,
                                 const std::string& path, std::optional<std::size_t> count) {
  schema::lookup(path);
  const std::string want =
      count ? "a list of " + std::to_string(*count) + " numbers" : std::string("a list of numbers");
  if (!node.IsDefined() || node.IsNull()) throw InputError(file, path, "missing key");
  if (!node.IsSequence())
    throw InputError(file, path, "expected " + want + ", got " + describe(node));
  if (count && node.size() != *count)
    throw InputError(file, path,
                     "expected " + want + ", got a list of " + std::to_string(node.size()));
  std::vector<double> out;
  out.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i)
    out.push_back(read_number(node[i], file, join(path, i)));
  return out;
}

void throw_zero_vector(const std::string& file, const std::string& path) {
  throw InputError(file, path, "must be a non-zero vector");
}

YAML::Node load_file(const std::string& file) {
  // Read here rather than by YAML::LoadFile: a directory given as the file exited 1, and a NUL
  // byte came out as yaml-cpp's "unknown escape character".
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw InputError(file, "", "is a directory, not a YAML file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "", "cannot open file");
  std::string text;
  char buf[1 << 16];
  std::size_t line = 1;
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    const std::string_view chunk(buf, static_cast<std::size_t>(in.gcount()));
    if (const auto nul = chunk.find('\0'); nul != std::string_view::npos) {
      line += static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n') +
                                       std::count(chunk.begin(), chunk.begin() + nul, '\n'));
      throw InputError(
          file, "",
          "contains a NUL byte on line " + std::to_string(line) + ": not a YAML text file");
    }
    text.append(chunk);
    if (text.size() > kMaxYamlBytes)
      throw InputError(file, "",
                       "larger than " + std::to_string(kMaxYamlBytes >> 20) +
                           " MiB: not a case or geometry file");
  }
  if (in.bad()) throw InputError(file, "", "cannot read file");
  try {
    const YAML::Node root = YAML::Load(text);
    reject_duplicate_keys(root, file);
    return root;
  } catch (const YAML::ParserException& e) {
    throw InputError(file, "",
                     "YAML syntax error at line " + std::to_string(e.mark.line + 1) + ", column " +
                         std::to_string(e.mark.column + 1) + ": " + clip(e.msg));
  }
}

}  // namespace curvsph::yaml
