#include "curvsph/cad/trimmed_face_wall.hpp"

#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <cmath>
#include <limits>
#include <optional>

#include "curvsph/cad/elementary_face.hpp"

namespace curvsph::cad {

struct TrimmedFaceWall::Occ {
  TopoDS_Face face;
  Handle(ShapeAnalysis_Surface) analysis;  // UV of a 3-D point on the face's own surface
  struct Edge {
    Handle(Geom_Curve) curve;
    double first, last;
  };
  std::vector<Edge> edges;
  std::vector<gp_Pnt> vertices;
  double tol;
  std::optional<ElementaryFace> elementary;  // planes and cylinders: closed forms
};

TrimmedFaceWall::TrimmedFaceWall(std::shared_ptr<const NurbsSurfaceWall> surface,
                                 const TopoDS_Face& face, double scale, std::string label)
    : surf_(std::move(surface)),
      occ_(std::make_unique<Occ>()),
      scale_(scale),
      label_(std::move(label)) {
  occ_->face = face;
  occ_->analysis = new ShapeAnalysis_Surface(BRep_Tool::Surface(face));
  occ_->tol = std::max(BRep_Tool::Tolerance(face), 1e-9);
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge e = TopoDS::Edge(ex.Current());
    double f, l;
    Handle(Geom_Curve) c = BRep_Tool::Curve(e, f, l);
    if (!c.IsNull()) occ_->edges.push_back({c, f, l});
    TopoDS_Vertex v1, v2;
    TopExp::Vertices(e, v1, v2);
    if (!v1.IsNull()) occ_->vertices.push_back(BRep_Tool::Pnt(v1));
    if (!v2.IsNull()) occ_->vertices.push_back(BRep_Tool::Pnt(v2));
  }
  occ_->elementary = ElementaryFace::make(BRep_Tool::Surface(face), scale);
  if (occ_->elementary) {
    // Which way the fluid lies, from the NURBS wall's normal (it knows the face's orientation
    // and the fluid side) at a point just off the surface's middle.
    const auto b = uv_bounds();
    Vec3d p, su, sv;
    eval(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), p, su, sv);
    const Vec3d n = occ_->elementary->own_normal(p);
    const WallPoint<3> w = surf_->closest(p + 1e-6 * surf_->surface().size() * n);
    occ_->elementary->set_fluid_sign(w.normal.dot(n) > 0 ? 1.0 : -1.0);
  }
}

TrimmedFaceWall::~TrimmedFaceWall() = default;

const TopoDS_Face& TrimmedFaceWall::face() const {
  return occ_->face;
}

WallPoint<3> TrimmedFaceWall::closest(const Vec3d& x, const ParamSeed& seed) const {
  return answer(x, seed, true);
}

WallPoint<3> TrimmedFaceWall::closest_nurbs(const Vec3d& x, const ParamSeed& seed) const {
  return answer(x, seed, false);
}

