// Every analytic wall against brute force: for >= 10^4 random points per shape (uniform,
// close to the wall, near the centre / axis, near the points of highest curvature) the
// answer must be a point ON the wall, no dense sample of the wall may be closer, the normal
// must be unit and x = foot + distance * normal (so it points into the fluid), and the sign
// of the distance must match the side of the wall x is on. Zero wrong answers allowed.
#include <gtest/gtest.h>

#include <functional>
#include <numbers>
#include <random>

#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/ellipse.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/torus.hpp"

namespace curvsph {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kQueries = 10000;

template <int D>
struct BruteCase {
  const Wall<D>& wall;
  FluidSide side;
  std::vector<VecD<D>> samples;                       // dense points exactly on the wall
  std::vector<VecD<D>> queries;                       // points to ask about
  std::function<bool(const VecD<D>&)> interior;       // strictly inside the closed shape
  std::function<double(const VecD<D>&)> off_surface;  // ~0 for points on the wall
};

template <int D>
void run_case(const BruteCase<D>& c) {
  int wrong = 0;
  int max_iterations = 0;
  for (const VecD<D>& x : c.queries) {
    const WallPoint<D> p = c.wall.closest(x);
    max_iterations = std::max(max_iterations, p.iterations);
    const double scale = 1.0 + x.norm();
    double best2 = std::numeric_limits<double>::infinity();
    for (const VecD<D>& s : c.samples) best2 = std::min(best2, (x - s).squaredNorm());
    const double best = std::sqrt(best2);
    const bool fluid_side = c.interior(x) == (c.side == FluidSide::inside);
    std::string why;
    if (std::abs(p.normal.norm() - 1.0) > 1e-12) why = "normal not unit";
    if (std::abs(c.off_surface(p.foot)) > 1e-12 * scale) why = "foot not on the wall";
    if (std::abs((x - p.foot).norm() - std::abs(p.distance)) > 1e-12 * scale)
      why = "|x - foot| != |distance|";
    if (std::abs(p.distance) > best + 1e-12 * scale) why = "a sample of the wall is closer";
    if ((x - p.foot - p.distance * p.normal).norm() > 1e-10 * scale)
      why = "x != foot + distance * normal";
    if (std::abs(p.distance) > 1e-9 && (p.distance > 0) != fluid_side) why = "distance sign";
    if (D == 3 && p.k1 < p.k2) why = "k1 < k2";  // in 2-D only k1 is used (k2 = 0)
    if (!why.empty() && ++wrong <= 5)
      ADD_FAILURE() << c.wall.describe() << ": " << why << " at x = " << x.transpose()
                    << " (distance " << p.distance << ", brute force " << best << ")";
  }
  EXPECT_EQ(wrong, 0) << c.wall.describe();
  // The ellipse's safeguarded Newton must stay cheap even at the centre and near the axes.
  EXPECT_LE(max_iterations, 80) << c.wall.describe();
  ::testing::Test::RecordProperty("max_iterations", max_iterations);
}

// Log-uniform magnitude in [lo, hi] with a random sign: reaches both 1e-12 and 1e-1.
double log_uniform(std::mt19937_64& rng, double lo, double hi, bool signed_ = true) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  const double m = std::exp(u(rng));
  return signed_ && (rng() & 1) ? -m : m;
}

template <int D>
VecD<D> uniform_in(std::mt19937_64& rng, const VecD<D>& lo, const VecD<D>& hi) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  VecD<D> x;
  for (int i = 0; i < D; ++i) x[i] = lo[i] + u(rng) * (hi[i] - lo[i]);
  return x;
}

template <int D>
VecD<D> random_offset(std::mt19937_64& rng, double lo, double hi) {
  VecD<D> v;
  for (int i = 0; i < D; ++i) v[i] = log_uniform(rng, lo, hi);
  return v;
}

// Queries: 50% uniform in the box, 20% within [1e-9, 0.1] of the wall, 15% within
// [1e-12, 1e-2] of each special point (centre, axis points, tips).
template <int D>
std::vector<VecD<D>> make_queries(std::mt19937_64& rng, const VecD<D>& lo, const VecD<D>& hi,
                                  const std::vector<VecD<D>>& surface,
                                  const std::vector<VecD<D>>& special) {
  std::vector<VecD<D>> q;
  std::uniform_int_distribution<std::size_t> pick_s(0, surface.size() - 1);
  while (q.size() < kQueries / 2) q.push_back(uniform_in<D>(rng, lo, hi));
  while (q.size() < kQueries * 7 / 10)
    q.push_back(surface[pick_s(rng)] + random_offset<D>(rng, 1e-9, 0.1));
  std::size_t k = 0;
  while (q.size() < kQueries)
    q.push_back(special[k++ % special.size()] + random_offset<D>(rng, 1e-12, 1e-2));
  return q;
}

