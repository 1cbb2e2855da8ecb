#include "curvsph/cad/cad_solid_wall.hpp"

#include <fmt/format.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace curvsph::cad {

struct CadSolidWall::Occ {
  std::vector<TopoDS_Solid> solids;
  double tol = 1e-7;  // classifier tolerance, in the shape's own unit
};

bool is_closed_shell(const TopoDS_Shape& shape) {
  int shells = 0;
  for (TopExp_Explorer ex(shape, TopAbs_SHELL); ex.More(); ex.Next(), ++shells)
    if (!BRep_Tool::IsClosed(ex.Current())) return false;
  // Faces outside any shell make the shape open too.
  if (TopExp_Explorer(shape, TopAbs_FACE, TopAbs_SHELL).More()) return false;
  return shells > 0;
}

CadSolidWall::CadSolidWall(const TopoDS_Shape& shape,
                           std::vector<std::shared_ptr<const TrimmedFaceWall>> faces,
                           curvsph::FluidSide side, double scale, std::string label)
    : occ_(std::make_unique<Occ>()),
      faces_(std::move(faces)),
      side_(side),
      scale_(scale),
      label_(std::move(label)) {
  // The classifier wants solids: those of the file, or one per closed shell (oriented so that
  // its inside is finite: BRepLib::OrientClosedSolid).
  for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next())
    occ_->solids.push_back(TopoDS::Solid(ex.Current()));
  if (occ_->solids.empty())
    for (TopExp_Explorer ex(shape, TopAbs_SHELL); ex.More(); ex.Next()) {
      TopoDS_Solid s = BRepBuilderAPI_MakeSolid(TopoDS::Shell(ex.Current())).Solid();
      BRepLib::OrientClosedSolid(s);
      occ_->solids.push_back(s);
    }
  double tol = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next())
    tol = std::max(tol, BRep_Tool::Tolerance(TopoDS::Face(ex.Current())));
  tol = std::max(tol, 1e-12);
  Eigen::AlignedBox3d all;
  for (const auto& f : faces_) {
    Bnd_Box b;
    BRepBndLib::AddOptimal(f->face(), b, false, false);
    double x0, y0, z0, x1, y1, z1;
    b.Get(x0, y0, z0, x1, y1, z1);
    // Grown by the face's tolerance and a relative margin: the box must hold the face.
    const double g = tol + 1e-9 * std::max({x1 - x0, y1 - y0, z1 - z0});
    boxes_.emplace_back(scale * Vec3d(x0 - g, y0 - g, z0 - g),
                        scale * Vec3d(x1 + g, y1 + g, z1 + g));
    all.extend(boxes_.back());
  }
  length_ = all.isEmpty() ? 1.0 : all.diagonal().norm();
  // The classifier says ON within its tolerance: a relative 1e-9 of the part's size (the
  // file's own tolerance is a length in its unit, which `scale` magnifies).
  occ_->tol = 1e-9 * length_ / scale_;
}

CadSolidWall::~CadSolidWall() = default;

int CadSolidWall::classify(const Vec3d& x) const {
  const gp_Pnt p(x.x() / scale_, x.y() / scale_, x.z() / scale_);
  bool on = false;
  for (const TopoDS_Solid& s : occ_->solids) {
    // A classifier per call: it keeps state, and closest() is called from several threads.
    BRepClass3d_SolidClassifier cls(s, p, occ_->tol);
    const TopAbs_State st = cls.State();
    if (st == TopAbs_IN) return 1;
    if (st == TopAbs_ON) on = true;
  }
  return on ? 0 : -1;
}

double CadSolidWall::distance_lower_bound(const Vec3d& x) const {
  double lb = std::numeric_limits<double>::infinity();
  for (const auto& b : boxes_) lb = std::min(lb, b.exteriorDistance(x));
  return lb;
}

double CadSolidWall::min_radius_of_curvature() const {
  double r = std::numeric_limits<double>::infinity();
  for (const auto& f : faces_) r = std::min(r, f->min_radius_of_curvature());
  return r;
}

