#include "curvsph/setup/hydrostatic_start.hpp"

#include <algorithm>
#include <limits>

#include "curvsph/physics/compressible_column.hpp"

namespace curvsph {

template <int D>
void hydrostatic_start(const Case& c, const Eos& eos, const std::vector<Real>& rho0,
                       Particles<D>& P) {
  // The gravity a free surface balances: its components along non-periodic axes.
  Vec3d gn = c.gravity;
  for (int d = 0; d < D; ++d)
    if (c.periodic[static_cast<std::size_t>(d)]) gn[d] = 0;
  const double g = gn.head<D>().norm();
  if (!(g > 0)) return;
  const Vec3d up = -gn / g;
  const auto height = [&](std::size_t i) {
    double s = 0;
    for (int d = 0; d < D; ++d) s += up[d] * static_cast<double>(P.x[i][d]);
    return s;
  };
  // The top and bottom of each region's particles (the solver holds all of them here, before
  // any domain decomposition, so these are the global extents).
  const std::size_t n_phase = rho0.size();
  std::vector<double> top(n_phase, -std::numeric_limits<double>::infinity());
  std::vector<double> bottom(n_phase, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < P.size(); ++i) {
    const auto f = static_cast<std::size_t>(P.phase[i]);
    top[f] = std::max(top[f], height(i));
    bottom[f] = std::min(bottom[f], height(i));
  }
  // The surface half a spacing above the highest particle: a lattice fill puts its first row
  // dx/2 inside the region's face, and each particle stands for a cell of side dx, so the
  // column then weighs rho0 g H per unit area, H the filled height (as `initial.hydrostatic`
  // with the region's top as its surface).
  std::vector<CompressibleColumn> column;
  for (std::size_t f = 0; f < n_phase; ++f) {
    top[f] += 0.5 * c.dx;
    column.emplace_back(eos, rho0[f], g, top[f] > bottom[f] ? top[f] - bottom[f] : 0.0);
  }
  for (std::size_t i = 0; i < P.size(); ++i) {
    const auto f = static_cast<std::size_t>(P.phase[i]);
    const Real p = static_cast<Real>(column[f](top[f] - height(i)) + eos.p0);
    // Mass follows the density (taylor_green_initial explains why).
    const Real volume = P.mass[i] / rho0[f];
    P.rho[i] = eos.density(p, rho0[f]);
    P.mass[i] = P.rho[i] * volume;
    P.p[i] = p;
  }
}

template void hydrostatic_start<2>(const Case&, const Eos&, const std::vector<Real>&,
                                   Particles<2>&);
template void hydrostatic_start<3>(const Case&, const Eos&, const std::vector<Real>&,
                                   Particles<3>&);

}  // namespace curvsph
