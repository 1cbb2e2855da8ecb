#include "curvsph/setup/relax_closure.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "curvsph/geometry/plane.hpp"

namespace curvsph {

namespace {

// Whether the face of box [lo, hi] across `axis` at side `s` (0: lo, 1: hi) is free: some
// sample point of it is wet (the fill's lattice columns end at that part of the face).
template <int D>
bool free_face(const VecD<D>& lo, const VecD<D>& hi, int axis, int s, const WallSet<D>& walls,
               double dx) {
  const double clearance = 0.3 * dx;
  int n[D];
  for (int d = 0; d < D; ++d)
    n[d] = d == axis ? 1 : std::clamp(static_cast<int>(std::ceil((hi[d] - lo[d]) / dx)), 1, 64);
  long total = 1;
  for (int d = 0; d < D; ++d) total *= n[d];
  for (long k = 0; k < total; ++k) {
    VecD<D> p;
    long r = k;
    for (int d = 0; d < D; ++d) {
      const long j = r % n[d];
      r /= n[d];
      p[d] = d == axis ? (s ? hi[d] : lo[d]) : lo[d] + (hi[d] - lo[d]) * (j + 0.5) / n[d];
    }
    bool wet = true;
    for (std::size_t w = 0; w < walls.size() && wet; ++w)
      wet = walls[w].closest(p).distance > clearance;
    if (wet) return true;
  }
  return false;
}

}  // namespace

template <int D>
WallSet<D> relax_walls(const Case& c, const WallSet<D>& walls) {
  WallSet<D> out;
  for (const auto& w : walls.walls()) out.add(w);
  if (!c.relax.hold_free_faces) return out;
  for (const FluidSpec& f : c.fluids) {
    if (f.region.kind != RegionSpec::Kind::box) continue;
    const VecD<D> lo = f.region.min.head<D>(), hi = f.region.max.head<D>();
    for (int axis = 0; axis < D; ++axis) {
      if (c.periodic[axis]) continue;
      for (int s = 0; s < 2; ++s) {
        if (!free_face<D>(lo, hi, axis, s, walls, c.dx)) continue;
        VecD<D> point = lo, normal = VecD<D>::Zero();
        point[axis] = s ? hi[axis] : lo[axis];
        normal[axis] = s ? -1.0 : 1.0;  // into the fluid
        out.add(std::make_shared<PlaneWall<D>>(point, normal));
      }
    }
  }
  return out;
}

template WallSet<2> relax_walls<2>(const Case&, const WallSet<2>&);
template WallSet<3> relax_walls<3>(const Case&, const WallSet<3>&);

}  // namespace curvsph
