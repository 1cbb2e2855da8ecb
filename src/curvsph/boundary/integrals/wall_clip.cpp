#include "curvsph/boundary/integrals/wall_clip.hpp"

#include <algorithm>
#include <cmath>

#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/ellipse.hpp"
#include "curvsph/geometry/moving_wall.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/torus.hpp"

namespace curvsph {

namespace {

template <int D>
bool geometry_moves(const Wall<D>& w) {
  const auto* mw = dynamic_cast<const MovingWall<D>*>(&w);
  return mw && mw->geometry_moves();
}

template <int D>
double distance(const Wall<D>& w, const VecD<D>& x) {
  return w.closest(x).distance;
}

// The point of the edge a -> b where the signed distance d crosses 0, a and b on opposite
// sides (kept: d >= -tol). A kept end within tol of the surface is itself the crossing; else
// regula falsi with the Illinois halving between d > 0 and d < -tol (exact in one step when d
// is linear along the edge, as for planes).
template <int D>
VecD<D> crossing(const Wall<D>& w, const VecD<D>& a, double da, const VecD<D>& b, double db,
                 double tol) {
  if (da >= -tol && da <= 0) return a;
  if (db >= -tol && db <= 0) return b;
  const double eps = 1e-13 * (b - a).norm();
  double t0 = 0, t1 = 1, g0 = da, g1 = db, t = 0.5;
  int last = 0;
  for (int it = 0; it < 100; ++it) {
    t = (t0 * g1 - t1 * g0) / (g1 - g0);
    const double g = distance<D>(w, a + t * (b - a));
    if (std::abs(g) <= eps || t1 - t0 <= 1e-15) break;
    if ((g > 0) == (g0 > 0)) {
      t0 = t;
      g0 = g;
      if (last == 1) g1 *= 0.5;
      last = 1;
    } else {
      t1 = t;
      g1 = g;
      if (last == -1) g0 *= 0.5;
      last = -1;
    }
  }
  return a + t * (b - a);
}

// Twice the area vector of a planar polygon (fan about its first vertex).
Vec3d area_vector(const std::vector<Vec3d>& p) {
  Vec3d c = Vec3d::Zero();
  for (std::size_t i = 1; i + 1 < p.size(); ++i) c += (p[i] - p[0]).cross(p[i + 1] - p[0]);
  return c;
}

Vec3d centroid(const std::vector<Vec3d>& p) {
  Vec3d m = Vec3d::Zero();
  double w = 0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const double a = (p[i] - p[0]).cross(p[i + 1] - p[0]).norm();
    m += a * (p[0] + p[i] + p[i + 1]) / 3.0;
    w += a;
  }
  return w > 0 ? Vec3d(m / w) : p[0];
}

// Element j rebuilt from its clipped polygon `poly` (2-D: the two end points).
void add_clipped(const BoundaryElements<2>& el, std::size_t j, const std::vector<Vec2d>& poly,
                 BoundaryElements<2>& out) {
  if (poly.size() == 2 && (poly[1] - poly[0]).norm() > 1e-12 * el.area[j])
    out.add_segment(poly[0], poly[1]);
}

void add_clipped(const BoundaryElements<3>& el, std::size_t j, const std::vector<Vec3d>& poly,
                 BoundaryElements<3>& out) {
  if (poly.size() < 3) return;
  const int m = el.vertex_count[j];
  const std::vector<Vec3d> whole(el.vertices[j].begin(), el.vertices[j].begin() + m);
  const double whole_area = 0.5 * area_vector(whole).norm();
  const Vec3d whole_centroid = centroid(whole);
  const bool flat = el.gap[j] == 0.0;
  auto add = [&](const std::vector<Vec3d>& piece) {
    const double a = 0.5 * area_vector(piece).norm();
    if (!(a > 1e-12 * whole_area)) return;
    const int n = static_cast<int>(piece.size());
    if (flat) {
      out.add_polygon(piece.data(), n);
    } else {
      // The curved patch's true area and centre scaled and moved with its polygon (header).
      out.add_curved_patch(piece.data(), n, el.centre[j] + (centroid(piece) - whole_centroid),
                           el.normal[j], el.area[j] * a / whole_area, el.gap[j]);
    }
  };
  if (poly.size() <= 4) {
    add(poly);
  } else {
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) add({poly[0], poly[i], poly[i + 1]});
  }
}

template <int D>
void copy_element(const BoundaryElements<D>& el, std::size_t j, BoundaryElements<D>& out) {
  BoundaryElements<D> one;
  one.centre = {el.centre[j]};
  one.normal = {el.normal[j]};
  one.area = {el.area[j]};
  one.vertices = {el.vertices[j]};
  one.vertex_count = {el.vertex_count[j]};
  one.curvature = {el.curvature[j]};
  one.gap = {el.gap[j]};
  out.append(one);
}

}  // namespace

template <int D>
bool infinite_wall(const Wall<D>& body) {
  if (dynamic_cast<const PlaneWall<D>*>(&body)) return true;
  if constexpr (D == 3) return dynamic_cast<const CylinderWall*>(&body) != nullptr;
  return false;
}

