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

// All fluids of the case into P (mass = rho0 * volume, velocity from the fluid spec). Points
// closer than 0.3·dx to a wall, or on its far side, are dropped, so a region may overlap the
// walls; `inside_walls` fills the domain box on the fluid side of every wall. Fluids are
// painted in list order: where regions overlap, the fluid listed later wins.
template <int D>
void generate_particles(const Case& c, Particles<D>& P, const WallSet<D>& walls);

}  // namespace curvsph
