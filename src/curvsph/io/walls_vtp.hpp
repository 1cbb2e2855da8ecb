#pragma once
// The walls in the output (series.pvd, README "Outputs"): every wall tessellated at about dx
// from its exact geometry, one .vtp per wall of the case's `walls:` list (one ParaView block,
// named after the wall), polylines in 2-D and triangles in 3-D, with the point array
// `velocity`, the wall's surface velocity (its `motion`) at each vertex.
//
// The tessellation is the boundary-element discretisation of boundary/integrals/
// wall_elements.hpp, whatever the case's boundary method: its vertices lie on the exact wall
// (circle and ellipse arcs, sphere bands, torus and cylinder grids, NURBS curves and surfaces
// evaluated, CAD trimmed faces cut at their trim loops, STL triangles as they are), planes and
// cylinders clipped to the domain box (without one: to the particles' box grown by half its
// size and 4h, as the boundary integrals clip them). Vertices shared by neighbouring
// elements are merged (to 1e-9 dx), so a closed curve is one closed polyline.
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "curvsph/geometry/wall.hpp"
#include "curvsph/io/vtk_writer.hpp"

namespace curvsph {

template <int D>
struct WallMesh {
  std::vector<VecD<D>> points;
  // Cells: polylines (2-D) or triangles (3-D), VTK's layout (offsets: the end of each cell).
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<VecD<D>> velocity;  // the surface velocity at each point
};

// The mesh of the walls `walls` (the walls of one `walls:` entry) at spacing about dx; `clip`
// bounds infinite walls. A wall nobody discretises contributes nothing.
template <int D>
WallMesh<D> tessellate_walls(const std::vector<const Wall<D>*>& walls, double dx,
                             const Eigen::AlignedBox<double, D>& clip);

// The mesh as PolyData (points in double).
template <int D>
io::VtkPolyData wall_polydata(const WallMesh<D>& mesh);

}  // namespace curvsph
