#pragma once
// Spatial domain decomposition of the particles over MPI ranks (issue 8).
//
// Ownership: orthogonal recursive bisection (ORB). The ranks are split in two halves, the
// current box is cut across its longest axis where the global particle count matches the
// halves' shares, and each half recurses. Every rank holds the whole (small) tree, so the
// owner of a position is a descent of log2(ranks) comparisons. Outer sides on non-periodic
// axes reach to infinity (a particle never leaves every sub-domain); periodic axes use the
// domain box, positions being wrapped into it.
//
// Layout: a rank's Particles hold its owned particles at [0, owned()) and, between
// exchange_halo() and drop_halo(), halo copies of other ranks' particles at [owned(), size()).
// The solver's neighbour passes compute owned particles only; halo copies are neighbours
// whose fields come from their owners: the state at exchange_halo(), density, sigma and
// pressure by refresh() after the density pass, any other array a later pass reads of its
// neighbours (the delta-SPH density gradient, ...) by update_halo(). The halo is dropped at
// the start of the next step. Halo copies keep their wrapped position; the local cell list
// applies the periodic image itself, as it does for a rank's own particles.
//
// Halo width, by the pair rule of the passes (parallel/pair_rule.hpp):
//   owner rule: a rank receives the particles within halo_width of the bounding box of its
//     owned particles (not of its ORB box, which may reach half a particle spacing, or on a
//     non-periodic outer side infinitely, beyond them): every particle within halo_width of
//     an owned particle, and no layer more. halo_width is the kernel support 2h (no Verlet
//     skin: the neighbour lists are rebuilt every step), widened where a pass reads
//     neighbours of neighbours (BoundaryModel::halo_reach, surface tension);
//   midpoint rule: the particles within halo_width = h of the rank's ORB box, where the
//     midpoints of the pairs it computes lie; the passes' sums on halo copies go back to
//     their owners through sum() (the HaloSum of the pair rule).
//
// Every call is collective (all ranks call it in the same order). On one rank every call
// returns at once and the arrays are untouched: the serial solver is the same program.
#include <cstdint>
#include <limits>
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/parallel/communicator.hpp"
#include "curvsph/parallel/field_pack.hpp"
#include "curvsph/parallel/orb_tree.hpp"
#include "curvsph/parallel/pair_rule.hpp"

namespace curvsph {

struct DecompositionOptions {
  Real halo_width = 0;               // owner rule: >= the kernel support 2h; midpoint: h
  bool midpoint = false;             // the midpoint rule (parallel/pair_rule.hpp)
  double rebalance_imbalance = 0.1;  // re-bisect when max/mean owned count exceeds 1 + this
  bool check_conservation = false;   // count, mass and id sums checked after every migration
  Vec3d domain_min = Vec3d::Zero(), domain_max = Vec3d::Zero();
  std::array<bool, 3> periodic{false, false, false};
};

// Figures for metrics.json, summed or averaged over the run.
struct DecompositionStats {
  long migrations = 0, rebalances = 0;
  double imbalance_sum = 0, imbalance_max = 1;  // max owned / mean owned, per migration
  double halo_sum = 0, owned_sum = 0;           // local halo and owned counts, per exchange
  long conservation_checks = 0;
  std::int64_t count_error_max = 0, id_error_max = 0;
  double mass_rel_error_max = 0;
  double seconds = 0;  // time spent in the decomposition's own work (packing, search)
};

template <int D>
class Decomposition final : public HaloSum {
 public:
  void configure(const DecompositionOptions& o);
  bool active() const { return comm_.size() > 1; }
  bool midpoint() const { return active() && o_.midpoint; }
  // The pair rule of the neighbour passes: the midpoint rule (through this decomposition's
  // tree and halo) when configured on more than one rank, else the owner rule over the owned
  // particles. `cells`: the fluid cell list (minimal image, wrap).
  PairRule<D> pair_rule(const CellList<D>& cells);
  // Adds the halo copies' entries of a per-particle array to their owners' and zeroes them
  // (the reverse of update_halo; collective).
  void sum(Real* data, int per_particle) override;
  const mpi::Comm& comm() const { return comm_; }
  Index owned() const { return owned_; }