std::string CadSolidWall::describe() const {
  return fmt::format("{} ({} faces, closed, fluid {})", label_, faces_.size(), to_string(side_));
}

int CadSolidWall::face_points_near(const Vec3d& x, double reach, WallPoint<3>* out, int max) const {
  int n = 0;
  for (std::size_t k = 0; k < faces_.size() && n < max; ++k) {
    if (!(boxes_[k].exteriorDistance(x) < reach)) continue;
    WallPoint<3> p = faces_[k]->closest(x);
    if (std::abs(p.distance) < reach) out[n++] = p;
  }
  return n;
}

bool CadSolidWall::may_reach_behind(const Vec3d& x, double reach, const Vec3d& foot,
                                    const Vec3d& n) const {
  // A face's box reaches behind if a corner does; the face of the plane itself (its box thin
  // along n, when the plane is axis-aligned) does not by more than its tolerance.
  for (const auto& b : boxes_) {
    if (!(b.exteriorDistance(x) < reach)) continue;
    for (int c = 0; c < 8; ++c)
      if ((b.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - foot).dot(n) < -1e-3 * reach)
        return true;
  }
  return false;
}

WallPoint<3> CadSolidWall::closest(const Vec3d& x, const ParamSeed&) const {
  // Faces by the distance of their boxes (a lower bound of the distance to the face).
  const std::size_t n = faces_.size();
  std::vector<std::pair<double, std::size_t>> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = {boxes_[k].exteriorDistance(x), k};
  std::sort(order.begin(), order.end());
  // Feet closer than this are the same point of an edge or vertex; distances equal within it tie.
  const double tie = 1e-9 * length_;
  std::vector<WallPoint<3>> answers;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [lb, k] : order) {
    if (lb > best + tie) break;
    // No seed: the seed a caller keeps is that of whichever face answered last time.
    const WallPoint<3> p = faces_[k]->closest(x);
    answers.push_back(p);
    best = std::min(best, std::abs(p.distance));
  }
  std::size_t b = 0;
  for (std::size_t i = 1; i < answers.size(); ++i)
    if (std::abs(answers[i].distance) < std::abs(answers[b].distance)) b = i;
  WallPoint<3> r = answers[b];
  // The faces that reach the same foot at the same distance: an edge or vertex foot.
  int agree_plus = 0, agree_minus = 0;
  bool smooth = true;
  for (const WallPoint<3>& a : answers) {
    if (std::abs(std::abs(a.distance) - best) > tie || (a.foot - r.foot).norm() > tie) continue;
    (a.distance >= 0 ? agree_plus : agree_minus)++;
    if (a.normal.dot(r.normal) < std::cos(1e-3)) smooth = false;  // normals differ by > 0.06°
  }
  if (agree_plus + agree_minus < 2) return r;  // foot inside one face: its normal is right
  // A tangent junction (a pipe's straight part meeting its bend): one normal for the faces.
  if (smooth) return r;
  double sign;
  if (agree_minus == 0) {
    sign = 1.0;
  } else if (agree_plus == 0) {
    sign = -1.0;
  } else {
    const int c = classify(x);
    // ON away from the surface is the classifier failing (it does so within about 5 mm of
    // u_pipe.step's bore at scale 1000): the nearest face's side is the better guess then.
    if (c == 0 && (x - r.foot).norm() > tie)
      sign = r.distance >= 0 ? 1.0 : -1.0;
    else
      sign = c == 0 ? 0.0 : (c > 0) == (side_ == curvsph::FluidSide::inside) ? 1.0 : -1.0;
  }
  // A sharp edge or corner: normal along foot -> point into the fluid, flat (the box's rule).
  const Vec3d d = x - r.foot;
  const double len = d.norm();
  r.distance = sign * len;
  if (len > tie && sign != 0.0) r.normal = sign * d / len;
  r.k1 = r.k2 = 0.0;
  std::tie(r.dir1, r.dir2) = orthonormal_frame(r.normal);
  return r;
}

}  // namespace curvsph::cad
