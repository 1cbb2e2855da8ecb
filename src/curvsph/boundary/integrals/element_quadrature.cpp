#include "curvsph/boundary/integrals/element_quadrature.hpp"

#include <array>
#include <cmath>

namespace curvsph {

namespace {

constexpr double kGauss2 = 0.5773502691896257;  // 1/sqrt(3): 2-point Gauss-Legendre node

// Fills the kPoints slots of element b from points (relative to the centre) and unnormalised
// weights; the weights become area fractions.
template <int D, std::size_t N>
void store(ElementQuadrature<D>& q, std::size_t b, const std::array<VecD<D>, N>& y,
           const std::array<double, N>& w, const VecD<D>& centre) {
  double sum = 0;
  for (double wk : w) sum += wk;
  if (!(sum > 0)) {
    // A degenerate element (zero length or area, e.g. a sliver triangle of an STL mesh): its
    // whole weight at the centre, as the midpoint rule, rather than stopping the run.
    for (std::size_t k = 0; k < N; ++k) {
      q.offset[b * ElementQuadrature<D>::kPoints + k] = Vec<D>::Zero();
      q.weight[b * ElementQuadrature<D>::kPoints + k] = k == 0 ? 1 : 0;
    }
    return;
  }
  for (std::size_t k = 0; k < N; ++k) {
    q.offset[b * ElementQuadrature<D>::kPoints + k] = (y[k] - centre).template cast<Real>();
    q.weight[b * ElementQuadrature<D>::kPoints + k] = static_cast<Real>(w[k] / sum);
  }
}

// Parabola through a (u = -1), the centre c (u = 0) and b (u = 1); weights |y'(u)|.
void segment_points(ElementQuadrature<2>& q, std::size_t e, const Vec2d& a, const Vec2d& b,
                    const Vec2d& c) {
  const Vec2d half = 0.5 * (b - a), bow = 0.5 * (a + b) - c;
  std::array<Vec2d, 2> y;
  std::array<double, 2> w;
  for (int k = 0; k < 2; ++k) {
    const double u = k == 0 ? -kGauss2 : kGauss2;
    y[k] = c + u * half + u * u * bow;
    w[k] = (half + 2 * u * bow).norm();
  }
  store<2>(q, e, y, w, c);
}

// Bilinear patch through v0..v3 (s, t in [-1, 1]) lifted by (1 - s^2)(1 - t^2) d so that
// (0, 0) maps to the centre c; weights |dy/ds x dy/dt|.
void quad_points(ElementQuadrature<3>& q, std::size_t e, const std::array<Vec3d, 4>& v,
                 const Vec3d& c) {
  const auto bilinear = [&](double s, double t) {
    return 0.25 * ((1 - s) * (1 - t) * v[0] + (1 + s) * (1 - t) * v[1] + (1 + s) * (1 + t) * v[2] +
                   (1 - s) * (1 + t) * v[3]);
  };
  const Vec3d d = c - bilinear(0, 0);
  std::array<Vec3d, 4> y;
  std::array<double, 4> w;
  for (int k = 0; k < 4; ++k) {
    const double s = (k & 1) ? kGauss2 : -kGauss2, t = (k & 2) ? kGauss2 : -kGauss2;
    y[k] = bilinear(s, t) + (1 - s * s) * (1 - t * t) * d;
    const Vec3d ds =
        0.25 * ((1 - t) * (v[1] - v[0]) + (1 + t) * (v[2] - v[3])) - 2 * s * (1 - t * t) * d;
    const Vec3d dt =
        0.25 * ((1 - s) * (v[3] - v[0]) + (1 + s) * (v[2] - v[1])) - 2 * t * (1 - s * s) * d;
    w[k] = ds.cross(dt).norm();
  }
  store<3>(q, e, y, w, c);
}

// Degree-2 rule at barycentric (2/3, 1/6, 1/6) and its permutations, lifted by the bubble
// 27 l0 l1 l2 d towards the centre; equal weights (the fourth point has weight 0).
void triangle_points(ElementQuadrature<3>& q, std::size_t e, const std::array<Vec3d, 3>& v,
                     const Vec3d& c) {
  const Vec3d d = c - (v[0] + v[1] + v[2]) / 3;
  std::array<Vec3d, 4> y;
  std::array<double, 4> w = {1, 1, 1, 0};
  for (int k = 0; k < 3; ++k) {
    std::array<double, 3> l = {1.0 / 6, 1.0 / 6, 1.0 / 6};
    l[static_cast<std::size_t>(k)] = 2.0 / 3;
    y[k] = l[0] * v[0] + l[1] * v[1] + l[2] * v[2] + 27 * l[0] * l[1] * l[2] * d;
  }
  y[3] = c;
  store<3>(q, e, y, w, c);
}

}  // namespace

template <int D>
ElementQuadrature<D> element_quadrature(const BoundaryElements<D>& el) {
  ElementQuadrature<D> q;
  const std::size_t m = el.size();
  q.offset.assign(m * ElementQuadrature<D>::kPoints, Vec<D>::Zero());
  q.weight.assign(m * ElementQuadrature<D>::kPoints, 0);
  for (std::size_t b = 0; b < m; ++b) {
    const auto& v = el.vertices[b];
    if constexpr (D == 2) {
      segment_points(q, b, v[0], v[1], el.centre[b]);
    } else if (el.vertex_count[b] == 4) {
      quad_points(q, b, {v[0], v[1], v[2], v[3]}, el.centre[b]);
    } else {
      triangle_points(q, b, {v[0], v[1], v[2]}, el.centre[b]);
    }
  }
  return q;
}

template ElementQuadrature<2> element_quadrature<2>(const BoundaryElements<2>&);
template ElementQuadrature<3> element_quadrature<3>(const BoundaryElements<3>&);

}  // namespace curvsph
