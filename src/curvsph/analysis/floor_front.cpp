#include "curvsph/analysis/floor_front.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "curvsph/kernels/wendland.hpp"

namespace curvsph {

FloorFront floor_front(std::span<const Vec<2>> x, std::span<const Real> volume, double floor_y,
                       double x_start, double dx, double h) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  FloorFront f{nan, nan};
  if (x.empty()) return f;
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& p : x) lowest = std::min(lowest, static_cast<double>(p.y()));
  f.largest_x = -std::numeric_limits<double>::infinity();
  for (const auto& p : x)
    if (p.y() <= lowest + 2 * dx) f.largest_x = std::max(f.largest_x, static_cast<double>(p.x()));

  // The particles whose kernel (or whose image's) reaches the sampling line, sorted by x: each
  // sample then sums over a window of them only.
  const WendlandC2<2> W(static_cast<Real>(h));
  const double support = 2 * h, y_line = floor_y + dx / 2;
  std::vector<std::size_t> band;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i].y() - y_line) < support ||
        std::abs(2 * floor_y - x[i].y() - y_line) < support)
      band.push_back(i);
  if (band.empty()) return f;
  std::sort(band.begin(), band.end(),
            [&](std::size_t a, std::size_t b) { return x[a].x() < x[b].x(); });
  std::vector<double> bx(band.size());
  for (std::size_t k = 0; k < band.size(); ++k) bx[k] = x[band[k]].x();
  const auto phi = [&](double xs) {
    double s = 0;
    for (auto k = static_cast<std::size_t>(std::lower_bound(bx.begin(), bx.end(), xs - support) -
                                           bx.begin());
         k < bx.size() && bx[k] <= xs + support; ++k) {
      const auto& p = x[band[k]];
      const double ddx = p.x() - xs, dy = p.y() - y_line, dy_image = 2 * floor_y - p.y() - y_line;
      s += volume[band[k]] * (W.value(static_cast<Real>(std::hypot(ddx, dy))) +
                              W.value(static_cast<Real>(std::hypot(ddx, dy_image))));
    }
    return s;
  };
  // The last wet-to-dry crossing: a dry patch behind the front (a sheet that thins or lifts
  // off the floor there) does not move the front back to it.
  const double step = dx / 4, x_end = bx.back() + support + step;
  bool wet = false;
  double x_prev = x_start, phi_prev = 0;
  for (long n = 0;; ++n) {
    const double xs = x_start + static_cast<double>(n) * step;
    if (xs > x_end) break;
    const double p = phi(xs);
    if (wet && p < 0.5) f.wet_x = x_prev + (0.5 - phi_prev) / (p - phi_prev) * step;
    wet = p >= 0.5;
    x_prev = xs;
    phi_prev = p;
  }
  return f;
}

}  // namespace curvsph
