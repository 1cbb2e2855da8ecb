#pragma once
// Open boundaries: inflow and outflow planes with buffer layers (case key `open_boundaries`,
// io/open_boundary_spec.hpp). The method is the buffer-layer one of Tafuni, Domínguez,
// Vacondio & Crespo (2018, Comput. Methods Appl. Mech. Engrg. 342, 604-624) and Negi,
// Ramachandran & Haftu (2020, Comput. Methods Appl. Mech. Engrg.; arXiv:1907.04034, whose
// "do-nothing" outlet is the outflow buffer below), and of SPHinXsys' emitter buffers:
//
// - Behind each boundary (signed distance d = (x - point).n < 0, n into the fluid) lies a
//   buffer of layers = ceil(2h/dx) lattice layers (thickness L >= the kernel support), so the
//   support of a fluid particle at the boundary is full. Buffer particles are neighbours of
//   the fluid in every pair sum but are not integrated as fluid: their state is prescribed.
// - Inflow buffer: velocity prescribed (uniform or parabolic, ramped over `ramp` seconds),
//   moving along the normal; density (hence pressure) extrapolated from the fluid at zeroth
//   order, a Shepard average over the fluid around the mirror point x - 2 d n (Tafuni et al.
//   §3.2 extrapolate at that point to first order; the zeroth order is their "do nothing"
//   pressure), so that the deepest layer, which has no fluid neighbours, takes the fluid's
//   level too.
//   A buffer particle that crosses the boundary (d >= 0) becomes fluid, and a copy of it
//   enters the buffer at its back, x - L n (the buffer is periodic along the normal).
// - Outflow buffer: a fluid particle that crosses the boundary (d < 0) becomes a buffer
//   particle; its density is the one the fluid's density sum gives at rest at the prescribed
//   pressure (see density_level below), its velocity the Shepard average of the fluid around
//   its mirror point x - 2 d n (Tafuni et al. 2018 §3.2 extrapolate at that point; kept once
//   the fluid there is gone); it is deleted when it leaves the buffer's back (d < -L). One that
//   drifts back (d >= 0) becomes fluid again and is taken off the outflow count, and a copy
//   of it enters at the buffer's back, x - L n, as at an inflow, unless a particle of the
//   buffer lies within dx/2 of that place (the buffer is bidirectional: under a backflow it
//   stays full, under jitter across the boundary it does not overfill; SPHinXsys'
//   bidirectional buffers follow the same idea). The copy's id is id + K as at an inflow
//   (number_from); a particle that returns twice while its first copy is still in the buffer
//   repeats that id.
// - Density level (density.method summation). The density sum of a particle arrangement at
//   rest is not its set-up density: on a square lattice with h = 1.3 dx the Wendland C2 sum
//   sum_j W(|x_i - x_j|) dx^2 is 1.0105 (the discrete kernel sum departs from its integral,
//   1; Quinlan, Basa & Lastiwka 2006, Int. J. Numer. Meth. Engng 66, 2064), so fluid at rest
//   stands at rho = 1.0105 rho0 and p = p0 + 0.0105 rho0 c0^2 (to first order). An outflow
//   buffer at the equation-of-state density of its pressure, rho0 for p0, is then a pressure
//   step of -0.0105 rho0 c0^2, which (linear acoustics, u = dp / (rho0 c0)) drains the
//   channel at u = 0.0105 c0: 0.16 m/s at c0 = 15 (measured 0.15-0.18 at the outlet of the
//   Schäfer-Turek channel at t = 0.01 s), against a mean inflow of 1 m/s ramped over 1 s. The
//   buffer is therefore set at kappa rho(p_set), kappa the fluid's own level: the mean of rho_sum /
//   rho_set over the fluid particles at least one support from every wall at the first density sum
//   (1 with the continuity equation).
// - A fluid particle that flows back behind an inflow (d < 0 within the inflow's cross
//   section) is deleted and counted as outflow.
//
// The counts and masses that crossed (particles_inflow / particles_outflow, mass_inflow /
// mass_outflow in metrics.json) balance the fluid's mass exactly: mass in - mass out = change
// of the mass of the fluid particles (buffer == 0).
#include <cstdint>
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/physics/eos.hpp"

namespace curvsph {

template <int D>
class OpenBoundaries {
 public:
  OpenBoundaries() = default;
  OpenBoundaries(const Case& c, Real support);
  bool active() const { return !specs_.empty(); }
  std::size_t size() const { return specs_.size(); }
  Real buffer_depth() const { return depth_; }

