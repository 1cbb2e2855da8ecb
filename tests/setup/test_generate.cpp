// Particle generation: lattice counts, and fluids painted in list order where regions overlap.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace curvsph
