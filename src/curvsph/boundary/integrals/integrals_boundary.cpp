// Boundary integrals (BI) with a Shepard factor gamma: the wall terms of the momentum and
// continuity equations, consistent with the sigma-form fluid sums of physics/momentum.hpp and
// physics/density.hpp.
//
// Notation: r_ib = x_i - x_b, W_ib = (1/A_b) int_b W(|x_i - y|) dS_y (Gauss points on the
// element, element_quadrature.hpp; W at the centre leaves a curl at corners), n_b the unit
// element normal pointing INTO the
// fluid, A_b the element area (length in 2-D), V_j = m_j/rho_j = 1/sigma_j, grad_i W_ij =
// r_ij (1/r) dW/dr.
//
// 1. The BI gradient. For a field f and x inside the fluid domain Omega,
//      int_Omega grad f(y) W(x - y) dy = int_Omega f(y) grad_x W(x - y) dy
//                                       - int_dOmega f W n_in dS        (divergence theorem),
//    and int_Omega W = gamma(x), so the renormalised, discrete gradient is
//      <grad f>_i = (1/gamma_i) [ sum_j V_j f_j grad_i W_ij - sum_b f_b W_ib n_b A_b ].
//    For f = 1 the bracket is sum_j V_j grad_i W_ij - sum_b W_ib n_b A_b ~ 0 (both estimate
//    int_dOmega W n_in): the constant-field identity used below to symmetrise.
//
// 2. Pressure (sigma form). momentum.hpp uses grad p_i / sigma_i = grad(p/sigma)_i +
//    (p_i/sigma_i^2) grad sigma_i with the SPH sums of both gradients:
//      grad p_i / sigma_i ~ sum_j (p_j/sigma_j^2 + p_i/sigma_i^2) grad_i W_ij.
//    Taking both gradients with the BI operator of 1. (wall values (p/sigma)_b, sigma_b):
//      grad p_i / sigma_i = (1/gamma_i) [ sum_j (p_j/sigma_j^2 + p_i/sigma_i^2) grad_i W_ij
//                                       - sum_b (p_b/sigma_b + p_i sigma_b/sigma_i^2) W_ib n_b A_b
//                                       ]
//    and with the wall's number density taken as the particle's own, sigma_b = sigma_i:
//      grad p_i / sigma_i = (1/gamma_i) [ fluid sum - sum_b (p_b + p_i)/sigma_i W_ib n_b A_b ],
//    so, with rho_i = m_i sigma_i and a = -grad p / rho,
//      a_i = (1/gamma_i) a_i^fluid + (1/(gamma_i rho_i)) sum_b (p_b + p_i) W_ib n_b A_b.
//    Check (hydrostatics near a flat floor): the fluid sum ~ (1/sigma)[gamma grad p + sum_b
//    (p_b + p_i) W n A] (the (p_j - p_i) part gives gamma grad p plus a wall term, the 2 p_i
//    part gives 2 p_i sum_b W n A by the identity), the wall term removes the second piece and
//    1/gamma leaves grad p / sigma: exact for linear p whatever gamma is. With p_b + p_i > 0
//    the wall pushes the particle into the fluid (n_b points into it).
// 2b. That check assumes the discrete identity sum_j V_j grad_i W_ij = sum_b W_ib n_b A_b.
//    On a lattice at h/dx = 2 it holds only to a few % near a wall (first row: +2.7 %, second
//    -2.9 %, third -19 % of sum_b W n A), and the residual R_i multiplies 2 p_i: at the bottom
//    of a 0.5 m water column that is an acceleration of the order of g on the first rows
//    (measured at t = 0 on the N = 9800 lattice: -1.76 g, +0.60 g, +0.60 g on the floor's
//    first three rows, mean over rows of -0.88 g, +0.31 g, +0.31 g beside the side walls),
//    which rings the column acoustically (pressure errors ~ 5-10 % of rho0 g H, decaying
//    slowly under delta-SPH). With `boundary.pressure: consistent` the model subtracts p_i
//    times the residual,
//      bracket -= p_i [ sum_j (1/sigma_j^2 + 1/sigma_i^2) grad_i W_ij - (2/sigma_i) sum_b W n A ],
//    which leaves sum_j (p_j - p_i)/sigma_j^2 grad_i W_ij - sum_b (p_b - p_i)/sigma_i W n A:
//    exact for constant and linear p on any particle arrangement (zero- and first-order
//    consistent), at the price of momentum conservation between near-wall particles and of
//    the particle-regularising part of the symmetric form there. `symmetric` (the default)
//    keeps item 2 as it stands (conservative, as in AQUAgpusph). Measured on a 300-particle
//    tank (12 rows, h/dx = 2) to t sqrt(g/H) = 2.9: symmetric keeps KE/(MgH) below 7e-5 with
//    a pressure error falling from 0.08 to 0.024; consistent starts at 0.017 but its kinetic
//    energy grows steadily (6e-4 at the end: near-wall particles lose the regularising
//    force), so it is not the default. Where a free surface also truncates
//    the support (contact lines) the residual is mostly the free surface's, which the
//    symmetric form needs for a stable surface: the correction fades with the filled part of
//    the support, sum_j W_ij V_j / gamma_i, from 1 at 0.97 to 0 at 0.9.
//    On the N = 9800 tank (h/dx = 2) consistent keeps the pressure error at 0.003-0.007 up to
//    t sqrt(g/H) = 1, but a contact-line particle crosses a side wall at 1.06; with the wall
//    force of item 8 it runs on and its kinetic energy grows to 4.7e-4 MgH by t sqrt(g/H) =
//    1.6 (pressure error 0.14 at 2). In a continuity-
//    density scheme nothing else stiffens a particle against a wall: its own motion towards
//    the wall gives sum_j V_j (u_i - u_j).grad W - sum_b (u_i - u_b).n W A = 0 by the same
//    identity, so the density does not rise; the 2 p_i sum_b W n A of the symmetric form is
//    that stiffness, and its residual is the price.
//    The residual is not a defect of the formulation but of the start: sum_j V_j grad_i W_ij
//    is grad S_i (S = sum_j V_j W_ij) and sum_b W_ib n_b A_b is grad gamma_i (divergence
//    theorem on Calderon eq. 3), so R_i = grad (S - gamma)_i, and the p_i R_i part of the
//    symmetric form moves particles until S - gamma is flat: a packing in which the discrete
//    identity holds. The Cartesian lattice is not such a packing near walls; one is made
//    before the run by `setup: {relax: {map: integrals}}` (setup/relax_integrals.hpp). Measured
//    at t = 0 on the N = 9800 tank (h/dx = 2), per floor row, a_y/g with the terms separated
//    (fluid sum / gamma, wall term, total with gravity): lattice row 0: -68.67, +67.92, -1.759
//    (the 2 p_i R_i part: -1.739), row 1: +0.612, row 2: +0.614; packed (max h|R| 1.8e-2 ->
//    1e-4 in 1613 steps): row 0: -68.57, +69.55, -0.017 (2 p_i R_i part: -1e-4), row 1:
//    +0.002, row 2: -0.0002; side walls from -0.88 g to -1e-4 g. The symmetric form (with its
//    wall stiffness) is kept and starts in balance. (Those figures were measured with W_ib at
//    the element centres. That midpoint rule leaves a curl in sum_b W_ib n_b A_b at corners,
//    where the packing then stalled (max h|R| ~5e-4 at h/dx = 3 whatever the step count) and
//    the p_i R_i left there drove a circulation at the bottom corners that grew at h/dx = 3
//    and 4; element_quadrature.hpp has the measurements. With the element average the packing
//    converges at every corner, in ~100 steps.)
// 2c. Tried and not kept (same tank, to t sqrt(g/H) = 2): (i) the correction of 2b only in
//    the directions the wall elements face (projector N / lambda_max(N), N = sum_b W A n n^T),
//    keeping the tangential ordering force along the wall: error 0.004 up to t sqrt(g/H) =
//    0.79, then a contact-line particle crosses a side wall; with the wall force the kinetic
//    energy grows ~2.5x every 0.4 (8.8e-5 at 2, error 0.017, worst at the bottom corners).
//    (ii) p_b from particle i alone, p_i + rho_i g.(x_b - x_i) (the Neumann condition of a
//    mirror particle): a particle crosses a wall at t sqrt(g/H) = 0.26 (normal form), 0.46
//    (symmetric: p_i < 0 at a contact line makes 2 p_i pull to the wall), 0.8 (consistent).
//    (iii) p_b clamped at the background pressure where the hydrostatic extrapolation goes
//    negative above the free surface: the crossing comes sooner (0.68 against 0.79).
//
// 2d. `boundary.pressure: tensile_control`: the tensile instability control (TIC) of Sun,
//    Colagrossi, Marrone & Zhang (2017, delta+-SPH, CMAME 315) at the wall: a particle
//    in tension (p_i < 0) takes the difference form of 2b, (p_j - p_i) and (p_b - p_i),
//    instead of the sum form, whose 2 p_i term pulls a particle in tension towards its
//    neighbours and, through the wall term (p_b + p_i) W n A, onto the wall; p_i >= 0 keeps
//    the symmetric form and its wall stiffness. As in 2b the correction fades out where a
//    free surface cuts the support (Sun et al. also keep the sum form at the free surface).
//
// 3. Wall pressure. p_b is extrapolated from the fluid around the element centre x_b by a
//    Shepard average with the hydrostatic correction (grad p = rho g at rest):
//      p_b = sum_j (p_j + rho_j g.(x_b - x_j)) W_bj V_j / sum_j W_bj V_j.
//
// 4. Viscosity (no-slip). The Morris sum of momentum.hpp, 2 mu sum_j V_j (u_i - u_j) F_ij
//    (F = (1/r) dW/dr), applied to a linear field u_i - u_j = G r_ij near a wall gives
//    2 mu G sum_j V_j r_ij F_ij ~ 2 mu G sum_b W_ib n_b A_b instead of 0: the wall term that
//    makes it exact for linear fields is -2 mu sum_b (G n_b) W_ib A_b, with the wall-normal
//    derivative from the no-slip condition G n_b ~ (u_i - u_b)/(r_ib.n_b):
//      a_i += -(2 mu/(gamma_i rho_i)) sum_b (u_i - u_b) / max(r_ib.n_b, dx/2) W_ib A_b.
//    (r_ib.n_b is clamped at dx/2, the nominal distance of the first particle row, so that the
//    explicit viscous step stays stable for a particle that comes closer.)
//
// 5. Continuity. drho_i/dt = -rho_i <div u>_i with the BI divergence of 1., symmetrised by the
//    constant-field identity (u_j - u_i, u_b - u_i):
//      drho_i/dt = (rho_i/gamma_i) [ sum_j V_j (u_i - u_j).grad_i W_ij
//                                    - sum_b (u_i - u_b).n_b W_ib A_b ].
//    A particle moving towards the wall ((u_i - u_b).n_b < 0) is compressed.
//    delta-SPH: the diffusive term of density.hpp is a Laplacian of rho minus its linear part
//    (psi_ij . r_ij = 0 for a linear field with the renormalised gradient, which is exact for
//    linear fields near walls and free surfaces too), so a hydrostatic field gives 0 from the
//    fluid; its wall term is the flux of that non-linear part through the wall, taken as zero
//    (homogeneous Neumann condition on rho - linear part): the diffusive term only gets the
//    1/gamma renormalisation, so a hydrostatic state stays a steady state of the scheme.
//
// 6. Contract with the solver (boundary_model.hpp): fluid_forces() and continuity_rate() sum
//    the fluid part without 1/gamma; add_accelerations() / add_density_rate() divide the
//    accumulated value by gamma_i before adding the wall terms (body forces come after).
//    Summation density: sigma_i = sum_j W_ij is divided by gamma_i (add_density).
//
// 7. gamma: geometric / monolithic from the elements near the particle (a cell list over
//    element centres with radius 2h + the largest element radius, so the cost scales with
//    the particles near walls; the pairs with W_ib != 0 are kept from prepare() for the wall
//    terms of 3.-5., and only elements with a particle within 2h get a wall pressure);
//    volume: sum_j W_ij V_j over fluid particles (every particle,
//    free surface included: that is the "traditional" factor the paper compares against);
//    none: 1.
//
// 8. Optional wall force (boundary.wall_force, boundary/wall_force.hpp): for a particle at
//    distance d < d0 = 0.1 dx from a wall, a_i += (c0^2 / dx) (1 - d/d0)^2 n_w, from each wall
//    (each face of a tank) within d0. Particles at distance <= 0 are reported as penetrated.
//
// 9. Energy (boundary.pressure: conservative | conservative_wall | conservative_pairs).
//    With a static wall, no viscosity and E = sum_i m_i (|u_i|^2/2 - g.x_i + e(rho_i)),
//    de/drho = p/rho^2, the semi-discrete rate dE/dt = sum_i m_i u_i.(a_i - g) + sum_i V_i
//    (p_i/rho_i) drho_i/dt (V_i = m_i/rho_i = 1/sigma_i) vanishes when the pressure terms of 2.
//    are the negative adjoint of the divergence of 5. (our derivation). Pair by pair, for the
//    forms of 2. and 5. as they stand (symmetric):
//    - fluid pairs: the momentum gives -sum_ij (p_i/sigma_i^2)(u_i/gamma_i - u_j/gamma_j).
//      grad_i W_ij, the continuity +sum_ij p_i/(gamma_i sigma_i sigma_j)(u_i - u_j).grad_i W_ij:
//      they cancel (up to the sigma_i/sigma_j mismatch of plain SPH) only where gamma_i =
//      gamma_j. conservative_pairs puts p_j/(gamma_j sigma_j^2) in the pair term, m_i a_i =
//      -sum_j (p_i/(gamma_i sigma_i^2) + p_j/(gamma_j sigma_j^2)) grad_i W_ij: the two cancel
//      and the pair forces are equal and opposite, but by 1. the sum of p/gamma estimates
//      grad p + (p_w/gamma_w) grad gamma, which the wall term of 2. does not balance: kept to
//      measure this part of the budget only (it does not hold a tank at rest).
//    - wall: the momentum's (1/(gamma_i rho_i)) sum_b (p_b + p_i) W_ib A_b n_b works
//      sum_i (V_i/gamma_i) sum_b (p_b + p_i) W_ib A_b u_i.n_b, the continuity's wall term only
//      -sum_i (V_i/gamma_i) p_i sum_b W_ib A_b u_i.n_b: the power sum_i (V_i/gamma_i) sum_b p_b
//      W_ib A_b u_i.n_b is left (a wall pressure working on particles that move, the wall
//      itself at rest), and p_b, extrapolated from the neighbours (3.), follows the acoustic
//      field. The partner of p_b + p_i ~ 2 p_i is twice the continuity's wall term,
//        drho_i/dt = (rho_i/gamma_i) [ sum_j V_j (u_i - u_j).grad_i W_ij
//                                      - 2 sum_b (u_i - u_b).n_b W_ib A_b ]
//      (the relative velocity 2 (u_i - u_b).n_b of a mirror ghost), which leaves p_b - p_i in
//      that power. conservative_wall does only this. conservative also takes the wall
//      pressure from the particle itself, p_b = p_i + rho_i g.(x_b - x_i) (exact for the
//      hydrostatic field, as 3.), so that the power left is sum_i (m_i/gamma_i) sum_b
//      g.(x_b - x_i) W_ib A_b u_i.n_b: the work of a force that depends on x_i only (a
//      potential below a flat floor), not on the acoustic field.
//    The measured budgets are in docs/validation/cad_at_rest/integrals_findings.md.
// 10. Always on (boundary/wall_impact.hpp, which says why and gives the sources): the impact
//    pressure rho_i c0 max((u_w - u_i).n, 0) added to p_b + p_i of the elements of a wall a
//    particle approaches (n, u_w: the W A-weighted mean normal and velocity of the elements
//    of that wall facing one way near it), tapered by the particle's W A-weighted mean normal
//    distance to those elements (none beyond 3 dx/4), and the contact layer, item 8's law with
//    d0 = kWallLayer dx.
#include "curvsph/boundary/integrals/integrals_boundary.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include "curvsph/boundary/integrals/periodic_clip.hpp"
#include "curvsph/boundary/integrals/wall_clip.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/boundary/wall_impact.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/core/parallel.hpp"
#include "curvsph/geometry/moving_wall.hpp"

