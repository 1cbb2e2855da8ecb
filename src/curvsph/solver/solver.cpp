#include "curvsph/solver/solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/boundary/ghost/ghost_map.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/core/stage_report.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/parallel/agree.hpp"
#include "curvsph/physics/artificial_viscosity.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/momentum.hpp"
#include "curvsph/physics/particle_shifting.hpp"
#include "curvsph/physics/surface_tension.hpp"
#include "curvsph/setup/generate.hpp"
#include "curvsph/setup/hydrostatic_start.hpp"
#include "curvsph/setup/relax_closure.hpp"
#include "curvsph/setup/relax_integrals.hpp"

namespace curvsph {
namespace {

struct Stopwatch {
  double& acc;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  ~Stopwatch() {
    acc += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
};

}  // namespace

template <int D>
Solver<D>::Solver(const Case& c) : case_(c), W_(static_cast<Real>(c.h())) {
  if (c.dimension != D) throw InputError(c.file_name(), "dimension", "solver dimension mismatch");
  if (c.root["walls"] && c.root["walls"].IsSequence())
    walls_ = parse_walls<D>(c.root["walls"], c.file_name(), c.file.parent_path());
  contact_angles_ = parse_contact_angles<D>(c.root["walls"], c.file_name(), c.file.parent_path());
  {
    StageReport report("particle fill");
    generate_particles<D>(c, P_, walls_);
    report.result(fmt::format("{} particles", P_.size()));
  }
  for (const auto& f : c.fluids) {
    F_.rho0.push_back(static_cast<Real>(f.rho0));
    F_.viscosity.push_back(static_cast<Real>(f.viscosity));
    nu_max_ = std::max(nu_max_, static_cast<Real>(f.viscosity / f.rho0));
  }
  F_.eos.type = c.eos.type == EosSpec::Type::tait ? Eos::Type::tait : Eos::Type::linear;
  F_.eos.c0 = static_cast<Real>(c.eos.c0);
  F_.eos.gamma = static_cast<Real>(c.eos.gamma);
  F_.eos.p0 = static_cast<Real>(c.eos.p0);
  F_.gravity = c.gravity.head<D>().template cast<Real>();
  F_.drive = c.drive;
  F_.drive_v0 = static_cast<Real>(c.drive_v0);
  F_.drive_tau = static_cast<Real>(c.drive_tau);
  continuity_ = c.density.method == DensitySpec::Method::continuity;
  F_.delta_sph = continuity_ ? static_cast<Real>(c.density.delta_sph) : 0;
  F_.diffusion = c.density.diffusion == DensitySpec::Diffusion::antuono
                     ? FluidParams<D>::Diffusion::antuono
                 : c.density.diffusion == DensitySpec::Diffusion::molteni
                     ? FluidParams<D>::Diffusion::molteni
                     : FluidParams<D>::Diffusion::fourtakas;
  for (int d = 0; d < D; ++d)
    if (F_.diffusion == FluidParams<D>::Diffusion::fourtakas && c.periodic[d] && F_.gravity[d] != 0)
      throw InputError(c.file_name(), "density.diffusion_term",
                       "fourtakas takes gravity as a hydrostatic load, but gravity has a "
                       "component along the periodic axis " +
                           std::to_string(d) +
                           " (a body force that drives a periodic flow: use antuono or molteni)");

  Vec3d lo = c.domain_min, hi = c.domain_max;
  for (int d = 0; d < D; ++d)
    if (c.periodic[d] && !c.has_domain)
      throw InputError(c.file_name(), "domain", "periodic axes need domain.min and domain.max");
  cells_.configure(W_.support, lo, hi, c.periodic);
  for (Index i = 0; i < static_cast<Index>(P_.size()); ++i) cells_.wrap(P_.x[i]);
  if (c.relax.enabled && c.relax.map == "integrals") {
    // BI packing (setup/relax_integrals.hpp) against the closure of the fluid region: its box
    // faces, walls and free faces alike.
    if (c.fluids.size() != 1 || c.fluids[0].region.kind != RegionSpec::Kind::box)
      throw InputError(c.file_name(), "setup.relax.map",
                       "integrals packing needs one fluid with a box region");
    const RegionSpec& reg = c.fluids[0].region;
    const BoxWall<D> closure(reg.min.head<D>(), reg.max.head<D>(), FluidSide::inside);
    IntegralsRelaxOptions ro;
    ro.max_steps = c.relax.max_steps;
    ro.tolerance = c.relax.tolerance;
    ro.dx = c.dx;
    relax_ = relax_particles_integrals<D>(P_.x, closure, cells_, W_, ro);
  } else if (c.relax.enabled) {
    RelaxOptions ro;
    ro.max_steps = c.relax.max_steps;
    ro.tolerance = c.relax.tolerance;
    ro.map = parse_ghost_map(c.relax.map.empty() ? c.boundary.map : c.relax.map, c.file_name(),
                             "setup.relax.map");
    ro.dx = c.dx;
    relax_ = relax_particles<D>(P_.x, relax_walls<D>(c, walls_), cells_, W_, ro);
    // The packed particles keep the lattice's count but fill the strip that generation left
    // clear of the walls, so masses of rho0 dx^D would start the fluid below rho0 (7.5 % in
    // a relaxed Couette annulus at dx = 1.875 mm: in tension, and its ghosts pull particles
    // through the wall within 0.25 s). Each particle's volume is instead taken from the
    // packed arrangement, V_i = 1/n_i with n_i = sum_j W_ij + sum_g beta_g W_ig (as
    // SPHinXsys does after its relaxation), so that the fluid starts at its reference density.
    const std::vector<Real> n = std::move(relax_->node_density);  // not kept for the run
    relax_->node_density = {};
    for (Index i = 0; i < static_cast<Index>(P_.size()); ++i) {
      P_.sigma[i] = n[i];
      P_.mass[i] = P_.rho[i] / P_.sigma[i];
    }
  }

  if (!c.initial_field.empty())
    apply_initial_field<D>(c, F_.eos, F_.rho0, P_);
  else if (c.hydrostatic_start)
    hydrostatic_start<D>(c, F_.eos, F_.rho0, P_);  // the free-surface default
  open_ = OpenBoundaries<D>(c, W_.support);
  if (open_.active()) open_.setup(P_, walls_);  // the buffer layers (solver/open_boundaries.hpp)
  {
    StageReport report("boundary set-up (" + c.boundary.method + ")");
    boundary_ = make_boundary_model<D>(BoundaryContext<D>{case_, walls_, W_, F_, cells_});
  }
  if (boundary_) boundary_->check_setup(P_, c.file_name());

  // [mpi] The halo reaches as far as any pass reads neighbours (kernel support, more where
  // the boundary model reads further). Surface tension's curvature reads its neighbours'
  // colour normals, each a sum over their own neighbours (and images): twice the reach, so
  // that a halo copy's normal is complete where an owned particle reads it.
  // The midpoint rule (a halo of h) serves the fluid pair passes only: the boundary models
  // and surface tension read every neighbour of an owned particle and need the owner rule.
  // Open boundaries extrapolate the fluid's state over the whole support of a buffer particle.
  const bool full_reach = boundary_ || !c.surface_tension.empty() || open_.active();
  if (c.halo_rule == Case::HaloRule::midpoint && full_reach)
    throw InputError(c.file_name(), "parallel.halo_rule",
                     "midpoint needs a case without walls, surface tension and open boundaries "
                     "(they read the whole 2h neighbourhood of an owned particle); use auto or "
                     "owner");
  DecompositionOptions dop;
  dop.midpoint = c.halo_rule == Case::HaloRule::midpoint ||
                 (c.halo_rule == Case::HaloRule::automatic && !full_reach);
  dop.halo_width = dop.midpoint ? W_.h
                                : W_.support * (boundary_ ? boundary_->halo_reach() : Real(1)) *
                                      (c.surface_tension.empty() ? Real(1) : Real(2));
  dop.rebalance_imbalance = c.rebalance_imbalance;
  dop.check_conservation = c.check_conservation;
  dop.domain_min = c.domain_min;
  dop.domain_max = c.domain_max;
  dop.periodic = c.periodic;
  decomp_.configure(dop);
  tv_.background_pressure = static_cast<Real>(c.transport_pb);
}

template <int D>
void Solver<D>::build_neighbors() {
  Stopwatch sw{times_.neighbors};
  cells_.build(P_.x);
}

template <int D>
void Solver<D>::resort() {
  // Re-sort every field by cell for memory locality. Done at the start of a step, on the
  // previous build, so no per-step scratch array has to follow the permutation.
  Stopwatch sw{times_.neighbors};
  // After load_state(): the order of the build the stopped run would have re-sorted by.
  const auto& s = restart_order_.empty() ? cells_.sorted() : restart_order_;
  order_.assign(s.begin(), s.end());
  restart_order_.clear();
  // [mpi] The build may have indexed halo copies, dropped since (indices >= size()).
  std::erase_if(order_, [n = P_.size()](std::size_t k) { return k >= n; });
  P_.permute(order_);
  if (tv_.b.size() == order_.size()) {  // b follows its particles to the next drift
    tv_acc_.resize(order_.size());
    for (std::size_t k = 0; k < order_.size(); ++k) tv_acc_[k] = tv_.b[order_[k]];
    tv_.b.swap(tv_acc_);
  }
}

// The continuity rate D(x^{n+1/2}, v^{n+1/2}) into P.drho: the particles, the cell list and
// the walls (with their images) are put back half a step, x^{n+1/2} = x^{n+1} - dt/2 v^{n+1/2}
// (exact: the drift moved them by dt v^{n+1/2}), and restored after. This is the midpoint
// rule, second order, the rates at the half-step state as in the symplectic scheme of
// DualSPHysics (Crespo et al. 2015, Comput. Phys. Commun. 187: 204-216). Taken at the end
// positions x^{n+1} with the half-step velocity, the rate was first order in the geometry,
// and in a curved flow the lag is a spurious radial velocity: v^{n+1/2} lies along the chord,
// tilted outwards from the tangent at x^{n+1} by Omega dt / 2, so u_r = v^2 dt / (2 r). The
// continuity equation read its divergence, (dt / r) d(v^2/2)/dr, as a density rate in the
// fluid, and where a wall's images reflect u_r, a jump of 2 u_r across the wall: in Barker's
// Couette at dx = 1.5 mm and dt = 2.4e-3 s, -0.78 % of rho0 per second in the ring next to
// the turning cylinder (tests/boundary/test_couette_continuity.cpp). The continuity density
// fell there, its low pressure drew the rings inwards, and the flow from rest left the
// analytic profile by 0.0075 omega R_i every 10 s (docs/validation/couette/findings.md, "The
// continuity density in Couette from rest"). Positions only: densities and velocities are the
// step's.
template <int D>
void Solver<D>::continuity_at_midpoint(Real dt) {
  const Real half = dt / 2;
  x_end_.assign(P_.x.begin(), P_.x.end());
  parallel_for(static_cast<Index>(P_.size()), [&](Index i) {
    P_.x[i] -= half * P_.v[i];
    cells_.wrap(P_.x[i]);
  });
  walls_.set_time(rates_time_ - static_cast<double>(half));
  build_neighbors();
  if (boundary_) boundary_->prepare(P_, t_);
  const PairRule<D> rule = decomp_.pair_rule(cells_);
  DensityDiffusion<D> diffusion{F_.delta_sph * W_.h * F_.eos.c0, nullptr,
                                F_.hydrostatic_density_gradient()};
  if (F_.delta_sph > 0 && F_.diffusion == FluidParams<D>::Diffusion::antuono) {
    renormalised_density_gradient(P_, cells_, W_, grad_rho_, pair_, rule);
    decomp_.update_halo(grad_rho_);  // [mpi] continuity_rate reads grad_rho_[j]
    diffusion.grad_rho = grad_rho_.data();
  }
  continuity_rate(P_, cells_, W_, diffusion, pair_, rule);
  if (boundary_) boundary_->add_density_rate(P_);
  P_.x.swap(x_end_);
  walls_.set_time(rates_time_);
  build_neighbors();
}

template <int D>
void Solver<D>::compute_rates(Real dt_rho) {
  if (continuity_ && dt_rho > 0) {
    Stopwatch sw{times_.density};
    continuity_at_midpoint(dt_rho);
  }
  if (boundary_) prepare_boundary();
  // [mpi] The fluid pair passes follow the decomposition's pair rule: owned particles only
  // (owner rule), or the pairs whose midpoint this rank owns, halo sums sent to their owners
  // (midpoint rule); halo copies' fields come from their owners (exchange_halo, refresh,
  // update_halo).
  const PairRule<D> rule = decomp_.pair_rule(cells_);
  {
    Stopwatch sw{times_.density};
    if (continuity_) {
      // rho^{n+1} = rho^n + dt D(x^{n+1}, v^{n+1/2}): the density is advanced like a position,
      // with the half-step velocity, so the scheme stays symplectic for acoustic modes (a
      // density rate lagging half a step amplifies sound waves every step).
      // P.drho from continuity_at_midpoint() above.
      if (dt_rho > 0)
        parallel_for(decomp_.owned(), [&](Index i) { P_.rho[i] += dt_rho * P_.drho[i]; });
    } else {
      density_summation(P_, cells_, W_, rule);
      if (boundary_) boundary_->add_density(P_);
    }
    // Buffer particles take their state from the fluid or the boundary condition, not from
    // their (truncated) sums; set before the clamp, which must not count them.
    if (open_.active())
      open_.buffer_state(P_, cells_, W_, F_.eos, F_.rho0, t_ + dt_rho, decomp_.owned());
    if (case_.density.clamp)
      stray_.density_clamped +=
          clamp_density(P_, decomp_.owned(), F_.rho0, static_cast<Real>(case_.density.clamp_lo),
                        static_cast<Real>(case_.density.clamp_hi));
    update_pressure(P_, F_);
    decomp_.refresh(P_);  // [mpi] halo density, sigma, pressure from their owners
    if (open_.active() && decomp_.active()) {
      // [mpi] Again on the refreshed halo (the fluid next to a buffer may be another rank's),
      // then the buffer's halo copies.
      open_.buffer_state(P_, cells_, W_, F_.eos, F_.rho0, t_ + dt_rho, decomp_.owned());
      decomp_.refresh(P_);
      decomp_.update_halo(P_.v);
    }
  }
  {
    Stopwatch sw{times_.forces};
    fluid_forces(P_, cells_, W_, F_, pair_, rule, case_.pressure_difference);
    if (tv_.enabled()) {
      tv_.du.resize(P_.size(), Vec<D>::Zero());
      decomp_.update_halo(tv_.du);  // [mpi] the pair pass reads du[j]
      add_transport_stress(P_, cells_, W_, tv_, tv_acc_, rule);
    }
    add_artificial_viscosity(P_, cells_, W_, Real(case_.artificial_alpha) * W_.h * F_.eos.c0,
                             F_.rho0, pair_, rule,
                             case_.artificial_approaching ? ArtificialViscosityForm::approaching
                                                          : ArtificialViscosityForm::all_pairs);
    if (!case_.surface_tension.empty()) {
      const SurfaceTensionWalls<D> st_walls{&walls_, &contact_angles_,
                                            boundary_ ? boundary_->images() : WallImages<D>{},
                                            kContactLayer * W_.h};
      for (const auto& st : case_.surface_tension)
        add_surface_tension(
            P_, cells_, W_,
            SurfaceTensionPair{st.fluid_a, st.fluid_b, static_cast<Real>(st.coefficient)},
            surface_scratch_, st_walls);
    }
  }
  if (boundary_) {
    Stopwatch sw{times_.boundary};
    const bool loads = rates_time_ >= loads_from_;
    if (loads) {
      load_sums_.reset(decomp_.owned(), walls_);
      boundary_->track_loads(&load_sums_);
    }
    boundary_->add_accelerations(P_);
    if (loads) {
      boundary_->track_loads(nullptr);
      loads_ = load_sums_.totals();
      std::vector<double> flat;  // [mpi] one collective for every wall's six numbers
      for (const WallLoad& l : loads_) {
        flat.insert(flat.end(), l.force.begin(), l.force.end());
        flat.insert(flat.end(), l.moment.begin(), l.moment.end());
      }
      if (decomp_.comm().size() > 1) decomp_.comm().sum(flat);
      for (std::size_t k = 0; k < loads_.size(); ++k)
        for (std::size_t a = 0; a < 3; ++a) {
          loads_[k].force[a] = flat[6 * k + a];
          loads_[k].moment[a] = flat[6 * k + 3 + a];
        }
      loads_time_ = rates_time_;
    }
  }
  Stopwatch sw{times_.forces};
  body_forces(P_, F_);
  if (open_.active()) open_.freeze(P_, decomp_.owned());  // buffers are not integrated
  if (tv_.enabled()) {
    // The background-pressure push for the next drift, at these positions (walls prepared).
    shift_sums(P_, cells_, W_, static_cast<Real>(case_.dx), tv_.sums, rule);
    const Index n = rule.computed(P_);
    if (boundary_) boundary_->add_shift_sums(P_, n, static_cast<Real>(case_.dx), tv_.sums);
    transport_acceleration(P_, n, tv_);
  }
}

template <int D>
void Solver<D>::prepare_boundary() {
  Stopwatch sw{times_.boundary};
  Stopwatch sw_prepass{times_.boundary_prepass};
  const double shepard0 = boundary_->shepard_seconds();
  boundary_->prepare(P_, t_);
  times_.shepard += boundary_->shepard_seconds() - shepard0;
  // Owned particles only: a halo copy that went through a wall is its owner's report.
  const auto owned_penetrated = [&] {
    std::vector<Index> out;
    for (const Index i : boundary_->penetrated())
      if (i < decomp_.owned()) out.push_back(i);
    return out;
  };
  std::vector<Index> through = owned_penetrated();
  const mpi::Comm& comm = decomp_.comm();
  const bool stop = case_.boundary.penetration_stop && !through.empty();
  const double contact = case_.boundary.contact * case_.dx;
  // [mpi] every rank redoes its pre-pass when any put a particle back.
  if (!stop && comm.max(static_cast<std::int64_t>(through.size())) > 0) {
    // The last resort of boundary.penetration: project (stray_particles.hpp): a particle that
    // crossed a wall within this step is put back, and the pre-pass redone on the corrected
    // positions (the cell list rebuilt: a particle may change cell). Halo copies of a moved
    // particle keep their position until the next exchange.
    const double depth = contact > 0 ? contact : kProjectDepth * case_.dx;
    for (const Index i : through) {
      if (project_out_of_walls(walls_, P_.x[i], P_.v[i], depth) == WallFix::projected)
        ++stray_.projected;
      cells_.wrap(P_.x[i]);
    }
    cells_.build(P_.x);
    boundary_->prepare(P_, t_);
    through = owned_penetrated();
  }
  std::optional<InstabilityError> err;
  if (!through.empty()) {
    const Index i = through.front();
    err.emplace(
        fmt::format("step {}, t = {:.6g}: particle {} went through a wall ({} particles did){}",
                    steps_, t_, P_.id[i], through.size(),
                    case_.boundary.penetration_stop
                        ? " (boundary.penetration: stop)"
                        : "; putting it back on the fluid side failed (a wall thinner than "
                          "0.25 dx, or walls that leave no fluid side there)"),
        steps_, static_cast<long>(P_.id[i]), InstabilityError::Kind::penetration,
        static_cast<long>(through.size()));
  }
  mpi::raise_first(comm, err);  // [mpi] every rank stops together
}

template <int D>
void Solver<D>::apply_contacts() {
  const double contact = case_.boundary.contact * case_.dx;
  if (!boundary_ || !(contact > 0)) return;
  Stopwatch sw{times_.boundary};
  // The candidates from the pre-pass of this step (the positions have not moved since, but
  // for shifting, which removes the shift towards a wall within dx of it); each is checked
  // exactly by project_out_of_walls.
  close_.clear();
  boundary_->within(static_cast<Real>(contact), close_);
  std::sort(close_.begin(), close_.end());
  close_.erase(std::unique(close_.begin(), close_.end()), close_.end());
  const Index owned = decomp_.owned();
  for (const Index i : close_) {
    if (i >= owned) break;
    const WallFix fix = project_out_of_walls(walls_, P_.x[i], P_.v[i], contact);
    if (fix == WallFix::none) continue;
    if (fix == WallFix::projected) ++stray_.projected;  // (shifted through: not expected)
    if (fix == WallFix::contact) {
      ++stray_.contacts;
      contacted_.insert(P_.id[i]);
    }
    cells_.wrap(P_.x[i]);
  }
}

template <int D>
void Solver<D>::remove_strays() {
  const Index n = static_cast<Index>(P_.size());
  keep_.clear();
  // The removed particles' count, ids and mass leave the conservation check's reference.
  std::int64_t ids = 0, ids2 = 0;
  double mass = 0;
  for (Index i = 0; i < n; ++i) {
    // Buffer particles lie outside the domain by design; open_boundaries deletes them.
    if (!removal_box_.outside(P_.x[i]) || !P_.x[i].allFinite() ||  // NaN: check_state's
        P_.buffer[i] != 0) {
      keep_.push_back(static_cast<std::size_t>(i));
      continue;
    }
    ids += P_.id[i];
    ids2 += P_.id[i] * P_.id[i];
    mass += static_cast<double>(P_.mass[i]);
  }
  const auto removed = static_cast<std::int64_t>(static_cast<std::size_t>(n) - keep_.size());
  decomp_.forget(removed, ids, ids2, mass);  // [mpi] collective with check_conservation
  if (removed == 0) return;
  P_.permute(keep_);
  if (tv_.b.size() == static_cast<std::size_t>(n)) {  // b follows its particles
    tv_acc_.resize(keep_.size());
    for (std::size_t j = 0; j < keep_.size(); ++j) tv_acc_[j] = tv_.b[keep_[j]];
    tv_.b.swap(tv_acc_);
  }
  stray_.removed += static_cast<long>(removed);
}

template <int D>
void Solver<D>::restart(Particles<D> state, double t) {
  P_ = std::move(state);
  for (Index i = 0; i < static_cast<Index>(P_.size()); ++i) cells_.wrap(P_.x[i]);
  t_ = t;
}

template <int D>
void Solver<D>::initialize() {
  walls_.set_time(t_);  // moving walls where they are at the start (a restart's time)
  // Every rank holds every particle before distribute(): the count and the removal box are
  // global.
  if (!restored_) {  // else load_state() set them from the initial particles
    initial_count_ = static_cast<std::int64_t>(P_.size());
    removal_box_ = removal_box<D>(case_.has_domain, case_.domain_min, case_.domain_max,
                                  case_.periodic, P_.x, walls_, case_.dx);
  }
  // New particles of the open boundaries are numbered above every id present.
  if (open_.active()) open_.number_from(P_);
  decomp_.distribute(P_);  // [mpi] keep this rank's sub-domain
  fluid_mass_initial_ = fluid_mass();
  build_neighbors();
  if (restored_ && !decomp_.active()) {
    // Every field as the stopped run left it, in its order: the next step goes on from there.
    check_state();
    return;
  }
  restart_order_.clear();  // [mpi] an order of every particle, not of this rank's
  resort();
  decomp_.exchange_halo(P_);  // [mpi]
  build_neighbors();
  if (tv_.enabled() && decomp_.active())
    throw InputError(case_.file_name(), "transport_velocity",
                     "not available with more than one MPI rank (its per-particle state does "
                     "not migrate yet)");
  const Index owned = decomp_.owned();
  std::vector<Real> rho_set;
  if (!continuity_) rho_set.assign(P_.rho.begin(), P_.rho.begin() + owned);
  rates_time_ = t_;
  compute_rates(0);
  if (!continuity_ && !restored_ && open_.has_outflow()) {
    // The outflow buffers at the fluid's own density level (solver/open_boundaries.hpp),
    // measured on this first sum; the rates again with them (the first clamp count kept).
    const auto& comm = decomp_.comm();
    const auto s = open_.density_level_sums(P_, rho_set, walls_, owned);
    const std::int64_t count = comm.sum(s.count);
    if (count > 0) {
      const double mean = static_cast<double>(comm.sum(s.sum)) / static_cast<double>(count);
      open_.set_density_level(static_cast<Real>(1 + mean / OpenBoundaries<D>::kLevelUnit));
      const auto clamped = stray_.density_clamped;
      compute_rates(0);
      stray_.density_clamped = clamped;
    }
  }
  if (!continuity_ && !restored_) {
    const auto& comm = decomp_.comm();
    double sum = 0;
    for (Index i = 0; i < owned; ++i) sum += static_cast<double>(P_.rho[i]) / rho_set[i];
    const double mean =
        comm.sum(sum) / std::max<double>(1, static_cast<double>(decomp_.global_count()));
    InitialDensityError e;
    std::int64_t above = 0;
    for (Index i = 0; i < owned; ++i) {
      const double q = static_cast<double>(P_.rho[i]) / rho_set[i];
      e.max = std::max(e.max, std::abs(q - 1));
      e.local = std::max(e.local, std::abs(q / mean - 1));
      above += std::abs(q / mean - 1) > 0.01 ? 1 : 0;
    }
    e.max = comm.max(e.max);
    e.local = comm.max(e.local);
    e.local_above_1pct = static_cast<long>(comm.sum(above));
    initial_density_error_ = e;
  }
  check_state();
}

template <int D>
std::size_t Solver<D>::bytes_held() const {
  auto held = [](const auto& v) {
    return v.capacity() * sizeof(typename std::decay_t<decltype(v)>::value_type);
  };
  return P_.bytes() + cells_.bytes() + pair_.bytes() + held(grad_rho_) + shift_.bytes() +
         tv_.bytes() + held(tv_acc_) + held(order_);
}

template <int D>
Real Solver<D>::stable_dt() const {
  const Index n = decomp_.owned();
  const Real vmax = std::sqrt(parallel_max(n, 0, [&](Index i) { return P_.v[i].squaredNorm(); }));
  const Real amax = std::sqrt(parallel_max(n, 0, [&](Index i) { return P_.a[i].squaredNorm(); }));
  const Real dt = dt_limits(vmax, amax).min();
  return static_cast<Real>(decomp_.comm().min(static_cast<double>(dt)));  // [mpi]
}

template <int D>
typename Solver<D>::DtLimits Solver<D>::dt_limits(Real vmax, Real amax) const {
  const Real h = W_.h;
  const Real inf = std::numeric_limits<Real>::infinity();
  DtLimits l;
  l.acoustic = static_cast<Real>(case_.cfl) * h / (F_.eos.c0 + vmax);  // acoustic CFL
  l.force = amax > 0 ? Real(0.25) * std::sqrt(h / amax) : inf;         // Monaghan 1992
  l.viscous = nu_max_ > 0 ? Real(0.125) * h * h / nu_max_ : inf;       // Morris 1997
  l.set = case_.dt_max > 0 ? static_cast<Real>(case_.dt_max) : inf;    // time.dt_max
  return l;
}

template <int D>
void Solver<D>::check_dt(Real stable, Real dt) const {
  const double floor = 1e-12 * case_.t_end;
  if (stable >= floor && t_ + static_cast<double>(dt) != t_) return;
  // [mpi] dt is the minimum over the ranks, so every rank is here; each names its own
  // particle and raise_first keeps the lowest rank's.
  const Index n = decomp_.owned();
  if (n == 0) {  // a rank without particles has none to name
    mpi::raise_first(decomp_.comm(), std::optional<InstabilityError>());
    return;
  }
  Index iv = 0, ia = 0;
  for (Index i = 1; i < n; ++i) {
    if (!(P_.v[i].squaredNorm() <= P_.v[iv].squaredNorm())) iv = i;
    if (!(P_.a[i].squaredNorm() <= P_.a[ia].squaredNorm())) ia = i;
  }
  // Which limit of stable_dt() is the smallest: the acoustic one names the fastest particle,
  // the force one the most accelerated, the viscous one the fluid of the largest nu.
  const Real vmax = P_.v[iv].norm(), amax = P_.a[ia].norm();
  const DtLimits l = dt_limits(vmax, amax);
  const Real dt_cfl = l.acoustic, dt_force = l.force, dt_visc = l.viscous, dt_set = l.set;
  std::string limit;
  long id = -1;
  if (dt_set < std::min({dt_cfl, dt_force, dt_visc})) {
    limit = fmt::format("time.dt_max = {:.3g}", case_.dt_max);
  } else if (!(dt_visc < std::min(dt_cfl, dt_force))) {
    id = static_cast<long>(dt_force < dt_cfl ? P_.id[ia] : P_.id[iv]);
    limit = dt_force < dt_cfl
                ? fmt::format("particle {} with |a| = {:.3g} (force limit 0.25 sqrt(h / |a|))", id,
                              amax)
                : fmt::format("particle {} with |v| = {:.3g} (acoustic limit cfl h / (c0 + |v|))",
                              id, vmax);
  } else {
    std::size_t f = 0;
    for (std::size_t k = 0; k < F_.viscosity.size(); ++k)
      if (F_.viscosity[k] / F_.rho0[k] == nu_max_) f = k;
    limit = fmt::format(
        "the viscous limit 0.125 h^2 / nu of fluids.{} (nu = viscosity / rho0 = "
        "{:.3g})",
        f, nu_max_);
  }
  std::optional<InstabilityError> err;
  err.emplace(fmt::format("step {}, t = {:.6g}: time step collapsed: dt = {:.3g} {} (time.end "
                          "= {:.3g}); set by {}",
                          steps_, t_, static_cast<double>(dt),
                          stable >= floor ? "does not advance t" : "is below 1e-12 time.end",
                          case_.t_end, limit),
              steps_, id);
  mpi::raise_first(decomp_.comm(), err);
}

template <int D>
void Solver<D>::step(Real dt_cap) {
  decomp_.drop_halo(P_);  // [mpi] integrate owned particles only
  if (steps_ > 0 && steps_ % kResortEvery == 0) resort();
  restart_order_.clear();  // only a re-sort at the first step after load_state() reads it
  const Real stable = stable_dt();
  check_dt(stable, std::min(stable, dt_cap));
  stable_step_ = stable;
  dt_ = std::min(stable, dt_cap);
  const Real half = dt_ / 2;
  const Index n = static_cast<Index>(P_.size());
  {
    Stopwatch sw{times_.integrate};
    // Kick (v to the half step) and drift (x to the full step), with the transport velocity
    // v + dt/2 b where the case uses it (physics/transport_velocity.hpp).
    if (tv_.enabled()) {
      tv_.b.resize(P_.size(), Vec<D>::Zero());
      tv_.du.resize(P_.size());
      parallel_for(n, [&](Index i) { tv_.du[i] = half * tv_.b[i]; });
    }
    const Vec<D>* du = tv_.enabled() ? tv_.du.data() : nullptr;
    parallel_for(n, [&](Index i) {
      P_.v[i] += half * P_.a[i];
      P_.x[i] += dt_ * (du ? Vec<D>(P_.v[i] + du[i]) : P_.v[i]);
      cells_.wrap(P_.x[i]);
    });
  }
  if (open_.active()) {
    // Crossings of the open boundaries; what entered or left P_ moves the conservation
    // check's reference (as removed particles do).
    const auto ch = open_.after_drift(P_, dt_);
    for (Index i = 0; i < static_cast<Index>(P_.size()); ++i) cells_.wrap(P_.x[i]);
    decomp_.forget(ch.count, ch.ids, ch.ids2, ch.mass);
  }
  // Kick-drift-kick evaluates the rates at x^{n+1}: moving walls are placed at t^{n+1} before
  // the pre-pass, so ghosts, elements, wall velocities and the penetration check and contact
  // of this step all see the wall where the particles are.
  walls_.set_time(t_ + static_cast<double>(dt_));
  remove_strays();
  decomp_.migrate(P_);        // [mpi] to the new owners, re-bisecting when unbalanced
  decomp_.exchange_halo(P_);  // [mpi]
  build_neighbors();
  rates_time_ = t_ + dt_;
  compute_rates(dt_);
  {
    Stopwatch sw{times_.integrate};
    parallel_for(decomp_.owned(), [&](Index i) { P_.v[i] += half * P_.a[i]; });
  }
  if (case_.shifting > 0) {
    decomp_.update_halo(P_.v);  // [mpi] the kick above is right for owned particles only
    Stopwatch sw{times_.integrate};
    const Real dx = static_cast<Real>(case_.dx);
    const auto rule = decomp_.pair_rule(cells_);
    shift_sums(P_, cells_, W_, dx, shift_, rule);
    const Index n = rule.computed(P_);
    if (boundary_) boundary_->add_shift_sums(P_, n, dx, shift_);  // walls close the support
    if (open_.active()) open_.hold(P_, decomp_.owned());
    apply_shift(P_, n, cells_, W_, dx, static_cast<Real>(case_.shifting), shift_);
    if (open_.active()) open_.restore(P_);
  }
  apply_contacts();
  t_ += dt_;
  ++steps_;
  check_state();
}

template <int D>
void Solver<D>::check_state() const {
  const Index n = decomp_.owned();
  std::optional<InstabilityError> err;
  const bool range = !case_.density.clamp;  // density.clamp: false keeps the old stop
  for (Index i = 0; i < n; ++i) {
    const Real rho0 = F_.rho0[P_.phase[i]];
    const bool finite = P_.x[i].allFinite() && P_.v[i].allFinite() && std::isfinite(P_.rho[i]);
    if (!finite || (range && (P_.rho[i] < Real(0.5) * rho0 || P_.rho[i] > 2 * rho0))) {
      err.emplace(
          fmt::format("step {}, t = {:.6g}: particle {} has {} (rho = {:.6g}, rho0 = {:.6g}, "
                      "|v| = {:.6g})",
                      steps_, t_, P_.id[i], finite ? "density out of [0.5, 2] rho0" : "NaN/Inf",
                      P_.rho[i], rho0, P_.v[i].norm()),
          steps_, static_cast<long>(P_.id[i]));
      break;
    }
  }
  // More than time.max_removed_fraction removed: the domain is too small or the flow is lost.
  const auto& comm = decomp_.comm();
  const std::int64_t removed = comm.sum(static_cast<std::int64_t>(stray_.removed));
  if (!err && removed > 0 &&
      static_cast<double>(removed) >
          case_.max_removed_fraction * static_cast<double>(initial_count_))
    err.emplace(fmt::format("step {}, t = {:.6g}: {} of {} particles left the domain (more than "
                            "time.max_removed_fraction = {:g}); enlarge domain or check the walls",
                            steps_, t_, removed, initial_count_, case_.max_removed_fraction),
                steps_, -1);
  mpi::raise_first(comm, err);  // [mpi] every rank stops together
}

template <int D>
double Solver<D>::fluid_mass() const {
  double m = 0;
  for (Index i = 0; i < decomp_.owned(); ++i)
    if (P_.buffer[i] == 0) m += static_cast<double>(P_.mass[i]);
  return decomp_.comm().sum(m);
}

template class Solver<2>;
template class Solver<3>;

}  // namespace curvsph
