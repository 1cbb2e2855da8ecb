// Cell list against brute force on random periodic and open point sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {
namespace {

template <int D>
void check_against_brute_force(std::array<bool, 3> periodic, unsigned seed, Real support = 0.11) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const Vec3d lo(-0.3, 0.1, 0.2), hi(0.7, 0.8, 1.1);
  std::vector<Vec<D>> x(3000);
  for (auto& p : x)
    for (int d = 0; d < D; ++d) p[d] = lo[d] + (hi[d] - lo[d]) * U(rng);
  CellList<D> cells;
  cells.configure(support, lo, hi, periodic);
  cells.build(x);
  long pairs = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::vector<Index> found;
    cells.for_each_neighbor(x[i], x, [&](Index j, const Vec<D>& r, Real r2) {
      found.push_back(j);
      // The separation must be the minimal image.
      const Vec<D> s = cells.separation(x[i], x[j]);
      EXPECT_NEAR((r - s).norm(), 0.0, 1e-12);
      EXPECT_NEAR(r2, s.squaredNorm(), 1e-12);
    });
    std::vector<Index> brute;
    for (std::size_t j = 0; j < x.size(); ++j) {
      Vec<D> s = x[i] - x[j];
      for (int d = 0; d < D; ++d)
        if (periodic[d]) s[d] -= (hi[d] - lo[d]) * std::round(s[d] / (hi[d] - lo[d]));
      if (s.norm() < support) brute.push_back(static_cast<Index>(j));
    }
    // The overload on the list's own sorted copy of the positions must hand out the same
    // pairs in the same order with bit-identical r and r2 (the physics passes rely on it).
    std::size_t k = 0;
    cells.for_each_neighbor(x[i], [&](Index j, const Vec<D>& r, Real r2) {
      ASSERT_LT(k, found.size());
      EXPECT_EQ(j, found[k]);
      const Vec<D> s = cells.separation(x[i], x[j]);
      EXPECT_NEAR((r - s).norm(), 0.0, 1e-12);
      EXPECT_EQ(r2, r.squaredNorm());
      ++k;
    });
    EXPECT_EQ(k, found.size());
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, brute) << "particle " << i;
    pairs += static_cast<long>(found.size());
  }
  EXPECT_GT(pairs, static_cast<long>(x.size()));  // the test must see real neighbourhoods
}

TEST(CellList, MatchesBruteForce2DPeriodic) {
  check_against_brute_force<2>({true, true, false}, 1);
}
TEST(CellList, MatchesBruteForce2DMixed) {
  check_against_brute_force<2>({true, false, false}, 2);
}
TEST(CellList, MatchesBruteForce2DOpen) {
  check_against_brute_force<2>({false, false, false}, 3);
}
TEST(CellList, MatchesBruteForce3DPeriodic) {
  check_against_brute_force<3>({true, true, true}, 4);
}
TEST(CellList, MatchesBruteForce3DMixed) {
  check_against_brute_force<3>({false, true, false}, 5);
}

// Periodic axes only 2.33 supports long (0.7 / 0.3): two cells, each holding points whose
// nearest image lies on either side; the whole row is scanned in three images.
TEST(CellList, MatchesBruteForceOnShortPeriodicAxes2D) {
  check_against_brute_force<2>({true, true, false}, 6, 0.3);
}
TEST(CellList, MatchesBruteForceOnShortPeriodicAxes3D) {
  check_against_brute_force<3>({true, true, true}, 7, 0.3);
}

TEST(CellList, WrapKeepsPointsInTheBox) {
  CellList<2> cells;
  cells.configure(0.1, Vec3d(0, 0, 0), Vec3d(1, 2, 0), {true, true, false});
  Vec<2> p(1.25, -0.5);
  cells.wrap(p);
  EXPECT_NEAR(p[0], 0.25, 1e-14);
  EXPECT_NEAR(p[1], 1.5, 1e-14);
}

}  // namespace
}  // namespace curvsph
