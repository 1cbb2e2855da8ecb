#include "curvsph/cad/cad_import.hpp"

#include <fmt/format.h>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESSolid_Face.hxx>
#include <IGESSolid_Loop.hxx>
#include <IGESSolid_ManifoldSolid.hxx>
#include <IGESSolid_Shell.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <UnitsMethods.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <filesystem>
#include <map>

#include "curvsph/cad/cad_solid_wall.hpp"
#include "curvsph/cad/step_faces.hpp"
#include "curvsph/cad/stl_reader.hpp"
#include "curvsph/cad/trimmed_face_wall.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/trimesh_wall.hpp"
#include "curvsph/io/data_file.hpp"
#include "curvsph/nurbs/yaml_input.hpp"

namespace curvsph {
namespace cad {

std::string lower_ext(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

namespace {

// OCCT converts lengths from the unit the file declares to the session unit; make that
// the metre (both the XSTEP parameter and the session value, as OCCT 7.6 reads either).
void set_session_unit_metre() {
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  UnitsMethods::SetCasCadeLengthUnit(1000.0);  // in millimetres
}

const char* surface_type_name(GeomAbs_SurfaceType t) {
  switch (t) {
    case GeomAbs_Plane:
      return "plane";
    case GeomAbs_Cylinder:
      return "cylinder";
    case GeomAbs_Cone:
      return "cone";
    case GeomAbs_Sphere:
      return "sphere";
    case GeomAbs_Torus:
      return "torus";
    case GeomAbs_BezierSurface:
      return "bezier";
    case GeomAbs_BSplineSurface:
      return "bspline";
    case GeomAbs_SurfaceOfRevolution:
      return "revolution";
    case GeomAbs_SurfaceOfExtrusion:
      return "extrusion";
    case GeomAbs_OffsetSurface:
      return "offset";
    default:
      return "other";
  }
}

// The face's surface as a NURBS surface over its parameter bounds, scaled to metres.
nurbs::NurbsSurface to_nurbs(const TopoDS_Face& face, double scale) {
  Handle(Geom_Surface) s = BRep_Tool::Surface(face);  // location applied
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(s);
  if (b.IsNull()) {
    // Planes, cylinders, tori... are unbounded or periodic: trim to the face's box first.
    Handle(Geom_RectangularTrimmedSurface) t =
        new Geom_RectangularTrimmedSurface(s, u0, u1, v0, v1);
    b = GeomConvert::SurfaceToBSplineSurface(t);
  }
  const auto flat = [](const TColStd_Array1OfReal& k, const TColStd_Array1OfInteger& m) {
    std::vector<double> out;
    for (int i = k.Lower(); i <= k.Upper(); ++i)
      for (int r = 0; r < m(i); ++r) out.push_back(k(i));
    return out;
  };
  if (b->IsUPeriodic()) b->SetUNotPeriodic();  // clamped knots for our evaluator
  if (b->IsVPeriodic()) b->SetVNotPeriodic();
  std::vector<std::vector<Vec3d>> P(b->NbUPoles(), std::vector<Vec3d>(b->NbVPoles()));
  std::vector<std::vector<double>> W(b->NbUPoles(), std::vector<double>(b->NbVPoles()));
  for (int i = 1; i <= b->NbUPoles(); ++i)
    for (int j = 1; j <= b->NbVPoles(); ++j) {
      const gp_Pnt p = b->Pole(i, j);
      P[i - 1][j - 1] = scale * Vec3d(p.X(), p.Y(), p.Z());
      W[i - 1][j - 1] = b->Weight(i, j);
    }
  TColStd_Array1OfReal ku(1, b->NbUKnots()), kv(1, b->NbVKnots());
  TColStd_Array1OfInteger mu(1, b->NbUKnots()), mv(1, b->NbVKnots());
  b->UKnots(ku);
  b->VKnots(kv);
  b->UMultiplicities(mu);
  b->VMultiplicities(mv);
  return nurbs::NurbsSurface(b->UDegree(), b->VDegree(), P, W, flat(ku, mu), flat(kv, mv));
}

}  // namespace

namespace {

// OCCT's IGES transfer dereferences the entities a B-rep solid, shell, face or loop points to
// without checking them: a corrupt file whose pointer names no entity (found by fuzz/fuzz_cad,
// seed fuzz/corpus/cad/iges_shell_without_face.bin) crashed the run in
// IGESSolid_Face::Surface(). Refuse such a model before the transfer.
void check_iges_references(const Handle(IGESData_IGESModel) & model, const std::string& path,
                           const std::string& file, const std::string& key) {
  if (model.IsNull()) throw InputError(file, key, fmt::format("no IGES model in '{}'", path));
  auto missing = [&](Standard_Integer entity, const char* what) {
    throw InputError(file, key,
                     fmt::format("IGES file '{}' is corrupt: entity {} refers to a missing {}",
                                 path, entity, what));
  };
  for (Standard_Integer i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Standard_Transient) e = model->Value(i);
    if (const auto solid = Handle(IGESSolid_ManifoldSolid)::DownCast(e); !solid.IsNull()) {
      if (solid->Shell().IsNull()) missing(i, "shell");
      for (Standard_Integer k = 1; k <= solid->NbVoidShells(); ++k)
        if (solid->VoidShell(k).IsNull()) missing(i, "void shell");
    }
    if (const auto shell = Handle(IGESSolid_Shell)::DownCast(e); !shell.IsNull())
      for (Standard_Integer k = 1; k <= shell->NbFaces(); ++k)
        if (shell->Face(k).IsNull()) missing(i, "face");
    if (const auto face = Handle(IGESSolid_Face)::DownCast(e); !face.IsNull()) {
      if (face->Surface().IsNull()) missing(i, "surface");
      for (Standard_Integer k = 1; k <= face->NbLoops(); ++k)
        if (face->Loop(k).IsNull()) missing(i, "loop");
    }
  }
}

}  // namespace

TopoDS_Shape read_brep(const std::string& path, const std::string& file, const std::string& key) {
  const std::string ext = lower_ext(path);
  if (!std::filesystem::exists(path))
    throw InputError(file, key, fmt::format("CAD file '{}' not found", path));
  TopoDS_Shape shape;
  if (ext == ".step" || ext == ".stp") {
    STEPControl_Reader reader;  // registers the STEP statics before they are set
    set_session_unit_metre();
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw InputError(file, key, fmt::format("cannot read STEP file '{}'", path));
    // Entities the loader failed on (an unresolved reference is left null, which OCCT's
    // transfer dereferences: seed fuzz/corpus/cad/step_edge_without_element.bin).
    if (!reader.WS()->ModelCheckList().IsEmpty(Standard_True))
      throw InputError(file, key,
                       fmt::format("STEP file '{}' is corrupt: entities failed to load", path));
    check_step_surfaces(reader, path, file, key);
    reader.TransferRoots();
    shape = reader.OneShape();
    if (!shape.IsNull()) check_step_face_count(reader, shape, path, file, key);
  } else if (ext == ".iges" || ext == ".igs") {
    IGESControl_Reader reader;
    set_session_unit_metre();
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw InputError(file, key, fmt::format("cannot read IGES file '{}'", path));
    // Entities the loader failed on (a list it could not read is left null inside them).
    if (!reader.WS()->ModelCheckList().IsEmpty(Standard_True))
      throw InputError(file, key,
                       fmt::format("IGES file '{}' is corrupt: entities failed to load", path));
    check_iges_references(reader.IGESModel(), path, file, key);
    reader.TransferRoots();
    shape = reader.OneShape();
  } else {
    throw InputError(file, key, fmt::format("unknown CAD file type '{}' (step, iges, stl)", ext));
  }
  if (shape.IsNull()) throw InputError(file, key, fmt::format("no shape in '{}'", path));
  return shape;
}

std::vector<WallPtr<3>> faces_to_walls(const TopoDS_Shape& shape, FluidSide side, double scale,
                                       const std::vector<int>& faces) {
  std::vector<WallPtr<3>> walls;
  int index = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next(), ++index) {
    if (!faces.empty() && std::find(faces.begin(), faces.end(), index) == faces.end()) continue;
    const TopoDS_Face face = TopoDS::Face(ex.Current());
    // Outward (material) normal = Su x Sv, flipped on reversed faces; fluid inside the
    // solid wants the opposite.
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    const bool front = reversed == (side == FluidSide::inside);
    GeomAdaptor_Surface ad(BRep_Tool::Surface(face));
    auto sw = std::make_shared<NurbsSurfaceWall>(
        to_nurbs(face, scale),
        front ? NurbsSurfaceWall::Side::front : NurbsSurfaceWall::Side::back);
    const std::string label = fmt::format("face {} ({})", index, surface_type_name(ad.GetType()));
    sw->set_label(label);
    // The projection's certificate to 1e-7 of the face's size, not 1e-10: its hull bounds close
    // in quadratically along a long straight face (a 3.5 m pipe leg), and the answer is
    // polished by Newton anyway (max |d - d_exact| unchanged in test_cad_solid_*.cpp; the
    // U-pipe case's ghost pre-pass 0.70 s a step instead of 1.16 s).
    sw->set_tolerance(1e-7 * sw->surface().size());
    walls.push_back(std::make_shared<TrimmedFaceWall>(sw, face, scale, label));
  }
  return walls;
}

WallPtr<3> make_solid_wall(const TopoDS_Shape& shape, const std::vector<WallPtr<3>>& faces,
                           FluidSide side, double scale, const std::string& label) {
  std::vector<std::shared_ptr<const TrimmedFaceWall>> tf;
  for (const auto& w : faces) tf.push_back(std::dynamic_pointer_cast<const TrimmedFaceWall>(w));
  return std::make_shared<CadSolidWall>(
      shape, std::move(tf),
      side == FluidSide::inside ? curvsph::FluidSide::inside : curvsph::FluidSide::outside, scale,
      label);
}

std::string describe_shape(const TopoDS_Shape& shape) {
  std::map<std::string, int> count;
  int n = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next(), ++n)
    ++count[surface_type_name(
        GeomAdaptor_Surface(BRep_Tool::Surface(TopoDS::Face(ex.Current()))).GetType())];
  std::string s = fmt::format("{} faces:", n);
  for (const auto& [k, v] : count) s += fmt::format(" {} {}", v, k);
  return s;
}

}  // namespace cad

