// Boundary elements of trimmed CAD faces (wall_elements.hpp lists what they give): the face's
// parameter rectangle cut into cells of about dx, cells clear of the trim loops kept whole
// (curved quads, as the NURBS surfaces' cells) or dropped, cells that a trim loop touches
// clipped to the part inside the face (Sutherland & Hodgman 1974, the loop clipped by the
// cell's four half-planes) and fanned into triangles about the clipped polygon's centroid.
// Every loop sample in such a cell is a vertex of its triangles: the loops are sampled from
// the edges' curves on the surface at the edge parameter, which two faces sharing an edge
// share, so neighbouring faces meet vertex to vertex along their common edge.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "curvsph/boundary/integrals/wall_elements_freeform.hpp"
#include "curvsph/cad/trimmed_face_wall.hpp"
#include "curvsph/core/quadrature.hpp"

namespace curvsph::wall_elements_detail {

namespace {

using Uv = std::array<double, 2>;
using Loop = std::vector<Uv>;

double signed_area(const Loop& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Uv& s = p[i];
    const Uv& t = p[(i + 1) % p.size()];
    a += s[0] * t[1] - t[0] * s[1];
  }
  return 0.5 * a;
}

// Even-odd rule over all loops (crossing number of a ray in +u).
bool inside_loops(const std::vector<Loop>& loops, const Uv& q) {
  bool in = false;
  for (const Loop& p : loops)
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
      if ((p[i][1] > q[1]) != (p[j][1] > q[1]) &&
          q[0] < p[j][0] + (p[i][0] - p[j][0]) * (q[1] - p[j][1]) / (p[i][1] - p[j][1]))
        in = !in;
  return in;
}

// Whether segment a-b meets the closed rectangle [lo, hi] (Liang & Barsky clipping).
bool segment_meets(const Uv& a, const Uv& b, const Uv& lo, const Uv& hi) {
  double t0 = 0, t1 = 1;
  for (int d = 0; d < 2; ++d) {
    const double dd = b[d] - a[d];
    for (const auto& [p, q] : {std::pair{-dd, a[d] - lo[d]}, {dd, hi[d] - a[d]}}) {
      if (p == 0) {
        if (q < 0) return false;
      } else {
        const double r = q / p;
        if (p < 0)
          t0 = std::max(t0, r);
        else
          t1 = std::min(t1, r);
      }
    }
  }
  return t0 <= t1;
}

// Polygon p clipped to the half-plane coordinate d >= c (sign = +1) or <= c (sign = -1).
Loop clip(const Loop& p, int d, double c, double sign) {
  Loop out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Uv& s = p[i];
    const Uv& e = p[(i + 1) % p.size()];
    const bool s_in = sign * (s[d] - c) >= 0, e_in = sign * (e[d] - c) >= 0;
    if (s_in) out.push_back(s);
    if (s_in != e_in) {
      const double t = (c - s[d]) / (e[d] - s[d]);
      Uv x{s[0] + t * (e[0] - s[0]), s[1] + t * (e[1] - s[1])};
      x[static_cast<std::size_t>(d)] = c;  // exactly on the cell's side
      out.push_back(x);
    }
  }
  return out;
}

struct Face {
  const cad::TrimmedFaceWall* wall;
  double sign;  // +1 when S_u x S_v points into the fluid
  Vec3d point(const Uv& q) const {
    Vec3d p, su, sv;
    wall->eval(q[0], q[1], p, su, sv);
    return p;
  }
  Vec3d normal(const Uv& q) const {
    Vec3d p, su, sv;
    wall->eval(q[0], q[1], p, su, sv);
    return sign * su.cross(sv).normalized();
  }
  double jacobian(double u, double v) const {
    Vec3d p, su, sv;
    wall->eval(u, v, p, su, sv);
    return su.cross(sv).norm();
  }
};

