#pragma once
// B-spline basis functions and their derivatives (Piegl & Tiller, The NURBS Book, 2nd ed.):
// FindSpan (A2.1), BasisFuns (A2.2), DersBasisFuns (A2.3). Knot-vector validation with
// input errors that name the offending key (DESIGN.md §3 errors).
//
// Everything here works on caller-provided fixed-size buffers so the projection hot path
// does not allocate; hence the degree cap kMaxDegree (far above any CAD degree in use).
#include <string>
#include <vector>

namespace curvsph::nurbs {

inline constexpr int kMaxDegree = 15;
// Input limits (io/schema_table.cpp states them): largest / smallest weight, and the control
// net's extent relative to its coordinates' magnitude (below: all control points coincide).
inline constexpr double kMaxWeightRatio = 1e12;
inline constexpr double kMinRelativeExtent = 1e-12;
inline constexpr int kMaxOrder = kMaxDegree + 1;

// Where errors are reported: file name and the dotted key prefix of the NURBS entry
// ("walls.2"); keys of the NURBS data are appended ("walls.2.knots").
struct InputContext {
  std::string file;
  std::string prefix;
  std::string key(const std::string& k) const { return prefix.empty() ? k : prefix + "." + k; }
};

// Throws InputError unless `knots` is a valid knot vector for `n_ctrl` control points of
// degree `degree`: count = n_ctrl + degree + 1, non-decreasing, interior multiplicity
// <= degree, a non-empty parameter range, n_ctrl >= degree + 1. `knots_key` is the key to
// name ("knots", "knots_u").
void validate_knots(const std::vector<double>& knots, int degree, int n_ctrl,
                    const InputContext& ctx, const std::string& knots_key);

// A2.1: index of the knot span [U[s], U[s+1]) containing u, with n = number of control
// points - 1 and p the degree; u at the end of the range maps to the last non-empty span.
int find_span(int n, int p, double u, const double* U);

// A2.2: the p+1 non-vanishing basis functions N[0..p] = N_{span-p..span, p}(u).
void basis_funs(int span, double u, int p, const double* U, double* N);

// A2.3: derivatives ders[k][j] = d^k N_{span-p+j, p}/du^k for k = 0..nd (nd <= 2 here would
// do, but any nd <= p is supported), j = 0..p. ders is row-major [nd+1][kMaxOrder].
void ders_basis_funs(int span, double u, int p, int nd, const double* U, double ders[][kMaxOrder]);

}  // namespace curvsph::nurbs
