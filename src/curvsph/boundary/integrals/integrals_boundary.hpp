#pragma once
// `boundary: {method: integrals, shepard: geometric | volume | monolithic | none}`: walls
// closed by boundary elements (numerical boundary integrals: Macià et al. 2012, Cercos-Pita
// 2015; Ferrand et al. 2013 for the semi-analytical variant) with the Shepard factor gamma of
// Calderon-Sanchez et al. The derivation of every wall term is in integrals_boundary.cpp.
//
// Optional keys: `boundary.wall_force: true` adds a short-range repulsion for particles closer
// than 0.1 dx to a wall (Calderon §3.2; off by default); `boundary.pressure: consistent |
// symmetric | tensile_control` chooses the near-wall pressure gradient (items 2b and 2d of the
// .cpp); `conservative | conservative_wall | conservative_pairs` pair the wall and fluid terms
// of the momentum with the continuity's for energy (item 9; conservative by default: the
// symmetric form gains energy at walls, docs/validation/cad_at_rest/integrals_findings.md).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "curvsph/boundary/boundary_model.hpp"
#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/boundary/integrals/element_quadrature.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/wall_force.hpp"

namespace curvsph {

template <int D>
class IntegralsBoundary final : public BoundaryModel<D> {
 public:
  explicit IntegralsBoundary(const BoundaryContext<D>& ctx);

  std::string name() const override { return "integrals"; }
  // Wall elements within a support of a particle interpolate their pressure from the fluid
  // within a support of themselves.
  Real halo_reach() const override { return 2; }
  void check_setup(const Particles<D>& P, const std::string& file) override;
  void prepare(const Particles<D>& P, Real t) override;
  void add_density(Particles<D>& P) override;
  void add_density_rate(Particles<D>& P) override;
  void add_accelerations(Particles<D>& P) override;
  void add_shift_sums(const Particles<D>& P, Index n, Real dx,
                      ShiftScratch<D>& sums) const override;
  const std::vector<Index>& penetrated() const override { return penetrated_; }
  void within(Real reach, std::vector<Index>& out) const override {
    for (Index i = 0; i < static_cast<Index>(near_.size()); ++i)
      if (near_[i] && wall_dist_[i] < reach) out.push_back(i);
  }
  double shepard_seconds() const override { return shepard_seconds_; }
  void append_output(std::vector<Vec<D>>& x, std::vector<int>& kind) const override;

  // The Shepard factor of every particle from the last prepare().
  const std::vector<Real>& gamma() const { return gamma_; }
  const BoundaryElements<D>& elements() const { return el_; }
  // Wall pressure of every element from the last add_accelerations().
  const std::vector<Real>& wall_pressure() const { return p_wall_; }

 private:
  // The geometric (monolithic) Shepard factor at x from its candidate elements (prepare()).
  Real element_gamma(const Vec<D>& x, std::span<const std::size_t> idx,
                     std::span<const Vec<D>> shift) const;
  // Wall time of the gamma computation in prepare(): thread-seconds over the team size.
  double shepard_seconds_ = 0;
  void build_elements(const Particles<D>& P);
  // Places the body-frame elements of moving walls at the walls' current time (and refreshes
  // centres, normals, velocities, the element cell list and the element quadratures).
  void place_elements();
  // Adds the reaction R of particle i's wall terms to the wall loads (the .cpp says how it
  // is shared between walls).
  void add_loads(Index i, const Vec<D>& R, const Vec<D>& xi, WallLoadSums<D>& loads) const;
  // The pair list of prepare() must belong to the particles passed to the wall passes.
  void check_prepared(const Particles<D>& P) const;
  // Calls f(b, r_ib = x_i - x_b (periodic image applied), r2) for the elements whose
  // centre is within the candidate radius 2h + (largest element radius) of x.
  template <class F>
  void for_each_element(const Vec<D>& x, F&& f) const {
    elem_cells_.for_each_neighbor(x, ex_, f);
  }

