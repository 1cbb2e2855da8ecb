#pragma once
// Shepard-factor approach study (Calderon et al. Figs. 4-6): gamma along paths approaching
// 2-D walls, for the geometric, monolithic and volume modes, against a quadrature reference
// (W integrated over the fluid part of the support disc in polar coordinates).
// Approaches (h/dx from the options; elements and volume-mode particles at spacing dx):
//   wall             particle at distance d = 2h .. 0 above a flat wall (through a vertex)
//   corner_side      on one wall of a 90 deg corner, distance to the apex 3h .. 0
//   corner_diagonal  along the bisector of a 90 deg corner, distance to the apex 3h .. 0
//   circle_inside    radially towards a circle (radius circle_radius_over_h * h), fluid inside
//   circle_outside   radially towards the same circle, fluid outside
// Modes: geometric, monolithic, monolithic_contour (monolithic with the paper's "gamma = 1/2
// on the contour" rule, ShepardQuadrature::monolithic_contour_half), volume.
// Metrics: gamma_max_abs_error_<approach>_<mode> (plus _circle_<mode>, the worse of the two
// circle approaches).
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

struct ShepardApproachOptions {
  double h = 1.0;
  double h_over_dx = 2.0;
  int samples = 61;  // points along each path
  double circle_radius_over_h = 4.0;
};

struct ShepardApproachCurve {
  std::string approach;
  std::vector<double> distance_over_h;
  std::vector<double> reference;
  std::map<std::string, std::vector<double>> gamma;  // by mode name
};

struct ShepardApproachResult {
  std::vector<ShepardApproachCurve> curves;
  std::map<std::string, double> metrics;
};

ShepardApproachResult run_shepard_approach(const ShepardApproachOptions& options = {});

// Writes shepard_<approach>.csv (columns distance_over_h,gamma_reference,gamma_<mode>...)
// and metrics.json into `dir` (created if needed).
void write_shepard_approach(const ShepardApproachResult& result, const std::filesystem::path& dir);

// Reference: gamma(x) = integral of W over {y : |y - x| < 2h, inside(y)}, polar coordinates
// about x, fluid intervals along each ray by bisection on `inside`, radial integral by
// Gauss-Legendre (exact for the polynomial kernel), angle by adaptive Simpson.
double shepard_reference_2d(const Vec2d& x, double h,
                            const std::function<bool(const Vec2d&)>& inside);

}  // namespace curvsph
