#pragma once
// One weakly-compressible SPH simulation: particles, neighbour search, the density and force
// passes and kick-drift-kick time integration (DESIGN.md §1). Output and analysis live in
// run.cpp; this class only advances the state.
#include <algorithm>
#include <limits>
#include <optional>
#include <unordered_set>
#include <vector>

#include "curvsph/boundary/boundary_model.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/parallel/decomposition.hpp"
#include "curvsph/physics/fluid_terms.hpp"
#include "curvsph/physics/pair_factors.hpp"
#include "curvsph/physics/particle_shifting.hpp"
#include "curvsph/physics/surface_tension.hpp"
#include "curvsph/physics/transport_velocity.hpp"
#include "curvsph/setup/relax.hpp"
#include "curvsph/solver/open_boundaries.hpp"
#include "curvsph/solver/stray_particles.hpp"

namespace curvsph {

struct RestartState;  // solver/restart_state.hpp

// Seconds spent per phase (DESIGN.md §6: measure, then optimise).
struct PhaseTimes {
  double neighbors = 0, boundary = 0, density = 0, forces = 0, integrate = 0, output = 0;
  // The boundary pre-pass (BoundaryModel::prepare: ghost generation, or the Shepard factor
  // gamma of boundary integrals); a part of `boundary`, reported on its own because the
  // performance targets name it.
  double boundary_prepass = 0;
  // The part of boundary_prepass that computes the Shepard factor gamma (boundary integrals).
  double shepard = 0;
};

template <int D>
class Solver {
 public:
  explicit Solver(const Case& c);

  // Replaces the initial particles and time by a saved state (a snapshot of an earlier run of
  // the same case: positions, velocities, masses, densities); call before initialize().
  void restart(Particles<D> state, double t);
  // The whole state for `run --restart` (solver/solver_restart.cpp): save_state() after a
  // step; load_state() before initialize(), which then keeps the loaded state as it is (no
  // re-sort, no rate pass) so that the next step repeats the straight run's on one rank.
  // load_state throws InputError naming `file` on an inconsistent state.
  void save_state(RestartState& s) const;
  void load_state(const RestartState& s, const std::string& file);
  // Computes densities, pressures and accelerations of the initial state.
  void initialize();
  // Advances one time step of at most dt_cap (to land on output times); throws
  // InstabilityError when the state goes bad.
  void step(Real dt_cap = std::numeric_limits<Real>::infinity());

  double time() const { return t_; }
  Real dt() const { return dt_; }
  // The step the stability limits gave at the last step(), before the cap that lands on an
  // output time (what a progress line shows: the cut step looks like a collapse).
  Real stable_step() const { return stable_step_; }
  long steps() const { return steps_; }
  Particles<D>& particles() { return P_; }
  const Particles<D>& particles() const { return P_; }
  const CellList<D>& cells() const { return cells_; }
  const WendlandC2<D>& kernel() const { return W_; }
  const FluidParams<D>& fluid() const { return F_; }
  const Case& spec() const { return case_; }
  const WallSet<D>& walls() const { return walls_; }
  const BoundaryModel<D>* boundary() const { return boundary_.get(); }
  // Inflow and outflow buffers (case key open_boundaries; inactive without it).
  const OpenBoundaries<D>& open_boundaries() const { return open_; }
  // MPI domain decomposition: particles() holds the owned particles at [0, owned()) and,
  // after a step, halo copies behind them (parallel/decomposition.hpp).
  const Decomposition<D>& decomposition() const { return decomp_; }
  const PhaseTimes& phase_times() const { return times_; }
  PhaseTimes& phase_times() { return times_; }
  // The set-up relaxation (setup.relax), when the case asks for one.
  const std::optional<RelaxResult>& relax_result() const { return relax_; }
  // Summation density only: how far the first density sum (fluid and wall images) lands from
  // the density the set-up gave each particle (rho0, or an initial field), over all ranks:
  // the largest |rho/rho_set - 1|, and the largest deviation of rho/rho_set from its mean over
  // the fluid (`local`; a uniform offset is the kernel's lattice sum or the choice of masses,
  // a local one is a wall treatment's volume error, Barker Fig. 1, or a gap in the
  // arrangement), with the number of particles whose local deviation is above 1 %.
  struct InitialDensityError {
    double max = 0;
    double local = 0;
    long local_above_1pct = 0;
  };
  const std::optional<InitialDensityError>& initial_density_error() const {
    return initial_density_error_;
  }

  // Stray-particle counters (solver/stray_particles.hpp), this rank's: density clamp events,
  // particles put back from past a wall, particles removed (left the removal box), wall
  // contacts (particles stopped at boundary.contact from a wall); and the
  // particle count after set-up, over all ranks.
  struct StrayCounts {
    long density_clamped = 0, projected = 0, removed = 0, contacts = 0;
  };
  const StrayCounts& stray_counts() const { return stray_; }
  std::int64_t initial_count() const { return initial_count_; }
  // The mass of the fluid particles (buffer particles of open boundaries not counted), over
  // all ranks (collective), now and after set-up.
  double fluid_mass() const;
  double fluid_mass_initial() const { return fluid_mass_initial_; }
  // Distinct particles (ids) this rank stopped at the contact distance at least once: a
  // particle resting on the contact layer is stopped again at every step (contacts counts
  // those events).
  std::size_t contact_particles() const { return contacted_.size(); }

