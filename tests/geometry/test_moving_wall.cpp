// Moving walls (geometry/moving_wall.hpp): a translated, a rotated and an oscillated circle,
// sphere and NURBS circle answer closest point, normal, distance, curvature and wall velocity
// as the analytic circle / sphere at the moved place, at several times. The reference writes
// the motion out by hand (rotation by Rodrigues' formula, not the code's Eigen rotation).
// Also: motions that map a shape onto itself keep the geometry in place, the parser reads
// `oscillate` and refuses malformed motions, and boundary elements follow the wall.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/moving_wall.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/wall_parser.hpp"

namespace curvsph {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double kRel = 1e-12;

// |a - b| <= 1e-12 (1 + |b|)
template <class V>
void expect_close(const V& a, const V& b, const char* what, double rel = kRel) {
  EXPECT_LE((a - b).norm(), rel * (1.0 + b.norm()))
      << what << ": " << a.transpose() << " vs " << b.transpose();
}
void expect_close(double a, double b, const char* what, double rel = kRel) {
  EXPECT_LE(std::abs(a - b), rel * (1.0 + std::abs(b))) << what << ": " << a << " vs " << b;
}

// Rodrigues: v rotated by angle th about the unit axis a.
Vec3d rodrigues(const Vec3d& v, const Vec3d& a, double th) {
  return v * std::cos(th) + a.cross(v) * std::sin(th) + a * a.dot(v) * (1 - std::cos(th));
}
Vec2d rot2(const Vec2d& v, double th) {
  return Vec2d(std::cos(th) * v.x() - std::sin(th) * v.y(),
               std::sin(th) * v.x() + std::cos(th) * v.y());
}

// The analytic ball/disc of radius R about c with the fluid outside, queried at x, against the
// moving wall `w` at the same time; `uw` the expected wall velocity at the foot.
template <int D>
void expect_ball(const Wall<D>& w, const VecD<D>& c, double R, const VecD<D>& x,
                 const VecD<D>& uw_expected_at_foot_offset_from, double omega_or_zero,
                 const VecD<D>& v_lin, double rel = kRel) {
  const WallPoint<D> p = w.closest(x);
  const VecD<D> u = (x - c).normalized();
  expect_close(p.foot, VecD<D>(c + R * u), "foot", rel);
  expect_close(p.normal, u, "normal", rel);
  expect_close(p.distance, (x - c).norm() - R, "distance", rel);
  expect_close(p.k1, -1.0 / R, "k1", rel);
  // Velocity: v + omega x (foot - centre of rotation) (2-D: omega about z; 3-D handled by the
  // caller through v_lin = 0 and its own check).
  if constexpr (D == 2) {
    const VecD<2> r = p.foot - uw_expected_at_foot_offset_from;
    const VecD<2> expected = v_lin + omega_or_zero * VecD<2>(-r.y(), r.x());
    expect_close(w.velocity(p.foot), expected, "velocity", rel);
  }
}

TEST(MovingWall, TranslatedRotatedOscillatedCircle) {
  const Vec2d c0(0.3, -0.2);
  const double R = 0.25;
  const auto circle = std::make_shared<CircleWall>(c0, R, FluidSide::outside);
  const std::vector<Vec2d> queries = {{0.9, 0.4}, {-0.4, -0.1}, {0.31, 0.35}};
  for (const double t : {0.0, 0.37, 1.9, 12.5}) {
    SCOPED_TRACE(t);
    WallMotion<2> tr;
    tr.kind = WallMotion<2>::Kind::translate;
    tr.velocity = Vec2d(0.7, -0.3);
    MovingWall<2> wt(circle, tr);
    wt.set_time(t);
    WallMotion<2> ro;
    ro.kind = WallMotion<2>::Kind::rotate;
    ro.omega = 1.3;
    ro.center = Vec2d(-0.5, 0.1);  // not the circle's centre: the circle moves
    MovingWall<2> wr(circle, ro);
    wr.set_time(t);
    WallMotion<2> os;
    os.kind = WallMotion<2>::Kind::oscillate;
    os.amplitude = Vec2d(0.15, 0.05);
    os.frequency = 0.8;
    os.phase = 0.4;
    MovingWall<2> wo(circle, os);
    wo.set_time(t);
    EXPECT_TRUE(wt.geometry_moves() && wr.geometry_moves() && wo.geometry_moves());
    const Vec2d ct = c0 + tr.velocity * t;
    const Vec2d cr = ro.center + rot2(c0 - ro.center, ro.omega * t);
    const double arg = 2 * pi * os.frequency * t + os.phase;
    const Vec2d co = c0 + os.amplitude * std::sin(arg);
    const Vec2d vo = os.amplitude * (2 * pi * os.frequency * std::cos(arg));
    for (const Vec2d& q : queries) {
      const Vec2d x = q + (ct - c0);  // keep the queries outside the moving circle
      expect_ball<2>(wt, ct, R, x, ct, 0.0, tr.velocity);
      expect_ball<2>(wr, cr, R, q + (cr - c0), ro.center, ro.omega, Vec2d::Zero());
      expect_ball<2>(wo, co, R, q + (co - c0), co, 0.0, vo);
    }
  }
}

// The rational quadratic circle of 9 control points (Piegl & Tiller §7.5), counter-clockwise,
// fluid outside (right of the direction of travel).
std::shared_ptr<NurbsCurveWall> nurbs_circle(const Vec2d& c, double R) {
  const double w = std::sqrt(0.5);
  std::vector<Vec2d> P;
  for (const auto& [x, y] :
       {std::pair{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}})
    P.push_back(c + R * Vec2d(x, y));
  nurbs::NurbsCurve<2> curve(2, P, {1, w, 1, w, 1, w, 1, w, 1},
                             {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1});
  return std::make_shared<NurbsCurveWall>(std::move(curve), NurbsCurveWall::Side::right, 1e-14);
}

TEST(MovingWall, NurbsCurveFollowsItsMotion) {
  const Vec2d c0(0.1, 0.2);
  const double R = 0.5;
  const auto nurbs = nurbs_circle(c0, R);
  WallMotion<2> ro;
  ro.kind = WallMotion<2>::Kind::rotate;
  ro.omega = -0.9;
  ro.center = Vec2d(1.0, 0.0);
  WallMotion<2> os;
  os.kind = WallMotion<2>::Kind::oscillate;
  os.amplitude = Vec2d(0.0, 0.3);
  os.frequency = 2.0;
  for (const double t : {0.0, 0.21, 3.3}) {
    SCOPED_TRACE(t);
    MovingWall<2> wr(nurbs, ro);
    wr.set_time(t);
    MovingWall<2> wo(nurbs, os);
    wo.set_time(t);
    const Vec2d cr = ro.center + rot2(c0 - ro.center, ro.omega * t);
    const double arg = 2 * pi * os.frequency * t;
    const Vec2d co = c0 + os.amplitude * std::sin(arg);
    const Vec2d vo = os.amplitude * (2 * pi * os.frequency * std::cos(arg));
    for (const Vec2d& q : {Vec2d(0.9, 0.8), Vec2d(-0.6, 0.1), Vec2d(0.2, -0.45)}) {
      expect_ball<2>(wr, cr, R, q + (cr - c0), ro.center, ro.omega, Vec2d::Zero());
      expect_ball<2>(wo, co, R, q + (co - c0), co, 0.0, vo);
    }
  }
}

TEST(MovingWall, RotatedAndTranslatedSphere) {
  const Vec3d c0(0.2, 0.1, -0.3);
  const double R = 0.4;
  const auto sphere = std::make_shared<SphereWall>(c0, R, FluidSide::outside);
  WallMotion<3> ro;
  ro.kind = WallMotion<3>::Kind::rotate;
  ro.omega = 0.75;
  ro.center = Vec3d(-0.4, 0.3, 0.2);
  ro.axis = Vec3d(1, 2, 2) / 3.0;
  WallMotion<3> tr;
  tr.kind = WallMotion<3>::Kind::translate;
  tr.velocity = Vec3d(-0.2, 0.5, 0.1);
  for (const double t : {0.0, 0.6, 4.1}) {
    SCOPED_TRACE(t);
    MovingWall<3> wr(sphere, ro);
    wr.set_time(t);
    MovingWall<3> wt(sphere, tr);
    wt.set_time(t);
    const Vec3d cr = ro.center + rodrigues(c0 - ro.center, ro.axis, ro.omega * t);
    const Vec3d ct = c0 + tr.velocity * t;
    for (const Vec3d& q : {Vec3d(1, 0.5, 0.2), Vec3d(-0.3, -0.6, 0.1), Vec3d(0.2, 0.1, 0.5)}) {
      expect_ball<3>(wr, cr, R, q + (cr - c0), cr, 0.0, Vec3d::Zero());
      const WallPoint<3> p = wr.closest(q + (cr - c0));
      expect_close(wr.velocity(p.foot), Vec3d(ro.omega * ro.axis.cross(p.foot - ro.center)),
                   "velocity");
      // Principal directions stay tangent to the moved sphere.
      EXPECT_LT(std::abs(p.dir1.dot(p.normal)), 1e-12);
      EXPECT_LT(std::abs(p.dir2.dot(p.normal)), 1e-12);
      expect_ball<3>(wt, ct, R, q + (ct - c0), ct, 0.0, Vec3d::Zero());
      expect_close(wt.velocity(wt.closest(q + (ct - c0)).foot), tr.velocity, "velocity");
    }
  }
}

TEST(MovingWall, MotionsThatMapTheShapeOntoItselfKeepTheGeometry) {
  const auto circle = std::make_shared<CircleWall>(Vec2d(1, 2), 0.5, FluidSide::inside);
  WallMotion<2> spin;
  spin.kind = WallMotion<2>::Kind::rotate;
  spin.omega = 3;
  spin.center = Vec2d(1, 2);
  MovingWall<2> w(circle, spin);
  w.set_time(0.7);
  EXPECT_FALSE(w.geometry_moves());
  const Vec2d x(1.2, 2.1);
  // Bit for bit the static circle's answer (the Couette cases do not change).
  EXPECT_EQ(w.closest(x).foot, circle->closest(x).foot);
  const Vec2d f = circle->closest(x).foot;
  expect_close(w.velocity(f), Vec2d(3 * Vec2d(-(f.y() - 2), f.x() - 1)), "surface velocity");
  spin.center = Vec2d(1.1, 2);
  EXPECT_TRUE(MovingWall<2>(circle, spin).geometry_moves());
}

TEST(MovingWall, ParserReadsOscillateAndRefusesMalformedMotions) {
  const auto parse2 = [](const std::string& y) {
    return parse_walls<2>(YAML::Load(y), "geom.yaml", ".");
  };
  const WallSet<2> set = parse2(
      "[{shape: circle, center: [0, 0], radius: 1, fluid: outside, motion: {oscillate: "
      "{amplitude: [0.5, 0], frequency: 2, phase: 0.3}}}, {shape: circle, center: [0, 0], "
      "radius: 3, fluid: inside}]");
  ASSERT_EQ(set.size(), 2u);
  EXPECT_TRUE(set[0].moves());
  EXPECT_FALSE(set[1].moves());  // static walls are not decorated
  EXPECT_EQ(dynamic_cast<const CircleWall*>(&set[1]), &set[1].body());
  set.set_time(0.1);
  const double disp = 0.5 * std::sin(2 * pi * 2 * 0.1 + 0.3);
  expect_close(set[0].closest(Vec2d(3, 0)).foot, Vec2d(1 + disp, 0), "oscillated foot");
  set.set_time(0.0);
  expect_close(set[0].closest(Vec2d(3, 0)).foot, Vec2d(1 + 0.5 * std::sin(0.3), 0),
               "foot at t = 0 (with the phase)");

  const auto expect_error = [&](const std::string& motion, const std::string& key,
                                const std::string& reason, int dim = 2) {
    SCOPED_TRACE(motion);
    const std::string y =
        dim == 2
            ? "[{shape: circle, center: [0, 0], radius: 1, fluid: outside, motion: " + motion + "}]"
            : "[{shape: sphere, center: [0, 0, 0], radius: 1, fluid: outside, motion: " + motion +
                  "}]";
    try {
      if (dim == 2)
        parse2(y);
      else
        parse_walls<3>(YAML::Load(y), "geom.yaml", ".");
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "geom.yaml");
      EXPECT_EQ(e.key(), key) << e.what();
      EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    }
  };
  expect_error("{oscillate: {amplitude: [1, 0]}}", "walls.0.motion.oscillate.frequency",
               "missing key");
  expect_error("{oscillate: {amplitude: [1, 0], frequency: 1, omega: 2}}",
               "walls.0.motion.oscillate.omega", "unknown key");
  expect_error("{oscillate: {amplitude: [1, 0], frequency: -1}}",
               "walls.0.motion.oscillate.frequency", ">= 0");
  expect_error("{oscillate: {amplitude: [1, 0, 0], frequency: 1}}",
               "walls.0.motion.oscillate.amplitude", "list of 2 numbers");
  expect_error("{oscillate: 3}", "walls.0.motion.oscillate", "map");
  expect_error("{wobble: {}}", "walls.0.motion.wobble", "unknown key");
  expect_error("{rotate: {omega: 1, center: [0, 0, 0]}}", "walls.0.motion.rotate.axis",
               "missing key", 3);
}

