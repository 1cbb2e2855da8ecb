#pragma once
// Ghost particles (DESIGN.md §4) in structure-of-arrays, rebuilt every step from the fluid
// particles and the walls.
//
// Which ghosts. Every fluid particle i at distance d < support (= 2h) from a wall gets
//  - one ghost per wall within the support, at foot - zeta' n (ghost_map.hpp: zeta' and
//    beta from the map and the wall's principal curvatures at the foot point);
//  - for a box with the fluid inside, the box is treated face by face: one ghost per face
//    within the support, and
//  - corners: where two flat faces within the support (faces of a box, plane walls, a
//    polygon's side and another wall's face, planar faces of a CAD solid) meet at an edge,
//    the images of flat_corners.hpp: at 180/n degrees (90, 60, 45, ...) the multiply
//    reflected ghosts of the dihedral group (90 degrees: the double reflection; a third face
//    perpendicular to both adds their reflections across it, the triple one of a box corner),
//    above 120 degrees the single ghosts cut at the exterior bisector; other angles the
//    words of the two reflections that wind round the exterior from each face, cut at the
//    exterior bisector. A polygon's own corners are facet_images.hpp's.
// Ghosts are ordered by source particle, then wall, then face, then corner combinations;
// the order does not depend on the thread count.
//
// Velocity of a ghost (u the fluid velocity, u_w the wall velocity at the foot point):
//   no_slip:   u_g = u_w - (zeta'/d) (u - u_w)   (= 2 u_w - u for the mirror maps)
//   free_slip: u_g = u_w + (u - u_w) - 2 ((u - u_w).n) n   (normal component reflected)
// Corner ghosts compose the single-reflection maps in turn.
// The continuity equation takes the free-slip image whatever the mode (`v_slip`, filled for
// no_slip; `v` is the free-slip image already): the no-slip image reverses the tangential
// velocity, so a ghost's share of div u then counts the tangential stretching of the flow
// along the wall with the wrong sign, which the fluid sum cancels only where the support is
// full. Next to a free surface it is not: in the 2-D hydrostatic tank with mirror ghosts the
// first row along each side wall, about two supports below the surface, starts to sink at
// t ~ 0.5 s and the tank never settles (kinetic energy 8e-4 M g H at t = 3 s; 3.6e-7 with
// the free-slip image in the continuity equation only). Adami, Hu & Adams (2012) likewise
// keep the extrapolated no-slip velocity for the viscous term alone.
//
// Periodic domains: with `cells` set, ghost positions are wrapped with cells->wrap().
//
// Penetration: a fluid particle whose distance to a wall is <= 0 gets no ghost from that
// wall and is listed in `penetrated` (ascending); the solver should stop with exit code 3
// (InstabilityError). A particle within the support whose ghost has no root (the set-up
// check should have refused; see check_ghost_walls) is listed in `no_root` and gets no
// ghost from that wall.
//
// Contract for the density and force passes (the solver integrates this):
//  - build a CellList<D> over `x` (same support and periodic axes as the fluid's) and, for
//    each fluid particle i, visit the ghosts g within 2h of x_i;
//  - density (summation, Barker eq. 20): sigma_i += beta[g] * W(|x_i - x_g|);
//  - ghost fields copied from the source s = source[g]: sigma_g = sigma_s, p_g = p_s,
//    rho_g = rho_s; velocity v[g] as above (already computed);
//  - forces: the ghost enters the pressure and viscous sums like a fluid neighbour j with
//    those fields, its term weighted by beta[g] (it stands for beta[g] source volumes, as in
//    the density sum; beta = 1 for mirror and density_preserving). Barker's eq. 22
//    (sigma_g = sigma_s beta, unweighted) is not used: see ghost_boundary.cpp. Ghosts are not
//    integrated in time; rebuild them after every position update (allocation-free after the first
//    build: every vector is reused).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "curvsph/boundary/ghost/ghost_map.hpp"
#include "curvsph/core/types.hpp"
#include "curvsph/geometry/faceted.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

template <int D>
class BoxWall;

enum class GhostVelocity { no_slip, free_slip };

