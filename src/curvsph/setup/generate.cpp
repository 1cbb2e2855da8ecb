#include "curvsph/setup/generate.hpp"

#include <cmath>
#include <numbers>

#include "curvsph/core/error.hpp"

namespace curvsph {
namespace {

// Cell-centred lattice points of [lo, hi) per axis that satisfy `inside`.
template <class Inside>
void lattice(const Vec3d& lo, const Vec3d& hi, int dim, double dx, Inside inside,
             std::vector<GeneratedPoint>& out) {
  std::array<long, 3> n{1, 1, 1};
  for (int d = 0; d < dim; ++d) n[d] = std::max(1L, std::lround((hi[d] - lo[d]) / dx));
  const double vol = std::pow(dx, dim);
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i) {
        Vec3d x = Vec3d::Zero();
        const long idx[3] = {i, j, k};
        for (int d = 0; d < dim; ++d) x[d] = lo[d] + (idx[d] + 0.5) * dx;
        if (inside(x)) out.push_back({x, vol});
      }
}

}  // namespace

std::vector<GeneratedPoint> generate_region(const RegionSpec& r, int dim, double dx,
                                            const std::string& file, const std::string& key) {
  std::vector<GeneratedPoint> pts;
  switch (r.kind) {
    case RegionSpec::Kind::box:
      lattice(r.min, r.max, dim, dx, [](const Vec3d&) { return true; }, pts);
      break;
    case RegionSpec::Kind::disk:
    case RegionSpec::Kind::ball: {
      Vec3d lo = r.center, hi = r.center;
      for (int d = 0; d < dim; ++d) {
        lo[d] -= r.radius;
        hi[d] += r.radius;
      }
      lattice(lo, hi, dim, dx,
              [&](const Vec3d& x) {
                double d2 = 0;  // over the first dim axes only (z is 0 in 2-D)
                for (int d = 0; d < dim; ++d) d2 += (x[d] - r.center[d]) * (x[d] - r.center[d]);
                return d2 < r.radius * r.radius;
              },
              pts);
      break;
    }
    case RegionSpec::Kind::annulus: {
      if (dim != 2) throw InputError(file, key, "an annulus region is 2-D");
      // Rings at the cell centres across the gap; each ring holds the integer number of
      // particles closest to its circumference / dx, so spacing along and across match.
      const long rings = std::max(1L, std::lround((r.r_out - r.r_in) / dx));
      const double dr = (r.r_out - r.r_in) / rings;
      for (long k = 0; k < rings; ++k) {
        const double rad = r.r_in + (k + 0.5) * dr;
        const long m = std::max(3L, std::lround(2 * std::numbers::pi * rad / dx));
        const double vol = 2 * std::numbers::pi * rad * dr / m;
        // Alternate rings are rotated half a step so neighbours interleave.
        const double phase = (k % 2) * std::numbers::pi / m;
        for (long q = 0; q < m; ++q) {
          const double th = phase + 2 * std::numbers::pi * q / m;
          pts.push_back({r.center + Vec3d(rad * std::cos(th), rad * std::sin(th), 0), vol});
        }
      }
      break;
    }
    case RegionSpec::Kind::inside_walls:
      throw InputError(file, key, "inside_walls needs wall geometry, which this case lacks");
  }
  if (pts.empty())
    throw InputError(file, key, "the region holds no particle at this resolution");
  return pts;
}

template <int D>
void generate_particles(const Case& c, Particles<D>& P) {
  std::vector<GeneratedPoint> all;
  std::vector<int> phase;
  for (std::size_t f = 0; f < c.fluids.size(); ++f) {
    const auto pts = generate_region(c.fluids[f].region, D, c.dx, c.file_name(),
                                     "fluids." + std::to_string(f) + ".region");
    all.insert(all.end(), pts.begin(), pts.end());
    phase.insert(phase.end(), pts.size(), static_cast<int>(f));
  }
  P.resize(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const FluidSpec& fl = c.fluids[phase[i]];
    P.x[i] = all[i].x.head<D>().template cast<Real>();
    P.v[i] = fl.velocity.head<D>().template cast<Real>();
    P.mass[i] = static_cast<Real>(fl.rho0 * all[i].volume);
    P.rho[i] = static_cast<Real>(fl.rho0);
    P.sigma[i] = P.rho[i] / P.mass[i];
    P.phase[i] = phase[i];
    P.id[i] = static_cast<std::int64_t>(i);
  }
}

template void generate_particles<2>(const Case&, Particles<2>&);
template void generate_particles<3>(const Case&, Particles<3>&);

}  // namespace curvsph
