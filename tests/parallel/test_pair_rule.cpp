// The midpoint rule of parallel/pair_rule.hpp, emulated without MPI: a periodic box cut into
// four ORB boxes, each "rank" holding its owned particles and the halo copies within h of its
// box. Over the ranks every pair within the support must be computed exactly once, by a rank
// that holds both particles; the density sums, each rank's owned part plus the halo copies'
// partial sums sent to their owners, must equal the brute-force sum. And the symmetric
// shifting pass against a brute-force gather of its three sums.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>
#include <vector>

#include "../support/lattice.hpp"
#include "../support/solver_refusal.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/parallel/pair_rule.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/particle_shifting.hpp"

namespace curvsph {
namespace {

// x < 0.5 | x >= 0.5, then y cut at 0.37 on the left and 0.61 on the right (ranks 0..3).
template <int D>
OrbTree<D> four_boxes() {
  using Node = typename OrbTree<D>::Node;
  OrbTree<D> t;
  t.nodes = {Node{0, 0.5, {1, 2}, -1}, Node{1, 0.37, {3, 4}, -1}, Node{1, 0.61, {5, 6}, -1},
             Node{0, 0, {-1, -1}, 0},  Node{0, 0, {-1, -1}, 1},   Node{0, 0, {-1, -1}, 2},
             Node{0, 0, {-1, -1}, 3}};
  return t;
}

// Distance from x to rank r's box of four_boxes() in the periodic unit box.
template <int D>
double distance_to_box(const Vec<D>& x, int r) {
  Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Ones();
  (r < 2 ? hi : lo)[0] = 0.5;
  const double cut = r < 2 ? 0.37 : 0.61;
  (r % 2 == 0 ? hi : lo)[1] = cut;
  double d2 = 0;
  for (int d = 0; d < D; ++d) {
    double g = 1e300;
    for (int s = -1; s <= 1; ++s) {
      const double v = x[d] + s;
      g = std::min(g, std::max({lo[d] - v, v - hi[d], 0.0}));
    }
    d2 += g * g;
  }
  return std::sqrt(d2);
}

// The halo copies' entries go to a per-id inbox (their owners' share), then are zeroed.
struct Inbox final : HaloSum {
  const std::vector<std::int64_t>* ids = nullptr;
  Index owned = 0;
  std::map<std::int64_t, Real>* inbox = nullptr;
  void sum(Real* data, int per_particle) override {
    ASSERT_EQ(per_particle, 1);
    for (std::size_t i = static_cast<std::size_t>(owned); i < ids->size(); ++i) {
      (*inbox)[(*ids)[i]] += data[i];
      data[i] = 0;
    }
  }
};

template <int D>
void midpoint_rule_partitions_the_pairs(int n_side) {
  test::Lattice<D> L(n_side, 1.3, 0.3, 11);
  L.randomize_state(5);
  const auto tree = four_boxes<D>();
  const Real h = L.W.h;
  std::map<std::pair<std::int64_t, std::int64_t>, int> computed;  // pair of ids -> ranks
  std::mutex mutex;
  std::map<std::int64_t, Real> sigma_owned, inbox;
  long halo_total = 0;
  for (int r = 0; r < 4; ++r) {
    // This rank's particles: owned first, then the copies within h of its box.
    std::vector<std::size_t> pick;
    for (std::size_t i = 0; i < L.P.size(); ++i)
      if (tree.owner(L.P.x[i]) == r) pick.push_back(i);
    const auto owned = static_cast<Index>(pick.size());
    for (std::size_t i = 0; i < L.P.size(); ++i)
      if (tree.owner(L.P.x[i]) != r && distance_to_box<D>(L.P.x[i], r) < h) pick.push_back(i);
    halo_total += static_cast<long>(pick.size()) - owned;
    Particles<D> Q = L.P;
    Q.permute(pick);
    CellList<D> cells;
    cells.configure_like(L.cells, L.W.support);
    cells.build(Q.x);
    Inbox box;
    box.ids = &Q.id;
    box.owned = owned;
    box.inbox = &inbox;
    PairRule<D> rule(owned);
    rule.tree = &tree;
    rule.cells = &cells;
    rule.halo = &box;
    rule.rank = r;
    const Index n = rule.computed(Q);
    cells.for_each_pair([&](Index i, Index j, const Vec<D>& rij, Real) {
      if (!rule.template computes<true>(Q, n, i, j, rij)) return;
      const auto key = std::minmax(Q.id[i], Q.id[j]);
      const std::lock_guard<std::mutex> lock(mutex);  // the pair loop runs on threads
      ++computed[{key.first, key.second}];
    });
    density_summation(Q, cells, L.W, rule);
    for (Index i = 0; i < owned; ++i) sigma_owned[Q.id[i]] = Q.sigma[i];
  }
  EXPECT_GT(halo_total, 0);
  // Every pair within the support, once; none outside it (brute force over all pairs).
  long pairs = 0;
  for (std::size_t i = 0; i < L.P.size(); ++i)
    for (std::size_t j = i + 1; j < L.P.size(); ++j) {
      if (L.cells.separation(L.P.x[i], L.P.x[j]).norm() >= L.W.support) continue;
      ++pairs;
      const auto it = computed.find({L.P.id[i], L.P.id[j]});
      ASSERT_NE(it, computed.end()) << "pair " << i << "," << j << " computed by no rank";
      EXPECT_EQ(it->second, 1) << "pair " << i << "," << j;
    }
  EXPECT_EQ(static_cast<long>(computed.size()), pairs);
  // sigma = W(0) + sum_j W_ij, brute force.
  double worst = 0;
  for (std::size_t i = 0; i < L.P.size(); ++i) {
    double s = 0;
    for (std::size_t j = 0; j < L.P.size(); ++j) {
      const double q = L.cells.separation(L.P.x[i], L.P.x[j]).norm();
      if (q < L.W.support) s += L.W.value(q);
    }
    const double got = sigma_owned.at(L.P.id[i]) + inbox[L.P.id[i]];
    worst = std::max(worst, std::abs(got - s) / s);
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(PairRule, MidpointComputesEachPairOnceAndSumsMatchBruteForce2D) {
  midpoint_rule_partitions_the_pairs<2>(28);
}
TEST(PairRule, MidpointComputesEachPairOnceAndSumsMatchBruteForce3D) {
  midpoint_rule_partitions_the_pairs<3>(12);
}

// The shifting pass's sums and its result against a gather over all pairs (Lind et al. 2012
// in the form of particle_shifting.hpp): shift, density and velocity corrections.
template <int D>
void shifting_matches_gather(int n_side, Real C) {
  test::Lattice<D> L(n_side, 1.3, 0.3, 3);
  L.randomize_state(9);
  const Real dx = static_cast<Real>(L.dx);
  const Real w_dx = L.W.value(dx), scale = C * 4 * L.W.h * L.W.h, cap = Real(0.1) * dx;
  Particles<D> ref = L.P;
  for (std::size_t i = 0; i < L.P.size(); ++i) {
    Vec<D> s = Vec<D>::Zero(), g = Vec<D>::Zero();
    Mat<D> G = Mat<D>::Zero();
    for (std::size_t j = 0; j < L.P.size(); ++j) {
      if (j == i) continue;
      const Vec<D> r = L.cells.separation(L.P.x[i], L.P.x[j]);
      const Real q = r.norm();
      if (q >= L.W.support) continue;
      const Vec<D> gradW = L.W.gradient_factor(q) * r;
      const Real Vj = L.P.mass[j] / L.P.rho[j];
      s += (1 + Real(0.2) * std::pow(L.W.value(q) / w_dx, 4)) * Vj * gradW;
      g += Vj * (L.P.rho[j] - L.P.rho[i]) * gradW;
      G += Vj * (L.P.v[j] - L.P.v[i]) * gradW.transpose();
    }
    Vec<D> d = -scale * s;
    if (d.norm() > cap) d *= cap / d.norm();
    ref.x[i] += d;
    L.cells.wrap(ref.x[i]);
    ref.rho[i] += g.dot(d);
    ref.v[i] += G * d;
  }
  Particles<D> Q = L.P;
  ShiftScratch<D> scratch;
  shift_particles(Q, L.cells, L.W, dx, C, scratch);
  double ex = 0, er = 0, ev = 0;
  long capped = 0;
  for (std::size_t i = 0; i < Q.size(); ++i) {
    ex = std::max(ex, static_cast<double>(L.cells.separation(Q.x[i], ref.x[i]).norm() / dx));
    er = std::max(er, static_cast<double>(std::abs(Q.rho[i] - ref.rho[i])));
    ev = std::max(ev, static_cast<double>((Q.v[i] - ref.v[i]).norm()));
    capped += L.cells.separation(ref.x[i], L.P.x[i]).norm() > cap * (1 - 1e-9);
  }
  EXPECT_LT(ex, 1e-13);
  EXPECT_LT(er, 1e-13);
  EXPECT_LT(ev, 1e-12);
  EXPECT_GT(capped, 0);  // both branches of the cap are exercised
  EXPECT_LT(capped, static_cast<long>(Q.size()));
  testing::Test::RecordProperty("capped",
                                std::to_string(capped) + " of " + std::to_string(Q.size()));
}

TEST(ParticleShifting, SymmetricPassMatchesGather2D) {
  shifting_matches_gather<2>(20, 0.5);
}
TEST(ParticleShifting, SymmetricPassMatchesGather3D) {
  shifting_matches_gather<3>(10, 0.05);
}

// parallel.halo_rule: auto, midpoint, owner; midpoint is refused where walls read the whole
// 2h neighbourhood of an owned particle (the check does not wait for a second rank).
TEST(PairRule, HaloRuleCaseKey) {
  const char* text = R"(
name: t
dimension: 2
resolution: {dx: 0.05, h_over_dx: 1.3}
domain: {min: [-1, -1], max: [1, 1]}
fluids:
  - {name: water, rho0: 1000, viscosity: 0.001, region: {box: {min: [-0.5, -0.5], max: [0.5, 0.5]}}}
eos: {type: linear, c0: 20}
time: {end: 0.01}
)";
  auto refusal = [](const YAML::Node& root) { return test::solver_refusal<2>(root); };
  YAML::Node r = YAML::Load(text);
  EXPECT_EQ(read_case(r, "case.yaml").halo_rule, Case::HaloRule::automatic);
  r["parallel"] = YAML::Load("{halo_rule: midpoint}");
  EXPECT_EQ(read_case(r, "case.yaml").halo_rule, Case::HaloRule::midpoint);
  EXPECT_EQ(refusal(r), "");
  r["parallel"] = YAML::Load("{halo_rule: nearest}");
  EXPECT_NE(refusal(r).find("parallel.halo_rule"), std::string::npos) << refusal(r);
  r["parallel"] = YAML::Load("{halo_rule: midpoint}");
  r["walls"] = YAML::Load("[{shape: circle, center: [0, 0], radius: 0.9, fluid: inside}]");
  r["boundary"] = YAML::Load("{method: ghost, map: mirror}");
  const std::string why = refusal(r);
  EXPECT_NE(why.find("parallel.halo_rule"), std::string::npos) << why;
  EXPECT_NE(why.find("walls"), std::string::npos) << why;
  r["parallel"] = YAML::Load("{halo_rule: owner}");
  EXPECT_EQ(refusal(r), "");
}

}  // namespace
}  // namespace curvsph
