// Boundary elements cut to a periodic domain: a wall drawn past the seams keeps exactly the
// part inside (lengths and areas against the exact ones), curved elements are kept by centre.
#include <gtest/gtest.h>

#include <numeric>

#include "curvsph/boundary/integrals/periodic_clip.hpp"

using namespace curvsph;

TEST(PeriodicClip, FlatElementsCutAtTheSeamsCurvedByCentre) {
  // 2-D: a line from x = -1.37 to 1.52 in segments of 0.2 (none ends on a seam at +-1).
  const auto line = polyline_elements({{-1.37, 0.1}, {1.52, 0.1}}, 0.2);
  const auto cut =
      clip_to_periodic_domain<2>(line, Vec2d(-1, -5), Vec2d(1, 5), {true, false, false});
  EXPECT_NEAR(std::accumulate(cut.area.begin(), cut.area.end(), 0.0), 2.0, 1e-12);
  for (std::size_t j = 0; j < cut.size(); ++j)
    for (const Vec2d& v : cut.vertices[j]) EXPECT_LE(std::abs(v.x()), 1.0 + 1e-15);
  // Not periodic along y: nothing cut there.
  const auto same =
      clip_to_periodic_domain<2>(line, Vec2d(-5, 0.5), Vec2d(5, 0.6), {false, false, false});
  EXPECT_EQ(same.size(), line.size());
  // Arcs: kept when the centre lies in [lo, hi).
  const auto circle = circle_elements(Vec2d(0, 0), 1.0, 0.1, true);
  const auto half =
      clip_to_periodic_domain<2>(circle, Vec2d(0, -2), Vec2d(2, 2), {true, false, false});
  std::size_t right = 0;
  for (std::size_t j = 0; j < circle.size(); ++j) right += circle.centre[j].x() >= 0 ? 1 : 0;
  EXPECT_EQ(half.size(), right);
  // 3-D: a plate [-1.3, 1.3] x [0, 1] in patches of 0.25, periodic in x over [-1, 1]: the
  // cut patches keep their orientation.
  const auto plate = rectangle_elements(Vec3d(-1.3, 0, 0), Vec3d(2.6, 0, 0), Vec3d(0, 1, 0), 0.25);
  const auto p =
      clip_to_periodic_domain<3>(plate, Vec3d(-1, -1, -1), Vec3d(1, 2, 1), {true, false, false});
  EXPECT_NEAR(std::accumulate(p.area.begin(), p.area.end(), 0.0), 2.0, 1e-12);
  for (std::size_t j = 0; j < p.size(); ++j) EXPECT_NEAR(p.normal[j].z(), 1.0, 1e-12);
}
