#include "curvsph/io/probes.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace curvsph {
namespace {

template <int D>
struct Interpolated {
  Real fraction = 0;  // sum_j V_j W_j
  Real p = 0, p_wall = 0, rho = 0;
  Vec<D> vel = Vec<D>::Zero();
};

template <int D>
Interpolated<D> interpolate(const Vec<D>& x, const Particles<D>& P, const CellList<D>& cells,
                            const WendlandC2<D>& W, const Vec<D>& g = Vec<D>::Zero(),
                            const Vec<D>& face = Vec<D>::Zero()) {
  Interpolated<D> s;
  cells.for_each_neighbor(x, P.x, [&](Index j, const Vec<D>& r, Real r2) {
    if (r.dot(face) > 0) return;  // behind the sensor's face (r = x - x_j; probes.hpp)
    const Real w = W.value(std::sqrt(r2)) * P.mass[j] / P.rho[j];
    s.fraction += w;
    s.p_wall += w * (P.p[j] + P.rho[j] * g.dot(r));  // r = x - x_j
    s.p += w * P.p[j];
    s.rho += w * P.rho[j];
    s.vel += w * P.v[j];
  });
  if (s.fraction > 0) {
    s.p /= s.fraction;
    s.p_wall /= s.fraction;
    s.rho /= s.fraction;
    s.vel /= s.fraction;
  }
  return s;
}

}  // namespace

template <int D>
ProbeWriter<D>::ProbeWriter(std::vector<ProbeSpec> probes, const std::string& path, Real dx,
                            const Vec<D>& gravity)
    : probes_(std::move(probes)), dx_(dx), gravity_(gravity) {
  if (probes_.empty()) return;
  out_.open(path);
  if (!out_) throw std::runtime_error("cannot write " + path);
  out_ << "time";
  for (const auto& c : columns()) out_ << ',' << c;
  out_ << '\n';
}

template <int D>
std::vector<std::string> ProbeWriter<D>::columns() const {
  std::vector<std::string> cols;
  static const char* axis[] = {"x", "y", "z"};
  for (const auto& pr : probes_) {
    if (pr.kind == ProbeSpec::Kind::gauge) {
      cols.push_back(pr.name + ".height");
      continue;
    }
    for (const auto& f : pr.fields) {
      if (f == "vel")
        for (int d = 0; d < D; ++d) cols.push_back(pr.name + ".vel_" + axis[d]);
      else
        cols.push_back(pr.name + "." + f);
    }
  }
  return cols;
}

template <int D>
std::vector<double> ProbeWriter<D>::sample(const Particles<D>& P, const CellList<D>& cells,
                                           const WendlandC2<D>& W) const {
  std::vector<double> vals;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& pr : probes_) {
    const Vec<D> x0 = pr.point.head<D>().template cast<Real>();
    if (pr.kind == ProbeSpec::Kind::gauge) {
      // March along the gauge line to the far side of the particles' extent.
      const Vec<D> dir = pr.direction.head<D>().template cast<Real>();
      Real reach = 0;
      for (std::size_t j = 0; j < P.size(); ++j) reach = std::max(reach, (P.x[j] - x0).dot(dir));
      const Real step = dx_ / 4;
      Real height = 0;
      // An integer counter: s = k step carries no accumulated round-off (clang-tidy's
      // FloatLoopCounter), and the last sample is the one at or below reach + 2h.
      const auto samples = static_cast<long>(std::floor((reach + W.support) / step));
      for (long k = 0; k <= samples; ++k) {
        const Real s = static_cast<Real>(k) * step;
        if (interpolate<D>(x0 + s * dir, P, cells, W).fraction >= Real(0.5)) height = s;
      }
      vals.push_back(height);
      continue;
    }
    const auto s =
        interpolate<D>(x0, P, cells, W, gravity_, pr.normal.head<D>().template cast<Real>());
    const bool wet = s.fraction > Real(0.1);  // no fluid at the probe: write NaN, not 0
    for (const auto& f : pr.fields) {
      if (f == "p") vals.push_back(wet ? s.p : nan);
      if (f == "p_wall") vals.push_back(wet ? s.p_wall : nan);
      if (f == "rho") vals.push_back(wet ? s.rho : nan);
      if (f == "vel")
        for (int d = 0; d < D; ++d) vals.push_back(wet ? s.vel[d] : nan);
    }
  }
  return vals;
}

template <int D>
void ProbeWriter<D>::write_row(double t, const Particles<D>& P, const CellList<D>& cells,
                               const WendlandC2<D>& W) {
  if (probes_.empty()) return;
  out_ << fmt::format("{:.9g}", t);
  for (double v : sample(P, cells, W)) out_ << ',' << fmt::format("{:.9g}", v);
  out_ << '\n';
  out_.flush();
}

template class ProbeWriter<2>;
template class ProbeWriter<3>;

}  // namespace curvsph
