#pragma once
// Static contact angle at a wall: Brackbill, Kothe & Zemach (1992) wall adhesion, eq. (41).
//
// Sign convention. Surface tension acts between fluids a and b of a pair with the colour
// c = 1 on b (surface_tension.hpp), so the colour gradient n points INTO b. The contact angle
// theta is measured INSIDE b (the second fluid of the pair, the droplet of a wetting case),
// between the wall and the interface: theta < 90 deg, b wets the wall; theta > 90 deg, b beads.
// With n_w the wall's unit normal into the fluid (wall.hpp) and m = -n/|n| the interface
// normal pointing out of b, the condition is
//     m = n_w cos(theta) + t_w sin(theta),
// t_w the unit wall tangent in the plane of m and n_w pointing away from b along the wall,
// t_w = (m - (m.n_w) n_w) / |m - (m.n_w) n_w|. (A circular cap of b on a flat wall with its
// centre below the wall: at the right contact point m = (sin theta, cos theta) with n_w = e_y,
// t_w = e_x.) The turned colour gradient keeps its magnitude: n' = -|n| m.
//
// Which particles. A particle of the pair with a valid interface normal (surface_tension.hpp)
// whose nearest wall carries `contact_angle` and lies at a distance 0 < d < layer gets the
// turned normal; the curvature is then computed from the corrected normals. The wall normal
// is the geometry's own (Wall<D>::closest: analytic walls in closed form, NURBS by the
// safeguarded projection), so curved walls need nothing special.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// Thickness of the contact-angle layer in units of h (the solver's choice): about the first
// particle row (d ~ dx/2 = 0.33 h at h = 1.5 dx). With 1.5 h (two rows) the drop of
// cases/droplet_wall.yaml went to ~77 deg for 90 imposed; with 0.8 h it holds 87 deg.
inline constexpr Real kContactLayer = Real(0.8);

// The colour gradient n (pointing into fluid b) turned so that the interface makes the angle
// theta (radians, inside b) with a wall of unit normal n_wall (into the fluid). When n is
// parallel to n_wall the tangent is undefined and n is returned unchanged.
template <int D>
Vec<D> contact_angle_normal(const Vec<D>& n, const Vec<D>& n_wall, Real theta) {
  const Real len = n.norm();
  if (!(len > 0)) return n;
  const Vec<D> m = -n / len;
  const Vec<D> tangential = m - m.dot(n_wall) * n_wall;
  const Real t_len = tangential.norm();
  if (!(t_len > Real(1e-12))) return n;
  const Vec<D> m_turned = std::cos(theta) * n_wall + std::sin(theta) * (tangential / t_len);
  return -len * m_turned;
}

// Contact angle (radians) of every wall of the WallSet that parse_walls() builds from the same
// `walls:` list, in its order; empty where the element has no `contact_angle` (degrees, in
// (0, 180), else InputError naming walls.N.contact_angle). CAD elements yield several walls;
// when any element has a contact angle every element is parsed again once to count them.
template <int D>
std::vector<std::optional<Real>> parse_contact_angles(const YAML::Node& walls,
                                                      const std::string& file,
                                                      const std::filesystem::path& base_dir);

// The wall point that sets the contact angle at x: the nearest wall, when it has a contact
// angle and x lies within (0, layer) of it.
template <int D>
struct ContactWall {
  Vec<D> normal;
  Real theta;
};

template <int D>
std::optional<ContactWall<D>> contact_wall(const WallSet<D>& walls,
                                           const std::vector<std::optional<Real>>& angles,
                                           const Vec<D>& x, Real layer) {
  if (walls.empty()) return std::nullopt;
  const WallPoint<D> wp = walls.closest(x.template cast<double>());
  if (wp.wall < 0 || !(wp.distance > 0) || !(wp.distance < layer)) return std::nullopt;
  const auto& theta = angles.at(static_cast<std::size_t>(wp.wall));
  if (!theta) return std::nullopt;
  return ContactWall<D>{wp.normal.template cast<Real>(), static_cast<Real>(*theta)};
}

}  // namespace curvsph
