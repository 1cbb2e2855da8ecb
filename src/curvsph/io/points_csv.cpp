#include "curvsph/io/points_csv.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "curvsph/core/error.hpp"
#include "curvsph/io/quote.hpp"

namespace curvsph {
namespace {

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& reason) {
  throw InputError(file, "", fmt::format("line {}: {}", line, reason));
}

}  // namespace

template <int D>
std::vector<VecD<D>> parse_points_csv(const std::string& text, const std::string& file) {
  const std::string header = D == 2 ? "x,y" : "x,y,z";
  std::istringstream in(text);
  std::vector<VecD<D>> points;
  std::string raw;
  std::size_t line_no = 0;
  bool have_header = false;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string_view line = trim(raw);
    if (line.empty()) continue;
    const std::vector<std::string_view> cells = split(line);
    if (!have_header) {
      std::string got;
      for (auto c : cells) {
        if (!got.empty()) got += ',';
        got += c;
      }
      if (got != header)
        fail(file, line_no,
             fmt::format("expected the header '{}' for a {}-D geometry, got {}", header, D,
                         quote(got)));
      have_header = true;
      continue;
    }
    if (cells.size() != static_cast<std::size_t>(D))
      fail(file, line_no, fmt::format("expected {} columns, got {}", D, cells.size()));
    VecD<D> p;
    for (int i = 0; i < D; ++i) {
      const std::string_view c = cells[static_cast<std::size_t>(i)];
      // from_chars rejects a leading '+', which people do write.
      const std::string_view num = !c.empty() && c.front() == '+' ? c.substr(1) : c;
      double v = 0.0;
      const auto [ptr, ec] = std::from_chars(num.data(), num.data() + num.size(), v);
      if (num.empty() || ec != std::errc() || ptr != num.data() + num.size() || !std::isfinite(v))
        fail(file, line_no,
             fmt::format("column '{}': {} is not a finite number", header[2 * i], quote(c)));
      p[i] = v;
    }
    points.push_back(p);
  }
  if (!have_header)
    throw InputError(file, "", fmt::format("empty file: expected the header '{}'", header));
  return points;
}

template <int D>
std::vector<VecD<D>> read_points_csv(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "", "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_points_csv<D>(ss.str(), file);
}

template std::vector<VecD<2>> parse_points_csv<2>(const std::string&, const std::string&);
template std::vector<VecD<3>> parse_points_csv<3>(const std::string&, const std::string&);
template std::vector<VecD<2>> read_points_csv<2>(const std::string&);
template std::vector<VecD<3>> read_points_csv<3>(const std::string&);

}  // namespace curvsph
