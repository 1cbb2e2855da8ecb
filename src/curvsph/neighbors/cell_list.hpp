#pragma once
// Cell list with cell size >= the kernel support 2h and periodic wrap on any axis.
// Particle indices are bucketed by a counting sort; pair iteration visits the 3^D cells
// around a point and hands the caller the separation vector with the periodic image
// already applied, so physics terms never see the domain topology.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
class CellList {
 public:
  // Periodic axes use [min, max) of the given domain and need at least 3 cells; the other
  // axes take the particles' bounding box at every build.
  void configure(Real support, const Vec3d& domain_min, const Vec3d& domain_max,
                 std::array<bool, 3> periodic) {
    support_ = support;
    support2_ = support * support;
    for (int d = 0; d < D; ++d) {
      periodic_[d] = periodic[d];
      lo_[d] = static_cast<Real>(domain_min[d]);
      length_[d] = static_cast<Real>(domain_max[d] - domain_min[d]);
    }
  }

  Real support() const { return support_; }
  bool periodic(int d) const { return periodic_[d]; }
  Real length(int d) const { return length_[d]; }
  Real lower(int d) const { return lo_[d]; }

  // Wraps a position into the periodic box (non-periodic axes untouched).
  void wrap(Vec<D>& x) const {
    for (int d = 0; d < D; ++d) {
      if (!periodic_[d]) continue;
      const Real rel = x[d] - lo_[d];
      if (rel < 0 || rel >= length_[d])
        x[d] = lo_[d] + rel - length_[d] * std::floor(rel / length_[d]);
      if (x[d] >= lo_[d] + length_[d]) x[d] = lo_[d];  // round-off at the upper edge
    }
  }

  // Minimal-image separation a - b.
  Vec<D> separation(const Vec<D>& a, const Vec<D>& b) const {
    Vec<D> s = a - b;
    for (int d = 0; d < D; ++d) {
      if (!periodic_[d]) continue;
      s[d] -= length_[d] * std::round(s[d] / length_[d]);
    }
    return s;
  }