namespace curvsph {

template <int D>
IntegralsBoundary<D>::IntegralsBoundary(const BoundaryContext<D>& ctx)
    : spec_(ctx.spec),
      walls_(ctx.walls),
      W_(ctx.kernel),
      F_(ctx.fluid),
      fluid_cells_(ctx.cells),
      mode_(ShepardMode::geometric) {
  const Case& c = ctx.spec;
  try {
    mode_ = shepard_mode_from_string(c.boundary.shepard);
  } catch (const std::invalid_argument& e) {
    throw InputError(c.file_name(), "boundary.shepard", e.what());
  }
  consistent_ = c.boundary.pressure == "consistent";
  tensile_ = c.boundary.pressure == "tensile_control";
  no_tension_ = !c.boundary.wall_tension;
  const std::string& form = c.boundary.pressure;
  local_wall_ = form == "conservative";
  wall_pair_ = form == "conservative_wall" || local_wall_;
  fluid_pair_ = form == "conservative_pairs";
  if (wall_pair_ || fluid_pair_) {
    // Item 9 pairs the symmetric pressure terms with the continuity terms.
    if (c.pressure_difference)
      throw InputError(c.file_name(), "boundary.pressure",
                       "'" + form + "' needs pressure_gradient: symmetric");
  }
  dx_ = static_cast<Real>(c.dx);
  if (c.boundary.wall_force) wall_force_ = WallForce(F_.eos.c0, dx_);
  layer_ = WallForce(F_.eos.c0, dx_, kWallLayer);
}

template <int D>
void IntegralsBoundary<D>::build_elements(const Particles<D>& P) {
  const Case& c = spec_;
  // Infinite walls (planes, cylinders) are clipped to the domain box, or without one to the
  // particles' bounding box grown by half its size and 4h on every side, then to the fluid
  // side of the other walls.
  Bounds<D> bounds;
  if (c.has_domain) {
    bounds = Bounds<D>(c.domain_min.head<D>(), c.domain_max.head<D>());
  } else {
    for (const auto& x : P.x) bounds.extend(x.template cast<double>());
    const VecD<D> grow = VecD<D>::Constant(4 * c.h()) + 0.5 * bounds.sizes();
    bounds = Bounds<D>(bounds.min() - grow, bounds.max() + grow);
  }
  // Elements are generated once, in each wall's body frame (a moving wall's shape as given;
  // geometry/moving_wall.hpp), and placed rigidly in the world by place_elements().
  el_body_ = BoundaryElements<D>();
  wall_of_.clear();
  geometry_moves_ = false;
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    BoundaryElements<D> e;
    try {
      e = elements_from_wall<D>(walls_[k].body(), c.dx, bounds);
    } catch (const std::invalid_argument& err) {
      throw InputError(c.file_name(), "walls." + std::to_string(k), err.what());
    }
    // An infinite wall's elements end where another wall closes the fluid off (wall_clip.hpp):
    // behind a side wall the floor would count the corner twice.
    e = clip_by_other_walls<D>(e, walls_, k, 1e-9 * c.dx);
    // A wall drawn past a periodic seam would be counted twice (itself and its image).
    if (c.has_domain && (c.periodic[0] || c.periodic[1] || c.periodic[2]))
      e = clip_to_periodic_domain<D>(e, c.domain_min.head<D>(), c.domain_max.head<D>(), c.periodic);
    wall_of_.insert(wall_of_.end(), e.size(), static_cast<std::int32_t>(k));
    el_body_.append(e);
    const auto* mw = dynamic_cast<const MovingWall<D>*>(&walls_[k]);
    geometry_moves_ |= mw && mw->geometry_moves();
  }
  const std::size_t m = el_body_.size();
  ex_.resize(m);
  en_.resize(m);
  eu_.resize(m);
  ea_.resize(m);
  double rmax = 0;  // invariant under the rigid motions
  for (std::size_t b = 0; b < m; ++b) {
    ea_[b] = static_cast<Real>(el_body_.area[b]);
    rmax = std::max(rmax, el_body_.bounding_radius(b));
  }
  elem_cells_.configure(W_.support + static_cast<Real>(rmax), c.domain_min, c.domain_max,
                        c.periodic);
  p_wall_.assign(m, 0);
  place_elements();
  built_ = true;
}

