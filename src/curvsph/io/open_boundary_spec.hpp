#pragma once
// The `open_boundaries` section of a case file (DESIGN.md §3): inflow and outflow planes with
// buffer layers (solver/open_boundaries.hpp). Read and checked here, geometry included, so the
// solver receives planes whose normal points into the fluid and profiles that lie on them.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

struct OpenBoundarySpec {
  std::string name;
  enum class Kind { inflow, outflow } kind = Kind::inflow;
  Vec3d point = Vec3d::Zero();   // a point of the boundary line (2-D) or plane (3-D)
  Vec3d normal = Vec3d::Zero();  // unit, into the fluid
  // Inflow velocity: a uniform vector, or a parabolic profile along the normal that vanishes
  // on the edge of a segment (2-D: from..to), a rectangle (3-D: corners from, to) or a circle
  // (3-D: center, radius).
  enum class Profile { uniform, segment, rectangle, circle } profile = Profile::uniform;
  Vec3d velocity = Vec3d::Zero();                  // uniform
  double u_max = 0;                                // parabolic: the peak speed
  Vec3d from = Vec3d::Zero(), to = Vec3d::Zero();  // segment, rectangle
  Vec3d center = Vec3d::Zero();                    // circle
  double radius = 0;                               // circle
  double ramp = 0;  // seconds over which the inflow rises linearly from 0 (0: at once)
  // Outflow: the pressure given to the buffer particles (equation-of-state pressure, eos.p0
  // included); absent: eos.p0, the pressure of the reference density.
  std::optional<double> pressure;
};

struct Case;

// Reads `open_boundaries` (a list; absent or empty: none). `c` supplies the dimension and
// the domain box for the geometry checks. Throws InputError naming the file and the key.
std::vector<OpenBoundarySpec> read_open_boundaries(const YAML::Node& node, const Case& c);

}  // namespace curvsph
