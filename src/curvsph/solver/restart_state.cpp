#include "curvsph/solver/restart_state.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

#include "curvsph/core/error.hpp"
#include "curvsph/core/types.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMagic = "curvsph-restart 1\n";
static_assert(std::endian::native == std::endian::little, "the restart format is little-endian");

template <class T>
void append_values(std::string& out, const std::vector<T>& v) {
  static_assert(sizeof(T) == 8);
  const std::size_t o = out.size();
  out.resize(o + 8 * v.size());
  if (!v.empty()) std::memcpy(out.data() + o, v.data(), 8 * v.size());
}

const char* real_name() {
  return sizeof(Real) == sizeof(double) ? "double" : "float";
}

}  // namespace

fs::path restart_state_path(const fs::path& snapshot) {
  fs::path p = snapshot;
  return p.replace_extension(".restart");
}

void write_restart_state(const fs::path& file, const RestartState& s) {
  nlohmann::json header = s.header;
  nlohmann::json arrays = nlohmann::json::array();
  std::string data;
  for (const auto& [name, v] : s.reals) {
    arrays.push_back({{"name", name}, {"type", "f64"}, {"count", v.size()}});
    append_values(data, v);
  }
  for (const auto& [name, v] : s.ints) {
    arrays.push_back({{"name", name}, {"type", "i64"}, {"count", v.size()}});
    append_values(data, v);
  }
  header["arrays"] = std::move(arrays);
  const std::string text = header.dump();
  const fs::path tmp = fs::path(file).concat(".tmp");
  {
    std::ofstream out(tmp, std::ios::binary);
    out << kMagic << text.size() << '\n' << text;
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) throw std::runtime_error("cannot rename '" + tmp.string() + "': " + ec.message());
}

RestartState parse_restart_state(const std::string& bytes, const std::string& name) {
  auto fail = [&](const std::string& key, const std::string& why) -> void {
    throw InputError(name, key, why + " (not a restart state written by curvsph run)");
  };
  const std::size_t magic = std::strlen(kMagic);
  if (bytes.compare(0, magic, kMagic) != 0) fail("", "missing the 'curvsph-restart 1' header");
  const std::size_t eol = bytes.find('\n', magic);
  if (eol == std::string::npos || eol == magic || eol - magic > 12)
    fail("", "missing the header length");
  std::uint64_t len = 0;
  for (std::size_t k = magic; k < eol; ++k) {
    if (bytes[k] < '0' || bytes[k] > '9') fail("", "bad header length");
    len = 10 * len + static_cast<std::uint64_t>(bytes[k] - '0');
  }
  const std::size_t h0 = eol + 1;
  if (len > bytes.size() - h0) fail("", "truncated header");
  RestartState s;
  try {
    s.header = nlohmann::json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(h0),
                                     bytes.begin() + static_cast<std::ptrdiff_t>(h0 + len));
  } catch (const nlohmann::json::exception&) {
    fail("", "the JSON header does not parse");
  }
  if (!s.header.is_object()) fail("", "the JSON header is not an object");
  const auto it = s.header.find("arrays");
  if (it == s.header.end() || !it->is_array()) fail("arrays", "missing");
  std::size_t at = h0 + len;
  for (std::size_t k = 0; k < it->size(); ++k) {
    const nlohmann::json& a = (*it)[k];
    const std::string key = fmt::format("arrays.{}", k);
    if (!a.is_object() || !a.contains("name") || !a["name"].is_string() || !a.contains("type") ||
        !a["type"].is_string() || !a.contains("count") || !a["count"].is_number_unsigned())
      fail(key, "needs name, type and count");
    const auto count = a["count"].get<std::uint64_t>();
    const std::string type = a["type"].get<std::string>();
    if (count > (bytes.size() - at) / 8) fail(key, "truncated data");
    const std::size_t nbytes = 8 * static_cast<std::size_t>(count);
    const std::string aname = a["name"].get<std::string>();
    if (s.reals.count(aname) || s.ints.count(aname)) fail(key, "repeats '" + aname + "'");
    if (type == "f64") {
      auto& v = s.reals[aname];
      v.resize(static_cast<std::size_t>(count));
      if (nbytes) std::memcpy(v.data(), bytes.data() + at, nbytes);
    } else if (type == "i64") {
      auto& v = s.ints[aname];
      v.resize(static_cast<std::size_t>(count));
      if (nbytes) std::memcpy(v.data(), bytes.data() + at, nbytes);
    } else {
      fail(key, "type must be f64 or i64");
    }
    at += nbytes;
  }
  if (at != bytes.size()) fail("arrays", "trailing bytes after the arrays");
  return s;
}