WallPoint<3> TrimmedFaceWall::answer(const Vec3d& x, const ParamSeed& seed,
                                     bool allow_elementary) const {
  const ElementaryFace* el = allow_elementary && occ_->elementary ? &*occ_->elementary : nullptr;
  WallPoint<3> w;
  if (el && !el->closest(x, w)) el = nullptr;
  if (!el) w = surf_->closest(x, seed);
  // Trimming test in the face's own parameter space (the converted NURBS may be
  // parametrised differently, e.g. rational arcs of a cylinder).
  const gp_Pnt foot(w.foot.x() / scale_, w.foot.y() / scale_, w.foot.z() / scale_);
  gp_Pnt2d uv;
  if (el) {
    double u, v;
    el->parameters(w.foot, u, v);
    uv.SetCoord(u, v);
  } else {
    uv = occ_->analysis->ValueOfUV(foot, occ_->tol);
  }
  BRepClass_FaceClassifier cls(occ_->face, uv, occ_->tol);
  if (cls.State() != TopAbs_OUT) return w;
  // Outside the trimmed face: the nearest point of its boundary (edges and vertices).
  const gp_Pnt xp(x.x() / scale_, x.y() / scale_, x.z() / scale_);
  double best = std::numeric_limits<double>::infinity();
  gp_Pnt best_p;
  for (const gp_Pnt& v : occ_->vertices)
    if (xp.Distance(v) < best) best = xp.Distance(v), best_p = v;
  for (const auto& e : occ_->edges) {
    GeomAPI_ProjectPointOnCurve proj(xp, e.curve, e.first, e.last);
    if (proj.NbPoints() > 0 && proj.LowerDistance() < best)
      best = proj.LowerDistance(), best_p = proj.NearestPoint();
  }
  const Vec3d edge_foot = scale_ * Vec3d(best_p.X(), best_p.Y(), best_p.Z());
  WallPoint<3> e;
  if (el && el->closest(edge_foot, e)) {  // surface data at the edge point, in closed form
    e.foot = edge_foot;
    const Vec3d d = x - edge_foot;
    e.distance = std::copysign(d.norm(), d.dot(e.normal));
    return e;
  }
  // Surface data (normal, curvatures) at the edge point: its NURBS parameters by a seeded
  // projection of the edge point itself (distance ~0, so a couple of Newton steps).
  const WallPoint<3> on = surf_->closest(edge_foot, seed);
  WallPoint<3> r = surf_->at(on.param[0], on.param[1], x);
  r.foot = edge_foot;
  const Vec3d d = x - edge_foot;
  r.distance = std::copysign(d.norm(), d.dot(r.normal));
  r.iterations = w.iterations + on.iterations;
  return r;
}

std::array<double, 4> TrimmedFaceWall::uv_bounds() const {
  std::array<double, 4> b{};
  BRepTools::UVBounds(occ_->face, b[0], b[1], b[2], b[3]);
  return b;
}

void TrimmedFaceWall::eval(double u, double v, Vec3d& p, Vec3d& su, Vec3d& sv) const {
  gp_Pnt P;
  gp_Vec Du, Dv;
  BRep_Tool::Surface(occ_->face)->D1(u, v, P, Du, Dv);
  p = scale_ * Vec3d(P.X(), P.Y(), P.Z());
  su = scale_ * Vec3d(Du.X(), Du.Y(), Du.Z());
  sv = scale_ * Vec3d(Dv.X(), Dv.Y(), Dv.Z());
}

std::vector<std::vector<std::array<double, 2>>> TrimmedFaceWall::trim_loops(double spacing) const {
  std::vector<std::vector<std::array<double, 2>>> loops;
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(occ_->face);
  for (TopExp_Explorer wx(occ_->face, TopAbs_WIRE); wx.More(); wx.Next()) {
    std::vector<std::array<double, 2>> loop;
    // The wire explorer gives the edges in connection order, each with its orientation in
    // the wire; a seam edge comes twice, and CurveOnSurface picks the curve of each side.
    for (BRepTools_WireExplorer ex(TopoDS::Wire(wx.Current()), occ_->face); ex.More(); ex.Next()) {
      const TopoDS_Edge& e = ex.Current();
      double f, l;
      const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(e, occ_->face, f, l);
      if (c.IsNull()) continue;
      const bool reversed = e.Orientation() == TopAbs_REVERSED;
      // 3-D length from a fine polyline of the curve on the surface, then the sample count.
      constexpr int fine = 64;
      double length = 0;
      gp_Pnt prev = surface->Value(c->Value(f).X(), c->Value(f).Y());
      for (int i = 1; i <= fine; ++i) {
        const gp_Pnt2d uv = c->Value(f + (l - f) * i / fine);
        const gp_Pnt q = surface->Value(uv.X(), uv.Y());
        length += prev.Distance(q);
        prev = q;
      }
      const int n = std::max(2, static_cast<int>(std::ceil(scale_ * length / spacing)));
      for (int i = 0; i < n; ++i) {  // the end point is the next edge's start
        const double t = reversed ? l - (l - f) * i / n : f + (l - f) * i / n;
        const gp_Pnt2d uv = c->Value(t);
        loop.push_back({uv.X(), uv.Y()});
      }
    }
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace curvsph::cad
