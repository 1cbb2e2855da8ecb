#pragma once
// Cell list with cells of half the kernel support (h; the support where a periodic axis is too
// short for that) and periodic wrap on any axis.
// Particle indices are bucketed by a counting sort; pair iteration visits the cells
// (5^D at half-support cells) around a point and hands the caller the separation vector with the
// periodic image already applied, so physics terms never see the domain topology.
//
// build() also keeps a copy of the positions in cell order, one array per axis (sx_). The
// symmetric pair sweep gathers the candidates of a cell's half stencil from it once (periodic
// image applied) and every particle of the cell filters that one contiguous run without a
// data-dependent branch: the squared distances in one loop (SIMD across candidates), the hits
// compacted into an index buffer by a branch-free store, and only the hits reach the caller.
// With ~75-85 % of the candidates outside the support (docs/performance.md), the
// per-candidate branch of a plain scan mispredicts often, and so do the exits of short loops
// over each row of cells.
//
// for_each_pair() visits every pair within the support once, for the symmetric passes (the
// caller adds a pair's contribution to both particles: half the distance tests and kernel
// evaluations of a gather over for_each_neighbor). Threads take tiles of cells in four colours
// so that no two threads ever write the same particle (plan_tiles()).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "curvsph/core/periodic.hpp"
#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
class CellList {
 public:
  // Periodic axes use [min, max) of the given domain and must span at least two supports
  // (so that at most one image of a point lies within the support); the other axes take the
  // particles' bounding box at every build.
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
  // The same domain and periodicity as `other`, for another support (a second list over
  // other points in the same box: ghosts, packing).
  void configure_like(const CellList& other, Real support) {
    Vec3d lo = Vec3d::Zero(), hi = Vec3d::Zero();
    std::array<bool, 3> per{false, false, false};
    for (int d = 0; d < D; ++d) {
      lo[d] = other.lower(d);
      hi[d] = other.lower(d) + other.length(d);
      per[d] = other.periodic(d);
    }
    configure(support, lo, hi, per);
  }
  bool periodic(int d) const { return periodic_[d]; }
  Real length(int d) const { return length_[d]; }
  Real lower(int d) const { return lo_[d]; }

