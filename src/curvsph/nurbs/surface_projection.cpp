// Closest point on a NURBS surface: seeded 2-parameter Newton + branch-and-bound
// certificate over Bezier patches (see projection.hpp for the reasoning).
#include <algorithm>
#include <cmath>
#include <limits>

#include "curvsph/nurbs/bezier.hpp"
#include "curvsph/nurbs/projection.hpp"

namespace curvsph::nurbs {

using H4 = Eigen::Vector4d;

struct SurfaceProjector::Best {
  double dist = std::numeric_limits<double>::infinity();
  double u = 0.0, v = 0.0;
  Vec3d foot = Vec3d::Zero();
  bool from_newton = false;
  double gap = 0.0;
  void offer(const Vec3d& x, const Vec3d& p, double pu, double pv, bool newton) {
    const double d = (x - p).norm();
    if (d < dist) {
      dist = d;
      u = pu;
      v = pv;
      foot = p;
      from_newton = newton;
    }
  }
};

SurfaceProjector::SurfaceProjector(const NurbsSurface& s) : surf_(s) {
  const int p = s.degree_u(), q = s.degree_v();
  const int nu = s.count_u(), nv = s.count_v();
  // Decompose every column along u, then every row of the result along v (P&T §5.4).
  std::vector<std::vector<H4>> cols(nv);
  std::vector<double> bu, bv;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) cols[j].push_back(s.homogeneous()[i * nv + j]);
    bu = decompose_to_bezier(p, s.knots_u(), cols[j]);
  }
  const int nu2 = static_cast<int>(cols[0].size());
  std::vector<std::vector<H4>> rows(nu2);
  for (int i = 0; i < nu2; ++i) {
    for (int j = 0; j < nv; ++j) rows[i].push_back(cols[j][i]);
    bv = decompose_to_bezier(q, s.knots_v(), rows[i]);
  }
  std::vector<Aabb<3>> boxes;
  for (std::size_t a = 0; a + 1 < bu.size(); ++a)
    for (std::size_t b = 0; b + 1 < bv.size(); ++b) {
      Patch pt{{bu[a], bv[b]}, {bu[a + 1], bv[b + 1]}, static_cast<int>(bez_.size())};
      Aabb<3> box;
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
          const H4& h = rows[a * p + i][b * q + j];
          bez_.push_back(h);
          box.extend(Vec3d(h.head<3>() / h[3]));
        }
      patches_.push_back(pt);
      boxes.push_back(box);
    }
  bvh_.build(boxes, 1);
  patch_boxes_ = std::move(boxes);
}

double SurfaceProjector::lower_bound(const Vec3d& x, double reach) const {
  double lb = reach;
  bvh_.visit(
      x, [&] { return lb; }, [&](int s) { lb = std::min(lb, patch_boxes_[s].distance(x)); });
  return lb;
}

