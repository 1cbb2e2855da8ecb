// The geometric Shepard factor at the floor rim of the cad_at_rest study's cylinder (radius
// 0.06 m, floor and side meeting at 90 degrees along a circle) at the study's resolutions, where
// the radius is only 2.25 h (H/dx = 6) to 3.4 h (H/dx = 9); reference: adaptive quadrature of W
// over the solid (tests/support/shepard_reference.hpp). test_wall_elements_cad.cpp checks the
// same construction at R = 10 h.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "../support/shepard_reference.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/cad/cad_import.hpp"

using namespace curvsph;

TEST(RimShepard, StudyCylinderFloorRimAgainstQuadrature) {
  const double R = 0.06, Hc = 0.16, depth = 0.08;
  WallSet<3> walls;
  for (auto& w :
       cad::faces_to_walls(BRepPrimAPI_MakeCylinder(R, Hc).Shape(), cad::FluidSide::inside, 1.0))
    walls.add(w);
  const test::Columns fluid = [&](double X, double Y) {
    std::vector<std::pair<double, double>> out;
    if (X * X + Y * Y < R * R) out.push_back({0.0, Hc});
    return out;
  };
  for (int n : {6, 9}) {
    const double dx = depth / n, h = 2 * dx;
    const auto el = elements_from_walls<3>(walls, dx, {});
    const GeometricShepard<3> fast(el, h);
    std::vector<std::size_t> all(el.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    double worst = 0;
    // From the rim along the bisector of floor and side, and 0.25 h above the floor towards
    // the axis (the first row of particles lies 0.25 h = dx / 2 off each wall).
    for (double phi : {0.3, 2.0})
      for (int path = 0; path < 2; ++path)
        for (double d : {0.05, 0.25, 0.5, 1.0, 1.5}) {
          const Vec3d radial(std::cos(phi), std::sin(phi), 0);
          const Vec3d x =
              path == 0
                  ? Vec3d(R * radial - d * h * M_SQRT1_2 * radial + Vec3d(0, 0, d * h * M_SQRT1_2))
                  : Vec3d((R - d * h) * radial + Vec3d(0, 0, 0.25 * h));
          const double ref = test::reference_gamma_3d(x, h, fluid);
          const double e = std::max(std::abs(shepard_geometric<3>(el, x, h) - ref),
                                    std::abs(fast(el, all, x) - ref));
          worst = std::max(worst, e);
          EXPECT_LT(e, 0.005) << "H/dx " << n << " path " << path << " d/h " << d << " ref " << ref;
        }
    std::printf("study cylinder rim, H/dx = %d (R = %.2f h): max |gamma - ref| = %.2e\n", n, R / h,
                worst);
  }
}