TEST(MovingWall, BoundaryElementsFollowTheWall) {
  // A circle of radius 0.3 rotating about a point off its centre: the elements of the moved
  // wall lie on the moved circle, with normals out of it (fluid outside), same total length.
  const Vec2d c0(0.4, 0.0), p(0.0, 0.1);
  const double R = 0.3, omega = 0.8, t = 1.3;
  WallMotion<2> ro;
  ro.kind = WallMotion<2>::Kind::rotate;
  ro.omega = omega;
  ro.center = p;
  MovingWall<2> w(std::make_shared<CircleWall>(c0, R, FluidSide::outside), ro);
  w.set_time(t);
  const Bounds<2> bounds(Vec2d(-2, -2), Vec2d(2, 2));
  const BoundaryElements<2> el = elements_from_wall<2>(w, 0.02, bounds);
  const BoundaryElements<2> still = elements_from_wall<2>(w.body(), 0.02, bounds);
  ASSERT_EQ(el.size(), still.size());
  ASSERT_GT(el.size(), 50u);
  const Vec2d c = p + rot2(c0 - p, omega * t);
  double length = 0;
  for (std::size_t b = 0; b < el.size(); ++b) {
    expect_close(el.centre[b], Vec2d(c + R * (el.centre[b] - c).normalized()), "centre on circle");
    expect_close(el.normal[b], Vec2d((el.centre[b] - c).normalized()), "normal");
    for (int v = 0; v < 2; ++v) expect_close((el.vertices[b][v] - c).norm(), R, "vertex");
    length += el.area[b];
  }
  expect_close(length, 2 * pi * R, "length", 1e-9);
}

}  // namespace
}  // namespace curvsph
