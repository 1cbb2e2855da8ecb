#include "curvsph/cad/elementary_face.hpp"

#include <ElSLib.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <cmath>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph::cad {

std::optional<ElementaryFace> ElementaryFace::make(const Handle(Geom_Surface) & surface,
                                                   double scale) {
  const GeomAdaptor_Surface a(surface);
  ElementaryFace f;
  f.scale_ = scale;
  gp_Ax1 ax;
  if (a.GetType() == GeomAbs_Plane) {
    f.plane_ = a.Plane();
    ax = f.plane_.Axis();
  } else if (a.GetType() == GeomAbs_Cylinder) {
    f.cylinder_ = true;
    f.cyl_ = a.Cylinder();
    ax = f.cyl_.Axis();
    f.radius_ = scale * f.cyl_.Radius();
  } else {
    return std::nullopt;
  }
  f.origin_ = scale * Vec3d(ax.Location().X(), ax.Location().Y(), ax.Location().Z());
  f.axis_ = Vec3d(ax.Direction().X(), ax.Direction().Y(), ax.Direction().Z());
  return f;
}

Vec3d ElementaryFace::own_normal(const Vec3d& foot) const {
  if (!cylinder_) {
    // gp_Pln's normal is its axis when the frame is direct, minus it otherwise (Geom_Plane's
    // D1: N = Du x Dv = XDir x YDir).
    const gp_Ax3& p = plane_.Position();
    return p.Direct() ? axis_ : Vec3d(-axis_);
  }
  const Vec3d r = foot - origin_;
  const Vec3d radial = r - r.dot(axis_) * axis_;
  // Geom_CylindricalSurface's Du x Dv points out of the axis for a direct frame.
  return (cyl_.Position().Direct() ? 1.0 : -1.0) * radial.normalized();
}

bool ElementaryFace::closest(const Vec3d& x, WallPoint<3>& p) const {
  const Vec3d r = x - origin_;
  if (!cylinder_) {
    const Vec3d n = sign_ * own_normal(x);
    p.distance = r.dot(n);
    p.foot = x - p.distance * n;
    p.normal = n;
    p.k1 = p.k2 = 0;
    std::tie(p.dir1, p.dir2) = orthonormal_frame(n);
  } else {
    const double along = r.dot(axis_);
    const Vec3d radial = r - along * axis_;
    const double rho = radial.norm();
    if (!(rho > 1e-12 * radius_)) return false;
    const Vec3d out = radial / rho;
    p.foot = origin_ + along * axis_ + radius_ * out;
    p.normal = sign_ * own_normal(p.foot);
    p.distance = (x - p.foot).dot(p.normal);
    // Seen from the fluid the cylinder is concave (k = +1/R around) where the normal points
    // to the axis, convex (-1/R) where away; 0 along the axis.
    p.k1 = (p.normal.dot(out) < 0 ? 1.0 : -1.0) / radius_;
    p.k2 = 0;
    p.dir1 = axis_.cross(out);
    p.dir2 = axis_;
    sort_principal(p);
  }
  p.param_count = 0;
  p.iterations = 0;
  return true;
}

void ElementaryFace::parameters(const Vec3d& foot, double& u, double& v) const {
  const gp_Pnt q(foot.x() / scale_, foot.y() / scale_, foot.z() / scale_);
  if (cylinder_)
    ElSLib::Parameters(cyl_, q, u, v);
  else
    ElSLib::Parameters(plane_, q, u, v);
}

}  // namespace curvsph::cad