template <int D>
void IntegralsBoundary<D>::place_elements() {
  // Body frame -> world at the walls' current time: x = R x_body + s, normals rotated; area,
  // curvature and gap are invariant. Static walls' elements are copied unchanged.
  el_ = el_body_;
  const std::size_t m = el_.size();
  for (std::size_t b = 0; b < m; ++b) {
    const auto* mw =
        dynamic_cast<const MovingWall<D>*>(&walls_[static_cast<std::size_t>(wall_of_[b])]);
    if (mw && mw->geometry_moves()) {
      el_.centre[b] = mw->to_world(el_body_.centre[b]);
      el_.normal[b] = mw->rotation() * el_body_.normal[b];
      for (int v = 0; v < el_.vertex_count[b]; ++v)
        el_.vertices[b][static_cast<std::size_t>(v)] =
            mw->to_world(el_body_.vertices[b][static_cast<std::size_t>(v)]);
    }
    ex_[b] = el_.centre[b].template cast<Real>();
    en_[b] = el_.normal[b].template cast<Real>();
    eu_[b] =
        walls_[static_cast<std::size_t>(wall_of_[b])].velocity(el_.centre[b]).template cast<Real>();
  }
  elem_cells_.build(ex_);
  wq_ = element_quadrature(el_);
  if (mode_ == ShepardMode::geometric) geometric_ = GeometricShepard<D>(el_, W_.h, quad_);
}

