#pragma once
// Principal curvatures of a triangle mesh, estimated once per vertex so that a closest-point
// query only interpolates (DESIGN.md §4: the curvature-aware ghost maps need k1, k2 on STL
// walls too).
//
// Estimator: a local jet fit (Cazals & Pouget 2005, "Estimating differential quantities using
// polynomial fitting of osculating jets", CAGD 22): in a frame whose z axis is the vertex
// normal, the vertices of the vertex's 2-ring are fitted by least squares with
//   z = a x^2 + b x y + c y^2 + d x + e y + (the four cubic terms),
// the normal is tilted to the fitted one, (-d, -e, 1), and the fit repeated; the shape operator
// is then the Hessian [[2a, b], [b, 2c]]. Chosen by measurement (docs/geometry.md): at 2-degree
// facets 1.1 % on a latitude-longitude sphere, 0.15 % on an icosphere, 0.11 % on a cylinder,
// 0.9 % on a torus with jittered vertices; without the cubic terms the jittered torus gives
// 5.6 %, and the normal-difference estimator of Rusinkiewicz 2004 (exact on spheres) does not
// converge on irregular meshes (median 4.7 % there at every facet size).
//
// Sharp edges: an edge whose two faces turn by more than `feature_angle` (and every boundary
// edge) is a crease. A vertex on creases gets one estimate per smooth sector of its fan (the
// faces reachable around it without crossing a crease), and each fit uses only the 2-ring
// reachable from that sector without crossing a crease, so a cube face stays flat up to its
// edges and a cylinder's side is not bent by its caps.
#include <array>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/geometry/mesh_topology.hpp"

namespace curvsph {

struct MeshCurvature {
  // Per sector: the curvature tensor K (symmetric 3x3 stored as xx, yy, zz, xy, xz, yz) in
  // world coordinates, relative to the triangles' own normals (counter-clockwise): the normal
  // curvature along a unit tangent t is t^T K t, > 0 where the surface bends toward the normal.
  std::vector<std::array<double, 6>> tensor;
  // For each triangle corner: the sector whose tensor applies there.
  std::vector<std::array<int, 3>> corner_sector;
  double max_abs = 0.0;  // largest |principal curvature| of any sector
};

// face_n: unit normals of the triangles (zero for degenerate ones).
MeshCurvature mesh_curvature(const std::vector<Vec3d>& vertices,
                             const std::vector<std::array<int, 3>>& triangles,
                             const std::vector<Vec3d>& face_n, const MeshEdges& edges,
                             double feature_angle);

}  // namespace curvsph
