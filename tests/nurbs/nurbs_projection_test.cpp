// Closest point vs brute force (dense sampling + Newton polish) on random rational curves
// and surfaces: zero wrong answers, where wrong = farther than brute force by > 1e-9 size.
#include <gtest/gtest.h>

#include <random>

#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/nurbs_surface_wall.hpp"
#include "curvsph/nurbs/projection.hpp"
#include "test_shapes.hpp"

using namespace curvsph;
using namespace curvsph::nurbs;

namespace {

template <int D>
double brute_curve(const CurveProjector<D>& pr, const NurbsCurve<D>& c,
                   const std::vector<VecD<D>>& pts, const std::vector<double>& ts,
                   const VecD<D>& x) {
  std::size_t best = 0;
  double bd = 1e300;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double d = (pts[i] - x).squaredNorm();
    if (d < bd) bd = d, best = i;
  }
  int it = 0;
  const double t = pr.newton(x, ts[best], c.t0(), c.t1(), 1e-14 * c.size(), it);
  return std::min(std::sqrt(bd), (c.point(t) - x).norm());
}

template <int D>
void check_curve(const NurbsCurve<D>& c, unsigned seed, int n_points) {
  const CurveProjector<D> pr(c);
  std::vector<VecD<D>> pts;
  std::vector<double> ts;
  const int M = 6000;
  for (int i = 0; i <= M; ++i) {
    ts.push_back(c.t0() + (c.t1() - c.t0()) * i / M);
    pts.push_back(c.point(ts.back()));
  }
  VecD<D> lo = pts[0], hi = pts[0];
  for (const auto& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const VecD<D> mid = 0.5 * (lo + hi), half = 0.75 * (hi - lo);
  // The point of highest curvature: queries near its centre of curvature are the hard ones.
  double kmax = 0, tk = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const double k = curvature(c.eval(ts[i]));
    if (k > kmax) kmax = k, tk = ts[i];
  }
  const auto dk = c.eval(tk);
  const VecD<D> towards = (dk.d2 - dk.d2.dot(dk.d1.normalized()) * dk.d1.normalized()).normalized();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0), S(0.0, 1.0);
  int wrong = 0, searched = 0;
  double worst = 0;
  for (int k = 0; k < n_points; ++k) {
    VecD<D> x;
    const int kind = k % 4;
    if (kind == 0 || kind == 1) {
      for (int d = 0; d < D; ++d) x[d] = mid[d] + half[d] * U(rng);
    } else if (kind == 2) {  // around the centre of curvature of the sharpest bend
      x = dk.c + towards * (S(rng) * 2.0 / kmax);
      for (int d = 0; d < D; ++d) x[d] += 0.05 * U(rng) / kmax;
    } else {  // beyond the ends
      const bool start = S(rng) < 0.5;
      const auto de = c.eval(start ? c.t0() : c.t1());
      x = de.c + (start ? -1.0 : 1.0) * de.d1.normalized() * S(rng) * 0.3 * c.size();
      for (int d = 0; d < D; ++d) x[d] += 0.1 * c.size() * U(rng);
    }
    const double ref = brute_curve(pr, c, pts, ts, x);
    // The box bound used to skip far walls never exceeds the true distance.
    EXPECT_LE(pr.lower_bound(x, 1e300), ref + 1e-12 * c.size());
    // Seeded as a boundary particle would (nearest sample), and with a random bad seed.
    const double seed_t = k % 2 ? c.t0() + (c.t1() - c.t0()) * S(rng) : ts[k % ts.size()];
    const Projection a = pr.project(x, nullptr, 1e-12 * c.size());
    const Projection b = pr.project(x, &seed_t, 1e-12 * c.size());
    searched += b.searched;
    for (const Projection* r : {&a, &b}) {
      EXPECT_NEAR((c.point(r->param[0]) - x).norm(), r->distance, 1e-12 * c.size());
      const double excess = r->distance - ref;
      worst = std::max(worst, excess);
      if (excess > 1e-9 * c.size()) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0) << "worst excess " << worst;
  ::testing::Test::RecordProperty("searched", searched);
}

}  // namespace

TEST(NurbsProjection, RandomCurves2DMatchBruteForce) {
  for (unsigned s = 1; s <= 3; ++s) check_curve<2>(test::random_curve<2>(s, 1 + s, 10), s, 10000);
}

TEST(NurbsProjection, RandomCurve3DMatchesBruteForce) {
  check_curve<3>(test::random_curve<3>(9, 3, 12), 9, 10000);
}

TEST(NurbsProjection, ClosedCircleMatchesBruteForce) {
  check_curve<2>(test::nurbs_circle(0.7, Vec2d(0.1, -0.2)), 5, 10000);
}

