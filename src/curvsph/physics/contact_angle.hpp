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
// How the angle enters (surface_tension.hpp). The wall images continue the interface through
// the wall at theta: each image takes the colour and normal of the fluid particle at the point
// that the continuation map sends onto it, its normal continued by contact_angle_image_normal.
// Optionally (layer > 0) a particle of the pair with a valid interface normal whose nearest wall
// carries `contact_angle` and lies at a distance 0 < d < layer also gets the turned normal of
// contact_angle_normal (Brackbill's wall adhesion applied to the first row); the solver uses
// layer 0 (kContactLayer, measured below). The wall normal is the geometry's own
// (Wall<D>::closest: analytic walls in closed form, NURBS by the safeguarded projection), so
// curved walls need nothing special.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// Thickness of the contact-angle layer in units of h (the solver's choice): 0, no particle's
// colour gradient is turned. The angle enters through the wall images instead: their colours
// and normals continue the interface through the wall at theta (surface_tension.hpp), so a
// drop at the imposed angle sees the normals and curvature of its own continuation, and a drop
// at another angle sees a kink at the wall that pulls it towards theta. Turning the first row
// on top of that (0.8 h) sets normals that differ by 7-8 deg from what the colour gradient of
// the exact cap gives on the lattice, and the kink drives the drop away from the imposed angle:
// the exact 120 deg cap of cases/droplet_wall.yaml went from 118.2 to 111.6 deg in 1 s with it
// and stayed at 119.4 deg without it (findings.md).
inline constexpr Real kContactLayer = Real(0);

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

// Unit interface normal carried by a wall image (ghost) at a wall with contact angle theta, in
// the curvature sum, from the unit normal nh (either orientation) of the fluid particle it
// stands for (surface_tension.hpp). The interface is continued through the wall as the same
// curve: with m_theta = n_w cos(theta) + t_w sin(theta) the imposed normal at the contact line
// and p = n_w sin(theta) - t_w cos(theta) the interface tangent there (in the plane of n_w and
// t_w, t_w along the wall away from the drop), a normal turned by phi from m_theta (the
// interface bending away from the contact line) continues as the normal turned by -phi: nh
// reflected across the plane normal to p, nh - 2 (nh.p) p. At theta = 90 deg p = n_w and this
// is the mirror reflection of walls without a contact angle. It agrees to first order in phi
// with the exact transform of normals under the continuation map of surface_tension.hpp
// (C^-T, not an isometry); being a reflection it does not amplify the lattice noise of the
// normals (C^-T gave larger curvature errors near the wall on the exact cap, 1.7/R against
// 1.3/R at 60 deg, flat wall, R = 32 dx, tests/physics/test_contact_angle_cap.cpp). Copying nh
// unchanged (a straight continuation, the first version) dropped the bend of the interface
// across the wall. t_w is the tangential part of -nh; when nh is along n_w it is undefined and
// nh is returned.
template <int D>
Vec<D> contact_angle_image_normal(const Vec<D>& nh, const Vec<D>& n_wall, Real theta) {
  const Vec<D> m = -nh;
  const Vec<D> tangential = m - m.dot(n_wall) * n_wall;
  const Real t_len = tangential.norm();
  if (!(t_len > Real(1e-12))) return nh;
  const Vec<D> p = std::sin(theta) * n_wall - std::cos(theta) * (tangential / t_len);
  return nh - 2 * nh.dot(p) * p;
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
