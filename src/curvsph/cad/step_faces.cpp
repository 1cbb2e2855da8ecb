#include "curvsph/cad/step_faces.hpp"

#include <fmt/format.h>

#include <StepData_StepModel.hxx>
#include <StepGeom_ConicalSurface.hxx>
#include <StepGeom_CylindricalSurface.hxx>
#include <StepGeom_SphericalSurface.hxx>
#include <StepGeom_ToroidalSurface.hxx>
#include <StepShape_FaceSurface.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "curvsph/core/error.hpp"

namespace curvsph::cad {
namespace {

// The name and the radii of an elementary surface with an invalid radius; empty when valid.
std::string bad_radius(const Handle(StepGeom_Surface) & g) {
  if (const auto c = Handle(StepGeom_CylindricalSurface)::DownCast(g); !c.IsNull()) {
    if (!(c->Radius() > 0)) return fmt::format("CYLINDRICAL_SURFACE with radius {}", c->Radius());
  } else if (const auto s = Handle(StepGeom_SphericalSurface)::DownCast(g); !s.IsNull()) {
    if (!(s->Radius() > 0)) return fmt::format("SPHERICAL_SURFACE with radius {}", s->Radius());
  } else if (const auto k = Handle(StepGeom_ConicalSurface)::DownCast(g); !k.IsNull()) {
    // A cone's reference radius may be 0 (the placement at the apex).
    if (!(k->Radius() >= 0)) return fmt::format("CONICAL_SURFACE with radius {}", k->Radius());
  } else if (const auto t = Handle(StepGeom_ToroidalSurface)::DownCast(g); !t.IsNull()) {
    if (!(t->MajorRadius() > 0 && t->MinorRadius() > 0))
      return fmt::format("TOROIDAL_SURFACE with radii {} and {}", t->MajorRadius(),
                         t->MinorRadius());
  }
  return {};
}

int face_entities(const Handle(StepData_StepModel) & model) {
  int n = 0;
  for (int i = 1; i <= model->NbEntities(); ++i)
    if (!Handle(StepShape_FaceSurface)::DownCast(model->Value(i)).IsNull()) ++n;
  return n;
}

}  // namespace

void check_step_surfaces(const STEPControl_Reader& reader, const std::string& path,
                         const std::string& file, const std::string& key) {
  const Handle(StepData_StepModel) model = reader.StepModel();
  if (model.IsNull()) return;
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const auto face = Handle(StepShape_FaceSurface)::DownCast(model->Value(i));
    if (face.IsNull() || face->FaceGeometry().IsNull()) continue;
    const std::string bad = bad_radius(face->FaceGeometry());
    if (!bad.empty())
      throw InputError(
          file, key,
          fmt::format("STEP file '{}': face #{} lies on #{} {} (radii must be > 0)", path,
                      model->IdentLabel(face), model->IdentLabel(face->FaceGeometry()), bad));
  }
}

void check_step_face_count(const STEPControl_Reader& reader, const TopoDS_Shape& shape,
                           const std::string& path, const std::string& file,
                           const std::string& key) {
  const Handle(StepData_StepModel) model = reader.StepModel();
  if (model.IsNull()) return;
  TopTools_IndexedMapOfShape faces;  // distinct faces (a face shared by two shells once)
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  const int want = face_entities(model);
  if (faces.Extent() < want)
    throw InputError(file, key,
                     fmt::format("STEP file '{}': {} of its {} faces could not be read "
                                 "(OpenCASCADE dropped them)",
                                 path, want - faces.Extent(), want));
}

}  // namespace curvsph::cad
