#pragma once
// forces.csv (DESIGN.md §3, `output.forces_every`): a header `time`, then per wall
// NAME.fx,NAME.fy,NAME.mz in 2-D (per unit depth) or NAME.fx,NAME.fy,NAME.fz,NAME.mx,NAME.my,
// NAME.mz in 3-D, one row per forces time: the force the fluid exerts on the wall and its
// moment about the wall's moment_center (boundary/wall_loads.hpp says what is summed). A
// wall is one entry of the case's `walls:` list: the walls a CAD entry yields share its name
// and are summed.
#include <fstream>
#include <string>
#include <vector>

#include "curvsph/boundary/wall_loads.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// The walls of a set grouped by name, in the order of their first wall.
struct WallGroups {
  std::vector<std::string> names;
  std::vector<std::size_t> group;  // per wall of the set: its index in `names`

  template <int D>
  static WallGroups of(const WallSet<D>& walls) {
    WallGroups g;
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const std::string& n = walls[k].name.empty() ? "wall" + std::to_string(k) : walls[k].name;
      std::size_t i = 0;
      while (i < g.names.size() && g.names[i] != n) ++i;
      if (i == g.names.size()) g.names.push_back(n);
      g.group.push_back(i);
    }
    return g;
  }
  // Per-wall loads summed per group.
  std::vector<WallLoad> sum(const std::vector<WallLoad>& loads) const;
};

// The columns of one wall in dimension D: {"fx", "fy", "mz"} or the six of 3-D, and the
// matching values of a load.
std::vector<std::string> load_components(int dimension);
std::vector<double> load_values(const WallLoad& l, int dimension);

class ForcesCsv {
 public:
  ForcesCsv(const std::string& path, const WallGroups& groups, int dimension);
  // Column names after `time`.
  std::vector<std::string> columns() const;
  // One row from the per-wall loads of the set (summed per group).
  void write_row(double t, const std::vector<WallLoad>& loads);

 private:
  WallGroups groups_;
  int dimension_;
  std::ofstream out_;
};

}  // namespace curvsph
