// Wall-pressure probes (io/probes.hpp): on a lattice at rest with the hydrostatic pressure
// p = rho g (H - z) above a floor z = 0, a sensor on the floor must read rho g H (the field
// p_wall extrapolates the linear hydrostatic field exactly), while the plain Shepard average
// p reads the pressure at the centroid of the half support, lower by rho g times its height.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "curvsph/io/probes.hpp"

using namespace curvsph;

namespace {

// A lattice of n x n x rows particles of spacing 1/n filling the unit square's floor, density
// rho (cells_of: its cell list for the kernel W).
Particles<3> lattice_layer(int n, int rows, double rho) {
  const double dx = 1.0 / n;
  Particles<3> P;
  P.resize(static_cast<std::size_t>(n * n * rows));
  for (int k = 0; k < n * n * rows; ++k) {
    P.x[k] = Vec<3>((k % n + 0.5) * dx, (k / n % n + 0.5) * dx, (k / (n * n) + 0.5) * dx);
    P.rho[k] = rho;
    P.mass[k] = rho * dx * dx * dx;
    P.id[k] = k;
  }
  return P;
}

CellList<3> cells_of(const Particles<3>& P, const WendlandC2<3>& W) {
  CellList<3> cells;
  cells.configure(W.support, Vec3d::Zero(), Vec3d::Ones(), {false, false, false});
  cells.build(P.x);
  return cells;
}

}  // namespace

TEST(Probes, WallPressureOfAHydrostaticLayer) {
  const int n = 14;
  const double dx = 1.0 / n, rho = 998, g = 9.81, H = 1.0;
  const WendlandC2<3> W(2 * dx);
  Particles<3> P = lattice_layer(n, n, rho);
  for (std::size_t k = 0; k < P.size(); ++k) P.p[k] = rho * g * (H - P.x[k][2]);
  const CellList<3> cells = cells_of(P, W);
  ProbeSpec s;
  s.name = "S";
  s.point = Vec3d(0.5, 0.5, 0.0);
  s.fields = {"p", "p_wall"};
  const auto path = std::filesystem::temp_directory_path() / "curvsph_test_probes.csv";
  ProbeWriter<3> w({s}, path.string(), dx, Vec<3>(0, 0, -g));
  ASSERT_EQ(w.columns(), (std::vector<std::string>{"S.p", "S.p_wall"}));
  const auto v = w.sample(P, cells, W);
  EXPECT_NEAR(v[1], rho * g * H, 1e-9 * rho * g * H);
  // Centroid of the kernel-weighted half ball: z_c = int z W / int W over z > 0 (Wendland C2,
  // radial moment ratio int r^3 W dr / int r^2 W dr = 2h * 5/14... computed by quadrature here).
  double num = 0, den = 0;
  const int m = 20000;
  for (int i = 0; i < m; ++i) {
    const double r = (i + 0.5) / m * W.support;
    const double w3 = W.value(r) * r * r;
    num += w3 * r * 0.5;  // mean of cos(theta) over the upper hemisphere = 1/2
    den += w3;
  }
  const double zc = num / den;
  // The lattice's first row sits at dx/2, so the discrete centroid differs from the
  // continuous one by a few per cent of zc.
  EXPECT_NEAR(v[0], rho * g * (H - zc), 0.05 * rho * g * zc);
  EXPECT_LT(v[0], 0.97 * v[1]);
  std::filesystem::remove(path);
}

// A sensor with a face normal (probes.*.normal) reads only the fluid in front of its face:
// a sensor on top of a block at z = 0.5 whose kernel support reaches fluid below that plane
// (as the dam break's box-top sensors reach the run-up beside the box's front face). With
// p = 1000 Pa above the plane and -5000 Pa below it (no gravity), the sensor with the normal
// (0, 0, 1) reads 1000 Pa; without it, the W V-weighted mean of both, computed here by brute
// force over every particle (no cell list).
TEST(Probes, FaceNormalExcludesTheFluidBehindTheSensor) {
  const int n = 14;
  const double dx = 1.0 / n, rho = 1000;
  const WendlandC2<3> W(2 * dx);
  Particles<3> P = lattice_layer(n, n, rho);
  for (std::size_t k = 0; k < P.size(); ++k) P.p[k] = P.x[k][2] > 0.5 ? 1000.0 : -5000.0;
  const CellList<3> cells = cells_of(P, W);
  ProbeSpec s;
  s.name = "S";
  s.point = Vec3d(0.5, 0.5, 0.5);
  s.fields = {"p_wall"};
  ProbeSpec t;
  t.name = "T";
  t.point = s.point;
  t.fields = s.fields;
  t.normal = Vec3d(0, 0, 1);
  const auto path = std::filesystem::temp_directory_path() / "curvsph_test_probes_face.csv";
  ProbeWriter<3> w({s, t}, path.string(), dx);
  const auto v = w.sample(P, cells, W);
  double num = 0, den = 0;
  for (std::size_t k = 0; k < P.size(); ++k) {
    const double wk = W.value((P.x[k] - Vec<3>(0.5, 0.5, 0.5)).norm()) * P.mass[k] / P.rho[k];
    num += wk * P.p[k];
    den += wk;
  }
  EXPECT_NEAR(v[0], num / den, 1e-9 * 5000);
  EXPECT_LT(v[0], 0);  // half the support in tension: the mean is negative
  EXPECT_NEAR(v[1], 1000.0, 1e-9 * 1000);
  std::filesystem::remove(path);
}

// Water-height gauges (kind gauge): the height is the highest point of the gauge line where the
// kernel-weighted fluid fraction sum_j W V_j is at least 1/2, which for a lattice layer of n
// rows is its surface, n dx (a half space gives 1/2 exactly at its surface), to the march's
// step dx/4 and the lattice's departure from the half space (the sum at n dx is a little
// below 1/2: the reading is one step under). Checked against n dx within dx/2, and exactly
// against the same rule applied to a brute-force sum over all particles (no cell list).
// The layer fills the whole floor, so no side truncates the kernel.
TEST(Probes, GaugeReadsTheDepthOfALatticeLayer) {
  const int n = 14;
  const double dx = 1.0 / n, rho = 998;
  const WendlandC2<3> W(2 * dx);
  for (const int rows : {7, 4}) {
    const Particles<3> P = lattice_layer(n, rows, rho);
    const CellList<3> cells = cells_of(P, W);
    ProbeSpec s;
    s.name = "H";
    s.kind = ProbeSpec::Kind::gauge;
    s.point = Vec3d(0.5, 0.5, 0.0);
    s.direction = Vec3d(0, 0, 1);
    const auto path = std::filesystem::temp_directory_path() / "curvsph_test_gauge.csv";
    ProbeWriter<3> w({s}, path.string(), dx);
    const auto v = w.sample(P, cells, W);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_NEAR(v[0], rows * dx, dx / 2) << rows << " rows";
    double brute = 0;
    for (int k = 0; k * dx / 4 <= 1.0; ++k) {
      const Vec<3> x(0.5, 0.5, k * dx / 4);
      double frac = 0;
      for (std::size_t j = 0; j < P.size(); ++j)
        frac += W.value((x - P.x[j]).norm()) * P.mass[j] / P.rho[j];
      if (frac >= 0.5) brute = k * dx / 4;
    }
    EXPECT_NEAR(v[0], brute, 1e-12) << rows << " rows";
    std::filesystem::remove(path);
  }
}