  // Wraps a position into the periodic box (non-periodic axes untouched).
  void wrap(Vec<D>& x) const {
    for (int d = 0; d < D; ++d)
      if (periodic_[d]) x[d] = wrap_periodic(x[d], lo_[d], length_[d]);
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
    // Cells of size support / reach_ with a stencil of reach_ cells each way: reach 2 tests
    // 5^D (support/2)^D = 125/216 of the candidate volume of reach 1 in 3-D (the support
    // sphere is 33.5 h^3 of 216 h^3 at reach 1). A periodic axis needs 2 reach + 1 cells so
    // that no cell is visited twice; where one has fewer, reach 1 is used.
    reach_ = kMaxReach;
    for (int d = 0; d < D; ++d)
      if (periodic_[d] && std::floor(length_[d] / (support_ / kMaxReach)) < 2 * kMaxReach + 1)
        reach_ = 1;
    const Real cell = support_ / reach_;
    // Bounds of non-periodic axes from the particles.
    for (int d = 0; d < D; ++d) {
      if (periodic_[d]) {
        count_[d] = std::max(1, static_cast<int>(std::floor(length_[d] / cell)));
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
      count_[d] = std::max(1, static_cast<int>(std::floor((mx - origin_[d]) / cell)) + 1);
      cell_[d] = cell;
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
    for (int d = 0; d < D; ++d) {
      sx_[d].resize(n);
      for (Index s = 0; s < n; ++s) sx_[d][s] = x[sorted_[s]][d];
    }
    plan_tiles();
  }

  // Calls f(j, r_ij = x - x_j (periodic image applied), r2) for every indexed point j with
  // |r_ij| < support. x may be any point (a particle's own position included: j = i is
  // visited with r = 0). pos must be the array the list was built from (or that array moved
  // by less than the cell slack, as after particle shifting).
  //
  // The neighbour cells are visited as rows along axis 0: the cells of a row are adjacent in
  // the linear cell index, hence one contiguous range of sorted_ (split only where a periodic
  // axis 0 wraps). Cells are visited axis 0 fastest, as a cell-by-cell sweep would.
  template <class F>
  void for_each_neighbor(const Vec<D>& x, const std::vector<Vec<D>>& pos, F&& f) const {
    for_each_row(x, [&](Index begin, Index end, const Vec<D>& shift) {
      for (Index s = begin; s < end; ++s) {
        const Index j = sorted_[s];
        const Vec<D> r = x - (pos[j] + shift);
        const Real r2 = r.squaredNorm();
        if (r2 < support2_) f(j, r, r2);
      }
    });
  }

  // Calls f(i, j, r_ij = x_i - x_j (periodic image applied), r2) once for every unordered
  // pair i != j of the indexed points with |r_ij| < support, on the positions of the last
  // build(). Which of the two is `i` is an implementation detail; callers add the pair's
  // contribution to both (or to the one they own). Runs threaded: f may write to particles
  // i and j, and to nothing else shared. The visiting order (hence every per-particle sum)
  // is fixed by the cell grid alone, the same for any thread count.
  template <class F>
  void for_each_pair(F&& f) const {
    for_each_pair_acc(NoSum{}, without_sum(f), [](Index, NoSum) {});
  }

  // for_each_pair() with the visiting particle's share summed in a local: f(acc, i, j, r, r2)
  // adds i's term to acc (a copy of `zero` per visiting particle, which the compiler keeps in
  // registers) and j's term to j's storage; fin(i, acc) then adds acc to i's once.
  // The plain form loads and stores i's sums at every pair, and each pair's update of them
  // waits on the store of the one before. A particle is the visitor of exactly one cell
  // sweep, so fin runs once per particle; particles without pairs get fin(i, zero).
  template <class Acc, class F, class Fin>
  void for_each_pair_acc(const Acc& zero, F&& f, Fin&& fin) const {
    // One team for the four colours, with the barrier after each colour that is needed
    // anyway: three parallel regions fewer per pass (22 a dam-break step instead of 31).
#pragma omp parallel
    for (int colour = 0; colour < 4; ++colour) {
      // Tiles of one colour write disjoint particle sets (plan_tiles()); their order among
      // themselves does not change any particle's sum, so a dynamic schedule is safe.
      const std::vector<int>& tiles = tiles_of_colour_[colour];
      const int nt = static_cast<int>(tiles.size());
#pragma omp for schedule(dynamic, 1)
      for (int k = 0; k < nt; ++k) for_each_pair_in_tile(tiles[k], zero, f, fin);
    }
  }

  // The tiles of for_each_pair (exposed for the tests of its colouring): blocks of cells cut
  // along up to two axes. Tile k visits, for every particle i in its cells (cell order, then
  // sorted order), the pairs (i, j) with j "after" i: j's cell offset from i's,
  // o = (o_0, .., o_{D-1}) counted in unwrapped cells (periodic image included), is
  // lexicographically positive with axis D-1 most significant, or o = 0 and j comes later in
  // the sorted order. Seen from j the offset is -o, so every pair is visited from exactly one
  // side.
  int tile_count() const {
    return tile_n_[0] * tile_n_[1];
  }
  // Tiles of one colour run at the same time (0..3).
  int tile_colour(int k) const {
    return (k % tile_n_[0]) % 2 + 2 * ((k / tile_n_[0]) % 2);
  }
  template <class F>
  void for_each_pair_in_tile(int tile, F& f) const {
    auto g = without_sum(f);
    auto fin = [](Index, NoSum) {};
    for_each_pair_in_tile(tile, NoSum{}, g, fin);
  }
  template <class Acc, class F, class Fin>
  void for_each_pair_in_tile(int tile, const Acc& zero, F& f, Fin& fin) const {
    std::array<int, D> lo{}, hi{};
    for (int d = 0; d < D; ++d) hi[d] = count_[d];
    const int t[2] = {tile % tile_n_[0], tile / tile_n_[0]};
    for (int u = 0; u < 2; ++u) {
      const int a = tile_axis_[u];
      lo[a] = tile_begin_[u][t[u]];
      hi[a] = tile_begin_[u][t[u] + 1];
      if (lo[a] >= hi[a]) return;
    }
    std::array<int, D> c = lo;
    std::array<Range, kMaxRanges> ranges;
    Candidates& cand = candidates();
    while (true) {
      const Index cell = linear(c);
      const Index first = start_[cell];
      if (first < start_[cell + 1]) {
        const int nr = half_ranges(c, ranges);
        const Index m = gather(ranges, nr, cand);
        for (Index s = first; s < start_[cell + 1]; ++s) {
          const Index i = sorted_[s];
          Vec<D> x;
          for (int d = 0; d < D; ++d) x[d] = sx_[d][s];
          // The own cell leads the candidates: its pairs start right after i (once each).
          Acc acc = zero;
          scan_candidates(x, cand, s - first + 1, m,
                          [&](Index j, const Vec<D>& r, Real r2) { f(acc, i, j, r, r2); });
          fin(i, acc);
        }
      }
      int d = 0;
      while (d < D && ++c[d] == hi[d]) {
        c[d] = lo[d];
        ++d;
      }
      if (d == D) break;
    }
  }

  // Particle indices in cell order: the permutation that makes cells contiguous in memory.
  const std::vector<Index>& sorted() const {
    return sorted_;
  }
  Index cell_count() const {
    return static_cast<Index>(start_.size()) - 1;
  }
  // Bytes held by the index arrays and the sorted positions (memory-per-particle accounting
  // of the throughput study).
  std::size_t bytes() const {
    std::size_t b =
        (cell_of_.capacity() + start_.capacity() + fill_.capacity() + sorted_.capacity()) *
        sizeof(Index);
    for (int d = 0; d < D; ++d) b += sx_[d].capacity() * sizeof(Real);
    return b;
  }

 private:
  static constexpr int kMaxReach = 2;
  // Cells visited along one axis: 2 kMaxReach + 1 in a stencil, or 3 images of at most 2
  // cells where a periodic axis is shorter than 3 supports.
  static constexpr int kMaxAxisVisits = 2 * kMaxReach + 2;

  // Ranges of one cell's half stencil: at most kMaxAxisVisits^(D-1) rows of up to 3 ranges.
  static constexpr int kMaxRanges =
      3 * (D == 3 ? kMaxAxisVisits * kMaxAxisVisits : (D == 2 ? kMaxAxisVisits : 1));
  struct Range {
    Index begin = 0, end = 0;
    Vec<D> shift = Vec<D>::Zero();
    bool own = false;  // the range that starts at the visiting particle's own cell
  };

  // The accumulator of the passes without one (for_each_pair), and their pair callback.
  struct NoSum {};
  template <class F>
  static auto without_sum(F& f) {
    return [&f](NoSum&, Index i, Index j, const Vec<D>& r, Real r2) { f(i, j, r, r2); };
  }

  // The candidates of one cell's half stencil, gathered once for all of the cell's particles
  // into contiguous arrays (periodic image applied, own cell first): each particle then
  // filters one long run instead of some 13 rows of a few candidates each in 3-D, whose loop
  // exits (three a row, mispredicted) cost about as much as the candidate tests themselves.
  struct Candidates {
    std::array<std::vector<Real>, D> x;
    std::vector<Index> j;
    std::vector<Real> r2;
    std::vector<int> hits;
  };
  // One buffer per thread, shared by every pass and every list of this dimension: no
  // allocation once the largest stencil has been seen (a few KB; not in bytes()).
  static Candidates& candidates() {
    static thread_local Candidates c;
    return c;
  }

  Index gather(const std::array<Range, kMaxRanges>& ranges, int nr, Candidates& c) const {
    Index m = 0;
    for (int k = 0; k < nr; ++k) m += std::max<Index>(0, ranges[k].end - ranges[k].begin);
    if (static_cast<std::size_t>(m) > c.j.size()) {
      const std::size_t cap = static_cast<std::size_t>(m) + m / 2;
      for (int d = 0; d < D; ++d) c.x[d].resize(cap);
      c.j.resize(cap);
      c.r2.resize(cap);
      c.hits.resize(cap);
    }
    Index t = 0;
    std::array<Real*, D> out;
    for (int d = 0; d < D; ++d) out[d] = c.x[d].data();
    Index* const out_j = c.j.data();
    // One loop over a row's candidates for every array (rows hold a few dozen: each loop
    // exit is a likely misprediction, and a library copy an indirect call).
    auto put = [&](const Range& g) {
      for (Index s = g.begin; s < g.end; ++s, ++t) {
        for (int d = 0; d < D; ++d) out[d][t] = sx_[d][s] + g.shift[d];
        out_j[t] = sorted_[s];
      }
    };
    for (int k = 0; k < nr; ++k)
      if (ranges[k].own) put(ranges[k]);
    for (int k = 0; k < nr; ++k)
      if (!ranges[k].own) put(ranges[k]);
    return t;
  }

  // Calls g(j, r, r2) for every candidate t in [begin, end) within the support of x: the
  // squared distances in one branch-free (vectorisable) loop, the hits compacted by a
  // branch-free store. The candidates hold p + shift, so r and r2 are the bits of
  // for_each_neighbor's x - (p + shift) and its squaredNorm ((0 + r_0^2) + r_1^2 + ..., the
  // same sum) unless the compiler contracts one of them into FMAs (-march with FMA); then a
  // pair at the support's edge may be decided differently, where W and its gradient vanish.
  // So the filter is the exact test, and its r2 is handed on.
  template <class G>
  void scan_candidates(const Vec<D>& x, Candidates& c, Index begin, Index end, G&& g) const {
    Real* const __restrict r2b = c.r2.data();
    std::array<const Real*, D> cx;
    for (int d = 0; d < D; ++d) cx[d] = c.x[d].data();
    for (Index t = begin; t < end; ++t) {
      Real q = 0;
      for (int d = 0; d < D; ++d) {
        const Real rd = x[d] - cx[d][t];
        q += rd * rd;
      }
      r2b[t] = q;
    }
    int* const __restrict hits = c.hits.data();
    int nh = 0;
    for (Index t = begin; t < end; ++t) {
      hits[nh] = static_cast<int>(t);
      nh += r2b[t] < support2_;
    }
    const Index* jj = c.j.data();
    for (int h = 0; h < nh; ++h) {
      const Index t = hits[h];
      Vec<D> r;
      for (int d = 0; d < D; ++d) r[d] = x[d] - cx[d][t];
      g(jj[t], r, r2b[t]);
    }
  }

  // Tiles for the threads of for_each_pair: the two axes that cut into the most blocks (one
  // axis in effect when the other gives a single block). A pair's two cells differ by at most
  // reach_ cells along any axis that has a stencil, and along axis D-1 (the most significant
  // of the half-stencil order) j is never before i: a tile [b, e) along an axis writes
  // particles in [b - reach_, e + reach_) (axis D-1: [b, e + reach_)). So tiles are
  // 2 reach cells thick (reach along axis D-1), and two tiles of one colour — the parities of
  // both tile indices equal — are at least one whole tile apart along some axis, and their
  // written cells are disjoint. A periodic axis needs an even tile count (the colours must
  // alternate across the wrap); one too short for a stencil is not cut. (One axis of slabs
  // gave the dam break, whose water fills a fifth of the tank's length, ~5 slabs per colour
  // for 2 threads: thread scaling 1.70.)
  void plan_tiles() {
    std::array<int, D> n{}, thick{};
    for (int a = 0; a < D; ++a) {
      thick[a] = a == D - 1 ? reach_ : 2 * reach_;
      n[a] = periodic_[a] && count_[a] < 2 * reach_ + 1 ? 1 : std::max(count_[a] / thick[a], 1);
      if (periodic_[a] && n[a] % 2) --n[a];
      n[a] = std::max(n[a], 1);
    }
    std::array<int, D> order{};
    for (int a = 0; a < D; ++a) order[a] = a;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return n[a] > n[b]; });
    for (int u = 0; u < 2; ++u) {
      const int a = order[static_cast<std::size_t>(u)];
      tile_axis_[u] = a;
      tile_n_[u] = n[a];
      tile_begin_[u].resize(static_cast<std::size_t>(n[a]) + 1);
      for (int k = 0; k < n[a]; ++k) tile_begin_[u][k] = k * thick[a];
      tile_begin_[u][n[a]] = count_[a];  // the last tile takes the remainder
    }
    for (auto& v : tiles_of_colour_) v.clear();
    for (int k = 0; k < tile_count(); ++k) tiles_of_colour_[tile_colour(k)].push_back(k);
  }

