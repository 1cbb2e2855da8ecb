#pragma once
// CAD walls through OpenCASCADE (DESIGN.md §2 cad/):
//   {shape: cad, file: part.step|part.stp|part.iges|part.igs|part.stl, fluid: inside|outside,
//    scale (optional), faces (optional list of face indices to keep)}
// STEP/IGES: every B-rep face becomes a trimmed NURBS wall (B-spline surfaces as they are,
// other surface types converted by GeomConvert). Lengths are converted to metres from the
// unit the file declares; `scale` (optional) multiplies after that. STL is read as metres
// (times `scale`) into a triangle-mesh wall. `file` is relative to the case file's directory.
//
// A closed shell or solid with all its faces (no `faces` key) is ONE wall (CadSolidWall): the
// nearest face answers, the solid decides the side at edges and corners. An open shell, or a
// `faces` selection, stays one wall per face.
//
// Fluid side of a solid: face normals oriented outward from the material (OCCT: the
// surface normal Su x Sv, flipped for faces with TopAbs_REVERSED orientation); `inside`
// puts the fluid inside the closed shell (a pipe's bore), `outside` around it.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "curvsph/geometry/wall.hpp"

class TopoDS_Shape;

namespace curvsph {

std::vector<WallPtr<3>> make_cad_walls(const YAML::Node& node, const std::string& file,
                                       const std::string& key_prefix, const std::string& base_dir);

namespace cad {

enum class FluidSide { inside, outside };

// Reads a STEP or IGES file with lengths in metres (throws InputError naming `key`).
TopoDS_Shape read_brep(const std::string& path, const std::string& file, const std::string& key);
// One trimmed NURBS wall per face of `shape` (all faces when `faces` is empty).
std::vector<WallPtr<3>> faces_to_walls(const TopoDS_Shape& shape, FluidSide side, double scale,
                                       const std::vector<int>& faces = {});
// One wall for a closed shell: the faces of faces_to_walls(shape, side, scale) (all of them, in
// that order) under the solid's classifier (cad_solid_wall.hpp).
WallPtr<3> make_solid_wall(const TopoDS_Shape& shape, const std::vector<WallPtr<3>>& faces,
                           FluidSide side, double scale, const std::string& label);
// Human-readable inventory: face count and surface types.
std::string describe_shape(const TopoDS_Shape& shape);

}  // namespace cad
}  // namespace curvsph