  // Wall loads (forces.csv, boundary/wall_loads.hpp): the force and moment the fluid exerts
  // on each wall of walls(), summed over the ranks, computed in the wall pass of every step
  // whose new positions are at a time >= t (and by initialize() when its time is). Off (the
  // default) until asked for; collective under MPI, so every rank must ask alike.
  void want_wall_loads_from(double t) { loads_from_ = t; }
  const std::vector<WallLoad>& wall_loads() const { return loads_; }
  // The time of wall_loads() (NaN before any was computed).
  double wall_loads_time() const { return loads_time_; }

  // Bytes held by the particle fields, the fluid cell list and the solver's own per-particle
  // scratch (boundary models not included: they do not expose theirs).
  std::size_t bytes_held() const;

  // The time step the CFL, viscous and force limits allow for the current state.
  Real stable_dt() const;
  // The limits stable_dt() takes the smallest of, for given largest |v| and |a|: acoustic CFL,
  // force (Monaghan 1992), viscous (Morris 1997) and time.dt_max (inf where inactive).
  struct DtLimits {
    Real acoustic, force, viscous, set;
    Real min() const { return std::min({acoustic, force, viscous, set}); }
  };
  DtLimits dt_limits(Real vmax, Real amax) const;
  // Throws InstabilityError "time step collapsed" when the step dt (stable_dt() capped by the
  // caller) does not advance t, or stable_dt() is below 1e-12 time.end (a run of more than
  // 10^12 steps: rho0 = 1e-300 or a velocity of 1e200 gave dt = 0 for ever), naming the
  // particle whose |v| or |a| sets it.
  void check_dt(Real stable, Real dt) const;
  // Throws InstabilityError on NaN, on density outside [0.5, 2] rho0 when density.clamp is
  // off, and when more than time.max_removed_fraction of the particles were removed (on every
  // rank when any rank finds such a particle).
  void check_state() const;

 private:
  void build_neighbors();
  void resort();
  // Boundary pre-pass, density (summation; or continuity advanced by dt_rho), pressure and
  // accelerations at the current positions.
  void compute_rates(Real dt_rho);
  // The continuity equation's rate at the step's midpoint positions into P.drho (solver.cpp).
  void continuity_at_midpoint(Real dt);
  // Boundary pre-pass; particles past a wall are put back (or the run stops, with
  // boundary.penetration: stop) and the pre-pass is redone on the corrected positions.
  void prepare_boundary();
  // The wall contact (solver/stray_particles.hpp), at the end of a step: particles the last
  // pre-pass found closer than boundary.contact to a wall are stopped at that distance. Done
  // there rather than before the density pass so that the pre-pass runs once per step.
  void apply_contacts();
  // Removes particles outside the removal box (after the drift, before migration).
  void remove_strays();

  Case case_;
  WallSet<D> walls_;
  std::vector<std::optional<Real>> contact_angles_;  // per wall (physics/contact_angle.hpp)
  Particles<D> P_;
  CellList<D> cells_;
  WendlandC2<D> W_;
  FluidParams<D> F_;
  std::unique_ptr<BoundaryModel<D>> boundary_;
  OpenBoundaries<D> open_;
  Decomposition<D> decomp_;
  bool continuity_ = false;
  std::vector<Vec<D>> grad_rho_;
  std::vector<Vec<D>> x_end_;  // continuity_at_midpoint(): the end positions, kept
  PairFactors<D> pair_;        // per-particle factors of the pair sums, reused every step
  SurfaceTensionScratch<D> surface_scratch_;
  ShiftScratch<D> shift_;
  TransportVelocity<D> tv_;     // transport_velocity (off unless the case sets it)
  std::vector<Vec<D>> tv_acc_;  // scratch of its momentum term
  std::vector<std::size_t> order_;
  bool restored_ = false;             // load_state() ran
  std::vector<Index> restart_order_;  // the order the first resort() after it applies
  // The time is accumulated in double even in the float build: in float, t + dt stops
  // advancing once dt falls below half an ulp of t (3e-8 at t = 0.35), and a step capped to
  // land on an output time then never gets there.
  double t_ = 0;
  Real dt_ = 0;
  Real stable_step_ = 0;
  long steps_ = 0;
  Real nu_max_ = 0;
  PhaseTimes times_;
  std::optional<RelaxResult> relax_;
  std::optional<InitialDensityError> initial_density_error_;
  StrayCounts stray_;
  std::int64_t initial_count_ = 0;
  double fluid_mass_initial_ = 0;
  RemovalBox<D> removal_box_;
  std::vector<std::size_t> keep_;  // remove_strays() scratch
  std::vector<Index> close_;       // prepare_boundary() scratch
  std::unordered_set<std::int64_t> contacted_;
  double loads_from_ = std::numeric_limits<double>::infinity();
  double rates_time_ = 0;  // the time of the positions compute_rates() works on
  WallLoadSums<D> load_sums_;
  std::vector<WallLoad> loads_;
  double loads_time_ = std::numeric_limits<double>::quiet_NaN();
  static constexpr long kResortEvery = 20;
};

}  // namespace curvsph