  // The ranges of cell c's half stencil (for_each_pair_in_tile), into `out`; returns their
  // count. Rows along axis 0 as in for_each_row; a row whose offset (o_{D-1}, .., o_1) is
  // positive is scanned whole, the own row (offset 0) from c's own cell on (o_0 >= 0), a
  // negative one not at all.
  int half_ranges(const std::array<int, D>& c, std::array<Range, kMaxRanges>& out) const {
    int nr = 0;
    auto add = [&](Index begin, Index end, const Vec<D>& shift, bool own) {
      if (begin >= end && !own) return;
      out[nr].begin = begin;
      out[nr].end = end;
      out[nr].shift = shift;
      out[nr].own = own;
      ++nr;
    };
    std::array<std::array<int, kMaxAxisVisits>, D> cell{}, rel{};
    std::array<std::array<Real, kMaxAxisVisits>, D> offset{};
    std::array<int, D> visits{};
    for (int d = 1; d < D; ++d) visits[d] = axis_visits(c[d], d, cell[d], rel[d], offset[d]);
    std::array<int, D> at{};
    while (true) {
      int sign = 0;  // lexicographic sign of (o_{D-1}, .., o_1)
      for (int d = D - 1; d >= 1 && sign == 0; --d)
        sign = (rel[d][at[d]] > 0) - (rel[d][at[d]] < 0);
      if (sign >= 0) {
        Vec<D> shift = Vec<D>::Zero();
        Index row = 0;
        for (int d = D - 1; d >= 1; --d) {
          row = row * count_[d] + cell[d][at[d]];
          shift[d] = offset[d][at[d]];
        }
        const Index base = row * count_[0];
        if (sign > 0) {
          auto scan = [&](Index b, Index e, const Vec<D>& sh) { add(b, e, sh, false); };
          visit_row(c[0], base, shift, scan);
        } else {
          own_row(c[0], base, shift, add);
        }
      }
      int d = 1;
      while (d < D && ++at[d] == visits[d]) at[d++] = 0;
      if (d == D) break;
    }
    return nr;
  }

