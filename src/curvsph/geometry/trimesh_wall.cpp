#include "curvsph/geometry/trimesh_wall.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace curvsph {
namespace {

// Closest point on triangle abc to p by its Voronoi regions (barycentric tests on the
// vertex, edge and face regions). feature: 0..2 vertex, 3..5 edge (i, i+1), 6 face.
Vec3d closest_on_triangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c,
                          int& feature) {
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return feature = 0, a;
  const Vec3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return feature = 1, b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return feature = 3, Vec3d(a + d1 / (d1 - d3) * ab);
  const Vec3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return feature = 2, c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return feature = 5, Vec3d(a + d2 / (d2 - d6) * ac);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return feature = 4, Vec3d(b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b));
  const double den = 1.0 / (va + vb + vc);
  feature = 6;
  return a + ab * (vb * den) + ac * (vc * den);
}

}  // namespace

TriMeshWall::TriMeshWall(std::vector<Vec3d> vertices, std::vector<std::array<int, 3>> triangles,
                         Side fluid)
    : v_(std::move(vertices)),
      tris_(std::move(triangles)),
      sign_(fluid == Side::outside ? 1.0 : -1.0) {
  face_n_.resize(tris_.size());
  vert_n_.assign(v_.size(), Vec3d::Zero());
  std::vector<Aabb<3>> boxes(tris_.size());
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    const auto& T = tris_[t];
    // A degenerate triangle has no normal: zero, so it adds nothing to the pseudo-normals.
    face_n_[t] = (v_[T[1]] - v_[T[0]]).cross(v_[T[2]] - v_[T[0]]).normalized();
    for (int i = 0; i < 3; ++i) {
      const Vec3d e1 = (v_[T[(i + 1) % 3]] - v_[T[i]]).normalized();
      const Vec3d e2 = (v_[T[(i + 2) % 3]] - v_[T[i]]).normalized();
      vert_n_[T[i]] += std::acos(std::clamp(e1.dot(e2), -1.0, 1.0)) * face_n_[t];
      boxes[t].extend(v_[T[i]]);
    }
  }
  // Edge pseudo-normal: the sum of the normals of the two faces sharing the edge (the face's
  // own normal alone on a boundary or non-manifold edge, which a closed mesh does not have).
  const MeshEdges edges = mesh_edges(tris_);
  edge_n_.resize(tris_.size());
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int u = edges.across[t][i];
      edge_n_[t][i] = u >= 0 ? Vec3d(face_n_[t] + face_n_[u]) : face_n_[t];
    }
  curv_ = mesh_curvature(v_, tris_, face_n_, edges, kFeatureAngle);
  bvh_.build(boxes, 4);
  // Smooth faces: flood fill across the edges that are not creases (the curvature's test).
  // Coplanar (a planar face): every triangle's normal within 1e-4 rad of the face's mean and
  // every vertex within 1e-6 of the mesh's size of its plane, tolerances that a binary STL's
  // float32 vertices pass (their relative error is 6e-8).
  Aabb<3> all;
  for (const Vec3d& p : v_) all.extend(p);
  const double plane_tol = 1e-6 * all.diagonal(), cos_tol = std::cos(1e-4);
  const double smooth = std::cos(kFeatureAngle);
  face_of_.assign(tris_.size(), -1);
  std::vector<int> stack, members;
  for (std::size_t t0 = 0; t0 < tris_.size(); ++t0) {
    if (face_of_[t0] >= 0) continue;
    const int id = faces_++;
    face_of_[t0] = id;
    stack.assign(1, static_cast<int>(t0));
    members.clear();
    Vec3d sum = Vec3d::Zero();  // area-weighted normal
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      members.push_back(t);
      const auto& T = tris_[static_cast<std::size_t>(t)];
      sum += (v_[T[1]] - v_[T[0]]).cross(v_[T[2]] - v_[T[0]]);
      for (int i = 0; i < 3; ++i) {
        const int u = edges.across[t][i];
        if (u < 0 || face_of_[u] >= 0 || !(face_n_[t].dot(face_n_[u]) >= smooth)) continue;
        face_of_[u] = id;
        stack.push_back(u);
      }
    }
    const Vec3d n = sum.normalized();
    bool planar = sum.norm() > 0;
    const Vec3d o = v_[tris_[t0][0]];
    for (const int t : members)
      for (int i = 0; i < 3 && planar; ++i)
        planar = face_n_[t].dot(n) >= cos_tol && std::abs(n.dot(v_[tris_[t][i]] - o)) <= plane_tol;
    face_normal_.push_back(planar ? n : Vec3d::Zero());
  }
}

