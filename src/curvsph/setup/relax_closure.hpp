#pragma once
// The walls the ghost-map packing (setup/relax.hpp) holds the particles in. With
// `setup.relax.free_faces: hold`, a fluid whose box region ends inside the walls (the free
// surface of a tank) is packed against that face too: a plane wall on every free face, so the
// packing evens the node density up to the face instead of spreading the fluid past it
// (SPHinXsys packs a body inside its own shape in the same way). Without it
// (`open`, the default) a free face has no ghosts and its particles, short of neighbours,
// are driven outward.
//
// A face of a box region is free when it lies across a non-periodic axis and some of it (one
// point of a grid of sample points at about dx spacing, at most 64 per axis) is on the fluid
// side of every wall by more than the fill's clearance (0.3 dx, setup/generate.cpp): the fill
// ends there. A face that coincides with a wall (a tank floor) or lies beyond one is not free.
// Asking for most of the face instead left the top of a narrow-topped tank open (a 3-D wedge
// of 60 degree sides, the box region twice as wide as the water's surface: the packing spread
// the water to the apex, z = 0.80 for H = 0.5, and the run's pressure error was 0.60 of
// rho g H at 1 s).
#include "curvsph/geometry/wall.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {

// The case's walls followed by one plane per free face of each fluid's box region (only with
// c.relax.hold_free_faces; the walls alone otherwise).
template <int D>
WallSet<D> relax_walls(const Case& c, const WallSet<D>& walls);

}  // namespace curvsph