  // The own row of the half stencil: cells with o_0 >= 0 (c0 itself flagged `own`: the scan
  // starts after the visiting particle). shift is zero on the other axes here.
  template <class A>
  void own_row(int c0, Index base, Vec<D> shift, A& add) const {
    const int n0 = count_[0];
    const int r = reach_;
    const Index first = start_[base + c0];
    if (!periodic_[0]) {
      add(first, start_[base + std::min(c0 + r, n0 - 1) + 1], shift, true);
      return;
    }
    if (n0 < 2 * r + 1) {  // three images: o_0 = k + s n0 - c0 > 0 for s = 1, < 0 for s = -1
      add(first, start_[base + n0], shift, true);
      shift[0] = length_[0];
      add(start_[base], start_[base + n0], shift, false);
      return;
    }
    if (c0 + r >= n0) {  // the cells beyond the end are the first ones, one period right
      add(first, start_[base + n0], shift, true);
      shift[0] = length_[0];
      add(start_[base], start_[base + c0 + r + 1 - n0], shift, false);
    } else {
      add(first, start_[base + c0 + r + 1], shift, true);
    }
  }

  // The cells to visit along axis d around cell coordinate c: their index (`cell`), their
  // unwrapped offset from c (`rel`, periodic image included) and the periodic image shift of
  // each (`offset`); returns their count.
  int axis_visits(int c, int d, std::array<int, kMaxAxisVisits>& cell,
                  std::array<int, kMaxAxisVisits>& rel,
                  std::array<Real, kMaxAxisVisits>& offset) const {
    int n = 0;
    if (periodic_[d] && count_[d] < 2 * reach_ + 1) {
      // Too few cells to visit each once in a stencil: every cell, in each of the three
      // images that can reach x (the length is at least two supports, so at most one
      // image of a point lies within the support).
      for (int s = -1; s <= 1; ++s)
        for (int k = 0; k < count_[d]; ++k) {
          cell[n] = k;
          rel[n] = k + s * count_[d] - c;
          offset[n++] = static_cast<Real>(s) * length_[d];
        }
      return n;
    }
    for (int off = -reach_; off <= reach_; ++off) {
      int k = c + off;
      Real sh = 0;
      if (periodic_[d]) {
        if (k < 0) {
          k += count_[d];
          sh = -length_[d];
        } else if (k >= count_[d]) {
          k -= count_[d];
          sh = length_[d];
        }
      } else if (k < 0 || k >= count_[d]) {
        continue;
      }
      cell[n] = k;
      rel[n] = off;
      offset[n++] = sh;
    }
    return n;
  }

