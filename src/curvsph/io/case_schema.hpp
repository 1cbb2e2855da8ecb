#pragma once
// The one schema of every input key (case files, geometry files): type, range, default, unit
// and meaning of each key, declared once in io/schema_table.cpp (issue 34 item 1).
//
// The readers (the Keys class of io/case_file.cpp, the yaml:: helpers of io/yaml_read.hpp,
// the NURBS readers of nurbs/yaml_input.cpp) keep their own structure — `k.number("x", 1.0)` —
// and consult the schema on every read: the value's type and range are checked against the
// table, an unknown key is reported with the keys the table allows there, and `curvsph keys`
// and docs/keys.md print the same table. In strict mode (the test suite) reading a key the
// table does not declare, or passing a default other than the table's, is a programming error
// (std::logic_error), so a key cannot be added to a reader without its line in the table.
//
// Key paths are dotted, list elements by index in files and messages (`walls.2.radius`) and
// by `*` in the table (`walls.*.radius`).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace curvsph::schema {

enum class Type { number, integer, boolean, string, choice, vector, list, map };

// An interval of allowed values; `text` as written in the table, empty = any finite value.
struct Range {
  double lo = -1e308, hi = 1e308;
  bool lo_open = false, hi_open = false;
  std::string text, lo_text, hi_text;  // as written ("1e6", not 1000000)
  bool contains(double v) const;
};

struct Key {
  std::string path;          // "walls.*.radius"
  Type type = Type::number;  // for vector / list: the elements' range lies in `range`
  std::string type_text;     // as written: "choice: none | ghost | integrals"
  std::vector<std::string> choices;
  Range range;
  bool finite = true;    // numbers must be finite (every key so far)
  std::string fallback;  // "0.1", "required", "derived: ...", "optional", "-" (a map)
  std::string unit;      // "m", "kg/m^3", "-" (none)
  std::string meaning;   // one line
};

// The whole table, in the order of the file (sections first, then their keys).
const std::vector<Key>& keys();

// "walls.3.radius" -> "walls.*.radius".
std::string pattern(std::string_view path);
// The entry of a concrete path; nullptr when the table has none.
const Key* find(std::string_view path);
// The element entry of a list element's path ("walls.0.semi_axes.1": the entry of
// walls.*.semi_axes), for ranges that apply to each element.
const Key* find_element(std::string_view path);
// The names the table allows directly under the map at `path` ("boundary" -> method, map, ...).
std::vector<std::string> children(std::string_view path);
// True when the table declares the first component of `path` (a case or geometry key): reads
// under other roots (a test's own prefix) are not checked.
bool governs(std::string_view path);

// Strict mode: set by the test suite (CURVSPH_STRICT_SCHEMA=1 in the environment works too).
void set_strict(bool on);
bool strict();

// Checks used by the readers. `file` and `path` name the value for messages.
// The entry of `path`; in strict mode a governed path the table lacks is a logic_error.
const Key* lookup(std::string_view path);
// Range of a number read at `path` (InputError naming file, key and the table's range).
void check_number(const std::string& file, const std::string& path, double v);
// A reader's default must be the table's (strict mode; textual defaults compare as written).
void check_default(const std::string& path, double fallback);
void check_default(const std::string& path, std::string_view fallback);
// A reader's option `option` for `path` must be among the table's choices (strict mode).
void check_option(const std::string& path, std::string_view option);

// The table's default of `path` as a number, when it is one.
std::optional<double> default_number(std::string_view path);

// The reference printed by `curvsph keys [PREFIX]` and docs/keys.md.
std::string render_text(std::string_view prefix);
std::string render_markdown();

}  // namespace curvsph::schema