template <int D>
void IntegralsBoundary<D>::check_setup(const Particles<D>& P, const std::string& file) {
  build_elements(P);
  if (el_.size() == 0)
    throw InputError(file, "boundary.method", "integrals need walls (no boundary elements)");
}

template <int D>
void IntegralsBoundary<D>::prepare(const Particles<D>& P, Real /*t*/) {
  if (!built_) {
    build_elements(P);
  } else if (geometry_moves_) {
    place_elements();  // the walls were set to this stage's time by the solver
  } else if (walls_.any_moves()) {
    // Walls that slide along themselves: the elements stay, their velocity may change in time.
    for (std::size_t b = 0; b < el_.size(); ++b)
      eu_[b] = walls_[static_cast<std::size_t>(wall_of_[b])]
                   .velocity(el_.centre[b])
                   .template cast<Real>();
  }
  const Index n = static_cast<Index>(P.size());
  gamma_.resize(P.size());
  near_.resize(P.size());
  wall_dist_.resize(P.size());
  wall_normal_.resize(P.size());
  pair_count_.resize(P.size());
  pair_local_.resize(P.size());
  pair_thread_.resize(P.size());
  active_.assign(ex_.size(), 0);
  // An element is active (its wall pressure is extrapolated) when a particle lies within 2h;
  // the margin covers the round-off between this separation and the fluid cell list's, so
  // that no element with fluid in its support is left at p_b = 0.
  const Real active2 = W_.support2 * (1 + Real(1e-9));
#pragma omp parallel
  {
#pragma omp single
    thread_pairs_.resize(static_cast<std::size_t>(omp_get_num_threads()));
    const int thread = omp_get_thread_num();
    // The buffer is moved out for the loop (capacity kept) and back after it: the vectors'
    // own pointers sit side by side in thread_pairs_, and a push_back through a reference
    // writes the shared cache line for every pair, bouncing it between the cores.
    std::vector<Pair> buf = std::move(thread_pairs_[static_cast<std::size_t>(thread)]);
    buf.clear();
    double gamma_seconds = 0;  // this thread's time in the Shepard factor
    // Dynamic schedule: the Shepard factor costs only near walls, and particles are sorted by
    // cell, so a static split hands one thread the floor of a tank (dam break, dx 0.036, 2
    // threads: 1.5e9 against 0.64e9 instructions in this loop, callgrind --separate-threads).
    // Each particle records the buffer that holds its pairs; results do not depend on the
    // schedule.
#pragma omp for schedule(dynamic, 64)
    for (Index i = 0; i < n; ++i) {
      const Vec<D>& x = P.x[i];
      // Candidate elements, with the periodic image shift of each (x_b image = x_b + s).
      thread_local std::vector<std::size_t> idx;
      thread_local std::vector<Vec<D>> shift;
      idx.clear();
      shift.clear();
      const Index first = static_cast<Index>(buf.size());
      for_each_element(x, [&](Index b, const Vec<D>& r, Real r2) {
        idx.push_back(static_cast<std::size_t>(b));
        shift.push_back(x - r - ex_[b]);
        // W averaged over the element (element_quadrature.hpp: why not W at its centre).
        const Real w = wq_.mean_kernel(W_, static_cast<std::size_t>(b), r);
        if (r2 < active2 || w != 0) {
          // Test before setting: dozens of particles lie within 2h of each element, and a
          // store by both threads to the same cache line for every one of them bounces the
          // line between the cores; a load leaves it shared once the flag is set.
          std::atomic_ref<unsigned char> flag(active_[b]);
          if (!flag.load(std::memory_order_relaxed)) flag.store(1, std::memory_order_relaxed);
        }
        if (w != 0) buf.push_back({b, r, w});
      });
      pair_local_[i] = first;
      pair_thread_[i] = thread;
      pair_count_[i] = static_cast<Index>(buf.size()) - first;
      near_[i] = !idx.empty();
      if (near_[i]) {
        const WallPoint<D> wp = walls_.closest(x.template cast<double>());
        wall_dist_[i] = static_cast<Real>(wp.distance);
        wall_normal_[i] = wp.normal.template cast<Real>();
      }
      // Only particles that compute a gamma are timed (two clock reads, ~50 ns).
      const bool timed = mode_ == ShepardMode::volume || (mode_ != ShepardMode::none && near_[i]);
      const double t0 = timed ? omp_get_wtime() : 0;
      Real g = 1;
      switch (mode_) {
        case ShepardMode::volume: {
          Real s = 0;
          fluid_cells_.for_each_neighbor(x, P.x, [&](Index j, const Vec<D>&, Real r2) {
            s += W_.value(std::sqrt(r2)) * P.mass[j] / P.rho[j];
          });
          g = s;
          break;
        }
        case ShepardMode::geometric:
        case ShepardMode::monolithic:
          if (!idx.empty()) g = element_gamma(x, idx, shift);
          break;
        case ShepardMode::none:
          break;
      }
      gamma_[i] = g;
      if (timed) gamma_seconds += omp_get_wtime() - t0;
    }
    thread_pairs_[static_cast<std::size_t>(thread)] = std::move(buf);
#pragma omp atomic
    shepard_seconds_ += gamma_seconds / omp_get_num_threads();
  }
  penetrated_.clear();
  for (Index i = 0; i < n; ++i)
    if (near_[i] && wall_dist_[i] <= 0) penetrated_.push_back(i);
}

