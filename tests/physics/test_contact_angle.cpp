// Contact angle (issue #6): the turned interface normal of physics/contact_angle.hpp against
// the normal of an exact circular cap meeting a flat wall and a curved (circle) wall at a
// known angle, and the circle-fit measurement of analysis/contact_angle_fit.hpp on synthetic
// caps whose angle is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "curvsph/analysis/contact_angle_fit.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/physics/contact_angle.hpp"

namespace curvsph {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

WallSet<2> walls_from(const char* yaml) {
  return parse_walls<2>(YAML::Load(yaml), "walls.yaml", ".");
}

// A drop of radius r centred at C meets the wall at P: its outward normal there is
// m = (P - C)/r, and the angle inside the drop is acos(m . n_w) (the definition of
// contact_angle.hpp, evaluated on the exact circle). The colour gradient of a particle at P
// points into the drop; we give contact_angle_normal the gradient of an interface at a wrong
// angle (`wrong`, on the same side of the wall normal) and the angle of the circle, and expect
// the circle's own inward normal back, magnitude kept.
void expect_turns_to_cap(const Vec2d& P, const Vec2d& C, const Vec2d& n_wall, double wrong) {
  const double r = (P - C).norm();
  const Vec2d m = (P - C) / r;
  const double theta = std::acos(m.dot(n_wall));
  const Vec2d t = (m - m.dot(n_wall) * n_wall).normalized();
  const Vec2d m_wrong = std::cos(wrong) * n_wall + std::sin(wrong) * t;
  const Vec<2> turned = contact_angle_normal<2>((-3.0 * m_wrong).cast<Real>(), n_wall.cast<Real>(),
                                                static_cast<Real>(theta));
  EXPECT_NEAR(turned.x(), -3.0 * m.x(), 1e-9) << "theta " << theta / kDeg;
  EXPECT_NEAR(turned.y(), -3.0 * m.y(), 1e-9) << "theta " << theta / kDeg;
}

TEST(ContactAngle, TurnedNormalOnAFlatWallIsTheCapNormal) {
  // Wall y = 0, fluid above; cap of radius 1 with angle t: centre (0, -cos t), contact points
  // (+-sin t, 0).
  for (double t : {20.0, 30.0, 60.0, 90.0, 120.0, 150.0}) {
    const Vec2d C(0, -std::cos(t * kDeg));
    for (double side : {-1.0, 1.0})
      for (double wrong : {5.0, 90.0, 175.0})
        expect_turns_to_cap(Vec2d(side * std::sin(t * kDeg), 0), C, Vec2d(0, 1), wrong * kDeg);
  }
}

TEST(ContactAngle, TurnedNormalOnACircleWallIsTheCapNormal) {
  // Fluid inside a circle of radius 1 (a bowl): wall normal at P is -P. A drop circle of
  // radius r centred at C cuts the bowl at P; its angle comes from the exact intersection.
  for (double r : {0.3, 0.5, 0.8})
    for (double cy : {-0.95, -0.8, -0.6}) {
      const Vec2d C(0.1, cy);
      // Intersection of |x| = 1 and |x - C| = r (right-hand point).
      const double d = C.norm();
      const double a = (1 + d * d - r * r) / (2 * d);
      if (!(a < 1)) continue;
      const Vec2d e = C / d, q(-e.y(), e.x());
      const Vec2d P = a * e + std::sqrt(1 - a * a) * q;
      ASSERT_NEAR(P.norm(), 1, 1e-12);
      ASSERT_NEAR((P - C).norm(), r, 1e-12);
      const WallSet<2> bowl =
          walls_from("[{shape: circle, center: [0, 0], radius: 1, fluid: inside}]");
      const WallPoint<2> wp = bowl.closest(P * (1 - 1e-9));
      ASSERT_NEAR((wp.normal + P).norm(), 0, 1e-6);
      for (double wrong : {10.0, 170.0}) expect_turns_to_cap(P, C, wp.normal, wrong * kDeg);
    }
}

TEST(ContactAngle, NormalAlongTheWallNormalIsLeftAlone) {
  const Vec<2> n(0, -2);
  const Vec<2> out = contact_angle_normal<2>(n, Vec<2>(0, 1), Real(0.5));
  EXPECT_EQ(out, n);
}

TEST(ContactAngle, LayerSelectsParticlesNearAWallWithAnAngle) {
  const auto node = YAML::Load(
      "[{shape: plane, point: [0, 0], normal: [0, 1], contact_angle: 45},"
      " {shape: plane, point: [0, 1], normal: [0, -1]}]");
  const WallSet<2> walls = parse_walls<2>(node, "w.yaml", ".");
  const auto angles = parse_contact_angles<2>(node, "w.yaml", ".");
  ASSERT_EQ(angles.size(), 2u);
  ASSERT_TRUE(angles[0].has_value());
  EXPECT_NEAR(*angles[0], 45 * kDeg, 1e-6);
  EXPECT_FALSE(angles[1].has_value());
  EXPECT_TRUE(contact_wall<2>(walls, angles, Vec<2>(0.3, 0.05), Real(0.1)).has_value());
  EXPECT_FALSE(contact_wall<2>(walls, angles, Vec<2>(0.3, 0.15), Real(0.1)).has_value());
  EXPECT_FALSE(contact_wall<2>(walls, angles, Vec<2>(0.3, 0.95), Real(0.1)).has_value());
}

TEST(ContactAngle, RejectsAnAngleOutsideZeroTo180) {
  const auto node =
      YAML::Load("[{shape: plane, point: [0, 0], normal: [0, 1], contact_angle: 180}]");
  EXPECT_THROW(parse_contact_angles<2>(node, "w.yaml", "."), InputError);
}

TEST(ContactAngleFit, CircleFitIsExactOnAnArc) {
  std::vector<Vec2d> pts;
  for (int k = 0; k < 12; ++k) {
    const double a = 0.2 + 0.05 * k;
    pts.emplace_back(3 + 0.7 * std::cos(a), -2 + 0.7 * std::sin(a));
  }
  const auto c = fit_circle(pts);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->center.x(), 3, 1e-9);
  EXPECT_NEAR(c->center.y(), -2, 1e-9);
  EXPECT_NEAR(c->radius, 0.7, 1e-9);
}