  void build(const std::vector<Vec<D>>& x) {
    const Index n = static_cast<Index>(x.size());
    // Bounds of non-periodic axes from the particles.
    for (int d = 0; d < D; ++d) {
      if (periodic_[d]) {
        count_[d] = std::max(1, static_cast<int>(std::floor(length_[d] / support_)));
        cell_[d] = length_[d] / count_[d];
        origin_[d] = lo_[d];
        continue;
      }
      Real mn = n ? x[0][d] : 0, mx = n ? x[0][d] : 0;
      for (Index i = 1; i < n; ++i) {
        mn = std::min(mn, x[i][d]);
        mx = std::max(mx, x[i][d]);
      }
      origin_[d] = mn - Real(1e-9) * std::max(Real(1), std::abs(mn));
      count_[d] = std::max(1, static_cast<int>(std::floor((mx - origin_[d]) / support_)) + 1);
      cell_[d] = support_;
    }
    Index cells = 1;
    for (int d = 0; d < D; ++d) cells *= count_[d];
    cell_of_.resize(n);
    start_.assign(cells + 1, 0);
    for (Index i = 0; i < n; ++i) {
      cell_of_[i] = linear(coords(x[i]));
      ++start_[cell_of_[i] + 1];
    }
    for (Index c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    sorted_.resize(n);
    fill_.assign(start_.begin(), start_.end() - 1);
    for (Index i = 0; i < n; ++i) sorted_[fill_[cell_of_[i]]++] = i;
  }

  // Calls f(j, r_ij = x - x_j (periodic image applied), r2) for every indexed point j with
  // |r_ij| < support. x may be any point (a particle's own position included: j = i is
  // visited with r = 0). pos must be the array the list was built from (or that array moved
  // by less than the cell slack, as after particle shifting).
  //
  // The 3^D neighbour cells are visited as 3^(D-1) rows along axis 0: the three cells of a
  // row are adjacent in the linear cell index, hence one contiguous range of sorted_ (split
  // only where a periodic axis 0 wraps). That replaces 27 (3-D) per-cell set-ups and their
  // branches by 9 range scans. Cells are visited in the same order as a cell-by-cell sweep
  // (axis 0 fastest), so the sums come out bit for bit the same.
  template <class F>
  void for_each_neighbor(const Vec<D>& x, const std::vector<Vec<D>>& pos, F&& f) const {
    const std::array<int, D> c = coords(x);
    std::array<int, D> off{};
    for (int d = 1; d < D; ++d) off[d] = -1;
    while (true) {
      Vec<D> shift = Vec<D>::Zero();
      Index row = 0;
      bool inside = true;
      for (int d = D - 1; d >= 1 && inside; --d) {
        int k = c[d] + off[d];
        if (periodic_[d]) {
          if (count_[d] < 3 && off[d] != 0) {
            inside = false;  // tiny periodic axes: the centre cell already holds everyone
            break;
          }
          if (k < 0) {
            k += count_[d];
            shift[d] = -length_[d];
          } else if (k >= count_[d]) {
            k -= count_[d];
            shift[d] = length_[d];
          }
        } else if (k < 0 || k >= count_[d]) {
          inside = false;
        }
        row = row * count_[d] + k;
      }
      if (inside) visit_row(x, pos, c[0], row * count_[0], shift, f);
      int d = 1;
      while (d < D && ++off[d] > 1) off[d++] = -1;
      if (d == D) break;
    }
  }

  // Particle indices in cell order: the permutation that makes cells contiguous in memory.
  const std::vector<Index>& sorted() const { return sorted_; }
  Index cell_count() const { return static_cast<Index>(start_.size()) - 1; }
  // Bytes held by the index arrays (memory-per-particle accounting of the throughput study).
  std::size_t bytes() const {
    return (cell_of_.capacity() + start_.capacity() + fill_.capacity() + sorted_.capacity()) *
           sizeof(Index);
  }

 private:
  // The cells c0-1..c0+1 of the row starting at linear index base, in that order.
  template <class F>
  void visit_row(const Vec<D>& x, const std::vector<Vec<D>>& pos, int c0, Index base, Vec<D> shift,
                 F& f) const {
    const int n0 = count_[0];
    if (!periodic_[0]) {
      const int lo = std::max(c0 - 1, 0), hi = std::min(c0 + 1, n0 - 1);
      scan(x, pos, start_[base + lo], start_[base + hi + 1], shift, f);
      return;
    }
    if (n0 < 3) {  // the centre cell already holds every image along axis 0
      scan(x, pos, start_[base + c0], start_[base + c0 + 1], shift, f);
      return;
    }
    if (c0 == 0) {  // the left neighbour is the last cell, one period to the left
      shift[0] = -length_[0];
      scan(x, pos, start_[base + n0 - 1], start_[base + n0], shift, f);
      shift[0] = 0;
      scan(x, pos, start_[base], start_[base + 2], shift, f);
    } else if (c0 == n0 - 1) {  // the right neighbour is the first cell, one period right
      scan(x, pos, start_[base + n0 - 2], start_[base + n0], shift, f);
      shift[0] = length_[0];
      scan(x, pos, start_[base], start_[base + 1], shift, f);
    } else {
      scan(x, pos, start_[base + c0 - 1], start_[base + c0 + 2], shift, f);
    }
  }

  template <class F>
  void scan(const Vec<D>& x, const std::vector<Vec<D>>& pos, Index begin, Index end,
            const Vec<D>& shift, F& f) const {
    for (Index s = begin; s < end; ++s) {
      const Index j = sorted_[s];
      const Vec<D> r = x - (pos[j] + shift);
      const Real r2 = r.squaredNorm();
      if (r2 < support2_) f(j, r, r2);
    }
  }

  std::array<int, D> coords(const Vec<D>& x) const {
    std::array<int, D> c{};
    for (int d = 0; d < D; ++d) {
      int k = static_cast<int>(std::floor((x[d] - origin_[d]) / cell_[d]));
      c[d] = std::clamp(k, 0, count_[d] - 1);
    }
    return c;
  }
  Index linear(const std::array<int, D>& c) const {
    Index l = c[D - 1];
    for (int d = D - 2; d >= 0; --d) l = l * count_[d] + c[d];
    return l;
  }

  Real support_ = 0, support2_ = 0;
  std::array<bool, D> periodic_{};
  std::array<Real, D> lo_{}, length_{}, origin_{}, cell_{};
  std::array<int, D> count_{};
  std::vector<Index> cell_of_, start_, fill_, sorted_;
};

}  // namespace curvsph