// The geometric (or monolithic) Shepard factor at x from its candidate elements `idx`, seen
// through the periodic image shifts `shift` (x_b image = x_b + s).
template <int D>
Real IntegralsBoundary<D>::element_gamma(const Vec<D>& x, std::span<const std::size_t> idx,
                                         std::span<const Vec<D>> shift) const {
  const double h = W_.h;
  auto eval = [&](std::span<const std::size_t> cand, const VecD<D>& xs) {
    return mode_ == ShepardMode::geometric ? geometric_(el_, cand, xs)
                                           : shepard_monolithic<D>(el_, cand, xs, h, quad_);
  };
  const Real tol = Real(1e-6) * W_.h, tol2 = tol * tol;
  // Squared norms: this test runs over every candidate of every particle near a wall.
  const bool unshifted = std::all_of(shift.begin(), shift.end(),
                                     [&](const Vec<D>& s) { return s.squaredNorm() < tol2; });
  if (unshifted) return static_cast<Real>(eval(idx, x.template cast<double>()));
  // Elements seen through periodic images: 1 - gamma is additive over elements, so each
  // image group contributes 1 - gamma(x - s) over its own elements.
  thread_local std::vector<std::size_t> group;
  thread_local std::vector<unsigned char> done;
  done.assign(idx.size(), 0);
  double sum = 1;
  for (std::size_t k = 0; k < idx.size(); ++k) {
    if (done[k]) continue;
    group.clear();
    for (std::size_t l = k; l < idx.size(); ++l)
      if (!done[l] && (shift[l] - shift[k]).norm() < tol) {
        group.push_back(idx[l]);
        done[l] = 1;
      }
    sum -= 1 - eval(group, (x - shift[k]).template cast<double>());
  }
  return static_cast<Real>(sum);
}

