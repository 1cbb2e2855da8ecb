#pragma once
// Read-only view of the wall images (ghosts) a boundary model built in its last prepare(), for
// pair terms outside the model that sum over neighbours across a wall (the colour gradient
// and curvature of surface tension). Image g stands for fluid particle source[g]: it carries
// that particle's fields (phase = colour, mass, rho) with the volume weight beta[g]
// (sigma_g = sigma_s beta_g, Barker eq. 22). Valid until the next prepare(); empty (cells ==
// nullptr) for models without images.
#include <cstdint>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

template <int D>
struct WallImages {
  const std::vector<Vec<D>>* x = nullptr;
  const std::vector<Index>* source = nullptr;
  const std::vector<Real>* beta = nullptr;
  const std::vector<std::int32_t>* wall = nullptr;         // index in the WallSet
  const std::vector<VecD<D>>* normal = nullptr;            // that wall's normal, into the fluid
  const std::vector<std::uint8_t>* reflections = nullptr;  // 1 single, 2-3 corner images
  const CellList<D>* cells = nullptr;                      // built over *x
  bool empty() const { return cells == nullptr || x->empty(); }
};

}  // namespace curvsph
