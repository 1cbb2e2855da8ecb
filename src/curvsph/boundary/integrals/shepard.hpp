#pragma once
// Shepard factor gamma(x) = int_fluid W(y - x) dy near walls (Calderon et al.; DESIGN.md §4).
// With n the element normal pointing INTO the fluid,
//   gamma(x) = 1 - int_dOmega n(y).(y - x) F(|y - x|) dy      (x in the closed fluid domain).
// Modes (case key boundary.shepard):
//  - geometric:  F = F_D + F_Pext (kernels/boundary_kernel.hpp). The singular part is exact:
//                int_j n.(y - x) F_D = dtheta_j / (2 pi) (2-D), dOmega_j / (4 pi) (3-D), the
//                angle / solid angle element j subtends at x, positive seen from the fluid;
//                the polynomial part F_Pext is integrated with Gauss points (split at the
//                foot of x, sub-divided to pieces <= h/2; on arcs along the true arc).
//                Elements entirely beyond 2h contribute exactly nothing; elements crossing
//                the support sphere are integrated whole (F_Pext is smooth across 2h).
//                A point on the wall (within tolerance) is treated as the limit from the
//                fluid side along the mean normal of the elements it touches, so that the
//                contact point, a corner apex and a vertex between elements get gamma right.
//  - monolithic: all of F summed at the element centres (the paper's foil); optionally with
//                the paper's "gamma = 1/2 on the contour" rule (monolithic_contour_half).
//  - volume:     gamma_i = sum_j W_ij V_j over fluid particles (Calderon eq. 4).
//  - none:       gamma = 1.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/core/types.hpp"

namespace curvsph {

enum class ShepardMode { geometric, monolithic, volume, none };

// "geometric" | "monolithic" | "volume" | "none"; throws std::invalid_argument otherwise.
ShepardMode shepard_mode_from_string(std::string_view name);
const char* to_string(ShepardMode mode);

struct ShepardQuadrature {
  int gauss_points = 4;             // per piece (2-D) or per direction per triangle (3-D)
  double max_piece_over_h = 0.5;    // sub-divide elements into pieces no longer than this * h
  double on_wall_tolerance = 1e-9;  // in units of h: closer than this counts as on the wall
  // Monolithic mode only: the paper's contour rule (Calderon §2.2, after eq. 17): a point on
  // the contour skips the elements it lies on and takes their contribution as exactly -1/2
  // (gamma = 1/2 from them). Without it those elements contribute nothing (n.(y - x) = 0).
  bool monolithic_contour_half = false;
};

// Signed angle (2-D) / solid angle (3-D) element j subtends at x, positive when x is on the
// fluid side. 2-D arcs: the angle of the arc itself (not only of its chord).
template <int D>
double subtended_angle(const BoundaryElements<D>& el, std::size_t j, const VecD<D>& x);

template <int D>
double shepard_geometric(const BoundaryElements<D>& el, const VecD<D>& x, double h,
                         const ShepardQuadrature& quad = {});

template <int D>
double shepard_monolithic(const BoundaryElements<D>& el, const VecD<D>& x, double h,
                          const ShepardQuadrature& quad = {});

// The same over a candidate list of element indices (e.g. from a cell list over element
// centres): every element that reaches into the support ball of x must be in it; others may be.
template <int D>
double shepard_geometric(const BoundaryElements<D>& el, std::span<const std::size_t> candidates,
                         const VecD<D>& x, double h, const ShepardQuadrature& quad = {});
template <int D>
double shepard_monolithic(const BoundaryElements<D>& el, std::span<const std::size_t> candidates,
                          const VecD<D>& x, double h, const ShepardQuadrature& quad = {});

// The geometric factor of a fixed element set, evaluated many times (the solver: every particle
// near a wall, every step). Same singular part as shepard_geometric (exact solid angles); the
// polynomial part of each planar element is integrated exactly in the radial direction about
// the foot of x and with Gauss points along the element's edges (derivation in
// geometric_shepard.cpp), and an edge shared by two coplanar elements that are both in the sum
// cancels: only the rim of the patch of a flat wall near x is integrated. A flat face that covers
// the whole support disc of x on its plane gives the half-space value in closed form, without
// visiting its elements' edges (geometric_shepard.cpp, half_space_part). Elements whose distance
// from x is >= 2h are left out (F = F_D + F_Pext = 0 on them). The two evaluations agree to the
// quadrature error of shepard_geometric (tests/boundary/test_shepard_fast.cpp); this one is the
// more accurate. 2-D elements take shepard_geometric's path (a 2-D wall costs little).
template <int D>
class GeometricShepard {
 public:
  GeometricShepard() = default;
  GeometricShepard(const BoundaryElements<D>& el, double h, const ShepardQuadrature& quad = {});
  // Candidates as for shepard_geometric (the elements reaching into the support ball of x
  // must be among them). `el` must be the element set given to the constructor.
  double operator()(const BoundaryElements<D>& el, std::span<const std::size_t> candidates,
                    const VecD<D>& x) const;
  double h() const { return h_; }

