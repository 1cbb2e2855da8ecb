// Closest point on a NURBS curve: seeded Newton + branch-and-bound certificate
// (see projection.hpp for the reasoning).
#include <algorithm>
#include <cmath>
#include <limits>

#include "curvsph/nurbs/bezier.hpp"
#include "curvsph/nurbs/projection.hpp"

namespace curvsph::nurbs {

template <int D>
struct CurveProjector<D>::Best {
  double dist = std::numeric_limits<double>::infinity();
  double t = 0.0;
  VecD<D> foot = VecD<D>::Zero();
  bool from_newton = false;
  double gap = 0.0;
  void offer(const VecD<D>& x, const VecD<D>& p, double t_p, bool newton) {
    const double d = (x - p).norm();
    if (d < dist) {
      dist = d;
      t = t_p;
      foot = p;
      from_newton = newton;
    }
  }
};

template <int D>
CurveProjector<D>::CurveProjector(const NurbsCurve<D>& curve) : curve_(curve) {
  const int p = curve.degree();
  bez_ = curve.homogeneous();
  const std::vector<double> breaks = decompose_to_bezier(p, curve.knots(), bez_);
  std::vector<Aabb<D>> boxes;
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    segs_.push_back({breaks[s], breaks[s + 1], static_cast<int>(s) * p});
    Aabb<D> box;
    for (int i = 0; i <= p; ++i) {
      const HPoint& h = bez_[s * p + i];
      box.extend(VecD<D>(h.template head<D>() / h[D]));
    }
    boxes.push_back(box);
  }
  bvh_.build(boxes, 1);
  seg_boxes_ = std::move(boxes);
}

template <int D>
double CurveProjector<D>::lower_bound(const VecD<D>& x, double reach) const {
  double lb = reach;
  bvh_.visit(
      x, [&] { return lb; }, [&](int s) { lb = std::min(lb, seg_boxes_[s].distance(x)); });
  return lb;
}

template <int D>
double CurveProjector<D>::newton(const VecD<D>& x, double t, double lo, double hi, double tol,
                                 int& iterations) const {
  const bool wrap = curve_.closed() && lo <= curve_.t0() && hi >= curve_.t1();
  const double period = hi - lo;
  double t_prev = t, step = 0.0, f_prev = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 50; ++it) {
    ++iterations;
    const CurveDerivs<D> d = curve_.eval(t);
    const VecD<D> r = d.c - x;
    const double f = r.squaredNorm();
    if (f > f_prev && std::abs(step) * d.d1.norm() > 0.1 * tol) {
      // Delta grew: the step overshot (far from the minimum); halve it and retry.
      step *= 0.5;
      t = t_prev + step;
      if (wrap && (t < lo || t > hi)) t -= period * std::floor((t - lo) / period);
      continue;
    }
    const double g = r.dot(d.d1);  // Delta'/2 (Barker eq. 41)
    const double tt = d.d1.squaredNorm();
    const double h = tt + r.dot(d.d2);  // Delta''/2 (Barker eq. 42)
    step = -g / (h > 0.0 ? h : tt);     // eq. 44, or Gauss-Newton (descent) if h <= 0
    if (!std::isfinite(step)) break;
    t_prev = t;
    f_prev = f;
    double t_new = t + step;
    if (wrap) {
      // Across the seam of a closed curve; `step` stays unwrapped for the halving above.
      if (t_new < lo || t_new > hi) t_new -= period * std::floor((t_new - lo) / period);
    } else {
      t_new = std::clamp(t_new, lo, hi);  // Barker: divergence to an end stops there
      step = t_new - t;
    }
    t = t_new;
    if (std::abs(step) * std::sqrt(tt) <= tol) break;  // converged, or stuck at an end
  }
  return t;
}

