// The fill of a closed CAD solid (region inside_walls, one CadSolidWall): the U-bend pipe of
// data/cad filled at dx = a / 4 (a = its bore radius), the particle count against the
// solid's volume and area from OpenCASCADE's BRepGProp, every particle inside the pipe and at
// least 0.3 dx from its wall by the pipe's own geometry (centre line and bore radius).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>

#include "curvsph/cad/cad_import.hpp"
#include "curvsph/cad/cad_solid_wall.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/setup/generate.hpp"
#include "curvsph_build_paths.hpp"

using namespace curvsph;

namespace {
const std::string kDir = CURVSPH_SOURCE_DIR "/data/cad";

// The U-pipe's wall distance from its own geometry, > 0 inside (scale 1000): the bore radius
// less the distance to the centre line (two straight legs and the bend's circle, from the
// STEP entities #149, #186, #223, #227), and the distance to the end caps. The legs' edges sit
// on the bend 1 mm from where its torus starts; the surfaces agree there to 1.2e-6 m
// (R (1 - cos(1.1e-3 / R))): the accuracy of this reference.
double pipe_distance(const Vec3d& x) {
  constexpr double a = 0.038100000470877, x0 = -3.499000072479248;
  constexpr double yl[2] = {0.495999991893768, -0.494000017642975};
  constexpr double tx = -0.001002013417651, ty = 0.000999987125397, zc = 0.000999998301268;
  constexpr double R = 0.495001018939938;
  if (x.x() >= tx) return a - std::hypot(std::hypot(x.x() - tx, x.y() - ty) - R, x.z() - zc);
  const double axis =
      std::min(std::hypot(x.y() - yl[0], x.z() - zc), std::hypot(x.y() - yl[1], x.z() - zc));
  return std::min(a - axis, x.x() - x0);
}
}  // namespace

TEST(CadSolidFill, UPipeDistanceMatchesItsGeometry) {
  if (!std::filesystem::exists(kDir + "/u_pipe.step")) GTEST_SKIP() << "no u_pipe.step";
  const WallSet<3> walls =
      parse_walls<3>(YAML::Load("[{shape: cad, file: u_pipe.step, fluid: inside, scale: 1000}]"),
                     kDir + "/case.yaml", kDir);
  ASSERT_EQ(walls.size(), 1u);
  // Points across the bore (inside and up to 1 cm outside) of both legs, the bend, the
  // junctions and the caps (the caps' edges: both distances count there, min of the two).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  int n = 0;
  for (int i = 0; i < 1500; ++i) {
    const double r = 0.048 * std::sqrt(u(rng)), ph = 2 * M_PI * u(rng);
    const int where = i % 3;
    Vec3d x;
    if (where < 2) {  // a leg, x from beyond the cap to the junction
      const double y = where == 0 ? 0.495999991893768 : -0.494000017642975;
      x = Vec3d(-3.52 + 3.54 * u(rng), y + r * std::cos(ph), 0.001 + r * std::sin(ph));
    } else {  // the bend
      const double t = M_PI * (u(rng) - 0.5), rho = 0.495001018939938 + r * std::cos(ph);
      x = Vec3d(-0.001002 + rho * std::cos(t), 0.001 + rho * std::sin(t), 0.001 + r * std::sin(ph));
    }
    const double exact = pipe_distance(x);
    // Outside beyond a cap's rim the nearest point is the rim, which the model does not give.
    if (x.x() < -3.499 && exact < 0 && r > 0.0381) continue;
    const WallPoint<3> p = walls[0].closest(x);
    worst = std::max(worst, std::abs(p.distance - exact));
    ++n;
  }
  std::cout << "u_pipe: " << n << " points, max |d - d_pipe| = " << worst << " m\n";
  EXPECT_LT(worst, 5e-6);
}

TEST(CadSolidFill, UPipeHoldsItsVolumeAndNoParticleOutside) {
  if (!std::filesystem::exists(kDir + "/u_pipe.step")) GTEST_SKIP() << "no u_pipe.step";
  // The file declares millimetres for coordinates meant as metres (docs/geometry.md): scale 1000
  // gives the 3.5 m legs and the 38.1 mm bore.
  constexpr double scale = 1000, a = 0.0381, dx = a / 4;
  const WallSet<3> walls =
      parse_walls<3>(YAML::Load("[{shape: cad, file: u_pipe.step, fluid: inside, scale: 1000}]"),
                     kDir + "/case.yaml", kDir);
  ASSERT_EQ(walls.size(), 1u);
  const auto* solid = dynamic_cast<const cad::CadSolidWall*>(&walls[0]);
  ASSERT_NE(solid, nullptr);
  const Case c = read_case(YAML::Load(fmt::format(R"(
dimension: 3
resolution: {{dx: {}}}
domain: {{min: [-3.55, -0.58, -0.05], max: [0.58, 0.58, 0.05]}}
fluids:
  - {{name: water, rho0: 1000, region: {{inside_walls: true}}}}
eos: {{type: linear, c0: 10}}
time: {{end: 0}}
)",
                                                  dx)),
                           "u_pipe_fill.yaml");
  Particles<3> P;
  const auto t0 = std::chrono::steady_clock::now();
  generate_particles<3>(c, P, walls);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // The reference: the solid's volume and area (OpenCASCADE's Gauss integration over the
  // B-rep), lengths scaled to metres. Lattice points at >= 0.3 dx from the wall fill the solid
  // eroded by 0.3 dx: volume V - 0.3 dx A to first order (the bore's curvature adds
  // (0.3 dx)^2 A / (2 a) = 0.2 % here).
  const TopoDS_Shape shape = cad::read_brep(kDir + "/u_pipe.step", "case.yaml", "file");
  GProp_GProps vp, sp;
  BRepGProp::VolumeProperties(shape, vp);
  BRepGProp::SurfaceProperties(shape, sp);
  const double V = vp.Mass() * scale * scale * scale, A = sp.Mass() * scale * scale;
  const double eroded = (V - 0.3 * dx * A) / (dx * dx * dx);
  const double n = static_cast<double>(P.size());
  std::cout << "u_pipe at dx = " << dx << ": " << P.size() << " particles in " << seconds
            << " s; V / dx^3 = " << V / (dx * dx * dx) << " (ratio " << n * dx * dx * dx / V
            << "), (V - 0.3 dx A) / dx^3 = " << eroded << " (ratio " << n / eroded << ")\n";
  EXPECT_NEAR(n / eroded, 1.0, 0.02);

  // Inside and >= 0.3 dx from the wall by the pipe's own geometry, every particle.
  double nearest = 1e300;
  for (std::size_t i = 0; i < P.size(); ++i)
    nearest = std::min(nearest, pipe_distance(P.x[i].cast<double>()));
  std::cout << "  nearest particle: " << nearest / dx << " dx from the wall (pipe geometry)\n";
  EXPECT_GE(nearest, 0.3 * dx - 2e-6);
}
