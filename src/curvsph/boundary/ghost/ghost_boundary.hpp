#pragma once
// `boundary: {method: ghost}`: reflected ghost particles (Barker & Neethling; Vela Vela et al.)
// rebuilt every step by GhostSet, entering the fluid pair terms as extra neighbours with the
// fields of their source (ghosts.hpp, "Contract for the density and force passes").
#include <memory>

#include "curvsph/boundary/boundary_model.hpp"

namespace curvsph {

template <int D>
std::unique_ptr<BoundaryModel<D>> make_ghost_boundary(const BoundaryContext<D>& ctx);

}  // namespace curvsph