template <int D>
void IntegralsBoundary<D>::add_density(Particles<D>& P) {
  parallel_for(static_cast<Index>(P.size()), [&](Index i) {
    P.sigma[i] /= gamma_[i];
    P.rho[i] = P.mass[i] * P.sigma[i];
  });
}

template <int D>
void IntegralsBoundary<D>::check_prepared(const Particles<D>& P) const {
  if (pair_count_.size() != P.size())
    throw std::logic_error("IntegralsBoundary: prepare() must run on these particles first");
}

template <int D>
void IntegralsBoundary<D>::add_density_rate(Particles<D>& P) {
  check_prepared(P);
  // Balanced: the wall sums cost only near walls (the particles of a tank's floor are one
  // stretch of the cell order).
  parallel_for_balanced(static_cast<Index>(P.size()), [&](Index i) {
    Real wall = 0;
    for (const Pair& q : pairs_of(i)) {
      wall += (P.v[i] - eu_[q.b]).dot(en_[q.b]) * q.w * ea_[q.b];
    }
    // Item 9 (conservative, conservative_wall): twice the flux, the partner of the momentum's
    // p_b + p_i ~ 2 p_i.
    if (wall_pair_) wall *= 2;
    P.drho[i] = (P.drho[i] - P.rho[i] * wall) / gamma_[i];
  });
}