// Particles of a lattice (spacing dx) inside the fluid; the drop is the disk |x - C| < R.
void lattice_cap(const WallSet<2>& walls, const Vec2d& C, double R, double dx,
                 std::vector<Vec2d>& x, std::vector<int>& drop) {
  for (double px = -2.0 + dx / 2; px < 2.0; px += dx)
    for (double py = -2.0 + dx / 2; py < 2.0; py += dx) {
      const Vec2d p(px, py);
      if (walls.closest(p).distance < 0.3 * dx) continue;
      x.push_back(p);
      drop.push_back((p - C).norm() < R ? 1 : 0);
    }
}

TEST(ContactAngleFit, MeasuresTheAngleOfALatticeCapOnAFlatWall) {
  const WallSet<2> floor = walls_from("[{shape: plane, point: [0, 0], normal: [0, 1]}]");
  const double dx = 0.02, R = 0.6;  // 30 particles across the radius
  for (double t : {30.0, 60.0, 90.0, 120.0}) {
    const Vec2d C(0, -R * std::cos(t * kDeg));
    std::vector<Vec2d> x;
    std::vector<int> drop;
    lattice_cap(floor, C, R, dx, x, drop);
    const auto m = measure_contact_angles(x, drop, floor, 1.5 * dx, 1.5 * dx, 0.0);
    for (int s = 0; s < 2; ++s) {
      ASSERT_TRUE(m.side[s]) << "theta " << t << " side " << s;
      EXPECT_NEAR(m.side[s]->theta_deg, t, 3.0) << "side " << s;
    }
  }
}

TEST(ContactAngleFit, MeasuresTheAngleOfALatticeCapInABowl) {
  const WallSet<2> bowl =
      walls_from("[{shape: circle, center: [0, 0], radius: 1.9, fluid: inside}]");
  const double dx = 0.02, r = 0.6;
  for (double cy : {-1.9, -1.75, -1.6}) {
    const Vec2d C(0, cy);
    // Exact angle of the cap at the circle-circle intersection (as in the normal test).
    const double d = C.norm(), Rw = 1.9;
    const double a = (Rw * Rw + d * d - r * r) / (2 * d);
    const Vec2d P(std::sqrt(Rw * Rw - a * a), -a);
    const double expected = std::acos(((P - C) / r).dot(-P / Rw)) / kDeg;
    std::vector<Vec2d> x;
    std::vector<int> drop;
    lattice_cap(bowl, C, r, dx, x, drop);
    const auto m = measure_contact_angles(x, drop, bowl, 1.5 * dx, 1.5 * dx, 0.0);
    for (int s = 0; s < 2; ++s) {
      ASSERT_TRUE(m.side[s]) << "cy " << cy << " side " << s;
      EXPECT_NEAR(m.side[s]->theta_deg, expected, 3.0) << "cy " << cy << " side " << s;
    }
  }
}

}  // namespace
}  // namespace curvsph
