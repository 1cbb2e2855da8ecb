#include "curvsph/io/forces_csv.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace curvsph {

std::vector<WallLoad> WallGroups::sum(const std::vector<WallLoad>& loads) const {
  std::vector<WallLoad> out(names.size());
  for (std::size_t k = 0; k < loads.size() && k < group.size(); ++k)
    for (std::size_t a = 0; a < 3; ++a) {
      out[group[k]].force[a] += loads[k].force[a];
      out[group[k]].moment[a] += loads[k].moment[a];
    }
  return out;
}

std::vector<std::string> load_components(int dimension) {
  if (dimension == 2) return {"fx", "fy", "mz"};
  return {"fx", "fy", "fz", "mx", "my", "mz"};
}

std::vector<double> load_values(const WallLoad& l, int dimension) {
  if (dimension == 2) return {l.force[0], l.force[1], l.moment[2]};
  return {l.force[0], l.force[1], l.force[2], l.moment[0], l.moment[1], l.moment[2]};
}

ForcesCsv::ForcesCsv(const std::string& path, const WallGroups& groups, int dimension)
    : groups_(groups), dimension_(dimension), out_(path) {
  if (!out_) throw std::runtime_error("cannot open '" + path + "' for writing");
  out_ << "time";
  for (const auto& c : columns()) out_ << ',' << c;
  out_ << '\n';
  out_.flush();
}

std::vector<std::string> ForcesCsv::columns() const {
  std::vector<std::string> out;
  for (const auto& n : groups_.names)
    for (const auto& c : load_components(dimension_)) out.push_back(n + "." + c);
  return out;
}

void ForcesCsv::write_row(double t, const std::vector<WallLoad>& loads) {
  out_ << fmt::format("{:.9g}", t);
  for (const WallLoad& l : groups_.sum(loads))
    for (double v : load_values(l, dimension_)) out_ << ',' << fmt::format("{:.9g}", v);
  out_ << '\n';
  out_.flush();
}

}  // namespace curvsph