TEST(NurbsProjection, RandomSurfaceMatchesBruteForce) {
  const NurbsSurface s = test::random_surface(4, 3, 2, 7, 6);
  const SurfaceProjector pr(s);
  const int G = 120;
  std::vector<Vec3d> pts;
  std::vector<std::array<double, 2>> uv;
  for (int i = 0; i <= G; ++i)
    for (int j = 0; j <= G; ++j) {
      const double u = s.u0() + (s.u1() - s.u0()) * i / G, v = s.v0() + (s.v1() - s.v0()) * j / G;
      uv.push_back({u, v});
      pts.push_back(s.point(u, v));
    }
  Vec3d lo = pts[0], hi = pts[0];
  for (const auto& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> U(-1.0, 1.0), S(0.0, 1.0);
  int wrong = 0;
  double worst = 0;
  const double lo_p[2] = {s.u0(), s.v0()}, hi_p[2] = {s.u1(), s.v1()};
  for (int k = 0; k < 10000; ++k) {
    Vec3d x;
    if (k % 2) {
      for (int d = 0; d < 3; ++d) x[d] = 0.5 * (lo[d] + hi[d]) + 0.7 * (hi[d] - lo[d]) * U(rng);
    } else {  // near the surface, both sides (the usual SPH query)
      const auto& q = uv[static_cast<std::size_t>(S(rng) * (uv.size() - 1))];
      const SurfaceDerivs d = s.eval(q[0], q[1]);
      x = d.s + d.su.cross(d.sv).normalized() * 0.3 * U(rng);
    }
    std::size_t bi = 0;
    double bd = 1e300;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double d = (pts[i] - x).squaredNorm();
      if (d < bd) bd = d, bi = i;
    }
    double u = uv[bi][0], v = uv[bi][1];
    int it = 0;
    pr.newton(x, u, v, lo_p, hi_p, 1e-14 * s.size(), it);
    const double ref = std::min(std::sqrt(bd), (s.point(u, v) - x).norm());
    EXPECT_LE(pr.lower_bound(x, 1e300), ref + 1e-12 * s.size());
    const double seed[2] = {uv[(bi + 37 * k) % uv.size()][0], uv[(bi + 37 * k) % uv.size()][1]};
    const Projection r = pr.project(x, k % 3 ? seed : nullptr, 1e-12 * s.size());
    const double excess = r.distance - ref;
    worst = std::max(worst, excess);
    if (excess > 1e-9 * s.size()) ++wrong;
  }
  EXPECT_EQ(wrong, 0) << "worst excess " << worst;
}

TEST(NurbsCurveWall, CircleCurvatureAndSigns) {
  const double R = 0.025;
  for (auto side : {NurbsCurveWall::Side::left, NurbsCurveWall::Side::right}) {
    const NurbsCurveWall w(test::nurbs_circle(R), side);
    const double s = side == NurbsCurveWall::Side::left ? 1.0 : -1.0;  // left = inside
    EXPECT_NEAR(w.min_radius_of_curvature(), R, 1e-12);
    for (int k = 0; k < 360; ++k) {
      const double t = 4.0 * k / 360.0;
      const auto d = w.curve().eval(t);
      EXPECT_NEAR(d.c.norm(), R, 1e-15);
      EXPECT_NEAR(s * signed_curvature(d), s / R, 1e-12 / R);
      const double th = 2 * M_PI * (k + 0.5) / 360.0;
      const Vec2d x = 0.6 * R * Vec2d(std::cos(th), std::sin(th));
      const WallPoint<2> p = w.closest(x);
      EXPECT_NEAR(p.k1, s / R, 1e-12 / R);
      EXPECT_NEAR(p.distance, s * 0.4 * R, 1e-12);
      EXPECT_LT((p.foot - R * Vec2d(std::cos(th), std::sin(th))).norm(), 1e-12);
      EXPECT_LT((p.normal - (-s) * Vec2d(std::cos(th), std::sin(th))).norm(), 1e-12);
    }
  }
}

TEST(NurbsCurveWall, BoundaryParticlesSeedFastNewton) {
  const NurbsCurveWall w(test::random_curve<2>(3, 3, 10), NurbsCurveWall::Side::left);
  const double dx = 0.01;
  const auto bp = w.boundary_particles(dx);
  ASSERT_GT(bp.points.size(), 10u);
  for (std::size_t i = 1; i < bp.points.size(); ++i)
    EXPECT_NEAR(arc_length(w.curve(), bp.params[i - 1], bp.params[i]), bp.spacing,
                1e-9 * bp.spacing);
  EXPECT_NEAR(bp.spacing, dx, 0.5 * dx);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int max_it = 0;
  for (std::size_t i = 0; i < bp.points.size(); i += 3) {
    const Vec2d x = bp.points[i] + 2.5 * dx * Vec2d(U(rng), U(rng));
    std::size_t nearest = 0;
    for (std::size_t j = 0; j < bp.points.size(); ++j)
      if ((bp.points[j] - x).norm() < (bp.points[nearest] - x).norm()) nearest = j;
    ParamSeed seed;
    seed.param[0] = bp.params[nearest];
    seed.valid = true;
    const WallPoint<2> a = w.closest(x, seed), b = w.closest(x);
    EXPECT_NEAR(std::abs(a.distance), std::abs(b.distance), 1e-9);
    max_it = std::max(max_it, a.iterations);
  }
  EXPECT_LE(max_it, 10);
}
