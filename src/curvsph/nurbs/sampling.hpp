#pragma once
// Arc length of NURBS curves by adaptive Gauss-Legendre quadrature of |C'(t)| (DESIGN.md §4;
// not Barker's eq. 46, which is no arc length), arc-length sampling of curves (boundary
// particles at spacing dx, each with its parameter as the Newton seed, Barker §3.2) and
// near-uniform sampling of surfaces (seeds only, Barker §3.3).
#include <array>
#include <vector>

#include "curvsph/nurbs/curve.hpp"
#include "curvsph/nurbs/surface.hpp"

namespace curvsph::nurbs {

// Length of C over [a, b]; relative tolerance rel_tol.
template <int D>
double arc_length(const NurbsCurve<D>& c, double a, double b, double rel_tol = 1e-12);
template <int D>
double arc_length(const NurbsCurve<D>& c) {
  return arc_length(c, c.t0(), c.t1());
}

template <int D>
struct CurveSamples {
  std::vector<VecD<D>> points;
  std::vector<double> params;
  double spacing = 0.0;  // the arc-length spacing used (total length / segments, about dx)
};

// Points at equal arc-length spacing close to dx; open curves include both ends, closed
// curves omit the duplicate end point.
template <int D>
CurveSamples<D> sample_arc_length(const NurbsCurve<D>& c, double dx);

struct SurfaceSamples {
  std::vector<Vec3d> points;
  std::vector<std::array<double, 2>> params;
};

// Tensor grid whose parameters follow the chord length of iso-curves, so neighbouring
// points are about dx apart where the surface is not strongly distorted.
SurfaceSamples sample_surface(const NurbsSurface& s, double dx);

}  // namespace curvsph::nurbs
