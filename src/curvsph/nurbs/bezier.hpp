#pragma once
// Bezier extraction and subdivision on homogeneous control points, the building blocks of
// the global closest-point search: a rational Bezier piece with positive weights lies in
// the convex hull of its (projected) control points (P&T §4.2 property), and de Casteljau
// halves it into two Bezier pieces (P&T A1.5 applied to homogeneous points).
#include <vector>

namespace curvsph::nurbs {

// Inserts knot u once (Boehm's algorithm, P&T A5.1 with r = 1) into a degree-p B-spline with
// control points P (any Eigen vector type: homogeneous points) and knots U.
template <class H>
void insert_knot(int p, double u, std::vector<double>& U, std::vector<H>& P) {
  const int n = static_cast<int>(P.size()) - 1;
  int k = p;  // span index: U[k] <= u < U[k+1]
  while (k < n && U[k + 1] <= u) ++k;
  std::vector<H> Q(P.size() + 1);
  for (int i = 0; i <= k - p; ++i) Q[i] = P[i];
  for (int i = k - p + 1; i <= k; ++i) {
    const double a = (u - U[i]) / (U[i + p] - U[i]);
    Q[i] = a * P[i] + (1.0 - a) * P[i - 1];
  }
  for (int i = k + 1; i <= n + 1; ++i) Q[i] = P[i - 1];
  U.insert(U.begin() + k + 1, u);
  P = std::move(Q);
}

// Raises every interior knot to multiplicity p (P&T §5.4 decomposition): afterwards
// segment s has control points P[s*p .. s*p+p] over [breaks[s], breaks[s+1]].
// Returns the break points (distinct knots of the parameter range).
template <class H>
std::vector<double> decompose_to_bezier(int p, std::vector<double> U, std::vector<H>& P) {
  const int n = static_cast<int>(P.size()) - 1;
  const double a = U[p], b = U[n + 1];
  std::vector<double> breaks{a};
  for (std::size_t i = static_cast<std::size_t>(p) + 1; i < U.size(); ++i) {
    const double u = U[i];
    if (u <= breaks.back() || u >= b) continue;
    int mult = 0;
    for (double v : U) mult += (v == u);
    for (int r = mult; r < p; ++r) insert_knot(p, u, U, P);
    breaks.push_back(u);
  }
  breaks.push_back(b);
  return breaks;
}

// de Casteljau at fraction tau of a degree-p Bezier with points in[0..p] (stride s between
// consecutive points): left[0..p] over [0, tau], right[0..p] over [tau, 1]. No allocation.
template <class H>
void split_bezier(const H* in, int p, double tau, H* left, H* right, int s = 1) {
  H tmp[16];
  for (int i = 0; i <= p; ++i) tmp[i] = in[i * s];
  left[0] = tmp[0];
  right[p * s] = tmp[p];
  for (int r = 1; r <= p; ++r) {
    for (int i = 0; i <= p - r; ++i) tmp[i] = (1.0 - tau) * tmp[i] + tau * tmp[i + 1];
    left[r * s] = tmp[0];
    right[(p - r) * s] = tmp[p - r];
  }
}

}  // namespace curvsph::nurbs
