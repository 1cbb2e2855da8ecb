#include "curvsph/analysis/shepard_approach.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph {

namespace {

constexpr double pi = std::numbers::pi;

double radial_mass(const WendlandC2<2>& W, double r1, double r2) {
  // 6-point Gauss-Legendre: exact for W(r) r (degree 6) on [r1, r2] inside the support.
  static const double xg[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                               0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
  static const double wg[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                               0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
  double s = 0;
  for (int i = 0; i < 6; ++i) {
    const double r = 0.5 * (r1 + r2) + 0.5 * (r2 - r1) * xg[i];
    s += wg[i] * W.value(static_cast<Real>(r)) * r;
  }
  return 0.5 * (r2 - r1) * s;
}

double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa,
                        double fm, double fb, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b), flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tol)
    return left + right + (left + right - whole) / 15;
  return adaptive_simpson(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) +
         adaptive_simpson(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}

struct Setup {
  std::string name;
  BoundaryElements<2> elements;
  std::function<bool(const Vec2d&)> inside;
  std::function<Vec2d(double)> path;  // position at distance t (in units of h... absolute)
  double t_max;
  Vec2d lattice_origin;
};

}  // namespace

double shepard_reference_2d(const Vec2d& x, double h,
                            const std::function<bool(const Vec2d&)>& inside) {
  const WendlandC2<2> W(static_cast<Real>(h));
  const double R = 2 * h;
  auto ray = [&](double phi) {
    const Vec2d e(std::cos(phi), std::sin(phi));
    const int n = 256;
    double sum = 0, start = 0;
    bool in = inside(x + 1e-13 * h * e);
    for (int k = 1; k <= n; ++k) {
      const double r = R * k / n;
      const bool now = inside(x + r * e);
      if (now == in) continue;
      double lo = R * (k - 1) / n, hi = r;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (inside(x + mid * e) == in ? lo : hi) = mid;
      }
      if (in) sum += radial_mass(W, start, lo);
      start = lo;
      in = now;
    }
    if (in) sum += radial_mass(W, start, R);
    return sum;
  };
  double total = 0;
  for (int s = 0; s < 16; ++s) {
    const double a = 2 * pi * s / 16, b = 2 * pi * (s + 1) / 16;
    const double fa = ray(a), fb = ray(b), fm = ray(0.5 * (a + b));
    total += adaptive_simpson(ray, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), 1e-9, 20);
  }
  return total;
}

ShepardApproachResult run_shepard_approach(const ShepardApproachOptions& o) {
  if (!(o.h > 0) || !(o.h_over_dx > 0) || o.samples < 2)
    throw std::invalid_argument("shepard_approach: h, h_over_dx must be > 0 and samples >= 2");
  const double h = o.h, dx = h / o.h_over_dx, L = 8 * h, R = o.circle_radius_over_h * h;
  std::vector<Setup> setups;
  setups.push_back({"wall", polyline_elements({{-L, 0}, {L, 0}}, dx),
                    [](const Vec2d& y) { return y[1] >= 0; }, [](double t) { return Vec2d(0, t); },
                    2 * h, Vec2d(0, 0)});
  const auto corner = polyline_elements({{0, L}, {0, 0}, {L, 0}}, dx);
  auto quadrant = [](const Vec2d& y) { return y[0] >= 0 && y[1] >= 0; };
  setups.push_back(
      {"corner_side", corner, quadrant, [](double t) { return Vec2d(t, 0); }, 3 * h, Vec2d(0, 0)});
  setups.push_back({"corner_diagonal", corner, quadrant,
                    [](double t) { return Vec2d(t / std::sqrt(2.0), t / std::sqrt(2.0)); }, 3 * h,
                    Vec2d(0, 0)});
  // Circle elements start half an element below the x axis: the path crosses an element centre.
  const int m = std::max(3, static_cast<int>(std::lround(2 * pi * R / dx)));
  setups.push_back({"circle_inside", circle_elements(Vec2d(0, 0), R, dx, true, -pi / m),
                    [R](const Vec2d& y) { return y.norm() <= R; },
                    [R](double t) { return Vec2d(R - t, 0); }, 2 * h, Vec2d(0, 0)});
  setups.push_back({"circle_outside", circle_elements(Vec2d(0, 0), R, dx, false, -pi / m),
                    [R](const Vec2d& y) { return y.norm() >= R; },
                    [R](double t) { return Vec2d(R + t, 0); }, 2 * h, Vec2d(0, 0)});

  ShepardApproachResult result;
  ShepardQuadrature contour;  // the paper's "gamma = 1/2 on the contour" monolithic rule
  contour.monolithic_contour_half = true;
  for (const Setup& s : setups) {
    // Volume-mode particles: cell-centred lattice of spacing dx in the fluid.
    std::vector<Vec2d> pos;
    std::vector<double> vol;
    const int nb = static_cast<int>(std::ceil((L + 4 * h) / dx));
    for (int i = -nb; i < nb; ++i)
      for (int j = -nb; j < nb; ++j) {
        const Vec2d y = s.lattice_origin + Vec2d((i + 0.5) * dx, (j + 0.5) * dx);
        if (s.inside(y)) {
          pos.push_back(y);
          vol.push_back(dx * dx);
        }
      }
    ShepardApproachCurve c;
    c.approach = s.name;
    for (int k = 0; k < o.samples; ++k) {
      const double t = s.t_max * (1.0 - double(k) / (o.samples - 1));
      const Vec2d x = s.path(t);
      c.distance_over_h.push_back(t / h);
      c.reference.push_back(shepard_reference_2d(x, h, s.inside));
      c.gamma["geometric"].push_back(shepard_geometric<2>(s.elements, x, h));
      c.gamma["monolithic"].push_back(shepard_monolithic<2>(s.elements, x, h));
      c.gamma["monolithic_contour"].push_back(shepard_monolithic<2>(s.elements, x, h, contour));
      c.gamma["volume"].push_back(shepard_volume<2>(pos, vol, x, h));
    }
    for (const auto& [mode, g] : c.gamma) {
      double e = 0;
      for (std::size_t k = 0; k < g.size(); ++k) e = std::max(e, std::abs(g[k] - c.reference[k]));
      result.metrics["gamma_max_abs_error_" + s.name + "_" + mode] = e;
      double& circle = result.metrics["gamma_max_abs_error_circle_" + mode];
      if (s.name.rfind("circle_", 0) == 0) circle = std::max(circle, e);
    }
    result.curves.push_back(std::move(c));
  }
  result.metrics["h_over_dx"] = o.h_over_dx;
  return result;
}

void write_shepard_approach(const ShepardApproachResult& result, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  for (const auto& c : result.curves) {
    const auto path = dir / ("shepard_" + c.approach + ".csv");
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
    out << "distance_over_h,gamma_reference";
    for (const auto& [mode, g] : c.gamma) out << ",gamma_" << mode;
    out << "\n";
    for (std::size_t k = 0; k < c.reference.size(); ++k) {
      out << fmt::format("{:.17g},{:.17g}", c.distance_over_h[k], c.reference[k]);
      for (const auto& [mode, g] : c.gamma) out << fmt::format(",{:.17g}", g[k]);
      out << "\n";
    }
  }
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : result.metrics) j[k] = v;
  std::ofstream out(dir / "metrics.json");
  if (!out) throw std::runtime_error("cannot write '" + (dir / "metrics.json").string() + "'");
  out << j.dump(2) << "\n";
}

}  // namespace curvsph
