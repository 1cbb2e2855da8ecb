#pragma once
// Median of a sample (the mean of the two middle values for an even count). The timing
// studies (ghost_cost, shepard_cost) take it over per-repeat ratios of back-to-back timings,
// which a shared machine's drift between repeats does not move.
#include <algorithm>
#include <vector>

namespace curvsph {

inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace curvsph