template <int D>
void CurveProjector<D>::search(const VecD<D>& x, double tol, Best& best) const {
  const int p = curve_.degree();
  const int n = p + 1;
  struct Node {
    double lb, a, b;
    int off, depth;
  };
  thread_local std::vector<Node> heap;
  thread_local std::vector<HPoint> pool;
  heap.clear();
  pool.clear();
  const auto cmp = [](const Node& l, const Node& r) { return l.lb > r.lb; };
  // Lower bound on the distance from x to a Bezier piece (see projection.hpp): the larger of
  // the distances from x to the piece's box in world axes and in the frame of the current
  // foot (axis 0 along n = (x - foot)/d, where x sits at (d, 0, ..)).
  Eigen::Matrix<double, D, D> frame;
  const auto set_frame = [&] {
    const VecD<D> nrm = (x - best.foot) / best.dist;
    frame.row(0) = nrm.transpose();
    if constexpr (D == 2) {
      frame.row(1) << -nrm.y(), nrm.x();
    } else {
      const VecD<D> t1 =
          (std::abs(nrm.x()) < 0.9 ? VecD<D>::UnitX() : VecD<D>::UnitY()).cross(nrm).normalized();
      frame.row(1) = t1.transpose();
      frame.row(2) = nrm.cross(t1).transpose();
    }
  };
  double frame_dist = -1.0;  // best.dist the frame was built for
  const auto bound = [&](const HPoint* P, double& diag) {
    Aabb<D> box, fbox;
    const bool have_frame = std::isfinite(best.dist) && best.dist > 0.0;
    if (have_frame && frame_dist != best.dist) set_frame(), frame_dist = best.dist;
    for (int i = 0; i < n; ++i) {
      const VecD<D> q = P[i].template head<D>() / P[i][D];
      box.extend(q);
      if (have_frame) fbox.extend(VecD<D>(frame * (q - best.foot)));
    }
    diag = box.diagonal();
    if (!have_frame) return box.distance(x);
    VecD<D> xf = VecD<D>::Zero();
    xf[0] = best.dist;
    return std::max(box.distance(x), fbox.distance(xf));
  };
  const auto push = [&](const HPoint* P, double a, double b, int depth) {
    double diag;
    const double lb = bound(P, diag);
    if (lb >= best.dist - tol || diag <= tol) return;
    heap.push_back({lb, a, b, static_cast<int>(pool.size()), depth});
    pool.insert(pool.end(), P, P + n);
    std::push_heap(heap.begin(), heap.end(), cmp);
  };
  const auto cart = [](const HPoint& h) { return VecD<D>(h.template head<D>() / h[D]); };

  bvh_.visit(
      x, [&] { return best.dist - tol; },
      [&](int s) {
        const Segment& g = segs_[s];
        const HPoint* P = &bez_[g.first];
        best.offer(x, cart(P[0]), g.a, false);  // Bezier ends lie on the curve
        best.offer(x, cart(P[p]), g.b, false);
        push(P, g.a, g.b, 0);
      });
  HPoint left[kMaxOrder], right[kMaxOrder], cur[kMaxOrder];
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
    }  // best-first: nothing left can be nearer
    std::copy(pool.begin() + node.off, pool.begin() + node.off + n, cur);
    double diag;
    if (bound(cur, diag) >= best.dist - tol) continue;  // best improved since the push
    if (node.depth == 0) {
      // A whole Bezier piece still in play: a local Newton inside it usually finds its
      // minimum at once, which then prunes the rest.
      int it = 0;
      const double t = newton(x, 0.5 * (node.a + node.b), node.a, node.b, tol, it);
      best.offer(x, curve_.point(t), t, true);
      if (bound(cur, diag) >= best.dist - tol) continue;
    }
    if (node.depth > 80) continue;
    // Split at the current foot when it lies inside (its halves then end at the foot),
    // else in the middle.
    double tau = 0.5;
    if (best.t > node.a && best.t < node.b) {
      const double f = (best.t - node.a) / (node.b - node.a);
      if (f > 0.05 && f < 0.95) tau = f;
    }
    split_bezier(cur, p, tau, left, right);
    const double tm = node.a + tau * (node.b - node.a);
    best.offer(x, cart(left[p]), tm, false);
    push(left, node.a, tm, node.depth + 1);
    push(right, tm, node.b, node.depth + 1);
  }
}

template <int D>
Projection CurveProjector<D>::project(const VecD<D>& x, const double* seed_t, double tol) const {
  if (tol <= 0.0) tol = default_tolerance();
  Best best;
  Projection out;
  if (seed_t) {
    const double t0 = std::clamp(*seed_t, curve_.t0(), curve_.t1());
    const double t = newton(x, t0, curve_.t0(), curve_.t1(), tol, out.iterations);
    best.offer(x, curve_.point(t), t, true);
  }
  const double seeded = best.dist;
  search(x, tol, best);
  out.searched = best.dist < seeded;
  out.gap = best.gap;
  if (!best.from_newton) {
    // The search ended on a Bezier end or split point: polish it.
    int it = 0;
    const double t = newton(x, best.t, curve_.t0(), curve_.t1(), 0.01 * tol, it);
    best.offer(x, curve_.point(t), t, true);
  }
  out.param[0] = best.t;
  out.distance = best.dist;
  return out;
}

template class CurveProjector<2>;
template class CurveProjector<3>;

}  // namespace curvsph::nurbs