RestartState read_restart_state(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw InputError(file.string(), "--restart",
                     "no restart state beside the snapshot (curvsph run writes it at each "
                     "snapshot with output.restart: every, at the last one with the default "
                     "last); a snapshot alone lacks the state to continue from");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "--restart", "cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_restart_state(bytes, file.string());
}

void stamp_case(RestartState& s, const Case& c) {
  s.header["case"] = c.name;
  s.header["dimension"] = c.dimension;
  s.header["dx"] = c.dx;
  s.header["real"] = real_name();
}

void check_case(const RestartState& s, const Case& c, const std::string& file) {
  const auto& h = s.header;
  const std::string from = " the case " + c.file_name() + " ";
  if (!h.contains("case") || !h["case"].is_string() || h["case"].get<std::string>() != c.name)
    throw InputError(file, "name",
                     fmt::format("the snapshot belongs to case '{}', not to{}('{}')",
                                 h.value("case", nlohmann::json()).dump(), from, c.name));
  const std::int64_t dim = header_integer(s, "dimension", file);
  if (dim != c.dimension)
    throw InputError(
        file, "dimension",
        fmt::format("the snapshot is {}-D, the case {} is {}-D", dim, c.file_name(), c.dimension));
  const double dx = header_number(s, "dx", file);
  if (dx != c.dx)
    throw InputError(
        file, "resolution.dx",
        fmt::format("the snapshot was run at dx = {:.17g},{}has dx = {:.17g}", dx, from, c.dx));
  const auto real = h.find("real");
  if (real == h.end() || !real->is_string() || real->get<std::string>() != real_name())
    throw InputError(file, "real",
                     fmt::format("written by a build with Real = {}, this one has {}",
                                 real == h.end() ? "?" : real->dump(), real_name()));
}

double header_number(const RestartState& s, const std::string& key, const std::string& file) {
  const auto it = s.header.find(key);
  if (it == s.header.end() || !it->is_number())
    throw InputError(file, key, "missing or not a number in the restart state");
  return it->get<double>();
}

std::int64_t header_integer(const RestartState& s, const std::string& key,
                            const std::string& file) {
  const auto it = s.header.find(key);
  if (it == s.header.end() || !it->is_number_integer())
    throw InputError(file, key, "missing or not an integer in the restart state");
  return it->get<std::int64_t>();
}

namespace {
template <class Map>
const typename Map::mapped_type& array_of(const Map& m, const std::string& key, std::int64_t count,
                                          const std::string& file) {
  const auto it = m.find(key);
  if (it == m.end()) throw InputError(file, "arrays." + key, "missing in the restart state");
  if (count >= 0 && it->second.size() != static_cast<std::size_t>(count))
    throw InputError(file, "arrays." + key,
                     fmt::format("has {} values, expected {}", it->second.size(), count));
  return it->second;
}
}  // namespace

const std::vector<double>& real_array(const RestartState& s, const std::string& key,
                                      std::int64_t count, const std::string& file) {
  return array_of(s.reals, key, count, file);
}

const std::vector<std::int64_t>& int_array(const RestartState& s, const std::string& key,
                                           std::int64_t count, const std::string& file) {
  return array_of(s.ints, key, count, file);
}

}  // namespace curvsph
