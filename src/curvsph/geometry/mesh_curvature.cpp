#include "curvsph/geometry/mesh_curvature.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace curvsph {
namespace {

// A unit vector perpendicular to the unit vector n.
Vec3d any_perpendicular(const Vec3d& n) {
  const Vec3d a = std::abs(n.x()) < 0.6 ? Vec3d::UnitX() : Vec3d::UnitY();
  return (a - a.dot(n) * n).normalized();
}

struct Fit {
  Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();  // of z(x, y) in the frame (t1, t2)
  Vec3d t1, t2, n;                                    // the frame, n the fitted normal
};

// Least-squares jet z = a x^2 + b xy + c y^2 + d x + e y + (cubic terms) over the points q
// around p, in the frame of the unit normal n; returns the Hessian and the normal of the fitted
// surface at p. The cubic terms (Cazals & Pouget 2005, "Estimating differential quantities
// using polynomial fitting of osculating jets", CAGD 22: order-3 jets give curvatures with an
// O(h^2) error where a quadric gives O(h) on a neighbourhood that is not symmetric) are fitted
// where there are 14 points or more, the linear ones from 6, else the three quadratic ones.
// Coordinates are scaled by the mean tangential distance so the system is well conditioned at any
// mesh size; a complete orthogonal decomposition gives the minimum-norm solution where the points
// do not determine every coefficient (collinear neighbours), which is zero curvature on flat data.
Fit fit_jet(const Vec3d& p, const Vec3d& n, const std::vector<Vec3d>& q) {
  Fit f;
  f.n = n;
  f.t1 = any_perpendicular(n);
  f.t2 = n.cross(f.t1);
  if (q.empty()) return f;
  const int m = static_cast<int>(q.size());
  const int k = m >= 14 ? 9 : m >= 6 ? 5 : 3;
  Eigen::MatrixXd A(m, k);
  Eigen::VectorXd b(m);
  double s = 0.0;
  for (const Vec3d& x : q) s += std::hypot((x - p).dot(f.t1), (x - p).dot(f.t2));
  s = s > 0 ? s / m : 1.0;
  for (int i = 0; i < m; ++i) {
    const Vec3d d = (q[i] - p) / s;
    const double x = d.dot(f.t1), y = d.dot(f.t2);
    A(i, 0) = x * x;
    A(i, 1) = x * y;
    A(i, 2) = y * y;
    if (k >= 5) A(i, 3) = x, A(i, 4) = y;
    if (k == 9) A(i, 5) = x * x * x, A(i, 6) = x * x * y, A(i, 7) = x * y * y, A(i, 8) = y * y * y;
    b(i) = d.dot(n);
  }
  const Eigen::VectorXd c = A.completeOrthogonalDecomposition().solve(b);
  f.hessian << 2 * c(0), c(1), c(1), 2 * c(2);
  f.hessian /= s;
  if (k >= 5) f.n = (n - c(3) * f.t1 - c(4) * f.t2).normalized();
  return f;
}

}  // namespace

