// CSF curvature of a circular interface against 1/R, and the direction of the force.
#include <gtest/gtest.h>

#include "curvsph/io/case_file.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/surface_tension.hpp"
#include "curvsph/setup/generate.hpp"

namespace curvsph {
namespace {

TEST(SurfaceTension, CurvatureOfACircleIsOneOverR) {
  const double R = 0.2;
  const Case c = read_case(YAML::Load(R"(
dimension: 2
resolution: {dx: 0.01, h_over_dx: 1.5}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids:
  - {name: outer, rho0: 1, region: {box: {min: [0, 0], max: [1, 1]}}}
  - {name: drop, rho0: 1, region: {disk: {center: [0.5, 0.5], radius: 0.2}}}
eos: {type: linear, c0: 10}
time: {end: 0}
)"),
                           "drop.yaml");
  Particles<2> P;
  generate_particles<2>(c, P, WallSet<2>{});
  WendlandC2<2> W(static_cast<Real>(c.h()));
  CellList<2> cells;
  cells.configure(W.support, c.domain_min, c.domain_max, c.periodic);
  cells.build(P.x);
  density_summation(P, cells, W);
  SurfaceTensionScratch<2> s;
  add_surface_tension(P, cells, W, SurfaceTensionPair{0, 1, 1.0}, s);
  double sum = 0;
  long n = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<2> d = P.x[i] - Vec<2>(0.5, 0.5);
    if (!s.valid[i] || std::abs(d.norm() - R) > c.h()) continue;
    sum += s.kappa[i];
    ++n;
    // The force (along the colour gradient) points into the drop.
    EXPECT_LT(s.n[i].dot(d), 0) << "particle " << i;
  }
  ASSERT_GT(n, 50);
  EXPECT_NEAR(sum / n, 1 / R, 0.1 / R);  // mean curvature within 10 % on a raw lattice
}

}  // namespace
}  // namespace curvsph