std::vector<Vec2d> ellipse_samples(const Vec2d& c, double a, double b, int n) {
  std::vector<Vec2d> s;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    s.emplace_back(c + Vec2d(a * std::cos(t), b * std::sin(t)));
  }
  return s;
}

TEST(GeometryBruteForce, Circle) {
  std::mt19937_64 rng(1);
  const Vec2d c(0.3, -0.2);
  const double R = 0.05;  // small radius: high curvature
  const auto samples = ellipse_samples(c, R, R, 20000);
  const auto queries =
      make_queries<2>(rng, c - Vec2d(0.2, 0.2), c + Vec2d(0.2, 0.2), samples, {c, c + Vec2d(R, 0)});
  for (FluidSide side : {FluidSide::inside, FluidSide::outside}) {
    const CircleWall w(c, R, side);
    run_case<2>({w, side, samples, queries, [&](const Vec2d& x) { return (x - c).norm() < R; },
                 [&](const Vec2d& f) { return (f - c).norm() - R; }});
  }
}

void ellipse_case(double a, double b, FluidSide side, unsigned seed) {
  std::mt19937_64 rng(seed);
  const Vec2d c(-1.0, 0.5);
  const EllipseWall w(c, a, b, side);
  const auto samples = ellipse_samples(c, a, b, 40000);
  const double big = std::max(a, b);
  const Vec2d ext(2 * big, 2 * big);
  // The centre, the tips (highest and lowest curvature) and the evolute's cusps, where the
  // closest point jumps.
  const double ea = (a * a - b * b) / a, eb = (b * b - a * a) / b;
  const std::vector<Vec2d> special{
      c, c + Vec2d(a, 0), c - Vec2d(a, 0), c + Vec2d(0, b), c + Vec2d(ea, 0), c + Vec2d(0, eb)};
  const auto queries = make_queries<2>(rng, c - ext, c + ext, samples, special);
  run_case<2>({w, side, samples, queries,
               [&](const Vec2d& x) {
                 const Vec2d r = x - c;
                 return (r.x() / a) * (r.x() / a) + (r.y() / b) * (r.y() / b) < 1.0;
               },
               [&](const Vec2d& f) {
                 const Vec2d r = f - c;
                 return (r.x() / a) * (r.x() / a) + (r.y() / b) * (r.y() / b) - 1.0;
               }});
}

TEST(GeometryBruteForce, EllipseElongated) {
  ellipse_case(3.0, 0.3, FluidSide::inside, 2);
}
TEST(GeometryBruteForce, EllipseTallOutside) {
  ellipse_case(0.4, 1.0, FluidSide::outside, 3);
}
TEST(GeometryBruteForce, EllipseNearlyCircular) {
  ellipse_case(1.0, 1.0 - 1e-7, FluidSide::inside, 4);
}

template <int D>
std::vector<VecD<D>> box_samples(const VecD<D>& lo, const VecD<D>& hi, int n) {
  // n points per edge of every face (a grid on each face).
  std::vector<VecD<D>> s;
  for (int axis = 0; axis < D; ++axis)
    for (double face : {lo[axis], hi[axis]}) {
      const int m = D == 2 ? n : n * n;
      for (int k = 0; k < m; ++k) {
        VecD<D> p;
        int rest = k;
        for (int i = 0; i < D; ++i) {
          if (i == axis) {
            p[i] = face;
            continue;
          }
          p[i] = lo[i] + (hi[i] - lo[i]) * (rest % n) / (n - 1);
          rest /= n;
        }
        s.push_back(p);
      }
    }
  return s;
}

template <int D>
void box_case(FluidSide side, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  VecD<D> lo, hi;
  for (int i = 0; i < D; ++i) lo[i] = -0.5 - 0.25 * i, hi[i] = 0.7 + 0.1 * i;
  const BoxWall<D> w(lo, hi, side);
  const auto samples = box_samples<D>(lo, hi, n);
  std::vector<VecD<D>> special{0.5 * (lo + hi), lo, hi};
  const VecD<D> ext = VecD<D>::Constant(0.6);
  const auto queries = make_queries<D>(rng, lo - ext, hi + ext, samples, special);
  run_case<D>({w, side, samples, queries,
               [&](const VecD<D>& x) {
                 return (x.array() > lo.array()).all() && (x.array() < hi.array()).all();
               },
               [&](const VecD<D>& f) {
                 // 0 when on the boundary of the closed box, else its distance to it.
                 const VecD<D> out = (lo - f).cwiseMax(f - hi).cwiseMax(0.0);
                 if (out.norm() > 0) return out.norm();
                 return (f - lo).cwiseMin(hi - f).minCoeff();
               }});
}

