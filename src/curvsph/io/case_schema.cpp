#include "curvsph/io/case_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "curvsph/core/error.hpp"
#include "curvsph/io/quote.hpp"
#include "curvsph/io/schema_table.hpp"

namespace curvsph::schema {
namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string_view::npos) return {};
  return std::string(s.substr(b, s.find_last_not_of(' ') - b + 1));
}

double parse_bound(const std::string& s, const std::string& row) {
  if (s == "inf") return 1e308;
  if (s == "-inf") return -1e308;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0') throw std::logic_error("schema row " + row + ": bad bound " + s);
  return v;
}

// "(0, inf)", "[0.8, 4]", "" -> Range.
Range parse_range(const std::string& text, const std::string& row) {
  Range r;
  r.text = text;
  if (text.empty()) return r;
  const auto comma = text.find(',');
  if (text.size() < 5 || comma == std::string::npos ||
      (text.front() != '(' && text.front() != '[') || (text.back() != ')' && text.back() != ']'))
    throw std::logic_error("schema row " + row + ": bad range " + text);
  r.lo_open = text.front() == '(';
  r.hi_open = text.back() == ')';
  r.lo_text = trim(text.substr(1, comma - 1));
  r.hi_text = trim(text.substr(comma + 1, text.size() - comma - 2));
  r.lo = parse_bound(r.lo_text, row);
  r.hi = parse_bound(r.hi_text, row);
  return r;
}

Key parse_row(const Row& row) {
  Key k;
  k.path = row.path;
  k.type_text = row.type;
  const std::string t = row.type;
  if (t == "number") {
    k.type = Type::number;
  } else if (t == "integer") {
    k.type = Type::integer;
  } else if (t == "bool") {
    k.type = Type::boolean;
  } else if (t == "string") {
    k.type = Type::string;
  } else if (t == "vector") {
    k.type = Type::vector;
  } else if (t == "list") {
    k.type = Type::list;
  } else if (t == "map") {
    k.type = Type::map;
  } else if (t.rfind("choice:", 0) == 0) {
    k.type = Type::choice;
    std::string rest = t.substr(7);
    for (std::size_t pos = 0; pos <= rest.size();) {
      const auto bar = rest.find('|', pos);
      k.choices.push_back(trim(rest.substr(pos, bar - pos)));
      if (bar == std::string::npos) break;
      pos = bar + 1;
    }
  } else {
    throw std::logic_error("schema row " + k.path + ": unknown type " + t);
  }
  k.range = parse_range(row.range, k.path);
  k.fallback = row.fallback;
  k.unit = row.unit;
  k.meaning = row.meaning;
  return k;
}

struct Table {
  std::vector<Key> keys;
  std::map<std::string, std::size_t, std::less<>> index;
};

const Table& table() {
  static const Table t = [] {
    Table tb;
    for (int i = 0; i < row_count(); ++i) {
      Key k = parse_row(rows()[i]);
      if (tb.index.count(k.path)) throw std::logic_error("schema: key declared twice: " + k.path);
      tb.index.emplace(k.path, tb.keys.size());
      tb.keys.push_back(std::move(k));
    }
    return tb;
  }();
  return t;
}

std::atomic<int> g_strict{-1};  // -1: not yet read from the environment

std::string_view parent_of(std::string_view path) {
  const auto dot = path.rfind('.');
  return dot == std::string_view::npos ? std::string_view() : path.substr(0, dot);
}

std::string format_number(double v) {
  return fmt::format("{}", v);
}

