#pragma once
// The one question every boundary treatment asks of a wall (DESIGN.md §4):
// for a point x near it, where is the closest wall point, which way is the fluid,
// how far, and how curved is the wall there.
//
// Sign conventions (normative):
//  - normal: unit, pointing INTO the fluid;
//  - distance: signed, > 0 on the fluid side;
//  - curvatures: k1 >= k2, > 0 where the wall is concave seen from the fluid
//    (fluid inside a circle of radius R: k = 1/R; fluid outside a cylinder: k = -1/R).
//    In 2-D only k1 is used and k2 = 0.
#include <Eigen/Geometry>  // cross(): WallMotion below and the 3-D walls
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
struct WallPoint {
  VecD<D> foot = VecD<D>::Zero();
  VecD<D> normal = VecD<D>::Zero();
  double distance = 0.0;
  double k1 = 0.0;
  double k2 = 0.0;
  // Principal directions: in 3-D unit tangents for k1 and k2; in 2-D dir1 is the unit
  // tangent (direction of increasing u where the wall has a parameter) and dir2 = 0.
  VecD<D> dir1 = VecD<D>::Zero();
  VecD<D> dir2 = VecD<D>::Zero();
  // Surface parameters where the shape has them (u for curves, (u, v) for surfaces).
  std::array<double, 2> param{0.0, 0.0};
  int param_count = 0;
  // Index of the answering wall inside a WallSet (-1 for a single wall query).
  int wall = -1;
  // Newton iterations spent (0 for closed forms); for benchmarks and diagnostics.
  int iterations = 0;
};

// Optional seed for iterative projections (Barker §3.2: the nearest boundary particle's
// stored parameter). Walls with closed forms ignore it.
struct ParamSeed {
  std::array<double, 2> param{0.0, 0.0};
  bool valid = false;
};

// Rigid wall motion (DESIGN.md §3 `motion:`): what the case file says. The geometry moves
// with it (geometry/moving_wall.hpp); velocity_at gives the velocity of the wall point at x at
// time t (rigid motion: v(t) + omega x (x - c(t))).
template <int D>
struct WallMotion {
  enum class Kind { none, rotate, translate, oscillate } kind = Kind::none;
  double omega = 0.0;                     // rotate (2-D: about z; 3-D: about `axis`)
  VecD<D> center = VecD<D>::Zero();       // rotate
  VecD<3> axis = VecD<3>(0.0, 0.0, 1.0);  // rotate, 3-D
  VecD<D> velocity = VecD<D>::Zero();     // translate
  VecD<D> amplitude = VecD<D>::Zero();    // oscillate: x(t) = x0 + A sin(2 pi F t + phi)
  double frequency = 0.0;                 // oscillate, F in Hz
  double phase = 0.0;                     // oscillate, phi in radians
  VecD<D> velocity_at(const VecD<D>& x, double t = 0.0) const;
  // Displacement of the body at time t (translate, oscillate; zero for rotate).
  VecD<D> displacement(double t) const;
};

template <int D>
class Wall {
 public:
  virtual ~Wall() = default;
  // Closest point on the wall to x, with the sign conventions above. Never fails: iterative
  // shapes fall back to a global search so the answer is the global minimum within tolerance.
  virtual WallPoint<D> closest(const VecD<D>& x, const ParamSeed& seed = {}) const = 0;
  // Short human-readable description for messages ("circle r=0.025").
  virtual std::string describe() const = 0;
  // Smallest radius of curvature anywhere on the wall (+inf for flat walls); used to refuse
  // a kernel support too large for the wall (DESIGN.md §3 errors).
  virtual double min_radius_of_curvature() const = 0;
  // A cheap lower bound on the unsigned distance |x - closest(x).foot| (0: no bound known).
  // Lets callers that only care about points within some reach (ghosts within 2h) skip the
  // full closest-point query of iterative shapes far from the wall.
  virtual double distance_lower_bound(const VecD<D>& /*x*/) const { return 0.0; }
  // True when the signed distance is that of a closed surface: continuous across space, so
  // |d(x) - d(y)| <= |x - y| and an answer at y bounds the answer at x (the fill skips queries
  // with it). False for open walls, whose sign flips beyond their edges.
  virtual bool closed_surface() const { return false; }

