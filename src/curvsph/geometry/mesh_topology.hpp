#pragma once
// Edge adjacency of a triangle mesh: which triangle lies across each triangle edge, and the
// defects that keep a mesh from bounding a volume (edges used once, edges used three or more
// times, edges whose two triangles are not consistently oriented). Built once by sorting the
// edge list: no hash map, no default-constructed values.
#include <array>
#include <vector>

namespace curvsph {

struct MeshEdges {
  // For triangle t and its edge i (from corner i to corner i+1 mod 3): the triangle on the
  // other side; -1 where there is none or more than one (non-manifold edge).
  std::vector<std::array<int, 3>> across;
  long boundary = 0;      // edges used by one triangle
  long non_manifold = 0;  // edges used by three triangles or more
  long misoriented = 0;   // edges used twice in the same direction
  // One example edge of each defect as its two vertex indices ({-1, -1} where none).
  std::array<int, 2> boundary_example{-1, -1};
  std::array<int, 2> non_manifold_example{-1, -1};
  std::array<int, 2> misoriented_example{-1, -1};
  bool closed() const { return boundary == 0 && non_manifold == 0 && misoriented == 0; }
};

MeshEdges mesh_edges(const std::vector<std::array<int, 3>>& triangles);

}  // namespace curvsph