// The triangle a, b, c of the parameter plane (counter-clockwise) as an element: vertices on
// the surface, area = int |S_u x S_v| over it (collapsed Gauss-Legendre 8 x 8), centre and
// normal at its centroid, gap = the surface's largest distance from the vertices' plane.
void add_uv_triangle(BoundaryElements<3>& out, const Face& f, const Uv& a, const Uv& b,
                     const Uv& c) {
  std::array<Vec3d, 3> v = {f.point(a), f.point(b), f.point(c)};
  Vec3d pn = (v[1] - v[0]).cross(v[2] - v[0]);
  const double scale = (v[1] - v[0]).norm() + (v[2] - v[0]).norm();
  if (!(pn.norm() > 1e-14 * scale * scale)) return;
  const double twice = std::abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
  double area = 0;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 8; ++k) {
      const double s = 0.5 * (1 + kGaussLegendre8Nodes[static_cast<std::size_t>(i)]);
      const double t = 0.5 * (1 + kGaussLegendre8Nodes[static_cast<std::size_t>(k)]);
      const double w = 0.25 * kGaussLegendre8Weights[static_cast<std::size_t>(i)] *
                       kGaussLegendre8Weights[static_cast<std::size_t>(k)] * s;
      // Duffy: (s, t) -> a + s (b - a) + s t (c - b), Jacobian s |(b - a) x (c - a)|.
      const double u = a[0] + s * (b[0] - a[0]) + s * t * (c[0] - b[0]);
      const double vv = a[1] + s * (b[1] - a[1]) + s * t * (c[1] - b[1]);
      area += w * twice * f.jacobian(u, vv);
    }
  if (!(area > 0)) return;
  const Uv m{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
  const Vec3d centre = f.point(m), n = f.normal(m);
  if (pn.dot(n) < 0) std::swap(v[1], v[2]);
  pn = pn.normalized();
  double g = std::abs(pn.dot(centre - v[0]));
  for (const auto& [p, q] : {std::pair{a, b}, {b, c}, {c, a}})
    g = std::max(g, std::abs(pn.dot(f.point({0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])}) - v[0])));
  out.add_curved_patch(v.data(), 3, centre, n, area, 1.5 * g);
}

// The clipped polygon p fanned about its centroid; false (nothing added) unless every fan
// triangle is counter-clockwise or flat, i.e. p is star-shaped about its centroid.
bool add_fan(BoundaryElements<3>& out, const Face& f, const Loop& p) {
  const double area = signed_area(p);
  if (!(area > 0)) return true;  // nothing of the face in the cell
  Uv c{0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Uv& s = p[i];
    const Uv& t = p[(i + 1) % p.size()];
    const double w = s[0] * t[1] - t[0] * s[1];
    c[0] += (s[0] + t[0]) * w;
    c[1] += (s[1] + t[1]) * w;
  }
  c = {c[0] / (6 * area), c[1] / (6 * area)};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Uv& s = p[i];
    const Uv& t = p[(i + 1) % p.size()];
    if ((s[0] - c[0]) * (t[1] - c[1]) - (t[0] - c[0]) * (s[1] - c[1]) < -1e-12 * area) return false;
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    add_uv_triangle(out, f, c, p[i], p[(i + 1) % p.size()]);
  return true;
}

// The whole cell as a curved quad (as a NURBS surface's cells), area by Gauss-Legendre 8 x 8.
void add_whole_cell(BoundaryElements<3>& out, const Face& f, const Uv& lo, const Uv& hi) {
  auto S = [&](double u, double v) { return f.point({u, v}); };
  auto N = [&](double u, double v) { return f.normal({u, v}); };
  const double area = gauss_legendre_8(
      [&](double u) {
        return gauss_legendre_8([&](double v) { return f.jacobian(u, v); }, lo[1], hi[1]);
      },
      lo[0], hi[0]);
  if (area > 0) add_surface_cell(out, S, N, lo[0], hi[0], lo[1], hi[1], area);
}