  const Case& spec_;
  const WallSet<D>& walls_;
  const WendlandC2<D>& W_;
  const FluidParams<D>& F_;
  const CellList<D>& fluid_cells_;
  ShepardMode mode_;
  ShepardQuadrature quad_;
  GeometricShepard<D> geometric_;  // element quadrature tabulated once (geometric mode)
  ElementQuadrature<D> wq_;        // Gauss points of the wall terms' W_ib
  WallForce wall_force_;           // range 0 (never active) unless boundary.wall_force
  WallForce layer_;                // the contact layer (wall_impact.hpp item 2), always on
  bool consistent_ = false;        // boundary.pressure: consistent
  bool tensile_ = false;           // boundary.pressure: tensile_control (consistent where p_i < 0)
  bool no_tension_ = false;        // boundary.wall_tension: false
  // boundary.pressure (item 9 of the .cpp): conservative_wall | conservative double the
  // continuity's wall term, conservative takes p_b from p_i; conservative_pairs gives each
  // fluid pair p_j / gamma_j.
  bool wall_pair_ = false;
  bool local_wall_ = false;  // conservative: p_b from p_i (item 9)
  bool fluid_pair_ = false;
  Real dx_ = 0;
  bool built_ = false;

  BoundaryElements<D> el_;             // in the world, at the walls' current time
  BoundaryElements<D> el_body_;        // as generated, in each wall's body frame
  std::vector<std::int32_t> wall_of_;  // the wall of every element
  bool geometry_moves_ = false;  // some wall's geometry moves: elements re-placed every prepare
  std::vector<Vec<D>> ex_, en_, eu_;  // element centre, normal (into the fluid), velocity
  std::vector<Real> ea_;              // element area (length in 2-D)
  CellList<D> elem_cells_;            // over element centres, radius 2h + max element radius

  std::vector<Real> gamma_;
  std::vector<Real> p_wall_;
  std::vector<Index> penetrated_;
  std::vector<unsigned char> near_;  // particle has elements within the candidate radius
  std::vector<Real> wall_dist_;      // distance to the nearest wall (near particles only)
  std::vector<Vec<D>> wall_normal_;

  // Particle-element pairs with W_ib != 0, found once per step in prepare() and reused by
  // add_density_rate() and add_accelerations() (the element search was done three times a
  // step before). They stay in the buffer of the thread that found them: particle i's pairs
  // are thread_pairs_[pair_thread_[i]][pair_local_[i] ..] (pair_count_[i] of them), in the
  // order the element cell list visits them, so every wall sum adds in the same order as a
  // fresh search would, for any schedule. (Gathering them into one array in particle order
  // cost a memory-bound copy of ~40 bytes a pair every step, 30 MB on the dam break at
  // dx = 0.018; without it the pre-pass takes 10 % less time on one thread.) All buffers
  // keep their capacity from step to step.
  struct Pair {
    Index b;   // element
    Vec<D> r;  // r_ib = x_i - x_b (periodic image applied)
    Real w;    // W(|r_ib|) > 0
  };
  std::span<const Pair> pairs_of(Index i) const {
    const std::vector<Pair>& buf = thread_pairs_[static_cast<std::size_t>(pair_thread_[i])];
    return {buf.data() + pair_local_[i], static_cast<std::size_t>(pair_count_[i])};
  }
  std::vector<Index> pair_count_;                // pairs of particle i
  std::vector<Index> pair_local_;                // first pair of i in its thread's buffer
  std::vector<int> pair_thread_;                 // the thread whose buffer holds i's pairs
  std::vector<std::vector<Pair>> thread_pairs_;  // pairs, in the buffer of the finding thread
  // Elements with a particle within 2h (plus round-off): the only ones whose wall pressure
  // has fluid to extrapolate from; the others keep p_b = 0 without a fluid search.
  std::vector<unsigned char> active_;
};

template <int D>
std::unique_ptr<BoundaryModel<D>> make_integrals_boundary(const BoundaryContext<D>& ctx);

}  // namespace curvsph
