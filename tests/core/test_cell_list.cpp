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

// The symmetric visitor for_each_pair against brute force: every pair within the support
// exactly once (i != j), with the minimal-image r_ij = x_i - x_j; and its tile colouring: two
// tiles of one colour never touch the same particle (they run at the same time).
template <int D>
void check_pairs_against_brute_force(std::array<bool, 3> periodic, unsigned seed,
                                     Real support = 0.11, int min_tiles = 3, double len0 = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const Vec3d lo(-0.3, 0.1, 0.2), hi(-0.3 + len0, 0.8, 1.1);
  std::vector<Vec<D>> x(3000);
  for (auto& p : x)
    for (int d = 0; d < D; ++d) p[d] = lo[d] + (hi[d] - lo[d]) * U(rng);
  CellList<D> cells;
  cells.configure(support, lo, hi, periodic);
  cells.build(x);
  const Index n = static_cast<Index>(x.size());
  std::vector<std::pair<Index, Index>> found;
  std::array<std::vector<int>, 4> toucher;  // per colour, the tile that touched a particle
  for (auto& t : toucher) t.assign(n, -1);
  int conflicts = 0;
  ASSERT_GE(cells.tile_count(), min_tiles);  // else the colouring is not exercised
  for (int k = 0; k < cells.tile_count(); ++k) {
    auto f = [&](Index i, Index j, const Vec<D>& r, Real r2) {
      found.emplace_back(std::min(i, j), std::max(i, j));
      EXPECT_NE(i, j);
      const Vec<D> s = cells.separation(x[i], x[j]);
      EXPECT_NEAR((r - s).norm(), 0.0, 1e-12);
      EXPECT_EQ(r2, r.squaredNorm());
      for (const Index p : {i, j}) {
        int& t = toucher[static_cast<std::size_t>(cells.tile_colour(k))][p];
        if (t != -1 && t != k) ++conflicts;
        t = k;
      }
    };
    cells.for_each_pair_in_tile(k, f);
  }
  EXPECT_EQ(conflicts, 0);
  std::vector<std::pair<Index, Index>> brute;
  std::vector<int> brute_count(n, 0);
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j < n; ++j) {
      Vec<D> s = x[i] - x[j];
      for (int d = 0; d < D; ++d)
        if (periodic[d]) s[d] -= (hi[d] - lo[d]) * std::round(s[d] / (hi[d] - lo[d]));
      if (s.norm() < support) {
        brute.emplace_back(i, j);
        ++brute_count[i];
        ++brute_count[j];
      }
    }
  std::sort(found.begin(), found.end());
  ASSERT_EQ(found, brute);            // each pair once: a duplicate or a miss breaks the equality
  EXPECT_GT(brute.size(), x.size());  // real neighbourhoods
  // The threaded driver: per-particle counts written from both ends of each pair, as the
  // physics passes do; a race between two threads would lose increments.
  std::vector<int> count(n, 0);
  cells.for_each_pair([&](Index i, Index j, const Vec<D>&, Real) {
    ++count[i];
    ++count[j];
  });
  EXPECT_EQ(count, brute_count);
}

TEST(CellList, PairsMatchBruteForce2DPeriodic) {
  check_pairs_against_brute_force<2>({true, true, false}, 11);
}
TEST(CellList, PairsMatchBruteForce2DMixed) {
  check_pairs_against_brute_force<2>({false, true, false}, 12);
}
TEST(CellList, PairsMatchBruteForce2DOpen) {
  check_pairs_against_brute_force<2>({false, false, false}, 13);
}
TEST(CellList, PairsMatchBruteForce3DPeriodic) {
  check_pairs_against_brute_force<3>({true, true, true}, 14);
}
TEST(CellList, PairsMatchBruteForce3DMixed) {
  check_pairs_against_brute_force<3>({true, false, true}, 15);
}
TEST(CellList, PairsMatchBruteForce3DOpen) {
  check_pairs_against_brute_force<3>({false, false, false}, 16);
}
// A box three times longer along axis 0: the tiles are cut along axis 0 (and another), which the
// half stencil walks both ways (tiles 2 reach thick).
TEST(CellList, PairsMatchBruteForce2DSlabsAlongAxis0) {
  check_pairs_against_brute_force<2>({true, false, false}, 20, 0.11, 10, 3.0);
}
TEST(CellList, PairsMatchBruteForce3DSlabsAlongAxis0) {
  check_pairs_against_brute_force<3>({false, true, true}, 21, 0.11, 10, 3.0);
}
// Short periodic axes (reach 1, whole rows in three images; see above). In 2-D both axes are
// too short to cut: one slab. In 3-D axis 2 (3 cells) is cut in two.
TEST(CellList, PairsMatchBruteForceOnShortPeriodicAxes2D) {
  check_pairs_against_brute_force<2>({true, true, false}, 17, 0.3, 1);
}
TEST(CellList, PairsMatchBruteForceOnShortPeriodicAxes3D) {
  check_pairs_against_brute_force<3>({true, true, true}, 18, 0.3, 2);
}
// Only axis 1 is short (reach 1, three images): tiles are cut along axis 2 (and 0).
TEST(CellList, PairsMatchBruteForceOnOneShortPeriodicAxis3D) {
  check_pairs_against_brute_force<3>({false, true, false}, 19, 0.3, 3);
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
