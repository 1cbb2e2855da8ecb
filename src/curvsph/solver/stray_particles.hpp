#pragma once
// What a run does with one particle that misbehaves, so that no run is ended by one particle
// (DESIGN.md §3, "One stray particle ... is handled and counted, not fatal"):
//
//  - a density outside [lo, hi] rho0 (density.clamp) is set to the bound and counted
//    (DualSPHysics bounds the density the same way, to [700, 1300] kg/m^3 for water);
//  - a particle that comes closer to a wall than boundary.contact (a fraction of dx, default
//    0.1: Calderon et al.'s d0 of the wall force) is stopped there: put on that distance along
//    the wall normal with its normal velocity towards the wall removed, and counted
//    (wall_contacts). A last resort since both boundary families keep particles off their
//    walls themselves (boundary/wall_impact.hpp: the impact pressure of a particle
//    approaching a wall and the contact layer within 0.1 dx of it). Before those terms
//    neither family stiffened as a particle neared the wall, and 27-49 % of the particles of
//    the free-surface cases reached this contact (column on a cylinder, mirror_beta,
//    dx = 0.01: 821 of 2400; with the contact off 996 put back from past a wall over 1.5 s);
//    with them none of the 2-D cases reaches it (docs/validation/free_surface/findings.md).
//    The contact is the kinematic condition u.n = u_w.n, applied at d0 rather than at the
//    wall;
//  - a particle found past a wall (signed distance <= 0; with contact on, only one that
//    crossed in a single step) is put back the same way and counted (particles_projected;
//    boundary.penetration: project), or stops the run (penetration: stop);
//  - a particle outside the removal box (the domain box, or the box around the initial
//    particles and the bounded walls grown by its largest extent on every side; periodic axes
//    never) is removed and counted.
// NaN and Inf stay fatal (exit 3): they are never one particle's business.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// Depth, in dx, at which a particle found past a wall is put back when boundary.contact is 0:
// half the nominal distance of a first particle row (dx/2), so that it neither sits on the
// wall (where its own ghost coincides with it and the pair force vanishes) nor jumps into the
// second row.
inline constexpr double kProjectDepth = 0.25;

// What project_out_of_walls() did to a particle.
enum class WallFix { none, contact, projected };

// Clamps rho[i] of particles [0, n) to [lo, hi] times their fluid's rho0; returns how many
// were outside. Deterministic; parallel over particles.
template <int D>
long clamp_density(Particles<D>& P, Index n, const std::vector<Real>& rho0, Real lo, Real hi);

// Puts a particle closer than `depth` to a wall (or past it) at `depth` from every such wall
// (up to three passes, for corners where moving it off one wall moves it onto another), its
// normal velocity towards the wall removed; the wall velocity at the foot (WallMotion) is the
// reference. Returns projected when it was past a wall, contact when only closer than depth.
template <int D>
WallFix project_out_of_walls(const WallSet<D>& walls, Vec<D>& x, Vec<D>& v, double depth);

// The box outside which particles are removed (non-periodic axes only).
template <int D>
struct RemovalBox {
  Eigen::AlignedBox<double, D> box;
  std::array<bool, 3> periodic{false, false, false};
  bool outside(const Vec<D>& x) const {
    for (int d = 0; d < D; ++d)
      if (!periodic[static_cast<std::size_t>(d)] && !(x[d] >= box.min()[d] && x[d] <= box.max()[d]))
        return true;
    return false;
  }
};

// The domain box when the case has one, else the bounding box of x and of the bounded walls
// (box walls; the others by their boundary elements: a polygon or CAD tank) grown
// by its largest extent on every side (at least one dx).
template <int D>
RemovalBox<D> removal_box(bool has_domain, const Vec3d& lo, const Vec3d& hi,
                          const std::array<bool, 3>& periodic, const std::vector<Vec<D>>& x,
                          const WallSet<D>& walls, double dx);

}  // namespace curvsph