template <int D>
void IntegralsBoundary<D>::add_accelerations(Particles<D>& P) {
  check_prepared(P);
  // Wall pressure of every element with fluid around it (item 3 of the header comment).
  const Vec<D> g = F_.gravity;
  parallel_for_balanced(static_cast<Index>(ex_.size()), [&](Index b) {
    if (!active_[b]) {  // no particle within 2h: den would be 0 (prepare())
      p_wall_[b] = 0;
      return;
    }
    Real num = 0, den = 0;
    fluid_cells_.for_each_neighbor(ex_[b], P.x, [&](Index j, const Vec<D>& r, Real r2) {
      const Real wv = W_.value(std::sqrt(r2)) * P.mass[j] / P.rho[j];
      num += (P.p[j] + P.rho[j] * g.dot(r)) * wv;  // r = x_b - x_j
      den += wv;
    });
    p_wall_[b] = den > 0 ? num / den : 0;
  });
  const Real dn_min = Real(0.5) * dx_;
  const bool difference = spec_.pressure_difference;  // the fluid sums are consistent already
  WallLoadSums<D>* loads = this->loads_;
  const auto body = [&](Index i) {
    const Real inv_g = 1 / gamma_[i];
    Vec<D> a_before = P.a[i];
    P.a[i] *= inv_g;
    if (fluid_pair_) {
      // Item 9: each pair's p_j / sigma_j^2 over gamma_j instead of gamma_i. The fluid part
      // then conserves momentum pair by pair and is internal: the loads take the wall terms.
      Vec<D> d = Vec<D>::Zero();
      fluid_cells_.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
        if (j == i || gamma_[j] == gamma_[i]) return;
        const Real sj = P.sigma[j];
        d += (P.p[j] / (sj * sj) * (1 / gamma_[j] - inv_g) * W_.gradient_factor(std::sqrt(r2))) * r;
      });
      P.a[i] -= d / P.mass[i];
      a_before = P.a[i];
    }
    if (!near_[i]) return;
    const bool track = loads && i < loads->count();
    const Real mu = F_.viscosity[P.phase[i]];
    Vec<D> fp = Vec<D>::Zero(), fv = Vec<D>::Zero(), wn = Vec<D>::Zero();
    struct Group {
      std::int32_t wall = -1;
      Vec<D> n0 = Vec<D>::Zero(), wn = Vec<D>::Zero(), uw = Vec<D>::Zero();
      Real w = 0, wd = 0;  // sum W A, sum W A (x_i - x_b).n_b
    };
    constexpr int kGroups = 6;
    std::array<Group, kGroups> groups;
    int ng = 0;
    for (const Pair& q : pairs_of(i)) {
      const Index b = q.b;
      const Real wa = q.w * ea_[b];
      // boundary.wall_tension: false: the wall only pushes (case_file.hpp).
      // pressure_gradient: difference (physics/pressure_gradient.hpp): (p_b - p_i).
      // Item 9, conservative: the wall pressure from p_i itself, p_i + rho_i g.(x_b - x_i)
      // (exact for the hydrostatic field), so that its work pairs with p_i's continuity term.
      const Real pw = local_wall_ ? P.p[i] - P.rho[i] * g.dot(q.r) : p_wall_[b];
      const Real pb = difference ? pw - P.p[i] : pw + P.p[i];
      fp += (no_tension_ && !difference ? std::max(pb, Real(0)) : pb) * wa * en_[b];
      wn += wa * en_[b];
      // Item 10's groups: the elements of one wall facing one way (a box's faces apart).
      int k = 0;
      while (k < ng && !(groups[k].wall == wall_of_[b] && groups[k].n0.dot(en_[b]) > Real(0.5)))
        ++k;
      if (k == ng && ng < kGroups) groups[ng++] = {wall_of_[b], en_[b]};
      if (k < ng) {
        groups[k].wn += wa * en_[b];
        groups[k].uw += wa * eu_[b];
        groups[k].w += wa;
        groups[k].wd += wa * q.r.dot(en_[b]);
      }
      fv += (P.v[i] - eu_[b]) * (wa / std::max(q.r.dot(en_[b]), dn_min));
    }
    // Item 10: the impact pressure of i approaching a wall, added to p_b of its elements and
    // tapered by i's mean normal distance to them (wall_impact_reach: the term acts on a
    // particle about to touch the wall, not across the kernel support). Its
    // speed is taken along the mean normal sum_b W A n of the elements of one wall facing one
    // way (and against their mean velocity), not element by element: flow along a curved wall
    // then has none (an element's normal is tilted by the curvature); walls facing each other
    // (a gap under a cylinder) or the faces of a corner each take their own.
    for (int k = 0; k < ng; ++k) {
      const Group& q = groups[static_cast<std::size_t>(k)];
      const Real norm = q.wn.norm();
      if (norm > 0 && q.w > 0)
        fp += wall_impact_pressure(P.rho[i], F_.eos.c0, (q.uw / q.w - P.v[i]).dot(q.wn) / norm,
                                   q.wd / (q.w * dx_), kImpactReachIntegrals) *
              q.wn;
    }
    if (!difference && (consistent_ || (tensile_ && P.p[i] < 0))) {
      // Item 2b: remove p_i times the discrete residual of the constant-field identity (item
      // 2d: only where p_i < 0).
      const Real si = P.sigma[i];
      const Real inv_si2 = 1 / (si * si);
      Vec<D> c = Vec<D>::Zero();
      Real filled = 0;  // sum_j W_ij V_j: below gamma_i where a free surface cuts the support
      fluid_cells_.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
        const Real rr = std::sqrt(r2);
        filled += W_.value(rr) * P.mass[j] / P.rho[j];
        if (j == i) return;
        const Real sj = P.sigma[j];
        c += (1 / (sj * sj) + inv_si2) * W_.gradient_factor(rr) * r;
      });
      // Only the wall's share of the residual is removed: where the free surface also cuts
      // the support (filled < 0.97 gamma: contact lines) the residual holds the free-surface
      // deficit that the symmetric form needs, and the correction fades out (to 0 at 0.9).
      const Real blend = std::clamp((filled * inv_g - Real(0.9)) / Real(0.07), Real(0), Real(1));
      P.a[i] += blend * inv_g * P.p[i] / P.mass[i] * (c - (2 / si) * wn);
    }
    P.a[i] += inv_g / P.rho[i] * (fp - 2 * mu * fv);
    if (track) add_loads(i, Vec<D>(-P.mass[i] * (P.a[i] - a_before)), P.x[i], *loads);
    for (const WallForce* law : {&layer_, &wall_force_}) {  // item 10 and item 8
      if (!law->active(wall_dist_[i])) continue;
      if (!track) {
        P.a[i] += wall_force_push(walls_, P.x[i], *law);
        continue;
      }
      Vec<D> push = Vec<D>::Zero();
      wall_force_each(walls_, P.x[i], *law,
                      [&](std::size_t k, const Vec<D>& p, const VecD<D>& foot) {
                        push += p;
                        loads->add(i, k, Vec<D>(-P.mass[i] * p), foot);
                      });
      P.a[i] += push;
    }
  };
  if (loads)
    WallLoadSums<D>::for_blocks(static_cast<Index>(P.size()), true, body);
  else
    parallel_for_balanced(static_cast<Index>(P.size()), body);
}

