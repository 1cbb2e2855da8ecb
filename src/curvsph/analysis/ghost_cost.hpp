#pragma once
// Cost of the density-preserving ghost map against the mirror (Vela Vela et al., Table 1):
// random interior particles in a unit cylinder (periodic z in [-3, 3)), a unit sphere and a
// torus (a = 1, R = 3); for each, the time to place the ghosts (closest point on the wall +
// map + ghost position, for every particle within the support) with the mirror and with the
// density_preserving map, both measured in the same run, interleaved; the increase is the median
// over `repeats` of the ratio of back-to-back timings (odd count: a true median).
// Paper: +0.63 % (cylinder), +1.36 % (sphere), +10.3 % (torus).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace curvsph {

struct GhostCostOptions {
  std::size_t particles = 1000000;
  double support = 0.1;  // 2h
  int repeats = 31;
  std::uint64_t seed = 20240611;
};

struct GhostCostShape {
  std::string shape;    // cylinder | sphere | torus
  double mirror_s = 0;  // best time, mirror (reported; the increase uses paired ratios)
  double density_preserving_s = 0;
  double increase_pct = 0;  // 100 (median paired time ratio - 1)
  std::size_t ghosts = 0;   // ghosts placed (same count for both maps)
};

struct GhostCostResult {
  std::vector<GhostCostShape> shapes;
  double cylinder_pct = 0, sphere_pct = 0, torus_pct = 0;
  // ghost_cost_increase_pct_<shape>, ghost_time_mirror_s_<shape>,
  // ghost_time_density_preserving_s_<shape>, ghost_count_<shape>.
  std::map<std::string, double> metrics;
};

// Single-threaded timings (stable on a shared machine).
GhostCostResult ghost_cost_study(const GhostCostOptions& options = {});

}  // namespace curvsph