void add_cell(BoundaryElements<3>& out, const Face& f, const std::vector<Loop>& loops, const Uv& lo,
              const Uv& hi, int depth) {
  int touching = -1, count = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const Loop& p = loops[l];
    for (std::size_t i = 0; i < p.size(); ++i)
      if (segment_meets(p[i], p[(i + 1) % p.size()], lo, hi)) {
        touching = static_cast<int>(l);
        ++count;
        break;
      }
  }
  const Uv mid{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
  if (count == 0) {
    if (inside_loops(loops, mid)) add_whole_cell(out, f, lo, hi);
    return;
  }
  // One loop through the cell, the face on its left (outer loops run counter-clockwise,
  // holes clockwise): the cell's part of the face is the loop clipped to the cell.
  if (count == 1) {
    Loop p = loops[static_cast<std::size_t>(touching)];
    p = clip(clip(clip(clip(p, 0, lo[0], 1), 0, hi[0], -1), 1, lo[1], 1), 1, hi[1], -1);
    const bool outer = signed_area(loops[static_cast<std::size_t>(touching)]) > 0;
    if (outer && p.size() >= 3 && add_fan(out, f, p)) return;
    if (outer && p.size() < 3) return;
  }
  // Several loops, a hole, or a polygon not star-shaped: the cell in four, down to 1/8.
  if (depth < 3) {
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k)
        add_cell(out, f, loops, {i ? mid[0] : lo[0], k ? mid[1] : lo[1]},
                 {i ? hi[0] : mid[0], k ? hi[1] : mid[1]}, depth + 1);
    return;
  }
  // Left after that: kept whole or dropped by its centre (an error of at most dx / 8 along
  // the trim there).
  if (inside_loops(loops, mid)) add_whole_cell(out, f, lo, hi);
}

}  // namespace

bool trimmed_face_3d(const Wall<3>& w, double dx, const Bounds<3>&, BoundaryElements<3>& out) {
  const auto* wall = dynamic_cast<const cad::TrimmedFaceWall*>(&w);
  if (!wall) return false;
  std::vector<Loop> loops = wall->trim_loops(0.25 * dx);
  if (loops.empty()) return true;
  // Outer loop (the largest) counter-clockwise, the others (holes) clockwise.
  std::size_t outer = 0;
  for (std::size_t l = 0; l < loops.size(); ++l)
    if (std::abs(signed_area(loops[l])) > std::abs(signed_area(loops[outer]))) outer = l;
  for (std::size_t l = 0; l < loops.size(); ++l)
    if ((signed_area(loops[l]) > 0) != (l == outer)) std::reverse(loops[l].begin(), loops[l].end());
  // Fluid side: the wall's own normal at a point just inside the outer loop.
  Face f{wall, 1.0};
  {
    const Loop& p = loops[outer];
    const Uv a = p[0], b = p[1];
    const std::array<double, 4> bb = wall->uv_bounds();
    const double eps = 1e-4 * std::max(bb[1] - bb[0], bb[3] - bb[2]);
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    const Uv q{0.5 * (a[0] + b[0]) - eps * (b[1] - a[1]) / len,
               0.5 * (a[1] + b[1]) + eps * (b[0] - a[0]) / len};
    if (wall->closest(f.point(q)).normal.dot(f.normal(q)) < 0) f.sign = -1.0;
  }
  // Cells of about dx: counts from the 3-D lengths of iso-lines (the largest of five).
  const std::array<double, 4> b = wall->uv_bounds();
  auto count = [&](bool along_u) {
    double longest = 0;
    for (int l = 0; l < 5; ++l) {
      const double o =
          (along_u ? b[2] + (b[3] - b[2]) * (l + 0.5) / 5 : b[0] + (b[1] - b[0]) * (l + 0.5) / 5);
      double len = 0;
      Vec3d prev = f.point(along_u ? Uv{b[0], o} : Uv{o, b[2]});
      for (int i = 1; i <= 64; ++i) {
        const double t = along_u ? b[0] + (b[1] - b[0]) * i / 64 : b[2] + (b[3] - b[2]) * i / 64;
        const Vec3d q = f.point(along_u ? Uv{t, o} : Uv{o, t});
        len += (q - prev).norm();
        prev = q;
      }
      longest = std::max(longest, len);
    }
    return std::max(1, static_cast<int>(std::lround(longest / dx)));
  };
  const int nu = count(true), nv = count(false);
  for (int i = 0; i < nu; ++i)
    for (int k = 0; k < nv; ++k)
      add_cell(out, f, loops, {b[0] + (b[1] - b[0]) * i / nu, b[2] + (b[3] - b[2]) * k / nv},
               {b[0] + (b[1] - b[0]) * (i + 1) / nu, b[2] + (b[3] - b[2]) * (k + 1) / nv}, 0);
  return true;
}

}  // namespace curvsph::wall_elements_detail