// Wall loads (wall_loads.hpp). The reaction R = -m_i da_i of everything the wall terms did to
// particle i (the renormalisation by gamma_i included: without it the walls of a tank at rest
// would not carry the fluid's weight) goes to the walls of the particle's elements: all of it
// to the one wall when one wall is in reach (the usual case); otherwise the component of R in
// the span of the walls' mean normals N_k = sum_{b in k} W_ib A_b n_b to each wall along its
// own (a tank's corner particle pushes the floor down and the side wall sideways), and what
// is left, or all of R when those normals are not independent (a particle between two walls
// facing each other), in proportion to the walls' weights sum_{b in k} W_ib A_b. Each wall's
// share acts at the W_ib A_b-weighted centre of its elements. (Only particles with elements
// in reach: a Shepard factor below 1 away from walls, volume mode at a free surface, is not a
// wall's doing.)
template <int D>
void IntegralsBoundary<D>::add_loads(Index i, const Vec<D>& R, const Vec<D>& xi,
                                     WallLoadSums<D>& loads) const {
  constexpr int kMax = 8;
  std::array<std::int32_t, kMax> wall{};
  std::array<double, kMax> weight{};
  std::array<VecD<D>, kMax> normal{}, centre{};
  int m = 0;
  double total = 0;
  for (const Pair& q : pairs_of(i)) {
    const std::int32_t k = wall_of_[static_cast<std::size_t>(q.b)];
    int s = 0;
    while (s < m && wall[static_cast<std::size_t>(s)] != k) ++s;
    if (s == m) {
      if (m == kMax) continue;  // more walls in reach than kept: their share goes to the rest
      wall[static_cast<std::size_t>(m)] = k;
      weight[static_cast<std::size_t>(m)] = 0;
      normal[static_cast<std::size_t>(m)] = VecD<D>::Zero();
      centre[static_cast<std::size_t>(m)] = VecD<D>::Zero();
      ++m;
    }
    const auto u = static_cast<std::size_t>(s);
    const double w = static_cast<double>(q.w * ea_[q.b]);
    weight[u] += w;
    normal[u] += w * en_[q.b].template cast<double>();
    centre[u] += w * (xi - q.r).template cast<double>();  // the element's image seen from i
    total += w;
  }
  if (m == 0 || !(total > 0)) return;
  for (int s = 0; s < m; ++s)
    centre[static_cast<std::size_t>(s)] /= weight[static_cast<std::size_t>(s)];
  if (m == 1) {
    loads.add(i, static_cast<std::size_t>(wall[0]), R, centre[0]);
    return;
  }
  const VecD<D> r = R.template cast<double>();
  VecD<D> rest = r;
  if (m <= D) {
    Eigen::Matrix<double, D, D> G = Eigen::Matrix<double, D, D>::Identity();
    Eigen::Matrix<double, D, 1> rhs = Eigen::Matrix<double, D, 1>::Zero();
    std::array<VecD<D>, kMax> unit;
    unit.fill(VecD<D>::Zero());  // Eigen's default constructor leaves them unset
    bool ok = true;
    for (int s = 0; s < m && ok; ++s) {
      const double len = normal[static_cast<std::size_t>(s)].norm();
      ok = len > 1e-12 * weight[static_cast<std::size_t>(s)];
      if (ok) unit[static_cast<std::size_t>(s)] = normal[static_cast<std::size_t>(s)] / len;
    }
    if (ok) {
      for (int a = 0; a < m; ++a) {
        rhs[a] = unit[static_cast<std::size_t>(a)].dot(r);
        for (int b = 0; b < m; ++b)
          G(a, b) = unit[static_cast<std::size_t>(a)].dot(unit[static_cast<std::size_t>(b)]);
      }
      // Independent normals: G (the Gram matrix, identity outside the m x m block) is well
      // conditioned; two walls facing each other make it singular.
      if (std::abs(G.determinant()) > 1e-6) {
        const Eigen::Matrix<double, D, 1> c = G.ldlt().solve(rhs);
        for (int s = 0; s < m; ++s) {
          const VecD<D> part = c[s] * unit[static_cast<std::size_t>(s)];
          rest -= part;
          loads.add(i, static_cast<std::size_t>(wall[static_cast<std::size_t>(s)]),
                    part.template cast<Real>(), centre[static_cast<std::size_t>(s)]);
        }
      }
    }
  }
  for (int s = 0; s < m; ++s)
    loads.add(i, static_cast<std::size_t>(wall[static_cast<std::size_t>(s)]),
              (rest * (weight[static_cast<std::size_t>(s)] / total)).template cast<Real>(),
              centre[static_cast<std::size_t>(s)]);
}

// Shifting: the shift direction takes the residual of the constant-field identity of item 1,
// sum_j V_j grad_i W_ij - sum_b W_ib n_b A_b, which the BI packing (setup/relax_integrals.hpp)
// drives to zero. Within dx of a wall the shift towards it is removed, as for ghosts (the
// wall sum's push fades with the distance). The Taylor gradients stay the fluid's (see the
// ghost model for why).
template <int D>
void IntegralsBoundary<D>::add_shift_sums(const Particles<D>& P, Index n, Real dx,
                                          ShiftScratch<D>& sums) const {
  check_prepared(P);
  parallel_for(n, [&](Index i) {
    for (const Pair& q : pairs_of(i)) sums.s[i] -= (q.w * ea_[q.b]) * en_[q.b];
    if (near_[i] && wall_dist_[i] < dx) shift_toward_wall_removed(sums.s[i], wall_normal_[i]);
  });
}

template <int D>
void IntegralsBoundary<D>::append_output(std::vector<Vec<D>>& x, std::vector<int>& kind) const {
  x.insert(x.end(), ex_.begin(), ex_.end());
  kind.insert(kind.end(), ex_.size(), 2);
}

template <int D>
std::unique_ptr<BoundaryModel<D>> make_integrals_boundary(const BoundaryContext<D>& ctx) {
  return std::make_unique<IntegralsBoundary<D>>(ctx);
}

template class IntegralsBoundary<2>;
template class IntegralsBoundary<3>;
template std::unique_ptr<BoundaryModel<2>> make_integrals_boundary<2>(const BoundaryContext<2>&);
template std::unique_ptr<BoundaryModel<3>> make_integrals_boundary<3>(const BoundaryContext<3>&);

}  // namespace curvsph
