// GeometricShepard<3>'s set-up tables: the flat patches (connected coplanar elements joined by
// twin edges), each element's clearance to its patch's rim, and the rim edges binned for the
// rim path (shepard.hpp describes them; geometric_shepard.cpp uses them every step).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/shepard_quadrature.hpp"

namespace curvsph {

using shepard_detail::point_in_polygon;
using shepard_detail::segment_distance;

template <>
void GeometricShepard<3>::build_patches(const BoundaryElements<3>& el) {
  // Patches: connected components of the twin graph over exact flat elements (gap 0, centre
  // in the element's plane and inside it). Elements standing for a curved wall (gap > 0)
  // stay out: their on-wall band is handled by geometric_impl.
  const std::size_t n = el.size();
  const double grid = 1e-9 * h_;
  std::vector<std::int64_t> parent(n);
  std::vector<unsigned char> flat(n, 0);
  for (std::size_t j = 0; j < n; ++j) {
    parent[j] = static_cast<std::int64_t>(j);
    const bool exact = j >= el.gap.size() || el.gap[j] == 0.0;
    const double off = std::abs(el.normal[j].dot(el.centre[j] - el.vertices[j][0]));
    flat[j] = exact && off <= grid && point_in_polygon(el, j, el.centre[j], 0.0);
  }
  auto find = [&](std::int64_t a) {
    while (parent[static_cast<std::size_t>(a)] != a) {
      auto& pa = parent[static_cast<std::size_t>(a)];
      pa = parent[static_cast<std::size_t>(pa)];  // path halving
      a = pa;
    }
    return a;
  };
  for (std::size_t j = 0; j < n; ++j)
    for (int k = 0; k < el.vertex_count[j]; ++k) {
      const std::int64_t o = twin_[4 * j + static_cast<std::size_t>(k)];
      if (o < 0 || !flat[j] || !flat[static_cast<std::size_t>(o)]) continue;
      const std::int64_t a = find(static_cast<std::int64_t>(j)), b = find(o);
      if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  patch_.assign(n, -1);
  std::vector<std::int32_t> id(n, -1);
  std::int32_t count = 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (!flat[j]) continue;
    const auto root = static_cast<std::size_t>(find(static_cast<std::int64_t>(j)));
    if (id[root] < 0) id[root] = count++;
    patch_[j] = id[root];
  }
  // Rim of every patch: the edges whose twin is not a member of the same patch. clear_[j] =
  // distance from centre j to its patch's rim (brute force over the rim, once at set-up:
  // elements x rim edges of one patch). The patch is a union of elements glued along twin
  // edges, so its boundary lies on rim edges and the disc of radius clear_[j] about the
  // centre (inside element j) is inside the patch; a non-conforming mesh (T-junctions)
  // leaves inner edges without twins, which only makes clear_ smaller (conservative).
  // The same rim edges, all patches together, feed the rim path's tables (see shepard.hpp);
  // patch_rim_ok_ is cleared for a patch with a rim edge that has a twin elsewhere.
  std::vector<std::vector<std::array<Vec3d, 2>>> rim(static_cast<std::size_t>(count));
  patch_rim_ok_.assign(static_cast<std::size_t>(count), 1);
  rim_edges_.clear();
  double longest = 0;
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t j = 0; j < n; ++j) {
    if (patch_[j] < 0) continue;
    const auto& v = el.vertices[j];
    const int m = el.vertex_count[j];
    for (int k = 0; k < m; ++k) {
      const std::int64_t o = twin_[4 * j + static_cast<std::size_t>(k)];
      if (o >= 0 && patch_[static_cast<std::size_t>(o)] == patch_[j]) continue;
      if (o >= 0) patch_rim_ok_[static_cast<std::size_t>(patch_[j])] = 0;
      const Vec3d& a = v[static_cast<std::size_t>(k)];
      const Vec3d& b = v[static_cast<std::size_t>((k + 1) % m)];
      rim[static_cast<std::size_t>(patch_[j])].push_back({a, b});
      rim_edges_.push_back({a, b, patch_[j]});
      longest = std::max(longest, (b - a).norm());
      lo = lo.cwiseMin(0.5 * (a + b));
      hi = hi.cwiseMax(0.5 * (a + b));
    }
  }
  clear_.assign(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    if (patch_[j] < 0) continue;
    double d = std::numeric_limits<double>::infinity();
    for (const auto& e : rim[static_cast<std::size_t>(patch_[j])])
      d = std::min(d, segment_distance(e[0], e[1], el.centre[j]));
    clear_[j] = d;
  }
  rim_start_.clear();
  rim_index_.clear();
  if (rim_edges_.empty()) return;
  // Cells of at least 2h + the longest edge: an edge within 2h of x has its midpoint within
  // one cell of x's. Capped at ~2e6 cells (larger cells only cost more visits).
  rim_cell_ = 2.0 * h_ + longest;
  const Vec3d extent = hi - lo;
  while ((extent / rim_cell_).prod() > 2e6) rim_cell_ *= 1.5;
  rim_origin_ = lo;
  for (int d = 0; d < 3; ++d)
    rim_dims_[static_cast<std::size_t>(d)] = static_cast<int>(extent[d] / rim_cell_) + 1;
  auto cell_of = [&](const Vec3d& p) {
    int i[3];
    for (int d = 0; d < 3; ++d)
      i[d] = std::clamp(static_cast<int>((p[d] - rim_origin_[d]) / rim_cell_), 0,
                        rim_dims_[static_cast<std::size_t>(d)] - 1);
    return rim_cell_index(i[0], i[1], i[2]);
  };
  const std::size_t cells = static_cast<std::size_t>(rim_dims_[0]) *
                            static_cast<std::size_t>(rim_dims_[1]) *
                            static_cast<std::size_t>(rim_dims_[2]);
  rim_start_.assign(cells + 1, 0);
  for (const RimEdge& e : rim_edges_) ++rim_start_[cell_of(0.5 * (e.a + e.b)) + 1];
  for (std::size_t c = 0; c < cells; ++c) rim_start_[c + 1] += rim_start_[c];
  rim_index_.resize(rim_edges_.size());
  std::vector<std::uint32_t> fill(rim_start_.begin(), rim_start_.end() - 1);
  for (std::size_t i = 0; i < rim_edges_.size(); ++i)
    rim_index_[fill[cell_of(0.5 * (rim_edges_[i].a + rim_edges_[i].b))]++] =
        static_cast<std::uint32_t>(i);
}

}  // namespace curvsph