void SurfaceProjector::newton(const Vec3d& x, double& u, double& v, const double lo[2],
                              const double hi[2], double tol, int& iterations) const {
  const bool wrap_u = surf_.closed_u() && lo[0] <= surf_.u0() && hi[0] >= surf_.u1();
  const bool wrap_v = surf_.closed_v() && lo[1] <= surf_.v0() && hi[1] >= surf_.v1();
  const auto wrap = [](double t, double a, double b) {
    return (t < a || t > b) ? t - (b - a) * std::floor((t - a) / (b - a)) : t;
  };
  double up = u, vp = v, du = 0.0, dv = 0.0, f_prev = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 50; ++it) {
    ++iterations;
    const SurfaceDerivs d = surf_.eval(u, v);
    const Vec3d r = d.s - x;
    const double f = r.squaredNorm();
    if (f > f_prev && (du * d.su + dv * d.sv).norm() > 0.1 * tol) {
      du *= 0.5;  // Delta grew: halve the step and retry
      dv *= 0.5;
      u = wrap_u ? wrap(up + du, lo[0], hi[0]) : up + du;
      v = wrap_v ? wrap(vp + dv, lo[1], hi[1]) : vp + dv;
      continue;
    }
    const double gu = r.dot(d.su), gv = r.dot(d.sv);
    const double E = d.su.squaredNorm(), F = d.su.dot(d.sv), G = d.sv.squaredNorm();
    // Hessian of Delta/2 (Barker eq. 42 with two parameters); Gauss-Newton (J^T J, a
    // descent direction) where it is not positive definite.
    double huu = E + r.dot(d.suu), huv = F + r.dot(d.suv), hvv = G + r.dot(d.svv);
    if (!(huu > 0.0 && huu * hvv - huv * huv > 0.0)) {
      huu = E;
      huv = F;
      hvv = G;
    }
    const double eps = 1e-14 * (E + G) + 1e-300;  // degenerate points (poles)
    huu += eps;
    hvv += eps;
    const double det = huu * hvv - huv * huv;
    du = -(hvv * gu - huv * gv) / det;
    dv = -(huu * gv - huv * gu) / det;
    if (!std::isfinite(du) || !std::isfinite(dv)) break;
    // At an open parameter end: clamp that parameter and re-solve for the other one.
    if (!wrap_u && (u + du < lo[0] || u + du > hi[0])) {
      du = std::clamp(u + du, lo[0], hi[0]) - u;
      dv = -(gv + huv * du) / hvv;
    }
    if (!wrap_v && (v + dv < lo[1] || v + dv > hi[1])) {
      dv = std::clamp(v + dv, lo[1], hi[1]) - v;
      du = -(gu + huv * dv) / huu;
      if (!wrap_u) du = std::clamp(u + du, lo[0], hi[0]) - u;
    }
    up = u;
    vp = v;
    f_prev = f;
    u = wrap_u ? wrap(u + du, lo[0], hi[0]) : u + du;
    v = wrap_v ? wrap(v + dv, lo[1], hi[1]) : v + dv;
    if ((du * d.su + dv * d.sv).norm() <= tol) break;
  }
}

