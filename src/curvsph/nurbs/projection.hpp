#pragma once
// Closest point on a NURBS curve or surface (DESIGN.md §4, Barker §3.2).
//
// Fast path: Newton on Delta(t) = |x - C(t)|^2 (Barker eq. 39-44; two parameters on a
// surface) from the caller's seed, with the paper's safeguards: a Gauss-Newton step where
// Delta'' <= 0 (always a descent direction), step halving when Delta grows, clamping at open
// parameter ends, wrapping across the seam of closed curves/surfaces.
//
// Certificate and fallback: the curve/surface is cut once into rational Bezier pieces whose
// control points bound them (convex hull, weights > 0), kept in a BVH. A point at distance d
// is the global minimum within tol when every piece has a lower bound >= d - tol. The bound
// is the larger of two box distances: to the piece's box in world axes, and to its box in
// the frame of the current foot f with axis 0 along n = (x - f)/d. In that frame
// |x - y|^2 = (d - a)^2 + |t|^2 exactly (a, t: normal and tangential coordinates of y), so the
// frame box is tight where it matters: the piece under the foot is settled at once when the
// wall bends away from x, and pieces beside the foot are pruned by their tangential offset
// even where the wall bends toward x. Pieces still in play are halved (de Casteljau)
// best-first until pruned or smaller than tol (branch and bound); a better point found is
// polished by
// Newton. Without a seed the same search runs from scratch. So the answer is always the
// global minimum within tol; the seeded path does a few box tests and no allocation.
#include <vector>

#include "curvsph/geometry/bvh.hpp"
#include "curvsph/nurbs/curve.hpp"
#include "curvsph/nurbs/surface.hpp"

namespace curvsph::nurbs {

struct Projection {
  double param[2] = {0.0, 0.0};
  double distance = 0.0;  // unsigned Euclidean distance |x - foot|
  int iterations = 0;     // Newton iterations of the seeded path
  bool searched = false;  // the global search changed the seeded answer (or had no seed)
  // 0 when certified (no point nearer than distance - tol). Only when a continuum of nearly
  // equidistant points exhausts the search budget: at most this much nearer elsewhere.
  double gap = 0.0;
};

// Bezier pieces the certificate may split per query before it settles for a bound (`gap`).
inline constexpr int kSearchBudget = 3000;

template <int D>
class CurveProjector {
 public:
  // Keeps a reference: `curve` must outlive the projector.
  explicit CurveProjector(const NurbsCurve<D>& curve);

  // tol: absolute distance tolerance; <= 0 selects default_tolerance().
  Projection project(const VecD<D>& x, const double* seed_t, double tol = 0.0) const;
  // Safeguarded Newton alone, restricted to [lo, hi] (wrapping if the full range of a
  // closed curve). Returns the parameter; `iterations` counts derivative evaluations.
  double newton(const VecD<D>& x, double t, double lo, double hi, double tol,
                int& iterations) const;
  double default_tolerance() const { return 1e-10 * curve_.size(); }
  int segment_count() const { return static_cast<int>(segs_.size()); }
  // A lower bound on the distance from x to the curve: the smallest distance to the
  // bounding box of a Bezier piece (each piece lies in the hull of its control points), or
  // `reach` if no piece's box is nearer than reach. A few box tests, no allocation.
  double lower_bound(const VecD<D>& x, double reach) const;

 private:
  using HPoint = typename NurbsCurve<D>::HPoint;
  struct Segment {
    double a, b;
    int first;  // control points bez_[first .. first + p]
  };
  struct Best;
  void search(const VecD<D>& x, double tol, Best& best) const;

  const NurbsCurve<D>& curve_;
  std::vector<HPoint> bez_;
  std::vector<Segment> segs_;
  std::vector<Aabb<D>> seg_boxes_;
  Bvh<D> bvh_;
};

class SurfaceProjector {
 public:
  explicit SurfaceProjector(const NurbsSurface& surface);

  Projection project(const Vec3d& x, const double* seed_uv, double tol = 0.0) const;
  void newton(const Vec3d& x, double& u, double& v, const double lo[2], const double hi[2],
              double tol, int& iterations) const;
  double default_tolerance() const { return 1e-10 * surf_.size(); }
  int patch_count() const { return static_cast<int>(patches_.size()); }
  // As CurveProjector::lower_bound, over the Bezier patches' boxes.
  double lower_bound(const Vec3d& x, double reach) const;

 private:
  struct Patch {
    double a[2], b[2];
    int first;  // (p+1)(q+1) control points from bez_[first], row-major (u rows)
  };
  struct Best;
  void search(const Vec3d& x, double tol, Best& best) const;

  const NurbsSurface& surf_;
  std::vector<Eigen::Vector4d> bez_;
  std::vector<Patch> patches_;
  std::vector<Aabb<3>> patch_boxes_;
  Bvh<3> bvh_;
};

extern template class CurveProjector<2>;
extern template class CurveProjector<3>;

}  // namespace curvsph::nurbs
