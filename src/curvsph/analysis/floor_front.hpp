#pragma once
// Where the water on a dry floor ends: the surge front of a dam break (analysis/surge_front.hpp).
// Two definitions, both returned:
//  - largest_x: the largest x of the particles within 2 dx of the lowest particle (a droplet in
//    the air above the floor does not count, one particle sliding on the floor ahead does);
//  - wet_x: where the water layer on the floor ends, as a photograph sees the front: along the
//    line y = floor + dx/2 (the first particle row) from x_start on, the last x where the SPH
//    interpolant of the fluid's indicator function falls below 1/2,
//      phi(r) = sum_j V_j [W(|r - r_j|) + W(|r - r_j'|)],  V_j = m_j / rho_j,
//    (the SPH interpolant sum_j V_j A_j W of the field A = 1: Monaghan 2005, Rep. Prog. Phys. 68,
//    1703), r_j' the image of r_j in the floor: the floor's images complete the kernel support that
//    the floor cuts, so phi = 1 in water resting on the floor and 1/2 at the edge of a half-space
//    of water. At h = 2 dx an isolated particle on the floor (phi = 0.23), or spray 2.5 dx apart,
//    is not a wet floor; a continuous row of particles (phi = 0.61) is. A dry patch behind the
//    front (a sheet that thins or lifts there) does not move the front back. The crossing is
//    interpolated linearly between samples dx/4 apart. NaN when no sample is wet.
#include <span>

#include "curvsph/core/types.hpp"

namespace curvsph {

struct FloorFront {
  double largest_x;
  double wet_x;
};

// x: particle positions; volume: m/rho per particle; floor_y: the floor's height; x_start:
// where the walk starts (inside the water); h: smoothing length of the Wendland C2 kernel.
FloorFront floor_front(std::span<const Vec<2>> x, std::span<const Real> volume, double floor_y,
                       double x_start, double dx, double h);

}  // namespace curvsph
