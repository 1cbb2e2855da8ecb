// The scaling model's geometry against hand-computed volumes and counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "curvsph/analysis/scaling_model.hpp"

namespace curvsph::scaling {
namespace {

TEST(ScalingModel, TwoRanksCutTheBoxInHalvesAcrossX) {
  const auto b = orb_boxes(2, 1.0);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_DOUBLE_EQ(b[0].hi[0], 0.5);
  EXPECT_TRUE(b[0].cut[0]);
  EXPECT_FALSE(b[0].cut[1]);
  EXPECT_FALSE(b[0].cut[2]);
  // A slab 0.5 x 1 x 1 with neighbours on its two x faces: halo 2 w per 0.5 of depth.
  EXPECT_NEAR(halo_fraction(b[0], 0.05), 2 * 0.05 / 0.5, 1e-14);
  // Periodic: the one other rank touches both faces.
  EXPECT_EQ(neighbour_count(b, 0, 0.05, 1.0), 1);
}

TEST(ScalingModel, EightRanksGiveCubesWithSevenNeighbours) {
  const auto b = orb_boxes(8, 1.0);
  ASSERT_EQ(b.size(), 8u);
  for (const auto& x : b) EXPECT_NEAR(x.volume(), 0.125, 1e-15);
  // Box 0.5^3, w = 0.05: (0.5+2w)^3 with rounded edges and corners, minus 0.125, by hand.
  const double pi = std::numbers::pi, a = 0.5, w = 0.05;
  const double grown = a * a * a + 6 * a * a * w + 3 * pi * a * w * w + 4 * pi / 3 * w * w * w;
  EXPECT_NEAR(halo_fraction(b[0], w), (grown - a * a * a) / (a * a * a), 1e-14);
  // 2 x 2 x 2 periodic: every other box is adjacent.
  EXPECT_EQ(neighbour_count(b, 0, w, 1.0), 7);
}

TEST(ScalingModel, CubeOfAMillionParticlesAtSupport2p6dx) {
  // a = 100 dx, w = 2.6 dx: 0.156 + 3 pi 0.026^2 + 4 pi/3 0.026^3.
  EXPECT_NEAR(cube_halo_fraction(1e6, 1.0, 2.6), 0.16244, 1e-5);
}

// Brute force: every lattice site outside a box of m^3 sites, within w of the box.
TEST(ScalingModel, LatticeHaloMatchesSiteCount) {
  for (const auto& [m, w] : {std::pair{10, 2.6}, std::pair{7, 3.1}, std::pair{12, 1.5}}) {
    const int top = static_cast<int>(std::ceil(w));
    long count = 0;
    for (int i = -top; i < m + top; ++i)
      for (int j = -top; j < m + top; ++j)
        for (int k = -top; k < m + top; ++k) {
          auto gap = [&](int v) { return v < 0 ? -v : (v >= m ? v - (m - 1) : 0); };
          const int gi = gap(i), gj = gap(j), gk = gap(k);
          const int r2 = gi * gi + gj * gj + gk * gk;
          if (r2 > 0 && r2 < w * w) ++count;
        }
    const double md = m;
    EXPECT_NEAR(lattice_halo_fraction({md, md, md}, {true, true, true}, w),
                static_cast<double>(count) / (md * md * md), 1e-14)
        << "m = " << m << ", w = " << w;
  }
  // A slab cut on x only: 2 layers on each of its two faces at w = 2.6.
  EXPECT_NEAR(lattice_halo_fraction({63, 126, 126}, {true, false, false}, 2.6), 4.0 / 63, 1e-14);
}

// Brute force for the midpoint rule's halo: every site within w of the box reaching half a
// spacing beyond the m^3 owned sites (the ORB box, cut midway between layers).
TEST(ScalingModel, LatticeHaloFromTheOrbBoxMatchesSiteCount) {
  for (const auto& [m, w] : {std::pair{10, 1.3}, std::pair{7, 2.2}, std::pair{12, 0.9}}) {
    const int top = static_cast<int>(std::ceil(w + 0.5));
    long count = 0;
    for (int i = -top; i < m + top; ++i)
      for (int j = -top; j < m + top; ++j)
        for (int k = -top; k < m + top; ++k) {
          // Distance from the site to [-0.5, m - 0.5] per axis.
          auto gap = [&](int v) { return std::max({-0.5 - v, v - (m - 0.5), 0.0}); };
          const double gi = gap(i), gj = gap(j), gk = gap(k);
          const double r2 = gi * gi + gj * gj + gk * gk;
          if (r2 > 0 && r2 < w * w) ++count;
        }
    const double md = m;
    EXPECT_NEAR(lattice_halo_fraction({md, md, md}, {true, true, true}, w, 0.5),
                static_cast<double>(count) / (md * md * md), 1e-14)
        << "m = " << m << ", w = " << w;
  }
  // h = 1.3 dx: one layer per face, half the owner rule's two at 2h.
  EXPECT_NEAR(lattice_halo_fraction({63, 126, 126}, {true, false, false}, 1.3, 0.5), 2.0 / 63,
              1e-14);
}

TEST(ScalingModel, StepTimeAddsHaloComputeAndMessages) {
  StepModel m;
  m.rate = 1e5;
  m.halo_cost = 0.25;
  m.exchanges = 3;
  m.sized_exchanges = 2;
  m.reductions = 4;
  m.bytes_per_halo = 100;
  m.latency = 1e-6;
  m.bandwidth = 1e9;
  const StepTime t = step_time(m, 1e5, 0.1, 26, 64);
  EXPECT_DOUBLE_EQ(t.compute, 1.0);
  EXPECT_DOUBLE_EQ(t.halo_compute, 0.025);  // 1e4 halo copies at a quarter of the cost
  // 3 x 26 messages + 2 x 63 size exchanges + 4 x log2(64) reductions, 1 us each, + 1e4 x
  // 100 B / 1 GB/s.
  EXPECT_NEAR(t.communication, (78 + 126 + 24) * 1e-6 + 1e-3, 1e-15);
  EXPECT_DOUBLE_EQ(step_time(m, 1e5, 0.1, 26, 1).communication, 0.0);
}

}  // namespace
}  // namespace curvsph::scaling
