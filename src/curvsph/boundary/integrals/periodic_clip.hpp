#pragma once
// Boundary elements cut to a periodic domain. A wall drawn past a periodic seam (so that
// ghosts see it continue, e.g. cases/throttled_pipe.yaml, whose walls run 4 mm past each seam)
// would otherwise be counted twice by the boundary integrals: once as itself beyond the seam
// and once through the periodic image of its other end.
#include <array>

#include "curvsph/boundary/integrals/boundary_elements.hpp"

namespace curvsph {

// The part of `el` inside [lo, hi] along every periodic axis: flat elements (2-D segments,
// 3-D polygons with gap 0) clipped exactly at the seam planes (a clipped 3-D polygon with
// more than 4 vertices fanned into triangles), curved ones (arcs, curved patches) kept whole
// when their centre lies in [lo, hi).
template <int D>
BoundaryElements<D> clip_to_periodic_domain(const BoundaryElements<D>& el, const VecD<D>& lo,
                                            const VecD<D>& hi, const std::array<bool, 3>& periodic);

}  // namespace curvsph
