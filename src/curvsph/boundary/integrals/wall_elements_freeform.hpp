#pragma once
// Internal to wall_elements.cpp: the discretizers of the free-form walls (NURBS curves and
// surfaces, trimmed CAD faces, triangle meshes; wall_elements_freeform.cpp) and the curved
// patch helper they share with the analytic surfaces. Each returns false when the wall is not
// its type (the extension point described in wall_elements.hpp).
#include <functional>

#include "curvsph/boundary/integrals/wall_elements.hpp"

namespace curvsph::wall_elements_detail {

// The patch of the parameter cell [u0, u1] x [v0, v1] of surface S with unit normal function
// `normal` (into the fluid) and exact area: vertices S at the cell's corners (a repeated one,
// a pole, dropped), ordered to face the fluid, centre and normal at the cell's middle, gap =
// the surface's largest distance from the vertices' plane (wall_elements.cpp).
void add_surface_cell(BoundaryElements<3>& out, const std::function<Vec3d(double, double)>& S,
                      const std::function<Vec3d(double, double)>& normal, double u0, double u1,
                      double v0, double v1, double area);

bool nurbs_curve_2d(const Wall<2>& w, double dx, const Bounds<2>& bounds, BoundaryElements<2>& out);
bool nurbs_surface_3d(const Wall<3>& w, double dx, const Bounds<3>& bounds,
                      BoundaryElements<3>& out);
// wall_elements_cad.cpp
bool trimmed_face_3d(const Wall<3>& w, double dx, const Bounds<3>& bounds,
                     BoundaryElements<3>& out);
// A closed CAD solid: the elements of every face.
bool cad_solid_3d(const Wall<3>& w, double dx, const Bounds<3>& bounds, BoundaryElements<3>& out);
bool trimesh_3d(const Wall<3>& w, double dx, const Bounds<3>& bounds, BoundaryElements<3>& out);

}  // namespace curvsph::wall_elements_detail
