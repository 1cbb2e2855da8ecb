#pragma once
// Particle packing for boundary integrals (`setup: {relax: {map: integrals}}`): moves the
// initial particles until the discrete BI identity holds at every particle,
//   R_i = sum_j V_j grad_i W_ij - sum_b W_ib n_b A_b = 0,
// i.e. until the particles are an equilibrium of the BI pressure operator for a uniform
// pressure (the elements as in integrals_boundary.cpp, n_b into the fluid, W_ib the kernel
// averaged over the element by element_quadrature.hpp, without which the descent stalls at
// the corners: a midpoint-rule wall sum is not a gradient there).
//
// Why: in the continuum sum_b W n A is grad gamma (gamma = int_Omega W, Calderon eq. 3, by
// the divergence theorem) and sum_j V_j grad W_ij is grad S_i, S_i = sum_j V_j W_ij, so R_i =
// grad (S - gamma)_i. The symmetric BI momentum equation contains 2 p_i R_i / (gamma_i
// rho_i) (integrals_boundary.cpp, items 2 and 2b): a Cartesian lattice leaves R_i of a few %
// of sum_b W n A on the first rows at h/dx = 2 (measured: -1.76 g on the first floor row of
// the 0.5 m hydrostatic tank), and the particles start away from the scheme's own equilibrium
// and ring. The packing is the BI analogue of setup/relax.hpp's ghost-map relaxation (same
// damped first-order flow, dx_i = -alpha h^2 R_i, capped at max_shift dx): particles move
// down grad (S - gamma), towards where the fluid sum falls short of the geometric fill.
//
// The elements close the region the particles were generated in (a box fluid region: its
// faces, walls and free faces alike), so that free-surface particles are packed against a
// temporary lid rather than spreading out. Stops when max_i h |R_i| < tolerance or after
// max_steps steps; RelaxResult's spread fields hold max_i h |R_i| (dimensionless).
#include <vector>

#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/boundary/integrals/element_quadrature.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/setup/relax.hpp"

namespace curvsph {

struct IntegralsRelaxOptions {
  long max_steps = 2000;
  double tolerance = 1e-3;      // on max_i h |R_i|
  double dx = 0;                // particle spacing; V_j = dx^D
  double alpha = 0.25;          // step factor of dx_i = -alpha h^2 R_i (as relax.hpp)
  double max_shift = 0.2;       // largest move per step, in dx
  double wall_clearance = 0.1;  // smallest distance to the closure after a step, in dx
};

// max_i h |R_i| and R_i at the current positions (cells must be built over x; elem_cells over
// the element centres with radius 2h + the largest element radius).
template <int D>
double integrals_residual(const std::vector<Vec<D>>& x, const CellList<D>& cells,
                          const std::vector<Vec<D>>& ex, const std::vector<Vec<D>>& en,
                          const std::vector<Real>& ea, const ElementQuadrature<D>& wq,
                          const CellList<D>& elem_cells, const WendlandC2<D>& W, Real volume,
                          std::vector<Vec<D>>& R);

// Relaxes x in place against the elements of `closure` (the walls bounding the particles'
// region, fluid side = where the particles are). `cells` must be configured (support 2h,
// domain periodicity); it is rebuilt over x.
template <int D>
RelaxResult relax_particles_integrals(std::vector<Vec<D>>& x, const Wall<D>& closure,
                                      CellList<D>& cells, const WendlandC2<D>& W,
                                      const IntegralsRelaxOptions& opt);

}  // namespace curvsph