 private:
  // 3-D only: defined for GeometricShepard<3> alone (an explicit specialization rather than a
  // requires-clause, which clang 14, hence clang-tidy, rejects in the explicit instantiation
  // of GeometricShepard<2>).
  void build_patches(const BoundaryElements<D>& el);

  double h_ = 0;
  ShepardQuadrature quad_;
  // twin_[4 j + k]: the coplanar element sharing edge k of element j (reversed), or -1 (3-D).
  std::vector<std::int64_t> twin_;
  std::vector<double> radius_;  // bounding radius of every element (candidate test)
  std::vector<double> reach_;   // d(x, element) <= |x - centre| + reach (candidate test)
  // Flat-face fast path (3-D, operator()): patch_[j] numbers the connected set of coplanar
  // flat elements joined by twins (-1: not part of one), clear_[j] the distance from element
  // j's centre to the nearest edge of its patch that has no twin (the patch's rim), so the
  // disc of radius clear_[j] about the centre lies inside the patch.
  std::vector<std::int32_t> patch_;
  std::vector<double> clear_;
  // Rim path (3-D, operator()): a face whose support disc is cut by its rim is integrated
  // over the rim edges within 2h alone; the rest of the boundary of its elements within the
  // support, all of it 2h or more away, enters through the angle it subtends, which closes
  // to 2 pi around a foot inside the face. rim_edges_ holds every patch's rim (edges whose
  // twin is not in the patch), binned by midpoint on a grid of cells of rim_cell_ >= 2h + the
  // longest rim edge (CSR: rim_start_, rim_index_), so a particle visits the 27 cells about
  // it. patch_rim_ok_[p] = 0 where a rim edge has a twin outside the patch (the twin could
  // cancel it): such a patch takes the element path.
  struct RimEdge {
    Vec3d a, b;
    std::int32_t patch;
  };
  std::vector<RimEdge> rim_edges_;
  std::vector<std::uint32_t> rim_start_, rim_index_;
  Vec3d rim_origin_ = Vec3d::Zero();
  std::array<int, 3> rim_dims_{0, 0, 0};
  double rim_cell_ = 0;
  std::vector<unsigned char> patch_rim_ok_;
  // Index of rim cell (cx, cy, cz), all within rim_dims_ (x fastest).
  std::size_t rim_cell_index(int cx, int cy, int cz) const {
    return (static_cast<std::size_t>(cz) * static_cast<std::size_t>(rim_dims_[1]) +
            static_cast<std::size_t>(cy)) *
               static_cast<std::size_t>(rim_dims_[0]) +
           static_cast<std::size_t>(cx);
  }
};

template <int D>
double shepard_volume(std::span<const VecD<D>> positions, std::span<const double> volumes,
                      const VecD<D>& x, double h);

// gamma at every point of `points` (brute force over elements / fluid particles; the solver
// will feed candidates from its cell list). `fluid_positions` / `fluid_volumes` are used by
// the volume mode only.
template <int D>
std::vector<double> shepard_factor(ShepardMode mode, const BoundaryElements<D>& el,
                                   std::span<const VecD<D>> points, double h,
                                   std::span<const VecD<D>> fluid_positions = {},
                                   std::span<const double> fluid_volumes = {},
                                   const ShepardQuadrature& quad = {});

}  // namespace curvsph
