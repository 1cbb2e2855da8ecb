#include "curvsph/parallel/decomposition.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>

namespace curvsph {
namespace {

constexpr Real kInf = std::numeric_limits<Real>::infinity();

struct Clock {
  double& acc;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  ~Clock() { acc += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
};

}  // namespace

template <int D>
void Decomposition<D>::configure(const DecompositionOptions& o) {
  o_ = o;
  const auto P = static_cast<std::size_t>(comm_.size());
  send_.assign(P, {});
  recv_begin_.assign(P, 0);
  recv_count_.assign(P, 0);
  out_.assign(P, {});
  in_.assign(P, {});
  leave_.assign(P, {});
  boxes_.assign(P, Box{Vec<D>::Constant(-kInf), Vec<D>::Constant(kInf)});
  owned_bounds_ = boxes_;
  tree_ = OrbTree<D>{};
}

template <int D>
int Decomposition<D>::owner(const Vec<D>& x) const {
  return tree_.owner(x);
}

template <int D>
Real Decomposition<D>::distance_to(const Vec<D>& x, const Box& b) const {
  Real d2 = 0;
  for (int d = 0; d < D; ++d) {
    auto gap = [&](Real v) { return std::max({b.lo[d] - v, v - b.hi[d], Real(0)}); };
    Real g = gap(x[d]);
    if (o_.periodic[static_cast<std::size_t>(d)]) {
      // The nearest periodic image of x (positions are wrapped into the domain).
      const Real L = static_cast<Real>(o_.domain_max[d] - o_.domain_min[d]);
      g = std::min({g, gap(x[d] - L), gap(x[d] + L)});
    }
    d2 += g * g;
  }
  return std::sqrt(d2);
}

template <int D>
PairRule<D> Decomposition<D>::pair_rule(const CellList<D>& cells) {
  PairRule<D> rule(owned_);
  if (!midpoint()) return rule;
  rule.tree = &tree_;
  rule.cells = &cells;
  rule.halo = this;
  rule.rank = comm_.rank();
  // The pair rule's shortcut for two owned particles (pair_rule.hpp); halo_width = h, so the
  // kernel support is twice it.
  const Box& mine = boxes_[static_cast<std::size_t>(comm_.rank())];
  rule.owned_pairs_local = true;
  for (int d = 0; d < D; ++d) {
    if (!o_.periodic[static_cast<std::size_t>(d)]) continue;
    const Real L = static_cast<Real>(o_.domain_max[d] - o_.domain_min[d]);
    const Real extent = mine.hi[d] - mine.lo[d];
    if (extent < L && L - extent < 2 * o_.halo_width) rule.owned_pairs_local = false;
  }
  return rule;
}

template <int D>
void Decomposition<D>::sum(Real* data, int per_particle) {
  if (!active()) return;
  const auto P = static_cast<std::size_t>(comm_.size());
  const auto k = static_cast<std::size_t>(per_particle);
  for (std::size_t r = 0; r < P; ++r) {
    // The copies of rank r's particles go back to r, in the order r sent them.
    const auto count = static_cast<std::size_t>(recv_count_[r]);
    Real* copies = data + static_cast<std::size_t>(recv_begin_[r]) * k;
    out_[r].resize(count * k * sizeof(Real));
    if (count) std::memcpy(out_[r].data(), copies, count * k * sizeof(Real));
    std::fill(copies, copies + count * k, Real(0));
    in_[r].resize(send_[r].size() * k * sizeof(Real));
  }
  comm_.exchange(out_, in_, /*sizes_known=*/true);
  Clock c{stats_.seconds};
  std::vector<Real>& add = sum_buffer_;
  for (std::size_t r = 0; r < P; ++r) {
    const auto& idx = send_[r];
    add.resize(idx.size() * k);
    if (!idx.empty()) std::memcpy(add.data(), in_[r].data(), add.size() * sizeof(Real));
    for (std::size_t t = 0; t < idx.size(); ++t)
      for (std::size_t e = 0; e < k; ++e)
        data[static_cast<std::size_t>(idx[t]) * k + e] += add[t * k + e];
  }
}

// Every rank's bounding box of its owned particles, in one reduction (min of lo and of -hi;
// a rank's own slot is the only finite one before it).
template <int D>
void Decomposition<D>::gather_owned_bounds(const Particles<D>& P) {
  const auto R = static_cast<std::size_t>(comm_.size());
  bounds_.assign(R * 2 * D, static_cast<double>(kInf));
  double* mine = bounds_.data() + static_cast<std::size_t>(comm_.rank()) * 2 * D;
  for (Index i = 0; i < owned_; ++i)
    for (int d = 0; d < D; ++d) {
      mine[d] = std::min(mine[d], static_cast<double>(P.x[i][d]));
      mine[D + d] = std::min(mine[D + d], -static_cast<double>(P.x[i][d]));
    }
  comm_.min(bounds_);
  for (std::size_t r = 0; r < R; ++r)
    for (int d = 0; d < D; ++d) {
      owned_bounds_[r].lo[d] = static_cast<Real>(bounds_[r * 2 * D + static_cast<std::size_t>(d)]);
      owned_bounds_[r].hi[d] =
          static_cast<Real>(-bounds_[r * 2 * D + static_cast<std::size_t>(D + d)]);
    }
}

// Cuts the tree node's region across its longest axis so that the ranks [rank_lo, mid) get
// their share of the particles in it; recurses into both halves. `region` is finite (the
// particles' bounding box, the domain on periodic axes) and chooses the axis; `own` is the
// ownership box (infinite outer sides on non-periodic axes).
template <int D>
void Decomposition<D>::split(std::vector<int>& node_of, const Particles<D>& P, int node, Box region,
                             Box own, int rank_lo, int rank_hi) {
  if (rank_hi - rank_lo == 1) {
    tree_.nodes[static_cast<std::size_t>(node)].rank = rank_lo;
    boxes_[static_cast<std::size_t>(rank_lo)] = own;
    return;
  }
  const int mid = rank_lo + (rank_hi - rank_lo) / 2;
  int axis = 0;
  for (int d = 1; d < D; ++d)
    if (region.hi[d] - region.lo[d] > region.hi[axis] - region.lo[axis]) axis = d;
  const Index n = owned_;
  auto count_below = [&](Real cut) {
    std::int64_t c = 0;
    for (Index i = 0; i < n; ++i)
      if (node_of[static_cast<std::size_t>(i)] == node && P.x[i][axis] < cut) ++c;
    return comm_.sum(c);
  };
  std::int64_t here = 0;
  for (Index i = 0; i < n; ++i) here += node_of[static_cast<std::size_t>(i)] == node;
  here = comm_.sum(here);
  const std::int64_t target = here * (mid - rank_lo) / (rank_hi - rank_lo);
  // Bisection on the cut position: the count below is monotone in the cut; 40 halvings put
  // the cut within 1e-12 of the region's extent of the exact quantile.
  Real a = region.lo[axis], b = region.hi[axis];
  for (int it = 0; it < 40; ++it) {
    const Real c = Real(0.5) * (a + b);
    (count_below(c) < target ? a : b) = c;
  }
  // Between b (the smallest tried position with the target below it) and its neighbours: the
  // cut goes midway between the last particle below and the first above, so a lattice does
  // not put a layer of particles on the cut itself.
  Real below = -kInf, above = kInf;
  for (Index i = 0; i < n; ++i) {
    if (node_of[static_cast<std::size_t>(i)] != node) continue;
    const Real x = P.x[i][axis];
    if (x < b)
      below = std::max(below, x);
    else
      above = std::min(above, x);
  }
  below = static_cast<Real>(comm_.max(static_cast<double>(below)));
  above = static_cast<Real>(comm_.min(static_cast<double>(above)));
  const Real cut = std::isfinite(below) && std::isfinite(above) ? Real(0.5) * (below + above) : b;
  Node& nd = tree_.nodes[static_cast<std::size_t>(node)];
  nd.axis = axis;
  nd.cut = cut;
  const int left = static_cast<int>(tree_.nodes.size()), right = left + 1;
  tree_.nodes[static_cast<std::size_t>(node)].child[0] = left;
  tree_.nodes[static_cast<std::size_t>(node)].child[1] = right;
  tree_.nodes.resize(tree_.nodes.size() + 2);
  for (Index i = 0; i < n; ++i) {
    auto& k = node_of[static_cast<std::size_t>(i)];
    if (k == node) k = P.x[i][axis] < cut ? left : right;
  }
  Box rl = region, rr = region, ol = own, orr = own;
  rl.hi[axis] = rr.lo[axis] = cut;
  ol.hi[axis] = orr.lo[axis] = cut;
  split(node_of, P, left, rl, ol, rank_lo, mid);
  split(node_of, P, right, rr, orr, mid, rank_hi);
}

template <int D>
void Decomposition<D>::bisect(const Particles<D>& P) {
  Box region, own;
  for (int d = 0; d < D; ++d) {
    if (o_.periodic[static_cast<std::size_t>(d)]) {
      region.lo[d] = own.lo[d] = static_cast<Real>(o_.domain_min[d]);
      region.hi[d] = own.hi[d] = static_cast<Real>(o_.domain_max[d]);
      continue;
    }
    Real lo = kInf, hi = -kInf;
    for (Index i = 0; i < owned_; ++i) {
      lo = std::min(lo, P.x[i][d]);
      hi = std::max(hi, P.x[i][d]);
    }
    region.lo[d] = static_cast<Real>(comm_.min(static_cast<double>(lo)));
    region.hi[d] = static_cast<Real>(comm_.max(static_cast<double>(hi)));
    own.lo[d] = -kInf;
    own.hi[d] = kInf;
  }
  tree_.nodes.assign(1, Node{});
  std::vector<int> node_of(static_cast<std::size_t>(owned_), 0);
  split(node_of, P, 0, region, own, 0, comm_.size());
}

// Sends every owned particle whose owner is another rank; keeps the others in their order
// and appends the arrivals (sender rank order).
template <int D>
void Decomposition<D>::send_leavers(Particles<D>& P) {
  const auto R = static_cast<std::size_t>(comm_.size());
  for (auto& l : leave_) l.clear();
  keep_.clear();
  for (Index i = 0; i < owned_; ++i) {
    const int r = owner(P.x[i]);
    if (r == comm_.rank())
      keep_.push_back(static_cast<std::size_t>(i));
    else
      leave_[static_cast<std::size_t>(r)].push_back(i);
  }
  for (std::size_t r = 0; r < R; ++r) {
    out_[r].clear();
    if (!leave_[r].empty()) mpi::pack(P, leave_[r], mpi::FieldSet::all, out_[r]);
  }
  comm_.exchange(out_, in_);
  if (keep_.size() != P.size()) P.permute(keep_);  // permute() keeps only the listed indices
  for (std::size_t r = 0; r < R; ++r)
    if (!in_[r].empty()) mpi::unpack_append(P, in_[r], mpi::FieldSet::all);
  owned_ = static_cast<Index>(P.size());
}

template <int D>
void Decomposition<D>::distribute(Particles<D>& P) {
  owned_ = static_cast<Index>(P.size());
  if (o_.check_conservation) {
    count0_ = static_cast<std::int64_t>(P.size());
    id0_ = id2_0_ = 0;
    mass0_ = 0;
    for (Index i = 0; i < owned_; ++i) {
      id0_ += P.id[i];
      id2_0_ += P.id[i] * P.id[i];
      mass0_ += static_cast<double>(P.mass[i]);
    }
  }
  if (!active()) return;
  // Every rank generated the same particles: keep a strided share, then bisect and migrate
  // exactly as a re-balance would (one code path for both).
  std::vector<std::size_t> mine;
  for (std::size_t i = static_cast<std::size_t>(comm_.rank()); i < P.size();
       i += static_cast<std::size_t>(comm_.size()))
    mine.push_back(i);
  P.permute(mine);
  owned_ = static_cast<Index>(P.size());
  bisect(P);
  send_leavers(P);
  ++stats_.rebalances;
  check_conservation(P);
}

template <int D>
void Decomposition<D>::migrate(Particles<D>& P) {
  owned_ = static_cast<Index>(P.size());
  if (!active()) {
    check_conservation(P);
    return;
  }
  {
    Clock c{stats_.seconds};
    send_leavers(P);
  }
  const double n = static_cast<double>(owned_);
  const double mean = comm_.sum(n) / comm_.size();
  const double imbalance = mean > 0 ? comm_.max(n) / mean : 1.0;
  ++stats_.migrations;
  stats_.imbalance_sum += imbalance;
  stats_.imbalance_max = std::max(stats_.imbalance_max, imbalance);
  if (imbalance > 1 + o_.rebalance_imbalance) {
    Clock c{stats_.seconds};
    bisect(P);
    send_leavers(P);
    ++stats_.rebalances;
  }
  check_conservation(P);
}

template <int D>
void Decomposition<D>::forget(std::int64_t count, std::int64_t ids, std::int64_t ids2,
                              double mass) {
  if (!o_.check_conservation) return;
  std::vector<std::int64_t> s{count, ids, ids2};
  std::vector<double> m{mass};
  if (active()) {
    comm_.sum(s);
    comm_.sum(m);
  }
  count0_ -= s[0];
  id0_ -= s[1];
  id2_0_ -= s[2];
  mass0_ -= m[0];
}

template <int D>
void Decomposition<D>::check_conservation(const Particles<D>& P) {
  if (!o_.check_conservation) return;
  std::vector<std::int64_t> s{static_cast<std::int64_t>(owned_), 0, 0};
  std::vector<double> m{0};
  for (Index i = 0; i < owned_; ++i) {
    s[1] += P.id[i];
    s[2] += P.id[i] * P.id[i];
    m[0] += static_cast<double>(P.mass[i]);
  }
  comm_.sum(s);
  comm_.sum(m);
  ++stats_.conservation_checks;
  stats_.count_error_max = std::max(stats_.count_error_max, std::abs(s[0] - count0_));
  stats_.id_error_max =
      std::max({stats_.id_error_max, std::abs(s[1] - id0_), std::abs(s[2] - id2_0_)});
  if (mass0_ > 0)
    stats_.mass_rel_error_max =
        std::max(stats_.mass_rel_error_max, std::abs(m[0] - mass0_) / mass0_);
}

template <int D>
void Decomposition<D>::exchange_halo(Particles<D>& P) {
  owned_ = static_cast<Index>(P.size());
  if (!active()) return;
  const auto R = static_cast<std::size_t>(comm_.size());
  if (!o_.midpoint) gather_owned_bounds(P);  // the owner rule's halo reference
  {
    Clock c{stats_.seconds};
    for (auto& s : send_) s.clear();
    // Midpoint rule: within h of the ORB box, where the midpoints of the receiver's pairs
    // lie; owner rule: within 2h (or more) of the receiver's owned particles.
    const std::vector<Box>& to = o_.midpoint ? boxes_ : owned_bounds_;
    for (Index i = 0; i < owned_; ++i)
      for (std::size_t r = 0; r < R; ++r)
        if (static_cast<int>(r) != comm_.rank() && distance_to(P.x[i], to[r]) < o_.halo_width)
          send_[r].push_back(i);
    for (std::size_t r = 0; r < R; ++r) {
      out_[r].clear();
      if (!send_[r].empty()) mpi::pack(P, send_[r], mpi::FieldSet::halo, out_[r]);
    }
  }
  comm_.exchange(out_, in_);
  Clock c{stats_.seconds};
  for (std::size_t r = 0; r < R; ++r) {
    recv_begin_[r] = static_cast<Index>(P.size());
    recv_count_[r] = static_cast<Index>(mpi::unpack_append(P, in_[r], mpi::FieldSet::halo));
  }
  stats_.halo_sum += static_cast<double>(P.size() - static_cast<std::size_t>(owned_));
  stats_.owned_sum += static_cast<double>(owned_);
}

template <int D>
void Decomposition<D>::drop_halo(Particles<D>& P) {
  if (!active()) {
    owned_ = static_cast<Index>(P.size());
    return;
  }
  if (static_cast<Index>(P.size()) == owned_) return;
  P.for_each_field([&](const char*, auto& data) { data.resize(static_cast<std::size_t>(owned_)); });
}

template <int D>
Particles<D> Decomposition<D>::gather(const Particles<D>& P) const {
  Particles<D> all;
  if (!active()) {
    all = P;
    all.for_each_field(
        [&](const char*, auto& data) { data.resize(static_cast<std::size_t>(owned_)); });
    return all;
  }
  std::vector<Index> idx(static_cast<std::size_t>(owned_));
  std::iota(idx.begin(), idx.end(), Index(0));
  std::vector<std::byte> mine;
  mpi::pack(P, idx, mpi::FieldSet::all, mine);
  // Each rank's block is field-major on its own, so unpack rank by rank: the sizes come
  // from a gather of the counts, packed in front of the data.
  const std::int64_t n = owned_;
  std::vector<std::byte> head(sizeof n + mine.size());
  std::memcpy(head.data(), &n, sizeof n);
  if (!mine.empty()) std::memcpy(head.data() + sizeof n, mine.data(), mine.size());
  const auto buf = comm_.gather(head, 0);
  if (!comm_.root()) return all;
  const std::size_t rec = mpi::record_bytes(P, mpi::FieldSet::all);
  std::size_t at = 0;
  while (at < buf.size()) {
    std::int64_t k = 0;
    std::memcpy(&k, buf.data() + at, sizeof k);
    at += sizeof k;
    const std::size_t bytes = static_cast<std::size_t>(k) * rec;
    std::vector<std::byte> block(buf.begin() + static_cast<std::ptrdiff_t>(at),
                                 buf.begin() + static_cast<std::ptrdiff_t>(at + bytes));
    mpi::unpack_append(all, block, mpi::FieldSet::all);
    at += bytes;
  }
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return all.id[a] < all.id[b]; });
  all.permute(order);
  return all;
}

template class Decomposition<2>;
template class Decomposition<3>;

}  // namespace curvsph
