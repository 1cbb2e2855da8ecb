#pragma once
// Which pairs of a symmetric pass (CellList::for_each_pair) a rank computes, and which of the
// pair's two particles it adds the terms to (issue 8). A rank's particles are its owned ones,
// [0, owned), then halo copies of other ranks' particles (parallel/decomposition.hpp).
//
//   owner rule (the default, and the only rule on one rank): every pair with an owned
//     particle; the terms go to owned particles only. A pair of owned particles on two ranks
//     is computed by both. The halo must hold every neighbour of an owned particle: width 2h.
//   midpoint rule: the pair whose midpoint lies in this rank's ORB box, whoever owns its
//     particles; the terms go to both, and after the pass the halo copies' partial sums are
//     added to their owners' (HaloSum). Every pair is computed once over all ranks, and both
//     particles of a pair lie within |x_i - x_j|/2 < h of its midpoint: the halo needs a
//     width of h only, which halves the halo (the midpoint method of Bowers, Dror & Shaw 2006,
//     J. Chem. Phys. 124, 184109).
//
// The midpoint must be the same bits on every rank that sees the pair, whichever order the
// cell list hands i and j in (halo copies carry their owner's position bits): (x_i + x_j)/2
// without a periodic image, else from the particle with the smaller id through the
// minimal-image separation.
#include <type_traits>
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/parallel/orb_tree.hpp"

namespace curvsph {

// Adds the halo copies' entries of a per-particle array (`per_particle` Reals each, owned
// then halo layout) to their owners' entries and zeroes them. Called once per pass.
class HaloSum {
 public:
  virtual ~HaloSum() = default;
  virtual void sum(Real* data, int per_particle) = 0;
};

template <int D>
struct PairRule {
  Index owned = -1;  // computed particles [0, owned); -1: every particle (one rank, tests)
  // The midpoint rule when set (more than one rank).
  const OrbTree<D>* tree = nullptr;
  const CellList<D>* cells = nullptr;  // the minimal image and the wrap of the midpoint
  HaloSum* halo = nullptr;
  int rank = 0;
  // Every pair of two owned particles has its midpoint in this rank's box: on each periodic
  // axis the box either spans the domain (a wrapped midpoint stays inside) or leaves at least
  // the kernel support to the other ranks (no owned pair reaches across the seam).
  bool owned_pairs_local = false;

  PairRule(Index owned_particles = -1) : owned(owned_particles) {}  // NOLINT: owner rule

  bool midpoint() const { return tree != nullptr; }
  // The particles whose sums the pass completes: [0, computed).
  Index computed(const Particles<D>& P) const { return computed_count(P, owned); }
  // The particles a pass accumulates into (and must zero first): the halo copies too under
  // the midpoint rule.
  Index touched(const Particles<D>& P) const {
    return tree ? static_cast<Index>(P.size()) : computed(P);
  }
  // Runs body(std::true_type) under the midpoint rule, body(std::false_type) under the owner
  // rule, so that a pass's pair loop is compiled once per rule and the owner rule's (every
  // one-rank run's) carries none of the midpoint's tests: they cost 10 % of the serial
  // instructions when tested at run time per pair.
  template <class F>
  void dispatch(F&& body) const {
    if (tree)
      body(std::true_type{});
    else
      body(std::false_type{});
  }

  template <bool Midpoint>
  static bool adds_to(Index k, Index n) {
    return Midpoint || k < n;
  }

  // Whether this rank computes the pair (i, j) with separation r = x_i - x_j (periodic image
  // applied); n = computed(P).
  template <bool Midpoint>
  bool computes(const Particles<D>& P, Index n, Index i, Index j, const Vec<D>& r) const {
    if constexpr (!Midpoint) {
      return i < n || j < n;
    } else {
      // Two owned particles without a periodic image between them: the midpoint lies in this
      // rank's box, which is convex (and between the two positions to the last bit). Where no
      // owned pair can reach across a periodic seam (owned_pairs_local), that holds for every
      // owned pair and the positions need not be read.
      if (i < n && j < n && (owned_pairs_local || P.x[i] - P.x[j] == r)) return true;
      const Vec<D>& xi = P.x[i];
      const Vec<D>& xj = P.x[j];
      // Without a periodic image (r = x_i - x_j exactly) the midpoint (x_i + x_j)/2 is the
      // same bits in either order; across a seam it is taken from the smaller id (rare).
      if (xi - xj == r) return tree->owner(Real(0.5) * (xi + xj)) == rank;
      const bool i_first = P.id[i] < P.id[j];
      const Vec<D>& a = i_first ? xi : xj;
      const Vec<D>& b = i_first ? xj : xi;
      Vec<D> m = a - Real(0.5) * cells->separation(a, b);
      cells->wrap(m);
      return tree->owner(m) == rank;
    }
  }

  // The halo copies' partial sums to their owners (midpoint rule; nothing otherwise).
  template <class T>
  void sum_halo(std::vector<T>& v) const {
    // Real, Vec<D>, Mat<D>: packed Reals (Eigen fixed-size types hold their coefficients only).
    static_assert(sizeof(T) % sizeof(Real) == 0);
    if (halo)
      halo->sum(reinterpret_cast<Real*>(v.data()), static_cast<int>(sizeof(T) / sizeof(Real)));
  }
};

// The rule parameter of the passes: a plain `owned` count converts to the owner rule, and D is
// deduced from the other arguments.
template <int D>
using PairRuleArg = std::type_identity_t<PairRule<D>>;

}  // namespace curvsph
