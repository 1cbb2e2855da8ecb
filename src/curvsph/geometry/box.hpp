#pragma once
// An axis-aligned box (a rectangle in 2-D), fluid inside (a tank) or outside (an obstacle).
//
// Corners and edges. A box's wall is flat everywhere except on its edges and corners, where
// it is not differentiable. What this wall reports there:
//  - a point whose closest wall point lies on a face: that face's normal, k = 0;
//  - a point outside the box whose closest point is an edge or a corner vertex (its
//    projection is clamped in two or more axes): the normal is the unit vector from the
//    foot to the point (sign by the fluid side), k1 = k2 = 0 — the corner is treated as a
//    sharp feature, not a small rounded one; boundary treatments handle corners on their
//    own (double reflections, boundary integrals);
//  - a point inside the box at equal distance from several faces (the medial planes): the
//    first face in the order -x, +x, -y, +y, -z, +z wins, so the answer is reproducible.
// min_radius_of_curvature() is +inf: only the faces are curved (not at all); corners are
// sharp features, not curvature.
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph {

template <int D>
class BoxWall final : public Wall<D> {
 public:
  BoxWall(const VecD<D>& min, const VecD<D>& max, FluidSide side);
  // No surface parameters (param_count = 0).
  WallPoint<D> closest(const VecD<D>& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override;
  // The box itself, for discretisations (boundary elements) and face-by-face ghosts.
  const VecD<D>& min() const { return min_; }
  const VecD<D>& max() const { return max_; }
  FluidSide side() const { return side_; }

 private:
  VecD<D> min_, max_;
  FluidSide side_;
};

// YAML: {shape: box, min: [..], max: [..], fluid: inside|outside}.
template <int D>
WallPtr<D> make_box_wall(const YAML::Node& node, const std::string& file, const std::string& key);

}  // namespace curvsph
