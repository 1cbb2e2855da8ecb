#include "curvsph/analysis/scaling_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace curvsph::scaling {
namespace {

void split(std::vector<RankBox>& out, RankBox b, int ranks, double L) {
  if (ranks == 1) {
    for (int d = 0; d < 3; ++d)
      b.cut[static_cast<std::size_t>(d)] = b.hi[d] - b.lo[d] < L * (1 - 1e-12);
    out.push_back(b);
    return;
  }
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (b.hi[d] - b.lo[d] > b.hi[axis] - b.lo[axis]) axis = d;
  const int left = ranks / 2;
  const double cut = b.lo[axis] + (b.hi[axis] - b.lo[axis]) * left / ranks;
  RankBox l = b, r = b;
  l.hi[axis] = r.lo[axis] = cut;
  split(out, l, left, L);
  split(out, r, ranks - left, L);
}

}  // namespace

std::vector<RankBox> orb_boxes(int ranks, double L) {
  std::vector<RankBox> out;
  RankBox b;
  b.hi = {L, L, L};
  split(out, b, ranks, L);
  return out;
}

double halo_fraction(const RankBox& b, double w) {
  std::vector<double> cut_len;
  double other = 1;
  for (int d = 0; d < 3; ++d) {
    const double len = b.hi[d] - b.lo[d];
    if (b.cut[static_cast<std::size_t>(d)])
      cut_len.push_back(len);
    else
      other *= len;
  }
  const double pi = std::numbers::pi;
  double inner = 1, grown = 1;
  for (double l : cut_len) inner *= l;
  switch (cut_len.size()) {
    case 0:
      return 0;
    case 1:
      grown = cut_len[0] + 2 * w;
      break;
    case 2:
      grown = inner + 2 * w * (cut_len[0] + cut_len[1]) + pi * w * w;
      break;
    default:
      grown =
          inner +
          2 * w * (cut_len[0] * cut_len[1] + cut_len[1] * cut_len[2] + cut_len[0] * cut_len[2]) +
          pi * w * w * (cut_len[0] + cut_len[1] + cut_len[2]) + 4 * pi / 3 * w * w * w;
  }
  return (grown - inner) * other / (inner * other);
}

double cube_halo_fraction(double n, double dx, double w) {
  const double x = w / (std::cbrt(n) * dx);
  const double pi = std::numbers::pi;
  return 6 * x + 3 * pi * x * x + 4 * pi / 3 * x * x * x;
}

namespace {
// Positive integer k-tuples (k = 1, 2, 3), each entry less `offset`, with squared length
// below w^2.
double positive_points_within(int k, double w, double offset) {
  const int top = static_cast<int>(std::ceil(w + offset));
  long c = 0;
  for (int a = 1; a <= top; ++a)
    for (int b = 1; b <= (k > 1 ? top : 1); ++b)
      for (int e = 1; e <= (k > 2 ? top : 1); ++e) {
        const double da = a - offset, db = b - offset, de = e - offset;
        const double r2 = da * da + (k > 1 ? db * db : 0) + (k > 2 ? de * de : 0);
        if (r2 < w * w) ++c;
      }
  return static_cast<double>(c);
}
}  // namespace

double lattice_halo_fraction(const std::array<double, 3>& m, const std::array<bool, 3>& cut,
                             double w, double offset) {
  double halo = 0;
  for (int S = 1; S < 8; ++S) {
    double term = 1;
    int k = 0;
    for (int d = 0; d < 3; ++d) {
      const bool in = (S >> d) & 1;
      if (in && !cut[static_cast<std::size_t>(d)]) term = 0;
      if (in)
        ++k, term *= 2;
      else
        term *= m[static_cast<std::size_t>(d)];
    }
    if (term > 0) halo += term * positive_points_within(k, w, offset);
  }
  return halo / (m[0] * m[1] * m[2]);
}

int neighbour_count(const std::vector<RankBox>& boxes, int r, double w, double L) {
  const RankBox& a = boxes[static_cast<std::size_t>(r)];
  int count = 0;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    if (static_cast<int>(k) == r) continue;
    const RankBox& b = boxes[k];
    double d2 = 0;
    for (int d = 0; d < 3; ++d) {
      // Gap between the intervals, over the periodic images of b.
      double g = 1e300;
      for (int s = -1; s <= 1; ++s)
        g = std::min(g, std::max({0.0, b.lo[d] + s * L - a.hi[d], a.lo[d] - (b.hi[d] + s * L)}));
      d2 += g * g;
    }
    if (d2 < w * w) ++count;
  }
  return count;
}

StepTime step_time(const StepModel& m, double n, double f, int neighbours, int ranks) {
  StepTime t;
  t.compute = n / m.rate;
  t.halo_compute = n * f * m.halo_cost / m.rate;
  if (ranks > 1) {
    const double msgs = m.exchanges * neighbours;
    const double sizes = m.alltoall_sizes ? m.sized_exchanges * (ranks - 1) : 0;
    const double reduce = m.reductions * std::ceil(std::log2(static_cast<double>(ranks)));
    t.communication = (msgs + sizes + reduce) * m.latency + n * f * m.bytes_per_halo / m.bandwidth;
  }
  return t;
}

}  // namespace curvsph::scaling