std::vector<WallPtr<3>> make_cad_walls(const YAML::Node& node, const std::string& file,
                                       const std::string& key_prefix, const std::string& base_dir) {
  using namespace nurbs::yaml;
  const nurbs::InputContext ctx{file, key_prefix};
  reject_unknown_keys(node, {"shape", "file", "fluid", "scale", "faces", "motion", "name"}, ctx);
  const YAML::Node fn = require(node, "file", ctx);
  if (!fn.IsScalar()) throw InputError(file, ctx.key("file"), "expected a file name");
  const std::string side = read_choice(node, "fluid", {"inside", "outside"}, ctx);
  double scale = 1.0;
  if (node["scale"]) scale = read_double(node["scale"], "scale", ctx);
  if (!(scale > 0.0)) throw InputError(file, ctx.key("scale"), "scale must be > 0");
  std::vector<int> faces;
  if (node["faces"])
    for (double f : read_doubles(node["faces"], "faces", ctx)) faces.push_back(static_cast<int>(f));
  // Looked for once the other keys are checked: a wrong key is named before a missing file.
  const std::filesystem::path path =
      resolve_data_file(fn.as<std::string>(), base_dir, file, ctx.key("file"));
  const cad::FluidSide fs = side == "inside" ? cad::FluidSide::inside : cad::FluidSide::outside;
  if (cad::lower_ext(path.string()) == ".stl") {
    // STL has no unit: read as metres (times `scale`).
    // Both fluid sides need a closed surface: the sign of the distance is only defined there.
    cad::StlMesh mesh = cad::read_stl(path.string(), file, ctx.key("file"));
    cad::require_closed(mesh, path.string(), file, ctx.key("file"));
    std::vector<Vec3d> v = std::move(mesh.vertices);
    for (Vec3d& p : v) p *= scale;
    std::vector<std::array<int, 3>> t = std::move(mesh.triangles);
    return {std::make_shared<TriMeshWall>(
        std::move(v), std::move(t),
        fs == cad::FluidSide::inside ? TriMeshWall::Side::inside : TriMeshWall::Side::outside)};
  }
  // OpenCASCADE reports a geometry it cannot build (a Standard_ConstructionError from
  // Geom_RectangularTrimmedSurface on a corrupt STEP face, found by fuzz/fuzz_cad, seed
  // fuzz/corpus/cad/step_trimmed_surface_error.bin) with its own exceptions, not
  // std::exception: without this they ended the program (abort) instead of exit 2.
  try {
    const TopoDS_Shape shape = cad::read_brep(path.string(), file, ctx.key("file"));
    std::vector<WallPtr<3>> walls = cad::faces_to_walls(shape, fs, scale, faces);
    if (walls.empty()) throw InputError(file, ctx.key("file"), "no faces selected");
    // A closed shell (all its faces kept) is one wall: the side of a point is then a property
    // of the solid, not of whichever face is nearest (docs/geometry.md, CAD solids).
    if (faces.empty() && cad::is_closed_shell(shape))
      return {cad::make_solid_wall(shape, walls, fs, scale, path.filename().string())};
    return walls;
  } catch (const Standard_Failure& e) {
    throw InputError(file, ctx.key("file"),
                     fmt::format("OpenCASCADE cannot build the geometry of '{}': {} ({})",
                                 path.string(), e.GetMessageString(), e.DynamicType()->Name()));
  }
}

}  // namespace curvsph
