#pragma once
// Test particle sets: a periodic unit box filled with a (jittered) cell-centred lattice.
#include <cmath>
#include <random>

#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph::test {

// A periodic unit box filled with a cell-centred lattice of n^D particles, optionally jittered
// by up to `jitter` dx per axis (fixed seed), unit-ish masses.
template <int D>
struct Lattice {
  int n;
  double dx;
  Particles<D> P;
  CellList<D> cells;
  WendlandC2<D> W;

  Lattice(int n_, double h_over_dx, double jitter, unsigned seed = 7)
      : n(n_), dx(1.0 / n_), W(h_over_dx / n_) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-jitter, jitter);
    long total = 1;
    for (int d = 0; d < D; ++d) total *= n;
    P.resize(total);
    for (long k = 0; k < total; ++k) {
      long rest = k;
      for (int d = 0; d < D; ++d) {
        P.x[k][d] = (static_cast<double>(rest % n) + 0.5 + U(rng)) * dx;
        rest /= n;
      }
      P.mass[k] = std::pow(dx, D);
      P.rho[k] = 1;
      P.id[k] = k;
    }
    cells.configure(W.support, Vec3d::Zero(), Vec3d::Ones(), {true, true, true});
    for (auto& x : P.x) cells.wrap(x);
    cells.build(P.x);
  }

  // A random flow state (seeded): velocities in [-1, 1]^D, pressures in [-100, 100], masses
  // scaled by [0.5, 1.5], densities in [0.9, 1.1] with sigma = rho / m, and, with
  // `two_phases`, a random phase 0 or 1 — for pair passes that must hold for any state.
  void randomize_state(unsigned seed, bool two_phases = false) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-1, 1);
    for (std::size_t i = 0; i < P.size(); ++i) {
      for (int d = 0; d < D; ++d) P.v[i][d] = U(rng);
      P.p[i] = 100 * U(rng);
      P.mass[i] *= 1 + 0.5 * U(rng);
      P.rho[i] = 1 + 0.1 * U(rng);
      P.sigma[i] = P.rho[i] / P.mass[i];
      if (two_phases) P.phase[i] = U(rng) > 0 ? 1 : 0;
    }
  }

  // Far enough from the box faces that no neighbour crosses the periodic seam.
  bool interior(Index i, double margin) const {
    for (int d = 0; d < D; ++d)
      if (P.x[i][d] < margin || P.x[i][d] > 1 - margin) return false;
    return true;
  }
};

}  // namespace curvsph::test