template <int D>
bool clips_by_sign(const Wall<D>& body) {
  if (body.closed_surface()) return true;
  if (dynamic_cast<const PlaneWall<D>*>(&body) || dynamic_cast<const BoxWall<D>*>(&body))
    return true;
  if constexpr (D == 2)
    return dynamic_cast<const CircleWall*>(&body) || dynamic_cast<const EllipseWall*>(&body);
  else
    return dynamic_cast<const SphereWall*>(&body) || dynamic_cast<const CylinderWall*>(&body) ||
           dynamic_cast<const TorusWall*>(&body);
}

template <int D>
BoundaryElements<D> clip_to_walls(const BoundaryElements<D>& el,
                                  const std::vector<const Wall<D>*>& others, double tol) {
  if (others.empty()) return el;
  BoundaryElements<D> out;
  out.reserve(el.size());
  std::vector<VecD<D>> poly, next;
  std::vector<double> g;
  for (std::size_t j = 0; j < el.size(); ++j) {
    const int m = el.vertex_count[j];
    const double r = el.bounding_radius(j);
    // A curved 2-D element (an arc) cannot be cut as a polygon: kept or dropped by its centre.
    const bool whole_only = D == 2 && (el.curvature[j] != 0.0 || el.gap[j] != 0.0);
    poly.assign(el.vertices[j].begin(), el.vertices[j].begin() + m);
    bool cut = false;
    for (const Wall<D>* w : others) {
      // Signed distances are 1-Lipschitz: the centre's answer settles most elements.
      const double gc = distance<D>(*w, el.centre[j]);
      if (gc - r >= -tol) continue;
      if (whole_only || gc + r < -tol) {
        if (gc >= -tol) continue;
        poly.clear();
        cut = true;
        break;
      }
      g.resize(poly.size());
      bool all_in = true, all_out = true;
      for (std::size_t v = 0; v < poly.size(); ++v) {
        g[v] = distance<D>(*w, poly[v]);
        all_in = all_in && g[v] >= -tol;
        all_out = all_out && g[v] < -tol;
      }
      if (all_in) continue;
      cut = true;
      if (all_out) {
        poly.clear();
        break;
      }
      next.clear();
      if (D == 2) {  // the segment a -> b: its kept end and the crossing, in order
        const VecD<D> x = crossing<D>(*w, poly[0], g[0], poly[1], g[1], tol);
        next = g[0] >= -tol ? std::vector<VecD<D>>{poly[0], x} : std::vector<VecD<D>>{x, poly[1]};
      } else {  // Sutherland & Hodgman against the kept side
        const std::size_t n = poly.size();
        for (std::size_t e = 0; e < n; ++e) {
          const std::size_t f = (e + 1) % n;
          if (g[e] >= -tol) next.push_back(poly[e]);
          if ((g[e] >= -tol) != (g[f] >= -tol))
            next.push_back(crossing<D>(*w, poly[e], g[e], poly[f], g[f], tol));
        }
      }
      // A kept vertex on the surface is also its own crossing: drop the repeat.
      poly.clear();
      for (const auto& v : next)
        if (poly.empty() || (v - poly.back()).norm() > 1e-12 * r) poly.push_back(v);
      if (poly.size() > 2 && (poly.front() - poly.back()).norm() <= 1e-12 * r) poly.pop_back();
      if (poly.size() < (D == 2 ? 2u : 3u)) {
        poly.clear();
        break;
      }
    }
    if (!cut)
      copy_element(el, j, out);
    else if (!poly.empty())
      add_clipped(el, j, poly, out);
  }
  return out;
}

template <int D>
BoundaryElements<D> clip_by_other_walls(const BoundaryElements<D>& el, const WallSet<D>& walls,
                                        std::size_t k, double tol) {
  if (!infinite_wall<D>(walls[k].body()) || geometry_moves<D>(walls[k])) return el;
  std::vector<const Wall<D>*> others;
  for (std::size_t j = 0; j < walls.size(); ++j)
    if (j != k && !geometry_moves<D>(walls[j]) && clips_by_sign<D>(walls[j].body()))
      others.push_back(&walls[j].body());
  return clip_to_walls<D>(el, others, tol);
}

template bool infinite_wall<2>(const Wall<2>&);
template bool infinite_wall<3>(const Wall<3>&);
template bool clips_by_sign<2>(const Wall<2>&);
template bool clips_by_sign<3>(const Wall<3>&);
template BoundaryElements<2> clip_to_walls<2>(const BoundaryElements<2>&,
                                              const std::vector<const Wall<2>*>&, double);
template BoundaryElements<3> clip_to_walls<3>(const BoundaryElements<3>&,
                                              const std::vector<const Wall<3>*>&, double);
template BoundaryElements<2> clip_by_other_walls<2>(const BoundaryElements<2>&, const WallSet<2>&,
                                                    std::size_t, double);
template BoundaryElements<3> clip_by_other_walls<3>(const BoundaryElements<3>&, const WallSet<3>&,
                                                    std::size_t, double);

}  // namespace curvsph