int TriMeshWall::face_points_near(const Vec3d& x, double reach, WallPoint<3>* out, int max) const {
  if (faces_ < 2 || max <= 0) return 0;
  // The nearest triangle of each face within reach (a point is near few faces: a short list).
  struct Best {
    int face, t, f;
    double d;
    Vec3d foot;
  };
  thread_local std::vector<Best> best;  // capacity kept: this runs for every particle and step
  best.clear();
  bvh_.visit(
      x, [&] { return reach; },
      [&](int t) {
        const auto& T = tris_[t];
        int f;
        const Vec3d q = closest_on_triangle(x, v_[T[0]], v_[T[1]], v_[T[2]], f);
        const double d = (q - x).norm();
        if (!(d < reach)) return;
        const int id = face_of_[static_cast<std::size_t>(t)];
        auto it =
            std::find_if(best.begin(), best.end(), [&](const Best& b) { return b.face == id; });
        if (it == best.end())
          best.push_back({id, t, f, d, q});
        else if (d < it->d)
          *it = {id, t, f, d, q};
      });
  std::sort(best.begin(), best.end(), [](const Best& a, const Best& b) { return a.d < b.d; });
  int n = 0;
  for (const Best& b : best) {
    if (n == max) break;
    WallPoint<3> w = answer(x, b.t, b.f, b.foot, b.d);
    const Vec3d& plane = face_normal_[static_cast<std::size_t>(b.face)];
    if (plane.squaredNorm() > 0) {
      // A planar face: one normal wherever the foot is (a pseudo-normal on the face's rim
      // would lean towards the neighbouring face), and no curvature.
      w.normal = sign_ * plane;
      w.distance = std::copysign(b.d, (x - b.foot).dot(w.normal));
      w.k1 = w.k2 = 0;
    }
    out[n++] = w;
  }
  return n;
}

WallPoint<3> TriMeshWall::closest(const Vec3d& x, const ParamSeed&) const {
  double best = std::numeric_limits<double>::infinity();
  int best_t = -1, best_f = 6;
  Vec3d foot = Vec3d::Zero();
  bvh_.visit(
      x, [&] { return best; },
      [&](int t) {
        const auto& T = tris_[t];
        int f;
        const Vec3d q = closest_on_triangle(x, v_[T[0]], v_[T[1]], v_[T[2]], f);
        const double d = (q - x).norm();
        if (d < best) best = d, best_t = t, best_f = f, foot = q;
      });
  if (best_t < 0) return WallPoint<3>{};
  return answer(x, best_t, best_f, foot, best);
}

WallPoint<3> TriMeshWall::answer(const Vec3d& x, int best_t, int best_f, const Vec3d& foot,
                                 double best) const {
  WallPoint<3> w;
  const auto& T = tris_[best_t];
  Vec3d pseudo = best_f == 6  ? face_n_[best_t]
                 : best_f < 3 ? vert_n_[T[best_f]]
                              : edge_n_[best_t][best_f - 3];
  pseudo = sign_ * pseudo.normalized();
  w.foot = foot;
  w.normal = pseudo;
  w.distance = std::copysign(best, (x - foot).dot(pseudo));
  // Curvature: the corner tensors interpolated at the foot's barycentric coordinates,
  // restricted to the tangent plane of the returned normal; the fluid side's sign (the
  // tensors are relative to the triangles' own normals).
  const Vec3d a = v_[T[0]], e1 = v_[T[1]] - a, e2 = v_[T[2]] - a, r = foot - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double det = d11 * d22 - d12 * d12;
  double b1 = 0.0, b2 = 0.0;
  if (det > 0) {
    b1 = std::clamp((d22 * r.dot(e1) - d12 * r.dot(e2)) / det, 0.0, 1.0);
    b2 = std::clamp((d11 * r.dot(e2) - d12 * r.dot(e1)) / det, 0.0, 1.0 - b1);
  }
  const std::array<double, 3> bary{1.0 - b1 - b2, b1, b2};
  std::array<double, 6> K{};
  for (int c = 0; c < 3; ++c) {
    const auto& Kc = curv_.tensor[curv_.corner_sector[best_t][c]];
    for (int k = 0; k < 6; ++k) K[k] += bary[c] * Kc[k];
  }
  const auto form = [&](const Vec3d& p, const Vec3d& q) {
    return sign_ *
           (K[0] * p.x() * q.x() + K[1] * p.y() * q.y() + K[2] * p.z() * q.z() +
            K[3] * (p.x() * q.y() + p.y() * q.x()) + K[4] * (p.x() * q.z() + p.z() * q.x()) +
            K[5] * (p.y() * q.z() + p.z() * q.y()));
  };
  const Vec3d t1 =
      w.normal.cross(std::abs(w.normal.x()) < 0.6 ? Vec3d::UnitX() : Vec3d::UnitY()).normalized();
  const Vec3d t2 = w.normal.cross(t1);
  const double h11 = form(t1, t1), h12 = form(t1, t2), h22 = form(t2, t2);
  // Eigen-pairs of the symmetric 2x2 [[h11, h12], [h12, h22]] in closed form.
  const double mean = 0.5 * (h11 + h22), rad = std::hypot(0.5 * (h11 - h22), h12);
  const double phi = 0.5 * std::atan2(2.0 * h12, h11 - h22);
  w.k1 = mean + rad;
  w.k2 = mean - rad;
  w.dir1 = std::cos(phi) * t1 + std::sin(phi) * t2;
  w.dir2 = w.normal.cross(w.dir1);
  w.param = {static_cast<double>(best_t), 0.0};
  w.param_count = 0;
  return w;
}

std::string TriMeshWall::describe() const {
  return fmt::format("trimesh triangles={} fluid={}", tris_.size(),
                     sign_ > 0 ? "outside" : "inside");
}

double TriMeshWall::min_radius_of_curvature() const {
  return curv_.max_abs > 0 ? 1.0 / curv_.max_abs : std::numeric_limits<double>::infinity();
}

}  // namespace curvsph
