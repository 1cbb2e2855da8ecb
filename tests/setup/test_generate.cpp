// Particle generation: lattice counts, and fluids painted in list order where regions overlap.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/setup/generate.hpp"

namespace curvsph {
namespace {

Case two_fluid_case() {
  return read_case(YAML::Load(R"(
dimension: 2
resolution: {dx: 0.02}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids:
  - {name: outer, rho0: 1, region: {box: {min: [0, 0], max: [1, 1]}}}
  - {name: drop, rho0: 10, region: {disk: {center: [0.5, 0.5], radius: 0.2}}}
eos: {type: tait, c0: 10}
time: {end: 0}
)"),
                   "two_fluids.yaml");
}

TEST(Generate, LaterFluidClaimsOverlappingPoints) {
  const Case c = two_fluid_case();
  Particles<2> P;
  generate_particles<2>(c, P, WallSet<2>{});
  // Independent count: box lattice points outside the disk, plus disk lattice points.
  long outside = 0, inside = 0;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j) {
      const double x = (i + 0.5) * 0.02 - 0.5, y = (j + 0.5) * 0.02 - 0.5;
      if (x * x + y * y >= 0.04) ++outside;
    }
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const double x = 0.3 + (i + 0.5) * 0.02 - 0.5, y = 0.3 + (j + 0.5) * 0.02 - 0.5;
      if (x * x + y * y < 0.04) ++inside;
    }
  long drops = 0;
  for (std::size_t k = 0; k < P.size(); ++k) {
    const double r2 = (P.x[k] - Vec<2>(0.5, 0.5)).squaredNorm();
    if (P.phase[k] == 1) {
      ++drops;
      EXPECT_LT(r2, 0.04 + 1e-12);
      EXPECT_NEAR(P.mass[k], 10 * 0.02 * 0.02, 1e-15);
    } else {
      EXPECT_GE(r2, 0.04 - 1e-12);
    }
  }
  EXPECT_EQ(drops, inside);
  EXPECT_EQ(static_cast<long>(P.size()), outside + inside);
}

TEST(Generate, PeriodicBoxHoldsExactlyLOverDxSquared) {
  const Case c = read_case(YAML::Load(R"(
dimension: 2
resolution: {dx: 0.01}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids: [{rho0: 1, region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {type: linear, c0: 10}
time: {end: 0}
)"),
                           "box.yaml");
  Particles<2> P;
  generate_particles<2>(c, P, WallSet<2>{});
  EXPECT_EQ(P.size(), 10000u);
}

// setup.jitter: the lattice of a box region in the periodic unit square, every point moved by
// at most jitter dx per axis, the same for the same seed. A uniform offset on [-b, b] exceeds
// b/3 with probability 2/3 (a Bernoulli count over the independent offsets). `shift` moves
// the region along x so that it crosses the periodic seam at x = 1.
Case jittered_box(double jitter, unsigned seed, double shift = 0) {
  return read_case(YAML::Load(fmt::format(R"(
dimension: 2
resolution: {{dx: 0.05}}
domain: {{min: [0, 0], max: [1, 1], periodic: [true, true]}}
fluids: [{{rho0: 1, region: {{box: {{min: [{}, 0], max: [{}, 1]}}}}}}]
eos: {{type: linear, c0: 10}}
setup: {{random_seed: {}, jitter: {}}}
time: {{end: 0}}
)",
                                          shift, 1 + shift, seed, jitter)),
                   "jitter.yaml");
}

// Offsets from the lattice point of particle k (generation order: axis 0 fastest), minimal
// image; counts how many crossed the seam (an offset of nearly a period).
struct Offsets {
  int far = 0, moved = 0, wrapped = 0;
  double largest = 0;
};
Offsets offsets(const Particles<2>& P, double shift, double bound) {
  Offsets o;
  for (std::size_t k = 0; k < P.size(); ++k) {
    const Vec<2> lattice(shift + (k % 20 + 0.5) * 0.05, (k / 20 + 0.5) * 0.05);
    for (int d = 0; d < 2; ++d) {
      EXPECT_GE(P.x[k][d], 0);
      EXPECT_LT(P.x[k][d], 1);
      double off = P.x[k][d] - lattice[d];
      if (std::abs(off) > 0.5) {
        off -= std::round(off);
        ++o.wrapped;
      }
      o.largest = std::max(o.largest, std::abs(off));
      o.far += std::abs(off) > bound / 3;
    }
    o.moved += P.x[k] != lattice;
  }
  return o;
}

TEST(Generate, JitterMovesEveryLatticePointWithinItsBound) {
  Particles<2> P, Q, R;
  generate_particles<2>(jittered_box(0.2, 3), P, WallSet<2>{});
  generate_particles<2>(jittered_box(0.2, 3), Q, WallSet<2>{});
  generate_particles<2>(jittered_box(0.2, 4), R, WallSet<2>{});
  ASSERT_EQ(P.size(), 400u);
  const double bound = 0.2 * 0.05;
  const Offsets o = offsets(P, 0, bound);
  EXPECT_LE(o.largest, bound + 1e-12);
  EXPECT_EQ(o.moved, 400);
  // 800 offsets, P(|off| > b/3) = 2/3: mean 533, sd 13.3.
  EXPECT_NEAR(o.far, 533, 5 * 13.3);
  EXPECT_EQ(o.wrapped, 0);  // a lattice point sits dx/2 from the region's edge
  for (std::size_t k = 0; k < P.size(); ++k) {
    EXPECT_EQ(P.x[k], Q.x[k]);  // the seed fixes the start
    EXPECT_NE(P.x[k], R.x[k]);  // another seed another start
    EXPECT_DOUBLE_EQ(P.mass[k], 0.05 * 0.05);
  }
}

// A region across the periodic seam: a point jittered past x = 1 is still in its region and
// comes back as its periodic image near x = 0.
TEST(Generate, JitterAcrossThePeriodicSeamWraps) {
  Particles<2> P;
  const double shift = 0.02, bound = 0.2 * 0.05;
  generate_particles<2>(jittered_box(0.2, 5, shift), P, WallSet<2>{});
  ASSERT_EQ(P.size(), 400u);
  const Offsets o = offsets(P, shift, bound);
  EXPECT_LE(o.largest, bound + 1e-12);
  EXPECT_EQ(o.moved, 400);
  // The last column sits at x = 0.995: about a quarter of its 20 points (offset > 0.005 of
  // at most 0.01) cross; P(none of 20) = 0.75^20 = 3e-3 for a fixed seed (this one: > 0).
  EXPECT_GT(o.wrapped, 0);
}

TEST(Generate, JitterOutsideItsRangeIsRefusedWithTheKey) {
  for (double j : {-0.1, 0.5, 0.7}) {
    try {
      jittered_box(j, 1);
      FAIL() << "jitter " << j << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("setup.jitter"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace curvsph