  // Calls scan(begin, end, shift) for every contiguous range of sorted_ that holds the cells
  // within reach_ of x's cell, shift being the periodic image offset of that range.
  template <class S>
  void for_each_row(const Vec<D>& x, S&& scan) const {
    const std::array<int, D> c = coords(x);
    // Per axis 1..D-1, the cells to visit and the periodic image offset of each.
    std::array<std::array<int, kMaxAxisVisits>, D> cell{};
    std::array<std::array<Real, kMaxAxisVisits>, D> offset{};
    std::array<int, D> visits{};
    std::array<int, kMaxAxisVisits> rel{};  // unused here
    for (int d = 1; d < D; ++d) {
      visits[d] = axis_visits(c[d], d, cell[d], rel, offset[d]);
      if (visits[d] == 0) return;
    }
    std::array<int, D> at{};
    while (true) {
      Vec<D> shift = Vec<D>::Zero();
      Index row = 0;
      for (int d = D - 1; d >= 1; --d) {
        row = row * count_[d] + cell[d][at[d]];
        shift[d] = offset[d][at[d]];
      }
      visit_row(c[0], row * count_[0], shift, scan);
      int d = 1;
      while (d < D && ++at[d] == visits[d]) at[d++] = 0;
      if (d == D) break;
    }
  }

