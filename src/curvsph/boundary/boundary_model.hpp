#pragma once
// A wall boundary treatment (DESIGN.md §1, §7): one strategy object per run, chosen by
// `boundary.method` through one registration line in boundary_registry.cpp. The solver calls
//   prepare()        after the drift, before the density pass (ghosts / Shepard factors),
//   add_density()       summation path: wall contributions to sigma,
//   add_density_rate()  continuity path: wall contributions to drho/dt,
//   add_accelerations() after the fluid pair pass, before body forces,
// so the fluid pair loops never branch on the boundary method. prepare() also reports
// particles that went through a wall (the solver stops with exit 3).
//
// Renormalising models (boundary integrals with a Shepard factor gamma_i): the fluid passes
// (density_summation, continuity_rate with its delta-SPH term, fluid_forces) sum over fluid
// neighbours only and never divide by gamma. Such a model divides what is accumulated when
// its hook runs by gamma_i itself: add_density() sigma_i (and rho_i = m_i sigma_i),
// add_density_rate() drho_i, add_accelerations() a_i (pressure + viscous; body forces are
// added after the hook and are not renormalised), and then adds its wall terms, already
// divided by gamma_i. Additive models (ghosts) leave the fluid part as it is.
#include <memory>
#include <string>
#include <vector>

#include "curvsph/boundary/wall_images.hpp"
#include "curvsph/boundary/wall_loads.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/physics/fluid_terms.hpp"
#include "curvsph/physics/particle_shifting.hpp"

namespace curvsph {

template <int D>
struct BoundaryContext {
  const Case& spec;
  const WallSet<D>& walls;
  const WendlandC2<D>& kernel;
  const FluidParams<D>& fluid;
  const CellList<D>& cells;  // fluid cell list (configured with the domain's periodicity)
};

template <int D>
class BoundaryModel {
 public:
  virtual ~BoundaryModel() = default;
  virtual std::string name() const = 0;
  // Set-up checks on the initial particles (e.g. the ghost map has a root for every particle
  // the walls can see); throws InputError naming the wall.
  virtual void check_setup(const Particles<D>& /*P*/, const std::string& /*file*/) {}
  // Per step, at the new positions; t is the time of those positions (moving walls).
  virtual void prepare(const Particles<D>& P, Real t) = 0;
  virtual void add_density(Particles<D>& P) = 0;
  virtual void add_density_rate(Particles<D>& P) = 0;
  virtual void add_accelerations(Particles<D>& P) = 0;
  // Particle shifting (physics/particle_shifting.hpp): adds the walls' share to the fluid's
  // shift direction sums.s of particles [0, n), after shift_sums() and before apply_shift(),
  // so that a particle next to a wall sees a closed support (the fluid sum alone pushes it
  // into the wall). Called at the positions of the last prepare().
  virtual void add_shift_sums(const Particles<D>& P, Index n, Real dx,
                              ShiftScratch<D>& sums) const = 0;
  // Indices of fluid particles found on the wrong side of a wall by the last prepare().
  virtual const std::vector<Index>& penetrated() const = 0;
  // Appends to `out` the fluid particles closer than `reach` to a wall at the last prepare(),
  // the penetrated ones included (any order, possibly repeated): the candidates of the wall
  // contact (solver/stray_particles.hpp).
  virtual void within(Real reach, std::vector<Index>& out) const = 0;
  // Seconds, accumulated over every prepare(), spent computing the Shepard factor gamma (a part
  // of the pre-pass; 0 for models without one). Issue 7 names the geometric Shepard factor's
  // share of a step, and the rest of the pre-pass (the particle-element pair search) is paid
  // by every Shepard mode, gamma = 1 included.
  virtual double shepard_seconds() const { return 0; }
  // How far, in kernel supports, the model reads fluid particles around an owned particle:
  // the MPI halo must reach that far (issue 8). Ghosts of particles behind a convex wall can
  // lie closer to a particle than their source does; wall elements interpolate the wall
  // pressure from fluid within one support of the element, itself within one support.
  virtual Real halo_reach() const { return 1; }
  // Extra particles (ghosts, wall elements) for output; may be empty.
  // Wall images of the last prepare() for pair terms outside the model (surface tension).
  virtual WallImages<D> images() const { return {}; }
  virtual void append_output(std::vector<Vec<D>>& /*x*/, std::vector<int>& /*kind*/) const {}

  // Wall loads (forces.csv, wall_loads.hpp): with `sums` set (reset by the caller for the
  // particles that count and the current walls), the next add_accelerations() also adds to it
  // the reaction of every wall term it adds, per wall of the set; nullptr (the default): not
  // computed. The model's pass stays the one neighbour sweep.
  void track_loads(WallLoadSums<D>* sums) { loads_ = sums; }

 protected:
  WallLoadSums<D>* loads_ = nullptr;
};

// Builds the model named by case.boundary.method ("ghost", "integrals"); nullptr for "none".
template <int D>
std::unique_ptr<BoundaryModel<D>> make_boundary_model(const BoundaryContext<D>& ctx);

}  // namespace curvsph