TEST(GeometryBruteForce, Box2D) {
  box_case<2>(FluidSide::inside, 5000, 5);
  box_case<2>(FluidSide::outside, 5000, 6);
}
TEST(GeometryBruteForce, Box3D) {
  box_case<3>(FluidSide::outside, 60, 7);
}

TEST(GeometryBruteForce, Sphere) {
  std::mt19937_64 rng(8);
  const Vec3d c(0.1, 0.2, -0.3);
  const double R = 0.4;
  std::vector<Vec3d> samples;
  const int nt = 120, np = 240;
  for (int i = 0; i <= nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double t = kPi * i / nt, ph = 2 * kPi * j / np;
      samples.push_back(
          c + R * Vec3d(std::sin(t) * std::cos(ph), std::sin(t) * std::sin(ph), std::cos(t)));
    }
  const auto queries = make_queries<3>(rng, c - Vec3d::Constant(1), c + Vec3d::Constant(1), samples,
                                       {c, c + Vec3d(0, 0, R)});
  const SphereWall w(c, R, FluidSide::outside);
  run_case<3>({w, FluidSide::outside, samples, queries,
               [&](const Vec3d& x) { return (x - c).norm() < R; },
               [&](const Vec3d& f) { return (f - c).norm() - R; }});
}

TEST(GeometryBruteForce, Cylinder) {
  std::mt19937_64 rng(9);
  const Vec3d p0(0.2, 0.0, 0.1);
  const Vec3d axis = Vec3d(1.0, 2.0, -0.5).normalized();
  const double R = 0.3;
  const auto [e1, e2] = orthonormal_frame(axis);
  std::vector<Vec3d> samples;
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j < 200; ++j) {
      const double v = -2.0 + 4.0 * i / 200, ph = 2 * kPi * j / 200;
      samples.push_back(p0 + v * axis + R * (std::cos(ph) * e1 + std::sin(ph) * e2));
    }
  // Queries stay within |v| < 1 so every foot lies inside the sampled length.
  std::vector<Vec3d> near_axis;
  for (double v : {-0.5, 0.0, 0.7}) near_axis.push_back(p0 + v * axis);
  auto queries = make_queries<3>(rng, p0 - Vec3d::Constant(0.5), p0 + Vec3d::Constant(0.5), samples,
                                 near_axis);
  std::erase_if(queries, [&](const Vec3d& x) { return std::abs(axis.dot(x - p0)) > 1.0; });
  ASSERT_GT(queries.size(), 9000u);
  const auto radial = [&](const Vec3d& x) {
    const Vec3d r = x - p0;
    return (r - axis.dot(r) * axis).norm();
  };
  const CylinderWall w(p0, axis, R, FluidSide::inside);
  run_case<3>({w, FluidSide::inside, samples, queries,
               [&](const Vec3d& x) { return radial(x) < R; },
               [&](const Vec3d& f) { return radial(f) - R; }});
}

void torus_case(double big, double small, FluidSide side, unsigned seed) {
  std::mt19937_64 rng(seed);
  const Vec3d c(-0.1, 0.3, 0.2);
  const Vec3d axis = Vec3d(0.3, -0.2, 1.0).normalized();
  const auto [e1, e2] = orthonormal_frame(axis);
  std::vector<Vec3d> samples;
  const int nphi = 300, nth = 120;
  for (int i = 0; i < nphi; ++i)
    for (int j = 0; j < nth; ++j) {
      const double ph = 2 * kPi * i / nphi, th = 2 * kPi * j / nth;
      const Vec3d radial = std::cos(ph) * e1 + std::sin(ph) * e2;
      samples.push_back(c + (big + small * std::cos(th)) * radial + small * std::sin(th) * axis);
    }
  // The centre and points of the axis, the tube's centre circle, the inner equator.
  const std::vector<Vec3d> special{c, c + 0.5 * axis, c + big * e1, c + (big - small) * e2};
  const double ext = big + small + 0.5;
  const auto queries =
      make_queries<3>(rng, c - Vec3d::Constant(ext), c + Vec3d::Constant(ext), samples, special);
  const auto tube = [&](const Vec3d& x) {
    const Vec3d r = x - c;
    const double h = axis.dot(r);
    return std::hypot((r - h * axis).norm() - big, h);
  };
  const TorusWall w(c, axis, big, small, side);
  run_case<3>({w, side, samples, queries, [&](const Vec3d& x) { return tube(x) < small; },
               [&](const Vec3d& f) { return tube(f) - small; }});
}

TEST(GeometryBruteForce, TorusThinInside) {
  torus_case(1.0, 0.2, FluidSide::inside, 10);
}
TEST(GeometryBruteForce, TorusFatOutside) {
  torus_case(1.0, 0.6, FluidSide::outside, 11);
}

}  // namespace
}  // namespace curvsph