const char* to_string(GhostVelocity m);
// "no_slip" | "free_slip"; anything else: InputError(file, key, ...).
GhostVelocity parse_ghost_velocity(const std::string& name, const std::string& file = {},
                                   const std::string& key = {});

template <int D>
struct GhostOptions {
  GhostMapKind map = GhostMapKind::mirror;
  GhostVelocity velocity = GhostVelocity::no_slip;
  Real support = 0;                    // 2h
  const CellList<D>* cells = nullptr;  // periodic wrap of ghost positions (optional)
};

template <int D>
class GhostSet {
 public:
  // Per ghost.
  std::vector<Vec<D>> x;                  // position (wrapped when periodic)
  std::vector<Vec<D>> v;                  // velocity
  std::vector<Vec<D>> v_slip;             // free-slip image for the continuity equation
                                          // (no_slip only; empty for free_slip: use v)
  std::vector<Real> beta;                 // volume weight
  std::vector<Index> source;              // fluid particle it mirrors
  std::vector<std::int32_t> wall;         // index in the WallSet (last reflection for corners)
  std::vector<double> depth;              // zeta' behind the (last) wall, > 0
  std::vector<double> source_depth;       // d of the source in front of that wall, > 0
  std::vector<VecD<D>> foot;              // foot point on that wall
  std::vector<VecD<D>> normal;            // its normal, into the fluid
  std::vector<std::uint8_t> reflections;  // 1 single; 2 .. 7 corner ghosts
  // Corner ghosts (reflections > 1) of flat faces (flat_corners.hpp), ascending by ghost
  // index, with the distinct faces reflected across in their first order (the wall loads
  // split a corner ghost's reaction between them; `wall` and `normal` above keep the last
  // face only).
  struct Corner {
    Index ghost;
    std::array<std::int32_t, 3> wall;
    std::array<VecD<D>, 3> normal;
    std::uint8_t faces;  // how many of the above are set (1 to 3)
  };
  std::vector<Corner> corners;
  // Per build.
  std::vector<Index> penetrated;  // fluid particles with distance <= 0 to some wall
  std::vector<Index> no_root;     // fluid particles within the support without a ghost root

  std::size_t size() const { return x.size(); }

  // Rebuilds every array from the fluid positions x_f and velocities v_f. OpenMP-parallel
  // over contiguous particle blocks; deterministic (independent of the thread count).
  void build(const std::vector<Vec<D>>& x_f, const std::vector<Vec<D>>& v_f,
             const WallSet<D>& walls, const GhostOptions<D>& options);

  struct Record {
    Vec<D> x, v, v_slip;
    Real beta;
    Index source;
    std::int32_t wall;
    double depth, source_depth;
    VecD<D> foot, normal;
    std::uint8_t reflections;
  };

 private:
  std::vector<std::vector<Record>> thread_ghosts_;
  std::vector<std::vector<Corner>> thread_corners_;  // ghost index local to the thread's buffer
  std::vector<std::vector<Index>> thread_penetrated_, thread_no_root_;
  std::vector<std::size_t> offsets_;
  std::vector<const BoxWall<D>*> boxes_;    // per wall: the box (either side), else null
  std::vector<const Faceted<D>*> faceted_;  // per wall: a faceted wall (a polygon), else null
  std::vector<const MultiFace<D>*> multi_;  // per wall: a wall of several faces, else null
};

// Set-up refusal (exit 2): for every wall N, the curvatures at the closest points of the
// given fluid positions (all of them: where the fluid can reach the wall) are checked with
// check_ghost_support(), and the feet of those within the support (0 < d < 2h) with
// check_concave_support() (a concave radius of curvature below 2h); the first failure throws
// InputError(file, "walls.N", reason) naming the wall, its radius of curvature and the
// largest h that works.
// Walls without any sample are checked with the conservative convex worst case of their
// smallest radius of curvature (ghost_max_depth_convex).
template <int D>
void check_ghost_walls(GhostMapKind map, const WallSet<D>& walls, Real support,
                       const std::vector<Vec<D>>& x_f, const std::string& file);

}  // namespace curvsph
