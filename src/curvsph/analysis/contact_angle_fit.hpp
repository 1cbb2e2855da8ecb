#pragma once
// Contact angle measured from an interface shape (issue #6), 2-D: the interface near a
// contact point is fitted with a circle, the circle is intersected with the wall, and the
// angle between the circle and the wall is taken inside the drop, with the sign convention
// of physics/contact_angle.hpp: m = n_w cos(theta) + t_w sin(theta), m the interface normal
// pointing out of the drop, n_w the wall normal into the fluid, so theta = acos(m . n_w).
#include <optional>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

struct Circle2 {
  Vec2d center = Vec2d::Zero();
  double radius = 0;
};

// Least-squares circle: the algebraic fit of Kasa (1976) (minimises
// sum (|x|^2 + D x + E y + F)^2: centre (-D/2, -E/2), radius sqrt(D^2/4 + E^2/4 - F)) as the
// start of Gauss-Newton on the geometric residuals |x - c| - r. Needs 3 points not on a line.
std::optional<Circle2> fit_circle(const std::vector<Vec2d>& points);

struct MeasuredAngle {
  double theta_deg = 0;           // inside the drop
  Vec2d contact = Vec2d::Zero();  // circle-wall intersection
  Circle2 circle;                 // the fit
  std::size_t points = 0;         // interface points used
};

// The angle at the intersection of `circle` with the walls nearest to `near` (searched along
// the circle within +-max_arc of the circle point closest to `near`, bisection on the signed
// wall distance). `inside` is a point inside the drop near the contact point: it says on which
// side of the circle the drop lies. Empty when the circle does not cross a wall there.
std::optional<MeasuredAngle> circle_wall_angle(const Circle2& circle, const WallSet<2>& walls,
                                               const Vec2d& near, const Vec2d& inside,
                                               double max_arc);

// Interface points of a two-phase particle set: on every (drop, other) pair closer than
// `pair_distance`, the point where the smoothed drop colour (Shepard-normalised Wendland C2
// average of the indicator, h = pair_distance) crosses 1/2, interpolated linearly.
std::vector<Vec2d> interface_points(const std::vector<Vec2d>& x, const std::vector<int>& is_drop,
                                    double pair_distance);

// Both contact angles of a drop on a wall running roughly along +x: interface points within
// `contact_band` of a wall are contact candidates; on each side of the drop's centroid the
// candidate farthest from the centroid along x is the contact point; the interface points
// within `fit_radius` of it (<= 0: half the distance between the two contact points) are
// fitted with a circle; `inside` is the centroid of the drop
// points within fit_radius of the contact point. [0] left, [1] right; empty where it fails.
struct DropContactAngles {
  std::optional<MeasuredAngle> side[2];
};
DropContactAngles measure_contact_angles(const std::vector<Vec2d>& x,
                                         const std::vector<int>& is_drop, const WallSet<2>& walls,
                                         double pair_distance, double contact_band,
                                         double fit_radius);

}  // namespace curvsph
