#pragma once
// Checks of a STEP file's faces before and after OpenCASCADE transfers them: the STEP
// translator drops a face whose surface is invalid (a cylinder of negative radius) without an
// error, so that the wall would silently miss a face (issue 34).
#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>
#include <string>

namespace curvsph::cad {

// After ReadFile: every face's elementary surface (cylinder, cone, sphere, torus) has valid
// radii; otherwise an InputError naming `file`, `key`, the STEP file and the face entity (#N).
void check_step_surfaces(const STEPControl_Reader& reader, const std::string& path,
                         const std::string& file, const std::string& key);

// After the transfer: `shape` holds as many faces as the file has face entities.
void check_step_face_count(const STEPControl_Reader& reader, const TopoDS_Shape& shape,
                           const std::string& path, const std::string& file,
                           const std::string& key);

}  // namespace curvsph::cad