  // Moving walls (geometry/moving_wall.hpp). A static wall answers: never moves, velocity 0,
  // and is its own body; set_time does nothing. The solver calls WallSet::set_time at every
  // time at which it evaluates the walls (each stage of the integrator).
  virtual bool moves() const { return false; }
  virtual void set_time(double /*t*/) {}
  // Velocity of the wall point at x (x on the wall) at the time of the last set_time.
  virtual VecD<D> velocity(const VecD<D>& /*x*/) const { return VecD<D>::Zero(); }
  // The wall in its own body frame (the shape as the case file gives it): what a shape-specific
  // consumer (boundary elements, analyses) casts to. A static wall is its own body.
  virtual const Wall<D>& body() const { return *this; }

  // The motion the case file gave (Kind::none for a static wall).
  WallMotion<D> motion;
  // `walls.N.name` (default "wallN", N the entry of the `walls:` list; every wall a CAD entry
  // yields carries its entry's name) and `walls.N.moment_center` (default the origin): the
  // column names of forces.csv, the block names of the walls output, and the point the
  // moments of forces.csv are taken about. Set by parse_walls().
  std::string name;
  VecD<D> moment_center = VecD<D>::Zero();
};

template <int D>
using WallPtr = std::shared_ptr<const Wall<D>>;

// Several walls; the nearest (smallest |distance|) answers, and says which one it was.
template <int D>
class WallSet {
 public:
  void add(WallPtr<D> w) { walls_.push_back(std::move(w)); }
  std::size_t size() const { return walls_.size(); }
  bool empty() const { return walls_.empty(); }
  const Wall<D>& operator[](std::size_t i) const { return *walls_[i]; }
  const std::vector<WallPtr<D>>& walls() const { return walls_; }
  // Whether any wall moves (the solver then calls set_time at every stage).
  bool any_moves() const {
    for (const auto& w : walls_)
      if (w->moves()) return true;
    return false;
  }
  // Places every moving wall at time t. The walls are shared, const-qualified pointers, but
  // each wall was created non-const (make_shared) by its factory: casting the const away to
  // move it is well defined. Not thread-safe against concurrent queries (call between passes).
  void set_time(double t) const {
    for (const auto& w : walls_)
      if (w->moves()) const_cast<Wall<D>&>(*w).set_time(t);
  }

  WallPoint<D> closest(const VecD<D>& x) const {
    WallPoint<D> best;
    best.distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < walls_.size(); ++i) {
      WallPoint<D> p = walls_[i]->closest(x);
      if (std::abs(p.distance) < std::abs(best.distance)) {
        best = p;
        best.wall = static_cast<int>(i);
      }
    }
    return best;
  }

 private:
  std::vector<WallPtr<D>> walls_;
};

template <int D>
VecD<D> WallMotion<D>::displacement(double t) const {
  switch (kind) {
    case Kind::translate:
      return velocity * t;
    case Kind::oscillate:
      return amplitude * std::sin(2.0 * std::numbers::pi * frequency * t + phase);
    default:
      return VecD<D>::Zero();
  }
}

template <int D>
VecD<D> WallMotion<D>::velocity_at(const VecD<D>& x, double t) const {
  switch (kind) {
    case Kind::translate:
      return velocity;
    case Kind::oscillate:  // d/dt of A sin(2 pi F t + phi)
      return amplitude * (2.0 * std::numbers::pi * frequency *
                          std::cos(2.0 * std::numbers::pi * frequency * t + phase));
    case Kind::rotate: {
      if constexpr (D == 2) {
        const VecD<2> r = x - center;
        return VecD<2>(-omega * r.y(), omega * r.x());
      } else {
        return omega * axis.normalized().cross(VecD<3>(x - center));
      }
    }
    case Kind::none:
    default:
      return VecD<D>::Zero();
  }
}

}  // namespace curvsph