void SurfaceProjector::search(const Vec3d& x, double tol, Best& best) const {
  const int p = surf_.degree_u(), q = surf_.degree_v();
  const int n = (p + 1) * (q + 1);
  struct Node {
    double lb, a[2], b[2];
    int off, depth;
  };
  thread_local std::vector<Node> heap;
  thread_local std::vector<H4> pool;
  heap.clear();
  pool.clear();
  const auto cmp = [](const Node& l, const Node& r) { return l.lb > r.lb; };
  const auto cart = [](const H4& h) { return Vec3d(h.head<3>() / h[3]); };
  // Lower bound: the larger of the distances from x to the patch's box in world axes and in
  // the frame of the current foot (axis 0 along n = (x - foot)/d; x sits at (d, 0, 0)).
  Eigen::Matrix3d frame;
  double frame_dist = -1.0;
  const auto bound = [&](const H4* P, double& diag) {
    Aabb<3> box, fbox;
    const bool have_frame = std::isfinite(best.dist) && best.dist > 0.0;
    if (have_frame && frame_dist != best.dist) {
      const Vec3d nrm = (x - best.foot) / best.dist;
      const Vec3d t1 =
          (std::abs(nrm.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY()).cross(nrm).normalized();
      frame.row(0) = nrm.transpose();
      frame.row(1) = t1.transpose();
      frame.row(2) = nrm.cross(t1).transpose();
      frame_dist = best.dist;
    }
    for (int i = 0; i < n; ++i) {
      const Vec3d c = cart(P[i]);
      box.extend(c);
      if (have_frame) fbox.extend(Vec3d(frame * (c - best.foot)));
    }
    diag = box.diagonal();
    if (!have_frame) return box.distance(x);
    return std::max(box.distance(x), fbox.distance(Vec3d(best.dist, 0.0, 0.0)));
  };
  const auto push = [&](const H4* P, const double a[2], const double b[2], int depth) {
    double diag;
    const double lb = bound(P, diag);
    if (lb >= best.dist - tol || diag <= tol) return;
    heap.push_back({lb, {a[0], a[1]}, {b[0], b[1]}, static_cast<int>(pool.size()), depth});
    pool.insert(pool.end(), P, P + n);
    std::push_heap(heap.begin(), heap.end(), cmp);
  };
  // Bezier patch corners lie on the surface.
  const auto offer_corners = [&](const H4* P, const double a[2], const double b[2]) {
    best.offer(x, cart(P[0]), a[0], a[1], false);
    best.offer(x, cart(P[q]), a[0], b[1], false);
    best.offer(x, cart(P[p * (q + 1)]), b[0], a[1], false);
    best.offer(x, cart(P[p * (q + 1) + q]), b[0], b[1], false);
  };

  bvh_.visit(
      x, [&] { return best.dist - tol; },
      [&](int k) {
        const Patch& pt = patches_[k];
        offer_corners(&bez_[pt.first], pt.a, pt.b);
        push(&bez_[pt.first], pt.a, pt.b, 0);
      });
  thread_local std::vector<H4> cur, left, right;
  cur.resize(n);
  left.resize(n);
  right.resize(n);
  int expansions = 0;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), cmp);
    const Node node = heap.back();
    heap.pop_back();
    if (node.lb >= best.dist - tol) break;
    if (++expansions > kSearchBudget) {
      // Nearly equidistant points everywhere (x on a cylinder's axis, at a circle's centre):
      // hull bounds close in only quadratically there. Stop and report how much nearer an
      // unexplored point could at most be (best-first: node.lb is the smallest bound left).
      best.gap = best.dist - node.lb;
      break;
    }
    std::copy(pool.begin() + node.off, pool.begin() + node.off + n, cur.begin());
    double diag;
    if (bound(cur.data(), diag) >= best.dist - tol) continue;
    if (node.depth == 0) {
      int it = 0;
      double u = 0.5 * (node.a[0] + node.b[0]), v = 0.5 * (node.a[1] + node.b[1]);
      newton(x, u, v, node.a, node.b, tol, it);
      best.offer(x, surf_.point(u, v), u, v, true);
      if (bound(cur.data(), diag) >= best.dist - tol) continue;
    }
    if (node.depth > 120) continue;
    // Split across the direction in which the control net is longer.
    double ext_u = 0.0, ext_v = 0.0;
    for (int j = 0; j <= q; ++j)
      ext_u = std::max(ext_u, (cart(cur[p * (q + 1) + j]) - cart(cur[j])).norm());
    for (int i = 0; i <= p; ++i)
      ext_v = std::max(ext_v, (cart(cur[i * (q + 1) + q]) - cart(cur[i * (q + 1)])).norm());
    const int dir = ext_u >= ext_v ? 0 : 1;
    const double pb = dir == 0 ? best.u : best.v;
    double tau = 0.5;
    if (pb > node.a[dir] && pb < node.b[dir]) {
      const double f = (pb - node.a[dir]) / (node.b[dir] - node.a[dir]);
      if (f > 0.05 && f < 0.95) tau = f;
    }
    if (dir == 0) {
      for (int j = 0; j <= q; ++j) split_bezier(&cur[j], p, tau, &left[j], &right[j], q + 1);
    } else {
      for (int i = 0; i <= p; ++i)
        split_bezier(&cur[i * (q + 1)], q, tau, &left[i * (q + 1)], &right[i * (q + 1)], 1);
    }
    const double tm = node.a[dir] + tau * (node.b[dir] - node.a[dir]);
    double la[2] = {node.a[0], node.a[1]}, lb[2] = {node.b[0], node.b[1]};
    double ra[2] = {node.a[0], node.a[1]}, rb[2] = {node.b[0], node.b[1]};
    lb[dir] = tm;
    ra[dir] = tm;
    offer_corners(left.data(), la, lb);
    offer_corners(right.data(), ra, rb);
    push(left.data(), la, lb, node.depth + 1);
    push(right.data(), ra, rb, node.depth + 1);
  }
}

Projection SurfaceProjector::project(const Vec3d& x, const double* seed_uv, double tol) const {
  if (tol <= 0.0) tol = default_tolerance();
  const double lo[2] = {surf_.u0(), surf_.v0()}, hi[2] = {surf_.u1(), surf_.v1()};
  Best best;
  Projection out;
  if (seed_uv) {
    double u = std::clamp(seed_uv[0], lo[0], hi[0]), v = std::clamp(seed_uv[1], lo[1], hi[1]);
    newton(x, u, v, lo, hi, tol, out.iterations);
    best.offer(x, surf_.point(u, v), u, v, true);
  }
  const double seeded = best.dist;
  search(x, tol, best);
  out.searched = best.dist < seeded;
  out.gap = best.gap;
  if (!best.from_newton) {
    int it = 0;
    double u = best.u, v = best.v;
    newton(x, u, v, lo, hi, 0.01 * tol, it);
    best.offer(x, surf_.point(u, v), u, v, true);
  }
  out.param[0] = best.u;
  out.param[1] = best.v;
  out.distance = best.dist;
  return out;
}

}  // namespace curvsph::nurbs