  // Set-up, on the generated particles (every rank holds them all): drops fill particles
  // behind a boundary within its cross section, refuses (InputError) a boundary with no fluid
  // in front of it, and fills each buffer with lattice layers of mass rho0 dx^D (fluid 0).
  void setup(Particles<D>& P, const WallSet<D>& walls);
  // Ids of created particles: the copy of a buffer particle that entered the fluid takes its
  // id plus K, K = 1 + the largest id of P (every rank holds every particle). Every id below K
  // is unique, each buffer particle is copied once, so b + n K is unique; and it depends on
  // no rank's numbering, so runs on any number of ranks name their particles alike.
  void number_from(const Particles<D>& P);

  // The inflow velocity of boundary k at x and time t (ramp included).
  Vec<D> inflow_velocity(std::size_t k, const Vec<D>& x, double t) const;

  // After the drift, on the owned particles (no halo): inflow buffer particles keep to the
  // normal, crossings change a particle's role, particles are created at the inflow buffers'
  // backs and deleted past the outflow buffers' backs. Returns what left and entered P as
  // (count, id sum, id square sum, mass), the net of deleted minus created (for the
  // conservation reference of the domain decomposition).
  struct Change {
    std::int64_t count = 0, ids = 0, ids2 = 0;
    double mass = 0;
  };
  Change after_drift(Particles<D>& P, Real dt);

  // The density level kappa (see the head of the file): over this rank's owned fluid
  // particles [0, owned) at least one support from every wall, rho_set the set-up densities of
  // [0, owned), the sum of rho / rho_set - 1 in units of 2^-32 and the count; integers, so
  // that the caller's sum over the ranks, and kappa, do not depend on the partition.
  struct LevelSums {
    std::int64_t sum = 0, count = 0;
  };
  static constexpr double kLevelUnit = 4294967296.0;  // 2^32
  LevelSums density_level_sums(const Particles<D>& P, const std::vector<Real>& rho_set,
                               const WallSet<D>& walls, Index owned) const;
  void set_density_level(Real kappa) { level_ = kappa; }
  Real density_level() const { return level_; }
  bool has_outflow() const;

  // After the equation of state (halo densities and pressures current): the state of the
  // owned buffer particles [0, owned) at time t (velocity, density, number density, pressure).
  void buffer_state(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                    const Eos& eos, const std::vector<Real>& rho0, double t, Index owned);
  // After the force passes: buffer particles are not integrated (no acceleration, no density
  // rate).
  void freeze(Particles<D>& P, Index owned) const;
  // Around particle shifting: the buffer particles' positions, velocities and densities are
  // kept (the buffer's back has a truncated support that shifting would spread).
  void hold(const Particles<D>& P, Index owned);
  void restore(Particles<D>& P) const;

  // This rank's counters: particles and mass that entered the fluid through the inflows and
  // left it through the outflows (or back through an inflow).
  std::int64_t inflow_count() const { return in_count_; }
  std::int64_t outflow_count() const { return out_count_; }
  double inflow_mass() const { return in_mass_; }
  double outflow_mass() const { return out_mass_; }

 private:
  struct Plane {
    Vec<D> point, normal;
    Vec<D> tangent[D - 1];  // orthonormal basis of the plane
  };
  Real distance(std::size_t k, const Vec<D>& x) const {
    return (x - planes_[k].point).dot(planes_[k].normal);
  }
  // Inside boundary k's cross section (the profile's support, and the lateral box).
  bool in_section(std::size_t k, const Vec<D>& x) const;
  // The profile shape at x (1 at the peak), without the ramp.
  Real profile(std::size_t k, const Vec<D>& x) const;

  std::vector<OpenBoundarySpec> specs_;
  std::vector<Plane> planes_;
  Real dx_ = 0, depth_ = 0;
  int layers_ = 0;
  Real rho0_ = 1;
  Real level_ = 1;  // kappa: the outflow buffers' density over rho(p_set)
  VecD<D> box_lo_ = VecD<D>::Zero(), box_hi_ = VecD<D>::Zero();  // lateral bound of sections
  bool has_box_ = false;
  std::string file_;
  std::int64_t id_stride_ = 0;
  std::int64_t in_count_ = 0, out_count_ = 0;
  double in_mass_ = 0, out_mass_ = 0;
  // Scratch.
  std::vector<std::size_t> keep_;
  std::vector<Index> spawn_;
  std::vector<std::size_t> returned_;  // returned from an outflow buffer this step
  std::vector<std::byte> bytes_;
  struct Held {
    Index i;
    Vec<D> x, v;
    Real rho;
  };
  std::vector<Held> held_;
};

}  // namespace curvsph
