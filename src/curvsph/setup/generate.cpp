#include "curvsph/setup/generate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>

#include "curvsph/core/error.hpp"
#include "curvsph/core/periodic.hpp"

namespace curvsph {
namespace {

// Lattice points one region may span: far beyond any run's memory, and below the range of
// long, so that counts checked against it in double convert safely (dx = 1e-20 overflowed
// lround and gave one particle).
constexpr double kMaxLatticePoints = 1e12;

// A count of dx steps checked in double before it becomes a long.
long checked_count(double steps, double dx, const std::string& file, const std::string& key) {
  if (!(std::isfinite(steps) && steps < kMaxLatticePoints))
    throw InputError(file, "resolution.dx",
                     fmt::format("dx = {:g} gives {:.3g} lattice steps across {} (limit {:.0e})",
                                 dx, steps, key, kMaxLatticePoints));
  return std::max(1L, std::lround(steps));
}

// Cell-centred lattice points of [lo, hi) per axis that satisfy `inside`.
template <class Inside>
void lattice(const Vec3d& lo, const Vec3d& hi, int dim, double dx, Inside inside,
             std::vector<GeneratedPoint>& out, const std::string& file, const std::string& key) {
  std::array<long, 3> n{1, 1, 1};
  double total = 1;
  for (int d = 0; d < dim; ++d) {
    n[d] = checked_count((hi[d] - lo[d]) / dx, dx, file, key);
    total *= static_cast<double>(n[d]);
  }
  checked_count(total, dx, file, key);
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

// Bounding box of a region (the domain for inside_walls).
void region_bounds(const RegionSpec& r, const Case& c, int dim, Vec3d& lo, Vec3d& hi) {
  lo = hi = Vec3d::Zero();
  switch (r.kind) {
    case RegionSpec::Kind::box:
      lo = r.min;
      hi = r.max;
      break;
    case RegionSpec::Kind::disk:
    case RegionSpec::Kind::ball:
    case RegionSpec::Kind::annulus: {
      const double rad = r.kind == RegionSpec::Kind::annulus ? r.r_out : r.radius;
      for (int d = 0; d < dim; ++d) {
        lo[d] = r.center[d] - rad;
        hi[d] = r.center[d] + rad;
      }
      break;
    }
    case RegionSpec::Kind::inside_walls:
      lo = c.domain_min;
      hi = c.domain_max;
      break;
  }
}

// Whether x lies in the region (first dim axes); inside_walls regions hold every point.
bool region_contains(const RegionSpec& r, int dim, const Vec3d& x) {
  double d2 = 0;
  for (int d = 0; d < dim; ++d) d2 += (x[d] - r.center[d]) * (x[d] - r.center[d]);
  switch (r.kind) {
    case RegionSpec::Kind::box:
      for (int d = 0; d < dim; ++d)
        if (x[d] < r.min[d] || x[d] >= r.max[d]) return false;
      return true;
    case RegionSpec::Kind::disk:
    case RegionSpec::Kind::ball:
      return d2 < r.radius * r.radius;
    case RegionSpec::Kind::annulus:
      return d2 >= r.r_in * r.r_in && d2 < r.r_out * r.r_out;
    case RegionSpec::Kind::inside_walls:
      return true;
  }
  return false;
}

}  // namespace

AnnulusRings annulus_rings(const RegionSpec& r, double dx) {
  const long count = std::max(1L, std::lround((r.r_out - r.r_in) / dx));
  return {count, (r.r_out - r.r_in) / count};
}

void append_annulus_rings(const RegionSpec& r, const AnnulusRings& rings, long k_begin, long k_end,
                          double dx, std::vector<GeneratedPoint>& out) {
  // Rings at the cell centres across the gap; each ring holds the integer number of
  // particles closest to its circumference / dx, so spacing along and across match.
  for (long k = k_begin; k < k_end; ++k) {
    const double rad = r.r_in + (k + 0.5) * rings.dr;
    if (rad <= 0) continue;  // continued inwards past the centre
    const long m = std::max(3L, std::lround(2 * std::numbers::pi * rad / dx));
    const double vol = 2 * std::numbers::pi * rad * rings.dr / m;
    // Alternate rings are rotated half a step so neighbours interleave (parity of k, also
    // for the rings continued inwards, k < 0).
    const double phase = (((k % 2) + 2) % 2) * std::numbers::pi / m;
    for (long q = 0; q < m; ++q) {
      const double th = phase + 2 * std::numbers::pi * q / m;
      out.push_back({r.center + Vec3d(rad * std::cos(th), rad * std::sin(th), 0), vol});
    }
  }
}

std::vector<GeneratedPoint> generate_region(const RegionSpec& r, int dim, double dx,
                                            const std::string& file, const std::string& key) {
  std::vector<GeneratedPoint> pts;
  switch (r.kind) {
    case RegionSpec::Kind::box:
      lattice(
          r.min, r.max, dim, dx, [](const Vec3d&) { return true; }, pts, file, key);
      break;
    case RegionSpec::Kind::disk:
    case RegionSpec::Kind::ball: {
      Vec3d lo = r.center, hi = r.center;
      for (int d = 0; d < dim; ++d) {
        lo[d] -= r.radius;
        hi[d] += r.radius;
      }
      lattice(
          lo, hi, dim, dx,
          [&](const Vec3d& x) {
            double d2 = 0;  // over the first dim axes only (z is 0 in 2-D)
            for (int d = 0; d < dim; ++d) d2 += (x[d] - r.center[d]) * (x[d] - r.center[d]);
            return d2 < r.radius * r.radius;
          },
          pts, file, key);
      break;
    }
    case RegionSpec::Kind::annulus: {
      if (dim != 2) throw InputError(file, key, "an annulus region is 2-D");
      // Rings across the gap times particles on the outer ring, checked before lround.
      checked_count((r.r_out - r.r_in) / dx * (2 * std::numbers::pi * r.r_out / dx), dx, file, key);
      const AnnulusRings rings = annulus_rings(r, dx);
      append_annulus_rings(r, rings, 0, rings.count, dx, pts);
      break;
    }
    case RegionSpec::Kind::inside_walls:
      break;  // needs the walls: see generate_particles
  }
  if (pts.empty() && r.kind != RegionSpec::Kind::inside_walls)
    throw InputError(file, key, "the region holds no particle at this resolution");
  return pts;
}

double estimate_particle_count(const Case& c) {
  const int D = c.dimension;
  double count = 0;
  for (const FluidSpec& f : c.fluids) {
    const RegionSpec& r = f.region;
    double volume = 1;
    switch (r.kind) {
      case RegionSpec::Kind::box:
      case RegionSpec::Kind::inside_walls: {
        const bool box = r.kind == RegionSpec::Kind::box;
        for (int d = 0; d < D; ++d)
          volume *= box ? r.max[d] - r.min[d] : c.domain_max[d] - c.domain_min[d];
        break;
      }
      case RegionSpec::Kind::disk:
      case RegionSpec::Kind::ball:
        volume = D == 2 ? std::numbers::pi * r.radius * r.radius
                        : 4.0 / 3.0 * std::numbers::pi * std::pow(r.radius, 3);
        break;
      case RegionSpec::Kind::annulus:
        volume = std::numbers::pi * (r.r_out * r.r_out - r.r_in * r.r_in);
        break;
    }
    // Divided axis by axis: dx^D underflows to 0 for dx = 1e-200.
    for (int d = 0; d < D; ++d) volume /= c.dx;
    count += volume;
  }
  return count;
}

template <int D>
void generate_particles(const Case& c, Particles<D>& P, const WallSet<D>& walls) {
  std::vector<GeneratedPoint> all;
  std::vector<int> phase;
  // A lattice aligned with a wall sits dx/2 from it; annulus rings sit dr/2 >= dx/3 from their
  // walls (dr = gap / round(gap/dx)). Keep everything farther than 0.3 dx.
  const double clearance = 0.3 * c.dx;
  // The last answer of each closed wall (Wall::closed_surface: |d(x) - d(y)| <= |x - y|):
  // a lattice point near it whose distance that bound settles needs no query. The points come
  // row by row dx apart, so far from a CAD solid one query settles tens of points (the U-pipe
  // of data/cad at dx = a/4: 3.4 s instead of 17 s, docs/geometry.md).
  struct Known {
    VecD<D> y;
    double d;
    bool valid = false;
  };
  std::vector<Known> known(walls.size());
  auto wet = [&](const Vec3d& x) {
    const VecD<D> p = x.head<D>();
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const Wall<D>& w = walls[k];
      Known& kn = known[k];
      if (kn.valid) {
        const double r = (p - kn.y).norm();
        if (kn.d - r >= clearance) continue;  // farther than clearance on the fluid side
        if (kn.d + r < clearance) return false;
      }
      const double d = w.closest(p).distance;
      if (w.closed_surface()) kn = {p, d, true};
      if (d < clearance) return false;
    }
    return true;
  };
  for (std::size_t f = 0; f < c.fluids.size(); ++f) {
    const std::string key = "fluids." + std::to_string(f) + ".region";
    std::vector<GeneratedPoint> pts;
    if (c.fluids[f].region.kind == RegionSpec::Kind::inside_walls) {
      if (!c.has_domain || walls.empty())
        throw InputError(c.file_name(), key, "inside_walls needs walls and domain.min/max");
      RegionSpec box;
      box.min = c.domain_min;
      box.max = c.domain_max;
      pts = generate_region(box, D, c.dx, c.file_name(), key);
    } else {
      pts = generate_region(c.fluids[f].region, D, c.dx, c.file_name(), key);
    }
    // Fluids are painted in list order: a later fluid's region takes its points from the
    // earlier ones (a droplet listed after the surrounding fluid).
    auto claimed_later = [&](const Vec3d& x) {
      for (std::size_t g = f + 1; g < c.fluids.size(); ++g)
        if (c.fluids[g].region.kind != RegionSpec::Kind::inside_walls &&
            region_contains(c.fluids[g].region, D, x))
          return true;
      return false;
    };
    std::size_t kept = 0;
    for (const auto& p : pts)
      if (!claimed_later(p.x) && (walls.empty() || wet(p.x))) {
        all.push_back(p);
        ++kept;
      }
    if (c.jitter > 0 && !c.fluids[f].region.random) {
      // setup.jitter: a uniform offset of up to jitter dx per axis; a point whose move would
      // leave its region, come near a wall or enter a later fluid's region stays where it was
      // (so the count and volumes are those of the lattice).
      std::mt19937_64 rng(static_cast<std::uint64_t>(c.random_seed) * 104729u + 31u * f + 1u);
      std::uniform_real_distribution<double> u(-c.jitter * c.dx, c.jitter * c.dx);
      const bool bounded = c.fluids[f].region.kind != RegionSpec::Kind::inside_walls;
      for (std::size_t q = all.size() - kept; q < all.size(); ++q) {
        Vec3d x = all[q].x;
        for (int d = 0; d < D; ++d) x[d] += u(rng);
        if (bounded && !region_contains(c.fluids[f].region, D, x)) continue;
        if (!(walls.empty() || wet(x)) || claimed_later(x)) continue;
        all[q].x = x;
      }
    }
    if (c.fluids[f].region.random && kept > 0) {
      // Same count and volumes, uniformly random positions in the region (wet ones only).
      std::mt19937_64 rng(static_cast<std::uint64_t>(c.random_seed) * 7919u + f);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      Vec3d lo, hi;
      region_bounds(c.fluids[f].region, c, D, lo, hi);
      for (std::size_t q = all.size() - kept; q < all.size();) {
        Vec3d x = Vec3d::Zero();
        for (int d = 0; d < D; ++d) x[d] = lo[d] + (hi[d] - lo[d]) * u(rng);
        if (!region_contains(c.fluids[f].region, D, x) || !(walls.empty() || wet(x))) continue;
        all[q++].x = x;
      }
    }
    if (kept == 0)
      throw InputError(c.file_name(), key,
                       "no particle of this region is left (all on the far side of a wall or "
                       "inside the regions of fluids listed after it)");
    phase.insert(phase.end(), kept, static_cast<int>(f));
  }
  // A region that crosses a periodic seam (or a jittered point that did) holds points beyond
  // the domain: each becomes its periodic image inside [min, max), where the cell list and
  // the walls expect it.
  for (auto& p : all)
    for (int d = 0; d < D; ++d)
      if (c.has_domain && c.periodic[d])
        p.x[d] = wrap_periodic(p.x[d], c.domain_min[d], c.domain_max[d] - c.domain_min[d]);
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

template void generate_particles<2>(const Case&, Particles<2>&, const WallSet<2>&);
template void generate_particles<3>(const Case&, Particles<3>&, const WallSet<3>&);

}  // namespace curvsph