  // Start: every rank holds the same full particle set (generated deterministically);
  // bisects it and keeps its own share.
  void distribute(Particles<D>& P);
  // After the drift: particles that left the sub-domain go to their new owner; re-bisects
  // when the counts drift apart by more than rebalance_imbalance.
  void migrate(Particles<D>& P);
  // Appends halo copies (positions, velocities, masses, densities, pressures, sigma, phase,
  // id) of other ranks' particles within halo_width of this rank's owned particles' box.
  void exchange_halo(Particles<D>& P);
  // Density, sigma and pressure of the halo copies from their owners (after the density pass).
  void refresh(Particles<D>& P) { update_halo(P.rho, P.sigma, P.p); }
  // Any per-particle arrays laid out like the particles (owned then halo): halo entries from
  // their owners.
  template <class... T>
  void update_halo(std::vector<T>&... f);
  // Particles this rank removed from the run (solver/stray_particles.hpp: count, sums of ids
  // and squared ids, mass) leave the conservation check's reference with them. Collective
  // when check_conservation is on: every rank calls it at the same point of every step.
  void forget(std::int64_t count, std::int64_t ids, std::int64_t ids2, double mass);
  // Removes the halo copies (start of a step; before integrating owned particles only).
  void drop_halo(Particles<D>& P);
  // Owned particles of every rank on rank 0, sorted by id (output, probes, analyses);
  // empty on the other ranks.
  Particles<D> gather(const Particles<D>& P) const;

  // Global number of particles (owned, all ranks).
  std::int64_t global_count() const { return comm_.sum(static_cast<std::int64_t>(owned_)); }
  const DecompositionStats& stats() const { return stats_; }
  // The rank owning position x.
  int owner(const Vec<D>& x) const;

 private:
  using Node = typename OrbTree<D>::Node;
  struct Box {
    Vec<D> lo, hi;
  };
  void bisect(const Particles<D>& P);
  void split(std::vector<int>& node_of, const Particles<D>& P, int node, Box region, Box own,
             int rank_lo, int rank_hi);
  void send_leavers(Particles<D>& P);
  void check_conservation(const Particles<D>& P);
  // Distance from x to box b (periodic: nearest image).
  Real distance_to(const Vec<D>& x, const Box& b) const;
  void gather_owned_bounds(const Particles<D>& P);

  mpi::Comm comm_ = mpi::Comm::world();
  DecompositionOptions o_;
  OrbTree<D> tree_;
  std::vector<Box> boxes_;         // per rank: the ORB ownership boxes
  std::vector<Box> owned_bounds_;  // per rank: bounding box of its owned particles (halo)
  Index owned_ = 0;
  // Halo bookkeeping: owned indices sent to each rank, and where each rank's copies start.
  std::vector<std::vector<Index>> send_;
  std::vector<Index> recv_begin_, recv_count_;
  // Message buffers, per rank, reused by every exchange (no per-step allocation).
  std::vector<std::vector<std::byte>> out_, in_;
  std::vector<std::vector<Index>> leave_;
  std::vector<std::size_t> keep_;
  std::vector<double> bounds_;
  std::vector<Real> sum_buffer_;  // sum(): a message, aligned for Real
  std::int64_t count0_ = 0, id0_ = 0, id2_0_ = 0;
  double mass0_ = 0;
  DecompositionStats stats_;
};

template <int D>
template <class... T>
void Decomposition<D>::update_halo(std::vector<T>&... f) {
  if (!active()) return;
  const auto P = static_cast<std::size_t>(comm_.size());
  constexpr std::size_t record = (sizeof(T) + ... + 0);
  for (std::size_t r = 0; r < P; ++r) {
    const auto& idx = send_[r];
    out_[r].resize(idx.size() * record);
    std::byte* at = out_[r].data();
    auto put = [&](const auto& data) {
      using V = typename std::decay_t<decltype(data)>::value_type;
      for (const Index i : idx) {
        std::memcpy(at, &data[static_cast<std::size_t>(i)], sizeof(V));
        at += sizeof(V);
      }
    };
    (put(f), ...);
    // The layout of the halo is fixed since exchange_halo(): what each rank sends is known.
    in_[r].resize(static_cast<std::size_t>(recv_count_[r]) * record);
  }
  comm_.exchange(out_, in_, /*sizes_known=*/true);
  for (std::size_t r = 0; r < P; ++r) {
    const auto k = static_cast<std::size_t>(recv_count_[r]);
    const std::byte* at = in_[r].data();
    auto get = [&](auto& data) {
      using V = typename std::decay_t<decltype(data)>::value_type;
      std::memcpy(static_cast<void*>(data.data() + recv_begin_[r]), at, k * sizeof(V));
      at += k * sizeof(V);
    };
    if (k) (get(f), ...);
  }
}

}  // namespace curvsph
