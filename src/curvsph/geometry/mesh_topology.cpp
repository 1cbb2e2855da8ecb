#include "curvsph/geometry/mesh_topology.hpp"

#include <algorithm>
#include <tuple>

namespace curvsph {

MeshEdges mesh_edges(const std::vector<std::array<int, 3>>& triangles) {
  MeshEdges m;
  m.across.assign(triangles.size(), {-1, -1, -1});
  // One record per triangle edge, keyed by its unordered vertex pair; equal keys are adjacent
  // after sorting, so each run of equal keys is the set of triangles sharing that edge.
  struct Half {
    int lo, hi, tri, edge;
    bool forward;  // lo -> hi is the triangle's own direction
  };
  std::vector<Half> h;
  h.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = triangles[t][i], b = triangles[t][(i + 1) % 3];
      h.push_back({std::min(a, b), std::max(a, b), static_cast<int>(t), i, a < b});
    }
  std::sort(h.begin(), h.end(), [](const Half& x, const Half& y) {
    return std::tie(x.lo, x.hi, x.tri, x.edge) < std::tie(y.lo, y.hi, y.tri, y.edge);
  });
  for (std::size_t s = 0; s < h.size();) {
    std::size_t e = s + 1;
    while (e < h.size() && h[e].lo == h[s].lo && h[e].hi == h[s].hi) ++e;
    const std::array<int, 2> edge{h[s].lo, h[s].hi};
    if (e - s == 1) {
      if (m.boundary++ == 0) m.boundary_example = edge;
    } else if (e - s > 2) {
      if (m.non_manifold++ == 0) m.non_manifold_example = edge;
    } else {
      // Two triangles: a consistently oriented surface walks the edge once each way.
      if (h[s].forward == h[s + 1].forward && m.misoriented++ == 0) m.misoriented_example = edge;
      m.across[h[s].tri][h[s].edge] = h[s + 1].tri;
      m.across[h[s + 1].tri][h[s + 1].edge] = h[s].tri;
    }
    s = e;
  }
  return m;
}

}  // namespace curvsph