MeshCurvature mesh_curvature(const std::vector<Vec3d>& v,
                             const std::vector<std::array<int, 3>>& tris,
                             const std::vector<Vec3d>& face_n, const MeshEdges& edges,
                             double feature_angle) {
  MeshCurvature out;
  const int nv = static_cast<int>(v.size()), nt = static_cast<int>(tris.size());
  out.corner_sector.assign(nt, {-1, -1, -1});
  const double cos_feature = std::cos(feature_angle);
  const auto crease = [&](int t, int i) {
    const int u = edges.across[t][i];
    return u < 0 || face_n[t].dot(face_n[u]) < cos_feature;
  };
  const auto corner_of = [&](int t, int p) {
    for (int c = 0; c < 3; ++c)
      if (tris[t][c] == p) return c;
    return -1;
  };
  // Vertex -> incident triangles (compressed rows).
  std::vector<int> start(nv + 1, 0), inc(3 * nt);
  for (const auto& T : tris)
    for (int c = 0; c < 3; ++c) ++start[T[c] + 1];
  for (int i = 0; i < nv; ++i) start[i + 1] += start[i];
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t)
      for (int c = 0; c < 3; ++c) inc[fill[tris[t][c]]++] = t;
  }
  // Stamps (the sector id) mark the ring-1 vertices, the accepted faces and the collected
  // points of the sector being fitted, so no set is cleared between sectors.
  std::vector<int> ring_mark(nv, -1), point_mark(nv, -1), face_mark(nt, -1);
  std::vector<int> fan, queue;
  std::vector<Vec3d> pts;
  for (int p = 0; p < nv; ++p) {
    for (int j = start[p]; j < start[p + 1]; ++j) {
      const int t0 = inc[j];
      if (out.corner_sector[t0][corner_of(t0, p)] >= 0) continue;
      // A new sector: the faces around p reachable from t0 without crossing a crease.
      const int s = static_cast<int>(out.tensor.size());
      fan.assign(1, t0);
      out.corner_sector[t0][corner_of(t0, p)] = s;
      for (std::size_t r = 0; r < fan.size(); ++r) {
        const int t = fan[r], c = corner_of(t, p);
        for (int i : {c, (c + 2) % 3}) {  // the two edges of t at p
          if (crease(t, i)) continue;
          const int u = edges.across[t][i], cu = corner_of(u, p);
          if (cu < 0 || out.corner_sector[u][cu] >= 0) continue;
          out.corner_sector[u][cu] = s;
          fan.push_back(u);
        }
      }
      // Angle-weighted normal of the sector (Thuermer & Wuethrich 1998).
      Vec3d n = Vec3d::Zero();
      for (int t : fan) {
        const int c = corner_of(t, p);
        const Vec3d e1 = (v[tris[t][(c + 1) % 3]] - v[p]).normalized();
        const Vec3d e2 = (v[tris[t][(c + 2) % 3]] - v[p]).normalized();
        n += std::acos(std::clamp(e1.dot(e2), -1.0, 1.0)) * face_n[t];
      }
      // The 2-ring seen from this sector: faces reached across non-crease edges that touch
      // a vertex of the sector's 1-ring. (Growing it where its points spread much less one
      // way than the other, as next to the poles of a latitude-longitude mesh, was measured
      // worse: the larger ring's truncation error outweighs what it gains.)
      ring_mark[p] = s;
      for (int t : fan)
        for (int c = 0; c < 3; ++c) ring_mark[tris[t][c]] = s;
      queue = fan;
      for (int t : fan) face_mark[t] = s;
      for (std::size_t r = 0; r < queue.size(); ++r) {
        const int t = queue[r];
        for (int i = 0; i < 3; ++i) {
          const int u = edges.across[t][i];
          if (crease(t, i) || face_mark[u] == s) continue;
          const auto& U = tris[u];
          if (ring_mark[U[0]] != s && ring_mark[U[1]] != s && ring_mark[U[2]] != s) continue;
          face_mark[u] = s;
          queue.push_back(u);
        }
      }
      pts.clear();
      point_mark[p] = s;
      for (int t : queue)
        for (int c = 0; c < 3; ++c)
          if (point_mark[tris[t][c]] != s) {
            point_mark[tris[t][c]] = s;
            pts.push_back(v[tris[t][c]]);
          }
      std::array<double, 6> K{};
      if (n.norm() > 0) {
        // Fit, tilt the frame to the fitted normal, fit again: the Hessian in a frame whose
        // z axis is the surface normal is the shape operator (no metric correction left).
        Fit f = fit_jet(v[p], n.normalized(), pts);
        f = fit_jet(v[p], f.n, pts);
        const Eigen::Matrix<double, 3, 2> B =
            (Eigen::Matrix<double, 3, 2>() << f.t1, f.t2).finished();
        const Eigen::Matrix3d M = B * f.hessian * B.transpose();
        K = {M(0, 0), M(1, 1), M(2, 2), M(0, 1), M(0, 2), M(1, 2)};
        const double mean = 0.5 * f.hessian.trace();
        const double rad = std::hypot(0.5 * (f.hessian(0, 0) - f.hessian(1, 1)), f.hessian(0, 1));
        out.max_abs = std::max(out.max_abs, std::abs(mean) + rad);
      }
      out.tensor.push_back(K);
    }
  }
  return out;
}

}  // namespace curvsph
