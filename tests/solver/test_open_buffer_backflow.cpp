// Outflow buffers under a backflow (solver/open_boundaries.hpp): a buffer particle that drifts
// back into the fluid becomes fluid and a copy enters at the buffer's back where that place is
// empty (the buffer stays full), none where a buffer particle lies within dx/2 of it (no
// overfilling under jitter), with the outflow count and mass taken back. Reference: the
// kinematics and the bookkeeping by hand.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/open_boundaries.hpp"

namespace curvsph {
namespace {

// A plane channel 0 <= y <= 0.1, fluid 0 <= x <= 0.3, inflow at x = 0 (velocity INFLOW),
// outflow at x = 0.3; c0 = 15, p0 = 0.05 rho0 c0^2 as in cases/cylinder_channel_re100.yaml.
Case channel(const std::string& inflow) {
  return read_case(YAML::Load(R"(
name: buffer_backflow
dimension: 2
resolution: {dx: 0.01, h_over_dx: 1.3}
domain: {min: [-0.05, 0], max: [0.35, 0.1]}
fluids: [{name: f, rho0: 1, viscosity: 1.0e-3,
          region: {box: {min: [0, 0], max: [0.3, 0.1]}}}]
eos: {type: tait, c0: 15, gamma: 7, p0: 11.25}
density: {method: summation}
walls: [{shape: plane, point: [0, 0], normal: [0, 1]},
        {shape: plane, point: [0, 0.1], normal: [0, -1]}]
boundary: {method: ghost, map: mirror, velocity: free_slip}
open_boundaries:
  - {name: inlet, kind: inflow, point: [0, 0], normal: [1, 0], velocity: )" +
                              inflow +
                              R"(}
  - {name: outlet, kind: outflow, point: [0.3, 0], normal: [-1, 0]}
time: {end: 0.01}
)"),
                   "buffer_backflow.yaml");
}

TEST(OpenBufferBackflow, AReturningParticleLeavesACopyAtTheBackWhereThatPlaceIsEmpty) {
  const Case c = channel("[0.1, 0]");
  const Real support = Real(2.6) * Real(0.01);  // 2h
  OpenBoundaries<2> ob(c, support);
  ASSERT_NEAR(ob.buffer_depth(), 0.03, 1e-12);  // ceil(2h / dx) = 3 layers
  // Outflow buffer particles (buffer value 2: the second boundary, x >= 0.3, n = -e_x) after a
  // drift: 0 and 1 moved back across x = 0.3; 2 is past the buffer's back (deleted), and lies
  // beside 0's place at the back, which must still count as empty; 3 holds 1's place.
  const Real xs[4] = {Real(0.2995), Real(0.2990), Real(0.3305), Real(0.3285)};
  const Real ys[4] = {Real(0.045), Real(0.065), Real(0.045), Real(0.066)};
  Particles<2> P;
  P.resize(4);
  const Real m = Real(1e-4);
  for (std::size_t i = 0; i < 4; ++i) {
    P.x[i] = Vec<2>(xs[i], ys[i]);
    P.v[i] = Vec<2>(Real(-0.5), Real(0.1));
    P.mass[i] = m;
    P.rho[i] = 1;
    P.sigma[i] = 1 / m;
    P.id[i] = static_cast<std::int64_t>(10 + i);
    P.buffer[i] = 2;
  }
  ob.number_from(P);  // K = 14
  const auto ch = ob.after_drift(P, Real(1e-3));
  // Deleted: particle 2 (+1); created: the copy of particle 0 (-1), id 10 + 14.
  EXPECT_EQ(ch.count, 0);
  EXPECT_EQ(ch.ids, 12 - 24);
  EXPECT_EQ(ch.ids2, 12 * 12 - 24 * 24);
  EXPECT_NEAR(ch.mass, 0.0, 1e-12);
  ASSERT_EQ(P.size(), 4u);
  long copies = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    switch (P.id[i]) {
      case 10:  // the returning particles are fluid where they stand
      case 11:
        EXPECT_EQ(P.buffer[i], 0);
        EXPECT_NEAR(P.x[i].x(), xs[P.id[i] - 10], 1e-6);
        break;
      case 13:
        EXPECT_EQ(P.buffer[i], 2);
        break;
      case 24:  // 0's copy: at x - L n = x + 0.03 e_x, with its velocity
        EXPECT_EQ(P.buffer[i], 2);
        EXPECT_NEAR(P.x[i].x(), 0.2995 + 0.03, 1e-6);
        EXPECT_NEAR(P.x[i].y(), 0.045, 1e-6);
        EXPECT_NEAR(P.v[i].x(), -0.5, 1e-6);
        ++copies;
        break;
      default:
        ADD_FAILURE() << "unexpected particle id " << P.id[i];
    }
  }
  EXPECT_EQ(copies, 1);
  // Both returns are taken off the outflow: the fluid gained 2 m.
  EXPECT_EQ(ob.outflow_count(), -2);
  EXPECT_NEAR(ob.outflow_mass(), -2 * static_cast<double>(m), 1e-12);
  EXPECT_EQ(ob.inflow_count(), 0);
}

}  // namespace
}  // namespace curvsph
