// Particle shifting next to walls (BoundaryModel::add_shift_sums): the walls close the
// support of the shift sums, so that a uniform arrangement next to a wall is not shifted into
// it. References: the exact mirror symmetry of a lattice between two plane walls (ghosts),
// and a brute-force sum over all pairs and Gauss points of every element (boundary integrals),
// with the shift towards a wall removed within dx of it.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "../support/bi_tank.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/physics/particle_shifting.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

// The fluid's shift sums, then the walls' share when `walls` is set.
template <int D>
ShiftScratch<D> sums_of(const Solver<D>& s, bool walls) {
  ShiftScratch<D> sc;
  const Real dx = static_cast<Real>(s.spec().dx);
  shift_sums(s.particles(), s.cells(), s.kernel(), dx, sc);
  if (walls) s.boundary()->add_shift_sums(s.particles(), s.particles().size(), dx, sc);
  return sc;
}

// A plane channel, 16 rows between walls at y = 0 and 0.016, periodic along x, lattice at
// half a spacing from each wall: with mirror ghosts the images continue the lattice exactly.
Case channel(const std::string& map) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.001, h_over_dx: 1.5}
domain: {min: [0, 0], max: [0.016, 0.016], periodic: [true, false]}
fluids: [{rho0: 1000, viscosity: 1.0e-3, region: {box: {min: [0, 0], max: [0.016, 0.016]}}}]
eos: {type: tait, c0: 1, gamma: 7, p0: 0}
density: {method: summation, shifting: 0.05}
walls:
  - {shape: plane, point: [0, 0], normal: [0, 1]}
  - {shape: plane, point: [0, 0.016], normal: [0, -1]}
time: {end: 0.01}
output: {vtk: false}
)");
  root["boundary"] = YAML::Load("{method: ghost, map: " + map + ", velocity: no_slip}");
  return read_case(root, "shifting_test");
}

TEST(WallShifting, GhostsCloseTheLatticeSupportExactly) {
  Solver<2> s(channel("mirror"));
  s.initialize();
  const auto& P = s.particles();
  const ShiftScratch<2> with = sums_of(s, true), without = sums_of(s, false);
  double worst = 0, one_sided = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    worst = std::max(worst, static_cast<double>(with.s[i].norm()));
    // The first row: the fluid sum alone points into the fluid (+y), so the shift
    // -C (2h)^2 s would push the row into the wall.
    if (P.x[i].y() < 0.001) {
      EXPECT_GT(without.s[i].y(), 0) << "particle at " << P.x[i].transpose();
      one_sided = std::max(one_sided, static_cast<double>(without.s[i].norm()));
    }
  }
  EXPECT_GT(one_sided, 10.0);  // 1/m: a unit of sum V grad W ~ 1/h
  EXPECT_LT(worst, 1e-9 * one_sided);
}

TEST(WallShifting, ChannelWithShiftingKeepsItsParticles) {
  // Shifting on from a jittered lattice in a closed channel: before the walls entered the
  // sums, the first rows were pushed through the walls within a few steps (7 particles by
  // step 4).
  for (const std::string map : {"mirror", "mirror_beta", "density_preserving"}) {
    Case c = channel(map);
    c.jitter = 0.2;
    Solver<2> s(c);
    s.initialize();
    for (int k = 0; k < 50; ++k) s.step();
    double ymin = 1, ymax = 0;
    for (const auto& x : s.particles().x) {
      ymin = std::min(ymin, static_cast<double>(x.y()));
      ymax = std::max(ymax, static_cast<double>(x.y()));
    }
    EXPECT_GT(ymin, 0.1 * c.dx) << map;
    EXPECT_LT(ymax, 0.016 - 0.1 * c.dx) << map;
  }
}

// Brute force of the boundary-integral shift sum: every fluid pair with Sun et al.'s weight,
// minus every element's kernel mean (2 Gauss points along the segment) times n A.
Vec2 brute_bi_sum(const Particles<2>& P, std::size_t i, const BoundaryElements<2>& el,
                  const WendlandC2<2>& W, Real dx) {
  Vec2 g = Vec2::Zero();
  const double w_dx = W.value(dx);
  for (std::size_t j = 0; j < P.size(); ++j) {
    if (j == i) continue;
    const Vec2 r = P.x[i] - P.x[j];
    const double q = W.value(r.norm()) / w_dx;
    g += static_cast<Real>((1 + 0.2 * q * q * q * q) * P.mass[j] / P.rho[j]) *
         W.gradient_factor(r.norm()) * r;
  }
  const double k = 0.5 / std::sqrt(3.0);
  for (std::size_t b = 0; b < el.size(); ++b) {
    const Vec2d a = el.vertices[b][0], e = el.vertices[b][1];
    double mean = 0;
    for (const double u : {0.5 - k, 0.5 + k})
      mean += 0.5 * W.value((P.x[i] - (a + u * (e - a)).cast<Real>()).norm());
    g -= static_cast<Real>(mean * (e - a).norm()) * el.normal[b].cast<Real>();
  }
  return g;
}

TEST(WallShifting, IntegralsSubtractTheirWallSum) {
  // A 0.1 m wide box tank, water 0.048 m deep, packed for the BI operators.
  YAML::Node root = test::bi_tank("geometric");
  root["setup"] = YAML::Load("{relax: {map: integrals, max_steps: 3000, tolerance: 1.0e-5}}");
  const Case c = read_case(root, "shifting_test");
  Solver<2> s(c);
  s.initialize();
  const auto& P = s.particles();
  const ShiftScratch<2> with = sums_of(s, true), without = sums_of(s, false);
  const auto el = elements_from_walls<2>(s.walls(), c.dx, Bounds<2>(Vec2d(-1, -1), Vec2d(1, 1)));
  const Real dx = static_cast<Real>(c.dx);
  double err = 0, wall_rows = 0, closed = 0;
  int projected = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    Vec2 ref = brute_bi_sum(P, i, el, s.kernel(), dx);
    // Within dx of the nearest face of the box, no shift towards it (normal into the fluid).
    const Vec2 x = P.x[i];
    const std::array<std::pair<Real, Vec2>, 4> faces{{{x.x(), Vec2(1, 0)},
                                                      {Real(0.1) - x.x(), Vec2(-1, 0)},
                                                      {x.y(), Vec2(0, 1)},
                                                      {Real(0.08) - x.y(), Vec2(0, -1)}}};
    const auto& nearest = *std::min_element(faces.begin(), faces.end(),
                                            [](auto& a, auto& b) { return a.first < b.first; });
    if (nearest.first < dx && ref.dot(nearest.second) > 0) {
      ref -= ref.dot(nearest.second) * nearest.second;
      ++projected;
    }
    err = std::max(err, static_cast<double>((with.s[i] - ref).norm()));
    // Rows beside the floor and the side walls, clear of the free surface's open support.
    const bool near_wall = x.y() < 2 * c.dx || x.x() < 2 * c.dx || x.x() > 0.1 - 2 * c.dx;
    if (near_wall && x.y() < 0.048 - 2 * c.h()) {
      wall_rows = std::max(wall_rows, static_cast<double>(without.s[i].norm()));
      closed = std::max(closed, static_cast<double>(with.s[i].norm()));
    }
  }
  EXPECT_LT(err, 1e-9 * wall_rows);
  EXPECT_GT(projected, 0);
  // What is left is Sun et al.'s anti-clumping part of the first rows (no wall counterpart).
  EXPECT_LT(closed, 0.15 * wall_rows);
}

}  // namespace
}  // namespace curvsph
