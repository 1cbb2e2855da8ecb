#pragma once
// Initial particles in the fluid regions of a case (DESIGN.md §3): a cell-centred lattice of
// spacing dx in boxes, disks and balls (so a periodic box of side L holds exactly (L/dx)^D
// particles), concentric rings in an annulus (they follow its walls).
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {

struct GeneratedPoint {
  Vec3d x;
  double volume;
};

// Lattice/ring points of one region, each with the volume it represents.
std::vector<GeneratedPoint> generate_region(const RegionSpec& region, int dimension, double dx,
                                            const std::string& file, const std::string& key);

// The concentric rings of an annulus region: `count` rings of pitch dr = (r_out - r_in) / count
// (count = round((r_out - r_in) / dx)); ring k sits at r_in + (k + 1/2) dr.
struct AnnulusRings {
  long count;
  double dr;
};
AnnulusRings annulus_rings(const RegionSpec& annulus, double dx);

// Appends rings k_begin <= k < k_end of the annulus's ring pattern to `out`. Rings 0..count-1
// are the region's own; k < 0 and k >= count continue the same pattern beyond its edges (the
// arrangement the fluid would have without walls; couette_initial calibrates masses on it).
void append_annulus_rings(const RegionSpec& annulus, const AnnulusRings& rings, long k_begin,
                          long k_end, double dx, std::vector<GeneratedPoint>& out);

// The number of particles generate_particles will make, from the regions' volumes / dx^D
// (an inside_walls region counts its whole domain box; regions are not intersected), before
// any is made: the memory check of a run (solver/run_guards.hpp). A double: it may exceed
// every integer type.
double estimate_particle_count(const Case& c);

// All fluids of the case into P (mass = rho0 * volume, velocity from the fluid spec). Points
// closer than 0.3·dx to a wall, or on its far side, are dropped, so a region may overlap the
// walls; `inside_walls` fills the domain box on the fluid side of every wall. Fluids are
// painted in list order: where regions overlap, the fluid listed later wins.
template <int D>
void generate_particles(const Case& c, Particles<D>& P, const WallSet<D>& walls);

}  // namespace curvsph
