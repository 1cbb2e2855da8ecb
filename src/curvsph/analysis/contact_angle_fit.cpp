#include "curvsph/analysis/contact_angle_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace curvsph {

std::optional<Circle2> fit_circle(const std::vector<Vec2d>& points) {
  if (points.size() < 3) return std::nullopt;
  // Centre and scale the points first: the normal equations of the raw coordinates are badly
  // conditioned far from the origin.
  Vec2d mean = Vec2d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double scale = 0;
  for (const auto& p : points) scale = std::max(scale, (p - mean).norm());
  if (!(scale > 0)) return std::nullopt;
  Eigen::MatrixXd A(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec2d q = (points[k] - mean) / scale;
    A.row(static_cast<Eigen::Index>(k)) << q.x(), q.y(), 1.0;
    b[static_cast<Eigen::Index>(k)] = -q.squaredNorm();
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
  const double r2 = s[0] * s[0] / 4 + s[1] * s[1] / 4 - s[2];
  if (!(r2 > 0) || !s.allFinite()) return std::nullopt;
  // Kasa's algebraic fit shrinks the circle on a short noisy arc; a few Gauss-Newton steps on
  // the geometric residuals |p - c| - r (Chernov 2010, ch. 4) remove that bias.
  Eigen::Vector3d g(-s[0] / 2, -s[1] / 2, std::sqrt(r2));  // cx, cy, r in scaled coordinates
  for (int it = 0; it < 20; ++it) {
    Eigen::MatrixXd J(points.size(), 3);
    Eigen::VectorXd res(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec2d d = (points[k] - mean) / scale - Vec2d(g[0], g[1]);
      const double len = d.norm();
      if (!(len > 0)) return std::nullopt;
      const auto row = static_cast<Eigen::Index>(k);
      J.row(row) << -d.x() / len, -d.y() / len, -1.0;
      res[row] = len - g[2];
    }
    const Eigen::Vector3d step = J.colPivHouseholderQr().solve(-res);
    if (!step.allFinite()) break;
    g += step;
    if (step.norm() < 1e-12 * (1 + g.norm())) break;
  }
  if (!g.allFinite() || !(g[2] > 0)) return std::nullopt;
  Circle2 c;
  c.center = mean + scale * Vec2d(g[0], g[1]);
  c.radius = scale * g[2];
  return c;
}

std::optional<MeasuredAngle> circle_wall_angle(const Circle2& circle, const WallSet<2>& walls,
                                               const Vec2d& near, const Vec2d& inside,
                                               double max_arc) {
  if (walls.empty() || !(circle.radius > 0)) return std::nullopt;
  const Vec2d d0 = near - circle.center;
  const double phi0 = std::atan2(d0.y(), d0.x());
  auto at = [&](double phi) {
    return Vec2d(circle.center + circle.radius * Vec2d(std::cos(phi), std::sin(phi)));
  };
  auto dist = [&](double phi) { return walls.closest(at(phi)).distance; };
  const double span = std::min(max_arc / circle.radius, std::numbers::pi);
  const int steps = 400;
  const double dphi = span / steps;
  // Walk away from phi0 in both directions at once; the first sign change is the crossing
  // nearest to the contact point.
  std::optional<std::pair<double, double>> bracket;
  double f0 = dist(phi0), fp = f0, fm = f0;
  if (f0 == 0) bracket = std::make_pair(phi0, phi0);
  for (int k = 1; k <= steps && !bracket; ++k) {
    const double pp = phi0 + k * dphi, pm = phi0 - k * dphi;
    const double gp = dist(pp), gm = dist(pm);
    if ((fp > 0) != (gp > 0))
      bracket = std::make_pair(pp - dphi, pp);
    else if ((fm > 0) != (gm > 0))
      bracket = std::make_pair(pm + dphi, pm);
    fp = gp;
    fm = gm;
  }
  if (!bracket) return std::nullopt;
  double a = bracket->first, b = bracket->second, fa = dist(a);
  for (int it = 0; it < 60 && a != b; ++it) {
    const double m = (a + b) / 2, fm2 = dist(m);
    if ((fm2 > 0) == (fa > 0)) {
      a = m;
      fa = fm2;
    } else {
      b = m;
    }
  }
  MeasuredAngle out;
  out.circle = circle;
  out.contact = at((a + b) / 2);
  const WallPoint<2> wp = walls.closest(out.contact);
  const Vec2d radial = (out.contact - circle.center) / circle.radius;
  // The drop lies inside the circle (a convex cap) or outside it (a concave meniscus).
  const bool drop_inside = (inside - circle.center).norm() < circle.radius;
  const Vec2d m = drop_inside ? radial : Vec2d(-radial);
  out.theta_deg = std::acos(std::clamp(m.dot(wp.normal), -1.0, 1.0)) * 180 / std::numbers::pi;
  return out;
}

std::vector<Vec2d> interface_points(const std::vector<Vec2d>& x, const std::vector<int>& is_drop,
                                    double pair_distance) {
  // Unlike pairs closer than pair_distance straddle the interface.
  const double r2 = pair_distance * pair_distance;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<int> on_interface(x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!is_drop[i]) continue;
    for (std::size_t j = 0; j < x.size(); ++j)
      if (!is_drop[j] && (x[i] - x[j]).squaredNorm() < r2) {
        pairs.emplace_back(i, j);
        on_interface[i] = on_interface[j] = 1;
      }
  }
  // Smoothed colour at the interface particles: Shepard-normalised Wendland C2 average of
  // the drop indicator with h = pair_distance (support 2h); the sum is normalised, so a kernel
  // cut by a wall does not bias it. The lattice staircase of the raw indicator is smoothed out.
  const double h = pair_distance, support2 = 4 * h * h;
  std::vector<double> colour(x.size(), 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!on_interface[i]) continue;
    double num = 0, den = 0;
    for (std::size_t j = 0; j < x.size(); ++j) {
      const double d2 = (x[i] - x[j]).squaredNorm();
      if (d2 >= support2) continue;
      const double q = std::sqrt(d2) / h;
      const double w = std::pow(1 - q / 2, 4) * (2 * q + 1);
      num += w * is_drop[j];
      den += w;
    }
    colour[i] = num / den;
  }
  // The colour-1/2 crossing on each pair (linear between the two smoothed values).
  std::vector<Vec2d> out;
  out.reserve(pairs.size());
  for (const auto& [i, j] : pairs) {
    const double ci = colour[i], cj = colour[j];
    const double f = ci != cj ? std::clamp((ci - 0.5) / (ci - cj), 0.0, 1.0) : 0.5;
    out.push_back(x[i] + f * (x[j] - x[i]));
  }
  return out;
}

