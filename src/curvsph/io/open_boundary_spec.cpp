#include "curvsph/io/open_boundary_spec.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {
namespace {

Vec3d read_point(const YAML::Node& map, std::string_view key, int dim, const std::string& file,
                 const std::string& path) {
  const std::vector<double> v =
      yaml::read_numbers(yaml::child(map, key, file, path), file, yaml::join(path, key),
                         static_cast<std::size_t>(dim));
  Vec3d out = Vec3d::Zero();
  for (int d = 0; d < dim; ++d) out[d] = v[static_cast<std::size_t>(d)];
  return out;
}

// A length scale of the case for the "lies on the plane" tolerances: the domain's diagonal,
// or 10^4 dx without a domain.
double scale_of(const Case& c) {
  return c.has_domain ? (c.domain_max - c.domain_min).norm() : 1e4 * c.dx;
}

// The velocity key of an inflow: [u, v(, w)] or {parabolic: {...}, ramp: T}.
void read_velocity(const YAML::Node& node, const Case& c, OpenBoundarySpec& s,
                   const std::string& file, const std::string& path) {
  const int dim = c.dimension;
  const double tol = 1e-9 * scale_of(c);
  if (node.IsSequence()) {
    s.profile = OpenBoundarySpec::Profile::uniform;
    s.velocity = Vec3d::Zero();
    const auto v = yaml::read_numbers(node, file, path, static_cast<std::size_t>(dim));
    for (int d = 0; d < dim; ++d) s.velocity[d] = v[static_cast<std::size_t>(d)];
    if (!(s.velocity.dot(s.normal) > 0))
      throw InputError(file, path,
                       "the inflow velocity must point into the fluid (a positive component "
                       "along the normal)");
    return;
  }
  yaml::require_map(node, file, path);
  yaml::check_keys(node, {"parabolic", "ramp"}, file, path);
  if (yaml::has(node, "ramp"))
    s.ramp = yaml::read_nonnegative(node["ramp"], file, yaml::join(path, "ramp"));
  const std::string pp = yaml::join(path, "parabolic");
  const YAML::Node p = yaml::child(node, "parabolic", file, path);
  yaml::require_map(p, file, pp);
  s.u_max = yaml::read_positive(yaml::child(p, "max", file, pp), file, yaml::join(pp, "max"));
  const auto on_plane = [&](const Vec3d& x, const std::string& key) {
    const double off = (x - s.point).dot(s.normal);
    if (std::abs(off) > tol)
      throw InputError(file, yaml::join(pp, key),
                       fmt::format("lies {:.3g} off the boundary {} (point, normal): the profile "
                                   "must lie on it",
                                   off, dim == 2 ? "line" : "plane"));
  };
  if (yaml::has(p, "center") || yaml::has(p, "radius")) {
    if (dim == 2) throw InputError(file, pp, "a circle profile is 3-D; in 2-D give from and to");
    yaml::check_keys(p, {"max", "center", "radius"}, file, pp);
    s.profile = OpenBoundarySpec::Profile::circle;
    s.center = read_point(p, "center", dim, file, pp);
    s.radius =
        yaml::read_positive(yaml::child(p, "radius", file, pp), file, yaml::join(pp, "radius"));
    on_plane(s.center, "center");
    return;
  }
  yaml::check_keys(p, {"max", "from", "to"}, file, pp);
  s.from = read_point(p, "from", dim, file, pp);
  s.to = read_point(p, "to", dim, file, pp);
  on_plane(s.from, "from");
  on_plane(s.to, "to");
  if (dim == 2) {
    s.profile = OpenBoundarySpec::Profile::segment;
    if (!((s.to - s.from).norm() > tol))
      throw InputError(file, yaml::join(pp, "to"), "equals from");
    return;
  }
  // A rectangle from two corners is only defined with its edges along coordinate axes: the
  // plane must be normal to an axis.
  s.profile = OpenBoundarySpec::Profile::rectangle;
  int axis = 0;
  s.normal.cwiseAbs().maxCoeff(&axis);
  if (std::abs(std::abs(s.normal[axis]) - 1) > 1e-12)
    throw InputError(file, pp,
                     "a rectangle profile (from, to) needs a normal along a coordinate axis; "
                     "use center and radius for a circle");
  for (int d = 0; d < 3; ++d)
    if (d != axis && !(std::abs(s.to[d] - s.from[d]) > tol))
      throw InputError(file, yaml::join(pp, "to"),
                       "the rectangle's corners must differ along both axes of the plane");
}

}  // namespace

std::vector<OpenBoundarySpec> read_open_boundaries(const YAML::Node& node, const Case& c) {
  std::vector<OpenBoundarySpec> out;
  const std::string file = c.file_name();
  if (!node || node.IsNull()) return out;
  const std::size_t n = yaml::require_list(node, file, "open_boundaries");
  const int dim = c.dimension;
  std::set<std::string> names;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string path = yaml::join("open_boundaries", i);
    const YAML::Node b = node[i];
    yaml::require_map(b, file, path);
    yaml::check_keys(b, {"name", "kind", "point", "normal", "velocity", "pressure"}, file, path);
    OpenBoundarySpec s;
    s.name = yaml::has(b, "name") ? yaml::read_string(b["name"], file, yaml::join(path, "name"))
                                  : fmt::format("open{}", i);
    if (!names.insert(s.name).second)
      throw InputError(file, yaml::join(path, "name"), "duplicate open boundary name");
    const std::string kind = yaml::read_choice(
        yaml::child(b, "kind", file, path), {"inflow", "outflow"}, file, yaml::join(path, "kind"));
    s.kind = kind == "inflow" ? OpenBoundarySpec::Kind::inflow : OpenBoundarySpec::Kind::outflow;
    s.point = read_point(b, "point", dim, file, path);
    s.normal = read_point(b, "normal", dim, file, path);
    if (!(s.normal.norm() > 0)) yaml::throw_zero_vector(file, yaml::join(path, "normal"));
    s.normal.normalize();
    if (c.has_domain) {
      // The plane must cut the domain box and the normal point into it: the box's centre lies
      // on the fluid side.
      const double slack = 1e-9 * scale_of(c);
      for (int d = 0; d < dim; ++d)
        if (s.point[d] < c.domain_min[d] - slack || s.point[d] > c.domain_max[d] + slack)
          throw InputError(file, yaml::join(path, "point"),
                           fmt::format("lies outside the domain box on axis {}", d));
      const Vec3d mid = 0.5 * (c.domain_min + c.domain_max);
      if (!((mid - s.point).dot(s.normal) > 0))
        throw InputError(file, yaml::join(path, "normal"),
                         "must point into the domain (the normal of an open boundary points "
                         "into the fluid)");
    }
    if (s.kind == OpenBoundarySpec::Kind::inflow) {
      if (yaml::has(b, "pressure"))
        throw InputError(file, yaml::join(path, "pressure"),
                         "an inflow takes a velocity; its pressure is extrapolated from the fluid");
      read_velocity(yaml::child(b, "velocity", file, path), c, s, file,
                    yaml::join(path, "velocity"));
    } else {
      if (yaml::has(b, "velocity"))
        throw InputError(file, yaml::join(path, "velocity"),
                         "an outflow takes a pressure; its velocity is extrapolated from the "
                         "fluid");
      if (yaml::has(b, "pressure"))
        s.pressure = yaml::read_number(b["pressure"], file, yaml::join(path, "pressure"));
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace curvsph
