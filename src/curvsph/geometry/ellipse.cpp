#include "curvsph/geometry/ellipse.hpp"

#include <fmt/format.h>

#include <limits>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_yaml.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {

Vec2d ellipse_foot_first_quadrant(double e0, double e1, double y0, double y1, int& iterations) {
  iterations = 0;
  const double d = (e0 - e1) * (e0 + e1);  // e0^2 - e1^2 >= 0, without cancellation
  const double c0 = e0 * y0, c1 = e1 * y1;
  if (y1 > 0.0 && c1 > 0.0) {
    double lo = std::max(c1, c0 - d);          // F(lo) >= 0: one term alone is 1 there
    double hi = e1 * e1 + std::hypot(c0, c1);  // F(hi) < 0: every term is below its share
    auto F = [&](double u) {
      const double r0 = c0 / (u + d), r1 = c1 / u;
      return r0 * r0 + r1 * r1 - 1.0;
    };
    auto dF = [&](double u) {
      const double r0 = c0 / (u + d), r1 = c1 / u;
      return -2.0 * (r0 * r0 / (u + d) + r1 * r1 / u);
    };
    // Newton crawls (a factor ~1.5 per step) when started far left of the root, e.g. for
    // points just off the major axis. A Newton step is kept only while it converges (it is
    // under half the previous step) or the bracket halved; otherwise bisect (geometrically
    // while the bracket spans orders of magnitude).
    constexpr double eps = std::numeric_limits<double>::epsilon();
    double u = lo;
    double width = hi - lo;
    double last_step = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 300; ++it) {
      iterations = it + 1;
      const double f = F(u);
      if (f > 0.0)
        lo = u;
      else if (f < 0.0)
        hi = u;
      else
        break;
      if (!(hi - lo > 2.0 * eps * hi)) break;
      double next = u - f / dF(u);
      const bool newton_ok = next > lo && next < hi &&
                             (std::abs(next - u) <= 0.5 * last_step || hi - lo <= 0.5 * width);
      width = hi - lo;
      if (!newton_ok) next = (lo > 0.0 && hi > 4.0 * lo) ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
      last_step = std::abs(next - u);
      const bool converged = last_step <= 4.0 * eps * u;
      u = next;
      if (converged) break;
    }
    return Vec2d(e0 * e0 * y0 / (u + d), e1 * e1 * y1 / u);
  }
  // On the major axis (or so close that e1*y1 underflows): inside the evolute's segment the
  // foot leaves the axis, otherwise it is the tip.
  if (d > 0.0 && e0 * y0 < d) {
    const double x0 = e0 * e0 * y0 / d;
    const double q = x0 / e0;
    return Vec2d(x0, e1 * std::sqrt(std::max(0.0, (1.0 - q) * (1.0 + q))));
  }
  if (y0 == 0.0) return Vec2d(0.0, e1);  // the centre of a circle: any foot is closest
  return Vec2d(e0, 0.0);
}

EllipseWall::EllipseWall(const Vec2d& center, double a, double b, FluidSide side)
    : center_(center), a_(a), b_(b), side_(side) {}

WallPoint<2> EllipseWall::closest(const Vec2d& x, const ParamSeed&) const {
  WallPoint<2> p;
  const Vec2d r = x - center_;
  const bool swap = b_ > a_;  // work with the major axis first
  const double e0 = swap ? b_ : a_, e1 = swap ? a_ : b_;
  const double y0 = std::abs(swap ? r.y() : r.x()), y1 = std::abs(swap ? r.x() : r.y());
  const Vec2d q = ellipse_foot_first_quadrant(e0, e1, y0, y1, p.iterations);
  Vec2d f = swap ? Vec2d(q.y(), q.x()) : q;
  f.x() = r.x() < 0.0 ? -f.x() : f.x();
  f.y() = r.y() < 0.0 ? -f.y() : f.y();

  p.foot = center_ + f;
  const Vec2d outward = Vec2d(f.x() / (a_ * a_), f.y() / (b_ * b_)).normalized();
  const double implicit = (r.x() / a_) * (r.x() / a_) + (r.y() / b_) * (r.y() / b_);
  const double dist = (r - f).norm();
  const double gx = b_ * f.x() / a_, gy = a_ * f.y() / b_;  // a^2 sin^2 u + b^2 cos^2 u, rooted
  const double g2 = gx * gx + gy * gy;
  const double k_inside = a_ * b_ / (g2 * std::sqrt(g2));
  apply_side(p, side_, outward, implicit < 1.0 ? -dist : dist, k_inside, 0.0);
  p.dir1 = perp(outward);
  p.param[0] = std::atan2(f.y() / b_, f.x() / a_);
  p.param_count = 1;
  return p;
}

std::string EllipseWall::describe() const {
  return fmt::format("ellipse center=({}, {}) semi_axes=({}, {}) fluid {}", center_.x(),
                     center_.y(), a_, b_, to_string(side_));
}

double EllipseWall::min_radius_of_curvature() const {
  return std::min(b_ * b_ / a_, a_ * a_ / b_);
}

WallPtr<2> make_ellipse_wall(const YAML::Node& node, const std::string& file,
                             const std::string& key) {
  check_wall_keys(node, {"center", "semi_axes", "fluid"}, file, key);
  const Vec2d c = yaml::read_key(node, "center", file, key, yaml::read_vec<2>);
  const std::string axes_key = yaml::join(key, "semi_axes");
  const Vec2d ab = yaml::read_vec<2>(yaml::child(node, "semi_axes", file, key), file, axes_key);
  for (int i = 0; i < 2; ++i)
    if (!(ab[i] > 0.0))
      throw InputError(file, yaml::join(axes_key, static_cast<std::size_t>(i)),
                       fmt::format("semi-axis must be > 0, got {}", ab[i]));
  return std::make_shared<EllipseWall>(c, ab[0], ab[1], read_fluid_side(node, file, key));
}

}  // namespace curvsph