DropContactAngles measure_contact_angles(const std::vector<Vec2d>& x,
                                         const std::vector<int>& is_drop, const WallSet<2>& walls,
                                         double pair_distance, double contact_band,
                                         double fit_radius) {
  DropContactAngles out;
  Vec2d centroid = Vec2d::Zero();
  std::size_t n_drop = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (is_drop[i]) {
      centroid += x[i];
      ++n_drop;
    }
  if (n_drop == 0) return out;
  centroid /= static_cast<double>(n_drop);
  const std::vector<Vec2d> iface = interface_points(x, is_drop, pair_distance);
  std::optional<Vec2d> contact[2];
  for (const auto& p : iface) {
    if (walls.closest(p).distance >= contact_band) continue;
    const int s = p.x() < centroid.x() ? 0 : 1;
    if (!contact[s] || (s == 0 ? p.x() < contact[s]->x() : p.x() > contact[s]->x())) contact[s] = p;
  }
  // fit_radius <= 0: half the distance between the two contact points (each fit then takes
  // the interface from its contact point to about the apex: a short arc of a noisy contour
  // gives a poor circle).
  if (!(fit_radius > 0)) {
    if (!contact[0] || !contact[1]) return out;
    fit_radius = (*contact[1] - *contact[0]).norm() / 2;
  }
  for (int s = 0; s < 2; ++s) {
    if (!contact[s]) continue;
    std::vector<Vec2d> pts;
    for (const auto& p : iface)
      if ((p - *contact[s]).norm() < fit_radius) pts.push_back(p);
    Vec2d inside = Vec2d::Zero();
    std::size_t n_in = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (is_drop[i] && (x[i] - *contact[s]).norm() < fit_radius) {
        inside += x[i];
        ++n_in;
      }
    const auto c = fit_circle(pts);
    if (!c || n_in == 0) continue;
    auto m = circle_wall_angle(*c, walls, *contact[s], inside / static_cast<double>(n_in),
                               2 * fit_radius);
    if (m) m->points = pts.size();
    out.side[s] = m;
  }
  return out;
}

}  // namespace curvsph
