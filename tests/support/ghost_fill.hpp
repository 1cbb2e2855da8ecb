#pragma once
// The kernel sum that a point sees from a set of fluid cells and their ghosts: sum V W over the
// cells plus sum beta V_source W over the ghosts the walls make of them (the ghost's volume
// weight beta: Barker's volume factor, or a corner image's share). Tests compare it with the
// same sum over a fluid filling all space (1 where the support is covered exactly once).
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph::test {

// Cells: any type with `x` (positions) and `vol` (volumes). walls == nullptr: the cells alone.
template <class Cells>
std::vector<double> ghost_fill(const WallSet<3>* walls, GhostMapKind map, const Cells& c,
                               const std::vector<Vec<3>>& at, double h) {
  const WendlandC2<3> W(static_cast<Real>(h));
  GhostSet<3> g;
  if (walls) {
    GhostOptions<3> opt;
    opt.map = map;
    opt.support = W.support;
    g.build(c.x, std::vector<Vec<3>>(c.x.size(), Vec<3>::Zero()), *walls, opt);
    EXPECT_TRUE(g.penetrated.empty());
    EXPECT_TRUE(g.no_root.empty());
  }
  std::vector<double> s(at.size(), 0.0);
  for (std::size_t a = 0; a < at.size(); ++a) {
    for (std::size_t j = 0; j < c.x.size(); ++j)
      s[a] += c.vol[j] * W.value((c.x[j] - at[a]).norm());
    for (std::size_t q = 0; q < g.size(); ++q)
      s[a] += g.beta[q] * c.vol[static_cast<std::size_t>(g.source[q])] *
              W.value((g.x[q] - at[a]).norm());
  }
  return s;
}

}  // namespace curvsph::test