  // The cells c0-reach..c0+reach of the row starting at linear index base, in that order.
  template <class S>
  void visit_row(int c0, Index base, Vec<D> shift, S& scan) const {
    const int n0 = count_[0];
    const int r = reach_;
    if (!periodic_[0]) {
      const int lo = std::max(c0 - r, 0), hi = std::min(c0 + r, n0 - 1);
      scan(start_[base + lo], start_[base + hi + 1], shift);
      return;
    }
    if (n0 < 2 * r + 1) {  // too few cells for a stencil: the whole row, in three images
      for (int s = -1; s <= 1; ++s) {
        shift[0] = static_cast<Real>(s) * length_[0];
        scan(start_[base], start_[base + n0], shift);
      }
      return;
    }
    // n0 >= 2 r + 1 here (build() picks r so), so at most one end wraps.
    if (c0 - r < 0) {  // the left cells are the last ones, one period to the left
      shift[0] = -length_[0];
      scan(start_[base + n0 + c0 - r], start_[base + n0], shift);
      shift[0] = 0;
      scan(start_[base], start_[base + c0 + r + 1], shift);
    } else if (c0 + r >= n0) {  // the right cells are the first ones, one period right
      scan(start_[base + c0 - r], start_[base + n0], shift);
      shift[0] = length_[0];
      scan(start_[base], start_[base + c0 + r + 1 - n0], shift);
    } else {
      scan(start_[base + c0 - r], start_[base + c0 + r + 1], shift);
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
  int reach_ = 1;  // cells per support along each axis (build())
  std::array<bool, D> periodic_{};
  std::array<Real, D> lo_{}, length_{}, origin_{}, cell_{};
  std::array<int, D> count_{};
  std::vector<Index> cell_of_, start_, fill_, sorted_;
  std::array<std::vector<Real>, D> sx_;  // positions at build(), in cell order, per axis
  // plan_tiles(): the two cut axes, the tile count along each, the first cell of each tile
  // along it (+ end), and the tiles of each colour.
  std::array<int, 2> tile_axis_{0, D > 1 ? 1 : 0};
  std::array<int, 2> tile_n_{1, 1};
  std::array<std::vector<int>, 2> tile_begin_;
  std::array<std::vector<int>, 4> tiles_of_colour_;
};

}  // namespace curvsph
