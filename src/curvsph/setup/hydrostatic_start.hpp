#pragma once
// The default start of a free-surface case (setup.hydrostatic, on under gravity across a
// non-periodic axis when the case has no `initial` field): each fluid region at rest-pressure
// balance with gravity instead of at p = p0 everywhere. Started at p = 0, a tank's water first
// falls into its own compression wave: the 0.2 x 0.1 m pool of
// tests/setup/test_hydrostatic_start.cpp loads its walls with 1.40 (ghosts) and 1.35
// (integrals) times its weight at t = 0.01 s, started hydrostatic with 1.013 and 0.979.
//
// The rule. Heights s = -g_n.x / |g_n| along the gravity g_n that loads a free surface (the
// gravity's components along non-periodic axes; a component along a periodic axis drives a
// flow and is not balanced by pressure). Per fluid region (one `fluids` entry, its particles'
// phase) the surface is the top of its own particles, s_top = max s_i + dx/2 (half a spacing
// above the highest particle: a lattice fill's first row lies dx/2 inside the region's face,
// so a box region's surface is its top face), and each particle gets
//   p_i = p0 + P(s_top - s_i),  dP/dz = rho(P) |g_n|,  P(0) = 0
// (the compressible balance of physics/compressible_column.hpp, as `initial.hydrostatic`),
// rho_i = rho(p_i) from the EOS and m_i = rho_i V_i with the volume V_i = m_i / rho0 the fill
// (or packing) gave it, so that the number density stays the lattice's. Velocities are kept.
// A region whose top is not level (a fill under tilted gravity, two disjoint pools of one
// fluid at different heights) is not at rest under this start: set setup.hydrostatic: false
// or an `initial` field there.
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/physics/eos.hpp"

namespace curvsph {

template <int D>
void hydrostatic_start(const Case& c, const Eos& eos, const std::vector<Real>& rho0,
                       Particles<D>& P);

}  // namespace curvsph
