#pragma once
// The kernel averaged over a boundary element, (1/A_b) int_b W(|x - y|) dS_y, by Gauss points
// on the element's shape, for the wall terms of the boundary integrals (the W_ib of
// integrals_boundary.cpp) and the BI packing (setup/relax_integrals.cpp).
//
// Why not W at the element centre (the midpoint rule): the wall sum G(x) = sum_b W_ib n_b A_b
// stands for int_dOmega W n dS = grad gamma (Calderon eq. 3 and the divergence theorem), a
// gradient field. The midpoint rule's error near a wall's end, i.e. at every corner, is not
// a gradient: it carries a curl. The symmetric BI momentum equation holds 2 p_i (grad S_i -
// G(x_i)) / (gamma_i rho_i) (S = sum_j V_j W_ij), so a curl in G is a force with a curl, a
// circulation that no particle arrangement removes. Measured on the 2-D hydrostatic tank at
// N = 9800 (docs/validation/hydrostatic_tank/findings.md, session 10): the BI packing, a
// descent on S - gamma with G as grad gamma, stalls at max h|R| 4.7e-4 (h/dx = 3) whatever
// the step count (4000, 30 000) and step factor (0.25, 0.1), the residual sitting at the four
// corners; the run then drives the bottom-corner circulation that made the N ~ 1e5 runs at
// h/dx = 3 and 4 lose particles. With two Gauss points per element the packing reaches
// 1e-4 in 76 / 79 / 99 steps at h/dx = 2 / 3 / 4 (the midpoint rule: 1613 / never / never).
//
// Shapes (boundary_elements.hpp): 2-D elements are integrated along the parabola through
// their two vertices and their centre (a segment, or an arc: on a circle of radius 0.2 cut
// into arcs of 0.05 the points lie within 1.4e-6 of it, where the chord's midpoint is 1.6e-3
// off), two Gauss points; 3-D quadrilaterals on the bilinear patch through their vertices lifted by
// a bubble (1 - s^2)(1 - t^2) to pass through the centre (on the true wall for curved patches), 2 x
// 2 Gauss points; triangles by the 3-point rule of degree 2 at (2/3, 1/6, 1/6), the fourth point
// with weight 0. Weights are fractions of the element's area (sum 1): the area itself stays
// the element's own A_b.
#include <vector>

#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/core/types.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph {

template <int D>
struct ElementQuadrature {
  static constexpr int kPoints = D == 2 ? 2 : 4;  // per element
  std::vector<Vec<D>> offset;                     // y_bq - x_b, kPoints per element
  std::vector<Real> weight;                       // area fractions, kPoints per element

  std::size_t size() const { return weight.size() / kPoints; }

  // (1/A_b) int_b W(|x - y|) dS_y with r = x - x_b (periodic image applied by the caller).
  Real mean_kernel(const WendlandC2<D>& W, std::size_t b, const Vec<D>& r) const {
    Real w = 0;
    const std::size_t k0 = b * kPoints;
    for (int q = 0; q < kPoints; ++q) w += weight[k0 + q] * W.value((r - offset[k0 + q]).norm());
    return w;
  }
};

template <int D>
ElementQuadrature<D> element_quadrature(const BoundaryElements<D>& el);

}  // namespace curvsph