// "must be > 0 (got -1)", "must be >= 0.8 and <= 4, in [0.8, 4] (got 5)", "must be 2 or 3".
std::string range_message(const Key& k, double v) {
  const Range& r = k.range;
  const bool has_lo = r.lo > -1e308, has_hi = r.hi < 1e308;
  if (k.type == Type::integer && has_lo && has_hi && !r.lo_open && !r.hi_open && r.hi - r.lo == 1)
    return fmt::format("must be {} or {} (got {})", r.lo_text, r.hi_text, format_number(v));
  const std::string lo = fmt::format("{} {}", r.lo_open ? ">" : ">=", r.lo_text);
  const std::string hi = fmt::format("{} {}", r.hi_open ? "<" : "<=", r.hi_text);
  if (has_lo && has_hi)
    return fmt::format("must be {} and {}, in {} (got {})", lo, hi, r.text, format_number(v));
  return fmt::format("must be {} (got {})", has_lo ? lo : hi, format_number(v));
}

}  // namespace

bool Range::contains(double v) const {
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

const std::vector<Key>& keys() {
  return table().keys;
}

std::string pattern(std::string_view path) {
  std::string out;
  std::size_t pos = 0;
  while (pos <= path.size()) {
    const auto dot = path.find('.', pos);
    const std::string_view part = path.substr(pos, dot - pos);
    if (!out.empty() || pos > 0) out += '.';
    const bool index = !part.empty() && std::all_of(part.begin(), part.end(),
                                                    [](char ch) { return ch >= '0' && ch <= '9'; });
    out += index ? std::string_view("*") : part;
    if (dot == std::string_view::npos) break;
    pos = dot + 1;
  }
  return out;
}

const Key* find(std::string_view path) {
  const Table& t = table();
  const auto it = t.index.find(pattern(path));
  return it == t.index.end() ? nullptr : &t.keys[it->second];
}

const Key* find_element(std::string_view path) {
  // Nested lists (a NURBS surface's control_points.2.3.0) take the entry of the nearest
  // enclosing list the table declares.
  std::string p = pattern(path);
  while (p.size() >= 2 && p.compare(p.size() - 2, 2, ".*") == 0) {
    p.resize(p.size() - 2);
    if (const Key* k = find(p); k && (k->type == Type::vector || k->type == Type::list)) return k;
  }
  return nullptr;
}

std::vector<std::string> children(std::string_view path) {
  const std::string p = pattern(path);
  std::vector<std::string> out;
  for (const Key& k : keys())
    if (parent_of(k.path) == p) out.push_back(k.path.substr(p.empty() ? 0 : p.size() + 1));
  return out;
}

bool governs(std::string_view path) {
  const std::string_view root = path.substr(0, path.find('.'));
  return !root.empty() && find(root) != nullptr;
}

void set_strict(bool on) {
  g_strict = on ? 1 : 0;
}

bool strict() {
  if (g_strict < 0) {
    const char* env = std::getenv("CURVSPH_STRICT_SCHEMA");
    g_strict = env && std::string_view(env) == "1" ? 1 : 0;
  }
  return g_strict == 1;
}

const Key* lookup(std::string_view path) {
  if (!governs(path)) return nullptr;
  if (const Key* k = find(path)) return k;
  if (const Key* k = find_element(path)) return k;
  if (strict())
    throw std::logic_error("schema: key '" + pattern(path) +
                           "' is read but not declared in src/curvsph/io/schema_table.cpp");
  return nullptr;
}

void check_number(const std::string& file, const std::string& path, double v) {
  const Key* k = lookup(path);
  if (k && k->finite && !std::isfinite(v))
    throw InputError(file, path, fmt::format("must be a finite number (got {})", v));
  if (k && !k->range.contains(v)) throw InputError(file, path, range_message(*k, v));
}

void check_default(const std::string& path, double fallback) {
  const Key* k = lookup(path);
  if (!k || !strict() || k->fallback.rfind("derived", 0) == 0) return;
  const std::optional<double> d = default_number(path);
  if (!d || *d != fallback)
    throw std::logic_error(fmt::format("schema: the reader of '{}' defaults to {}, the table to {}",
                                       k->path, fallback, k->fallback));
}

void check_default(const std::string& path, std::string_view fallback) {
  const Key* k = lookup(path);
  if (!k || !strict() || k->fallback.rfind("derived", 0) == 0) return;
  if (k->fallback != fallback)
    throw std::logic_error(
        fmt::format("schema: the reader of '{}' defaults to '{}', the table to {}", k->path,
                    fallback, k->fallback));
}

void check_option(const std::string& path, std::string_view option) {
  if (!strict()) return;
  const Key* k = lookup(path);
  if (!k || k->choices.empty()) return;
  if (std::find(k->choices.begin(), k->choices.end(), option) == k->choices.end())
    throw std::logic_error(
        fmt::format("schema: the reader of '{}' accepts '{}', the table not", k->path, option));
}

std::optional<double> default_number(std::string_view path) {
  const Key* k = find(path);
  if (!k) return std::nullopt;
  if (k->fallback == "true") return 1.0;
  if (k->fallback == "false") return 0.0;
  char* end = nullptr;
  const double v = std::strtod(k->fallback.c_str(), &end);
  if (k->fallback.empty() || *end != '\0') return std::nullopt;
  return v;
}

namespace {

std::string type_cell(const Key& k) {
  return k.type == Type::choice ? "choice" : k.type_text;
}

std::string range_cell(const Key& k) {
  if (k.type == Type::choice) {
    std::string list;
    for (const auto& c : k.choices) list += (list.empty() ? "" : " | ") + c;
    return list;
  }
  if (!k.range.text.empty()) return k.range.text;
  // Lists hold maps or names as often as numbers: only a range says they are numeric.
  const bool numeric = k.type == Type::number || k.type == Type::integer || k.type == Type::vector;
  return numeric && k.finite ? "finite" : "";
}

}  // namespace

std::string render_text(std::string_view prefix) {
  std::string out;
  for (const Key& k : keys()) {
    if (!prefix.empty() && !(k.path == prefix || (k.path.rfind(std::string(prefix) + ".", 0) == 0)))
      continue;
    out += k.path + "\n";
    std::string line = "    " + type_cell(k);
    const std::string r = range_cell(k);
    if (!r.empty())
      line += k.type == Type::choice ? ": " + r : r == "finite" ? " (finite)" : " in " + r;
    if (k.fallback != "-") line += "; default: " + k.fallback;
    if (k.unit != "-") line += "; unit: " + k.unit;
    out += line + "\n    " + k.meaning + "\n";
  }
  return out;
}

std::string render_markdown() {
  auto cell = [](std::string s) {
    std::string out;
    for (char ch : s) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out;
  };
  std::string out =
      "# Input keys\n\n"
      "Every key of a case file (and of a geometry file: `dimension`, `walls`), generated from\n"
      "the schema in `src/curvsph/io/schema_table.cpp` by `curvsph keys --markdown` (`make "
      "keys`);\n"
      "do not edit by hand. `*` stands for a list element's index (`walls.0.radius`).\n"
      "`curvsph keys PREFIX` prints the keys under PREFIX.\n"
      "A default `derived: ...` is computed from other keys; `required` keys have none.\n"
      "Types: `vector` is a list of `dimension` numbers (a point, a direction); every number\n"
      "must be finite, and in a range for a vector or list applies to each element. Units are\n"
      "SI (`dx`: a fraction of the particle spacing, `rho0`: of the reference density).\n";
  std::string section;
  for (const Key& k : keys()) {
    const std::string root = k.path.substr(0, k.path.find('.'));
    if (root != section) {
      section = root;
      out += "\n## `" + root + "`\n\n| key | type | range | default | unit | meaning |\n";
      out += "|---|---|---|---|---|---|\n";
    }
    out += "| `" + k.path + "` | " + type_cell(k) + " | " + cell(range_cell(k)) + " | " +
           cell(k.fallback) + " | " + cell(k.unit) + " | " + cell(k.meaning) + " |\n";
  }
  return out;
}

}  // namespace curvsph::schema
