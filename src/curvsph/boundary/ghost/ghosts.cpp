#include "curvsph/boundary/ghost/ghosts.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "curvsph/boundary/ghost/convex_box.hpp"
#include "curvsph/boundary/ghost/convex_edges.hpp"
#include "curvsph/boundary/ghost/facet_images.hpp"
#include "curvsph/boundary/ghost/flat_corners.hpp"
#include "curvsph/boundary/ghost/plane_edges.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/box.hpp"

namespace curvsph {

const char* to_string(GhostVelocity m) {
  return m == GhostVelocity::free_slip ? "free_slip" : "no_slip";
}

GhostVelocity parse_ghost_velocity(const std::string& name, const std::string& file,
                                   const std::string& key) {
  if (name == "no_slip") return GhostVelocity::no_slip;
  if (name == "free_slip") return GhostVelocity::free_slip;
  throw InputError(
      file, key, fmt::format("unknown ghost velocity '{}' (expected no_slip or free_slip)", name));
}

namespace {

template <int D>
VecD<D> ghost_velocity(GhostVelocity mode, const VecD<D>& u, const VecD<D>& uw, const VecD<D>& n,
                       double ratio) {
  if (mode == GhostVelocity::no_slip) return uw - ratio * (u - uw);
  const VecD<D> rel = u - uw;
  return uw + rel - 2.0 * rel.dot(n) * n;
}

template <int D>
struct Generator {
  const WallSet<D>& walls;
  const std::vector<const BoxWall<D>*>& boxes;
  const std::vector<const Faceted<D>*>& faceted_walls;
  const std::vector<const MultiFace<D>*>& multi_walls;
  const GhostOptions<D>& opt;

  // Whether r is a fluid point: outside every wall (the sources of the convex edges' shares,
  // convex_box.hpp, convex_edges.hpp).
  const std::function<bool(const VecD<D>&)> in_fluid = [this](const VecD<D>& r) {
    for (std::size_t w = 0; w < walls.size(); ++w)
      if (!(walls[w].closest(r).distance > 0)) return false;
    return true;
  };

  using Record = typename GhostSet<D>::Record;
  using Corner = typename GhostSet<D>::Corner;

  // The velocity images of one reflection: {the mode's, the free-slip one} (the continuity
  // equation's, ghosts.hpp); the free-slip image is the mode's own for free_slip walls.
  std::pair<VecD<D>, VecD<D>> images(const VecD<D>& u, const VecD<D>& uw, const VecD<D>& n,
                                     double ratio) const {
    const VecD<D> slip = ghost_velocity<D>(GhostVelocity::free_slip, u, uw, n, 1.0);
    if (opt.velocity == GhostVelocity::free_slip) return {slip, slip};
    return {ghost_velocity<D>(opt.velocity, u, uw, n, ratio), slip};
  }

  void emit(std::vector<Record>& out, Index i, std::int32_t wall, const VecD<D>& xg,
            const VecD<D>& ug, const VecD<D>& ug_slip, double beta, double depth, double d,
            const VecD<D>& foot, const VecD<D>& n, std::uint8_t reflections) const {
    Record r;
    r.x = xg.template cast<Real>();
    if (opt.cells) opt.cells->wrap(r.x);
    r.v = ug.template cast<Real>();
    r.v_slip = ug_slip.template cast<Real>();
    r.beta = static_cast<Real>(beta);
    r.source = i;
    r.wall = wall;
    r.depth = depth;
    r.source_depth = d;
    r.foot = foot;
    r.normal = n;
    r.reflections = reflections;
    out.push_back(r);
  }

  // Reflects (x, u) across the flat faces of word w in turn (flat_corners.hpp) and emits the
  // result, with a corner record of the distinct faces in their first order (the wall loads'
  // split).
  void emit_corner(std::vector<Record>& out, std::vector<Corner>& corners, Index i,
                   const VecD<D>& x0, const VecD<D>& u0, const FlatFace<D>* flat,
                   const ReflectionWord& w) const {
    Corner c{static_cast<Index>(out.size()), {-1, -1, -1}, {}, 0};
    for (int r = 0; r < w.length; ++r) {
      const FlatFace<D>& F = flat[w.face[static_cast<std::size_t>(r)]];
      bool seen = false;
      for (int q = 0; q < c.faces; ++q)
        seen |= c.wall[static_cast<std::size_t>(q)] == F.wall &&
                c.normal[static_cast<std::size_t>(q)].dot(F.normal) > 1.0 - 1e-12;
      if (seen || c.faces >= 3) continue;
      c.wall[c.faces] = F.wall;
      c.normal[c.faces] = F.normal;
      ++c.faces;
    }
    corners.push_back(c);
    VecD<D> x = x0, u = u0, u_slip = u0, foot = x0, n = x0;
    double d = 0;
    for (int r = 0; r < w.length; ++r) {
      const FlatFace<D>& F = flat[w.face[static_cast<std::size_t>(r)]];
      n = F.normal;
      d = (x - F.foot).dot(n);
      foot = x - d * n;
      const VecD<D> uw = walls[F.wall].velocity(foot);
      // For free_slip walls u and u_slip are the same sequence.
      u_slip = ghost_velocity<D>(GhostVelocity::free_slip, u_slip, uw, n, 1.0);
      u = opt.velocity == GhostVelocity::free_slip ? u_slip
                                                   : ghost_velocity<D>(opt.velocity, u, uw, n, 1.0);
      x = foot - d * n;
    }
    const std::int32_t last = flat[w.face[static_cast<std::size_t>(w.length - 1)]].wall;
    emit(out, i, last, x, u, u_slip, 1.0, std::abs(d), std::abs(d), foot, n,
         static_cast<std::uint8_t>(w.length));
  }

  static constexpr int kMaxFlat = 12;

  // Single images that hold a share of a convex edge's solid (0 < share < 1: convex_box.hpp,
  // convex_edges.hpp, facet_images.hpp), for their corners with other walls' flat faces.
  struct SharedImage {
    std::int32_t wall;
    VecD<D> x, u, u_slip, normal;
    double weight;
  };
  struct Shared {
    std::array<SharedImage, kMaxFlat> image;
    int n = 0;
    void add(const SharedImage& s) {
      if (n < kMaxFlat) image[static_cast<std::size_t>(n++)] = s;
    }
  };

  // A faceted wall (a polygon): the images of facet_images.hpp, flat faces (kappa = 0, so
  // every map is the mirror, beta = 1 but at convex corners, where beta is the image's share
  // of the solid, 0 for a guard). Its single images join `flat` (group k) for the
  // corners with other walls' flat faces (flat_corners.hpp). False for walls that are not
  // faceted.
  bool faceted(std::vector<Record>& out, Index i, std::int32_t k, const VecD<D>& x,
               const VecD<D>& u, std::array<FlatFace<D>, kMaxFlat>& flat, int& nflat,
               Shared& shared) const {
    constexpr int kMaxFaces = 16, kMaxImages = 32;
    std::array<WallFacet<D>, kMaxFaces> faces;
    if (!faceted_walls[k]) return false;
    const int nf = faceted_walls[k]->facets_near(x, 2.0 * opt.support, faces.data(), kMaxFaces);
    if (nf < 0) return false;
    std::array<FacetImage<D>, kMaxImages> images;
    const int ni = facet_images<D>(x, faces.data(), nf, opt.support, images.data(), kMaxImages);
    emit_images(out, i, k, u, images.data(), ni, flat, nflat, shared);
    return true;
  }

  // A box with the fluid outside: the images of convex_box.hpp (the faces' shares of the solid
  // near its edges and corners, guards), emitted as a faceted wall's.
  void outside_box(std::vector<Record>& out, Index i, std::int32_t k, const BoxWall<D>& box,
                   const VecD<D>& x, const VecD<D>& u, std::array<FlatFace<D>, kMaxFlat>& flat,
                   int& nflat, Shared& shared) const {
    std::array<FacetImage<D>, 2 * D + 1> images;
    const int ni = box_outside_images<D>(x, box.min(), box.max(), opt.support, in_fluid,
                                         images.data(), static_cast<int>(images.size()));
    emit_images(out, i, k, u, images.data(), ni, flat, nflat, shared);
  }

  // Emits the images of x of wall k (facet_images.hpp); the whole single reflections join
  // `flat` (group k) for the corners with other walls' flat faces (flat_corners.hpp).
  void emit_images(std::vector<Record>& out, Index i, std::int32_t k, const VecD<D>& u,
                   const FacetImage<D>* images, int ni, std::array<FlatFace<D>, kMaxFlat>& flat,
                   int& nflat, Shared& shared) const {
    for (int g = 0; g < ni; ++g) {
      const FacetImage<D>& im = images[g];
      const VecD<D> uw = walls[k].motion.velocity_at(im.foot);
      const VecD<D> slip = uw + im.M * (u - uw);
      const VecD<D> ug = opt.velocity == GhostVelocity::free_slip
                             ? slip
                             : VecD<D>(uw + im.M.determinant() * (u - uw));
      const bool single = im.reflections == 1 && (im.M - (Eigen::Matrix<double, D, D>::Identity() -
                                                          2.0 * im.normal * im.normal.transpose()))
                                                         .norm() < 1e-12;
      // Shares of a convex corner's solid and guards stay out of the other walls' corners:
      // flat_corners.hpp's images stand for whole sources.
      if (single && im.weight == 1.0 && nflat < kMaxFlat)
        flat[static_cast<std::size_t>(nflat++)] = {im.foot, im.normal, k, k,
                                                   static_cast<Index>(out.size())};
      if (single && im.weight > 0 && im.weight < 1)
        shared.add({k, im.x, ug, slip, im.normal, im.weight});
      emit(out, i, k, im.x, ug, slip, im.weight, im.depth, im.source_depth, im.foot, im.normal,
           im.reflections);
    }
  }

  // A wall of several faces (a CAD solid, faceted.hpp): one ghost per face onto which x
  // projects (the foot inside the face: x - foot along its normal), with the map and the
  // face's own curvatures; planar faces join `flat` for the perpendicular corners below, and
  // a curved face's ghost is reflected across every planar face perpendicular to it (a pipe's
  // bore meeting its end cap: the double image of that edge). False when x projects onto no
  // face (the region of a convex edge or vertex): the closest point answers there.
  bool multiface(std::vector<Record>& out, Index i, std::int32_t k, const VecD<D>& x,
                 const VecD<D>& u, const WallPoint<D>& c, std::array<FlatFace<D>, kMaxFlat>& flat,
                 int& nflat, Shared& shared, bool& no_root) const {
    if (!multi_walls[k]) return false;
    constexpr int kMaxFaces = 16;
    std::array<WallPoint<D>, kMaxFaces> fp;
    const int nf = multi_walls[k]->face_points_near(x, opt.support, fp.data(), kMaxFaces);
    std::array<int, kMaxFaces> used{};
    int nused = 0;
    for (int f = 0; f < nf; ++f) {
      const WallPoint<D>& p = fp[static_cast<std::size_t>(f)];
      if (!(p.distance > 0 && p.distance < opt.support)) continue;
      if ((x - p.foot - p.distance * p.normal).norm() > 1e-6 * p.distance) continue;
      bool dup = false;  // a tangent junction: two faces, one foot
      for (int q = 0; q < nused; ++q)
        dup |= (fp[static_cast<std::size_t>(used[q])].foot - p.foot).norm() <= 1e-9 * p.distance;
      if (dup) continue;
      used[static_cast<std::size_t>(nused++)] = f;
    }
    if (nused == 0) {
      // Beyond every face near x (a convex edge's or vertex's region): the faces' shares,
      // planar and curved, cover the solid (convex_edges.hpp) and the closest-point image
      // stays as a guard of no volume (the contact layer's, as facet_images.hpp's).
      if (nf == 0) return false;
      const VecD<D> uw = walls[k].motion.velocity_at(c.foot);
      const auto [ug, ug_slip] = images(u, uw, c.normal, 1.0);
      emit(out, i, k, c.foot - c.distance * c.normal, ug, ug_slip, 0.0, c.distance, c.distance,
           c.foot, c.normal, 1);
      return true;
    }
    std::array<int, kMaxFaces> curved{};
    int ncurved = 0;
    const int flat0 = nflat;
    for (int q = 0; q < nused; ++q) {
      const WallPoint<D>& p = fp[static_cast<std::size_t>(used[q])];
      const GhostDepth g = ghost_map(opt.map, p.distance, p.k1, p.k2);
      if (!g.ok) {
        no_root = true;
        continue;
      }
      const VecD<D> uw = walls[k].motion.velocity_at(p.foot);
      const auto [ug, ug_slip] = images(u, uw, p.normal, g.depth / p.distance);
      const bool planar = p.k1 == 0.0 && p.k2 == 0.0;
      // A face's share of the solid at its image (convex_edges.hpp): below 1 near a convex
      // edge where another face has the same image; a planar face's share stays out of the
      // corners, a curved face's multiplies the map's volume factor.
      const double share = edge_share<D>(*multi_walls[k], VecD<D>(p.foot - g.depth * p.normal),
                                         p.normal, g.depth, opt.support, in_fluid);
      if (planar && share > 0 && share < 1)
        shared.add({k, p.foot - g.depth * p.normal, ug, ug_slip, p.normal, share});
      if (planar && share == 1.0 && nflat < kMaxFlat)
        flat[static_cast<std::size_t>(nflat++)] = {p.foot, p.normal, k, -1,
                                                   static_cast<Index>(out.size())};
      emit(out, i, k, p.foot - g.depth * p.normal, ug, ug_slip, share * g.beta, g.depth, p.distance,
           p.foot, p.normal, 1);
      if (p.k1 != 0.0 || p.k2 != 0.0) curved[static_cast<std::size_t>(ncurved++)] = used[q];
    }
    // Curved ghost x' reflected across a perpendicular planar face A: the image of x' behind
    // A, velocities composed (emit_corner's rule).
    for (int c = 0; c < ncurved; ++c) {
      const WallPoint<D>& p = fp[static_cast<std::size_t>(curved[c])];
      const GhostDepth g = ghost_map(opt.map, p.distance, p.k1, p.k2);
      const VecD<D> xg = p.foot - g.depth * p.normal;
      const VecD<D> uw = walls[k].motion.velocity_at(p.foot);
      const auto [ug, ug_slip] = images(u, uw, p.normal, g.depth / p.distance);
      for (int a = flat0; a < nflat; ++a) {
        const FlatFace<D>& A = flat[static_cast<std::size_t>(a)];
        if (std::abs(A.normal.dot(p.normal)) > 1e-6) continue;
        const double da = (xg - A.foot).dot(A.normal);
        const VecD<D> fa = xg - da * A.normal;
        const VecD<D> uwa = walls[k].motion.velocity_at(fa);
        const VecD<D> u2 = images(ug, uwa, A.normal, 1.0).first;
        const VecD<D> u2_slip =
            ghost_velocity<D>(GhostVelocity::free_slip, ug_slip, uwa, A.normal, 1.0);
        emit(out, i, k, fa - da * A.normal, u2, u2_slip, g.beta, da, da, fa, A.normal, 2);
      }
    }
    return true;
  }

  struct CurvedImage {
    std::int32_t wall;
    WallPoint<D> p;
    VecD<D> x, u, u_slip;
    double beta;
  };

  // A curved wall's image reflected across the flat faces of other walls it is mirror-
  // symmetric about (plane_edges.hpp), velocities composed (emit_corner's rule); the corner
  // record splits the reaction between the two walls.
  void plane_edges(std::vector<Record>& out, std::vector<Corner>& corners, Index i,
                   const VecD<D>& x, const CurvedImage& c,
                   const std::array<FlatFace<D>, kMaxFlat>& flat, int nflat) const {
    for (int a = 0; a < nflat; ++a) {
      const FlatFace<D>& A = flat[static_cast<std::size_t>(a)];
      if (A.wall == c.wall) continue;
      const auto im = plane_edge_image<D>(walls[c.wall], x, c.p, c.x, A, opt.support);
      if (!im) continue;
      const VecD<D> uwa = walls[A.wall].velocity(im->foot);
      const VecD<D> u2 = images(c.u, uwa, A.normal, 1.0).first;
      const VecD<D> u2_slip =
          ghost_velocity<D>(GhostVelocity::free_slip, c.u_slip, uwa, A.normal, 1.0);
      corners.push_back({static_cast<Index>(out.size()),
                         {c.wall, A.wall, -1},
                         {c.p.normal, A.normal, VecD<D>::Zero()},
                         2});
      emit(out, i, A.wall, im->x, u2, u2_slip, c.beta, im->depth, im->depth, im->foot, A.normal, 2);
    }
  }

  // A share of a convex edge's solid reflected across the flat faces of other walls
  // perpendicular to its face (a box standing on a floor: below the floor, under the box's
  // vertical edges), with the share: where flat_corners.hpp rotates the whole images of a
  // concave edge, the shares of the convex edge above it turn with them (the sum at the foot
  // of a box's vertical edge was 0.900). Velocities composed (emit_corner's rule).
  void shared_edges(std::vector<Record>& out, std::vector<Corner>& corners, Index i,
                    const SharedImage& s, const std::array<FlatFace<D>, kMaxFlat>& flat,
                    int nflat) const {
    for (int a = 0; a < nflat; ++a) {
      const FlatFace<D>& A = flat[static_cast<std::size_t>(a)];
      if (A.wall == s.wall || std::abs(A.normal.dot(s.normal)) > 1e-6) continue;
      const double da = (s.x - A.foot).dot(A.normal);
      if (!(da > 0 && da < opt.support)) continue;
      const VecD<D> fa = s.x - da * A.normal;
      const VecD<D> uwa = walls[A.wall].velocity(fa);
      const VecD<D> u2 = images(s.u, uwa, A.normal, 1.0).first;
      const VecD<D> u2_slip =
          ghost_velocity<D>(GhostVelocity::free_slip, s.u_slip, uwa, A.normal, 1.0);
      corners.push_back({static_cast<Index>(out.size()),
                         {s.wall, A.wall, -1},
                         {s.normal, A.normal, VecD<D>::Zero()},
                         2});
      emit(out, i, A.wall, fa - da * A.normal, u2, u2_slip, s.weight, da, da, fa, A.normal, 2);
    }
  }

  // Returns {penetrated, no_root}.
  std::pair<bool, bool> particle(Index i, const Vec<D>& xi, const Vec<D>& vi,
                                 std::vector<Record>& out, std::vector<Corner>& corners) const {
    std::array<FlatFace<D>, kMaxFlat> flat;
    int nflat = 0;
    std::array<CurvedImage, kMaxFlat> curved;  // single images across curved walls
    int ncurved = 0;
    Shared shared;
    bool penetrated = false, no_root = false;
    const VecD<D> x = xi.template cast<double>();
    const VecD<D> u = vi.template cast<double>();
    const double support = opt.support;
    const std::int32_t nwalls = static_cast<std::int32_t>(walls.size());

    for (std::int32_t k = 0; k < nwalls; ++k) {
      if (const BoxWall<D>* box = boxes[k]; box && box->side() == FluidSide::outside) {
        const VecD<D> lo = box->min() - VecD<D>::Constant(support);
        const VecD<D> hi = box->max() + VecD<D>::Constant(support);
        if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
        if (!(box->closest(x).distance > 0)) {
          penetrated = true;
          continue;
        }
        outside_box(out, i, k, *box, x, u, flat, nflat, shared);
        continue;
      }
      if (const BoxWall<D>* box = boxes[k]) {
        // Fluid inside a box: face by face.
        const VecD<D>& lo = box->min();
        const VecD<D>& hi = box->max();
        bool out_of_box = false;
        for (int a = 0; a < D; ++a) out_of_box |= !(x[a] > lo[a] && x[a] < hi[a]);
        if (out_of_box) {
          penetrated = true;
          continue;
        }
        for (int a = 0; a < D; ++a) {
          for (int s = 0; s < 2; ++s) {
            const double d = s == 0 ? x[a] - lo[a] : hi[a] - x[a];
            if (!(d < support)) continue;
            VecD<D> foot = x;
            foot[a] = s == 0 ? lo[a] : hi[a];
            const VecD<D> n = VecD<D>::Unit(a) * (s == 0 ? 1.0 : -1.0);
            const VecD<D> uw = box->velocity(foot);
            const auto [ug, ug_slip] = images(u, uw, n, 1.0);
            if (nflat < kMaxFlat) flat[nflat++] = {foot, n, k, -1, static_cast<Index>(out.size())};
            emit(out, i, k, foot - d * n, ug, ug_slip, 1.0, d, d, foot, n, 1);
          }
        }
        continue;
      }
      // Iterative walls (NURBS) first rule out particles far from them with a box bound:
      // no ghost is due beyond the support. Penetration is still caught: a particle moves
      // far less than 2h per step, so it is seen at distance <= 0 the step it crosses.
      if (walls[k].distance_lower_bound(x) >= support) continue;
      const WallPoint<D> p = walls[k].closest(x);
      if (!(p.distance > 0)) {
        penetrated = true;
        continue;
      }
      if (!(p.distance < support)) continue;
      if (faceted(out, i, k, x, u, flat, nflat, shared)) continue;
      if (multiface(out, i, k, x, u, p, flat, nflat, shared, no_root)) continue;
      const GhostDepth g = ghost_map(opt.map, p.distance, p.k1, p.k2);
      if (!g.ok) {
        no_root = true;
        continue;
      }
      const VecD<D> uw = walls[k].velocity(p.foot);
      const auto [ug, ug_slip] = images(u, uw, p.normal, g.depth / p.distance);
      if (p.k1 == 0.0 && p.k2 == 0.0 && nflat < kMaxFlat)
        flat[nflat++] = {p.foot, p.normal, k, -1, static_cast<Index>(out.size())};
      else if (ncurved < kMaxFlat)
        curved[ncurved++] = {k, p, p.foot - g.depth * p.normal, ug, ug_slip, g.beta};
      emit(out, i, k, p.foot - g.depth * p.normal, ug, ug_slip, g.beta, g.depth, p.distance, p.foot,
           p.normal, 1);
    }

    // Edges between flat faces (flat_corners.hpp): the single images that overlap a
    // neighbour's go, then the corner images are appended.
    if (nflat >= 2) {
      thread_local std::vector<ReflectionWord> words;
      thread_local std::vector<char> drop;
      flat_corner_images<D>(x, flat.data(), nflat, support, words, drop);
      for (int a = nflat; a-- > 0;)  // each erase shifts the later images down by one
        if (drop[static_cast<std::size_t>(a)]) {
          const Index g = flat[static_cast<std::size_t>(a)].image;
          out.erase(out.begin() + g);
          for (int b = 0; b < nflat; ++b)
            if (flat[static_cast<std::size_t>(b)].image > g)
              --flat[static_cast<std::size_t>(b)].image;
        }
      for (const ReflectionWord& w : words) emit_corner(out, corners, i, x, u, flat.data(), w);
    }
    for (int c = 0; c < ncurved; ++c) plane_edges(out, corners, i, x, curved[c], flat, nflat);
    for (int c = 0; c < shared.n; ++c) shared_edges(out, corners, i, shared.image[c], flat, nflat);
    return {penetrated, no_root};
  }
};

}  // namespace

template <int D>
void GhostSet<D>::build(const std::vector<Vec<D>>& x_f, const std::vector<Vec<D>>& v_f,
                        const WallSet<D>& walls, const GhostOptions<D>& options) {
  boxes_.resize(walls.size());
  faceted_.resize(walls.size());
  multi_.resize(walls.size());
  for (std::size_t k = 0; k < walls.size(); ++k) {
    multi_[k] = dynamic_cast<const MultiFace<D>*>(&walls[k]);
    faceted_[k] = dynamic_cast<const Faceted<D>*>(&walls[k]);
    const auto* box = dynamic_cast<const BoxWall<D>*>(&walls[k]);
    boxes_[k] = box;
  }
  const int max_threads = omp_get_max_threads();
  if (static_cast<int>(thread_ghosts_.size()) < max_threads) {
    thread_ghosts_.resize(max_threads);
    thread_corners_.resize(max_threads);
    thread_penetrated_.resize(max_threads);
    thread_no_root_.resize(max_threads);
  }
  offsets_.resize(max_threads + 1);
  const Generator<D> gen{walls, boxes_, faceted_, multi_, options};
  const Index n = static_cast<Index>(x_f.size());
  int used_threads = 1;

#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    const int T = omp_get_num_threads();
    // Contiguous blocks in thread order: concatenating the blocks keeps particle order.
    const Index begin = n * t / T, end = n * (t + 1) / T;
    // The buffers are moved out for the loop (capacity kept) and back after it: the vectors'
    // own pointers sit side by side in thread_ghosts_ etc., and a push_back through a
    // reference writes that shared cache line for every ghost, bouncing it between the cores.
    auto buf = std::move(thread_ghosts_[t]);
    auto pen = std::move(thread_penetrated_[t]);
    auto nor = std::move(thread_no_root_[t]);
    auto cor = std::move(thread_corners_[t]);
    cor.clear();
    buf.clear();
    pen.clear();
    nor.clear();
    for (Index i = begin; i < end; ++i) {
      const auto [p, r] = gen.particle(i, x_f[i], v_f[i], buf, cor);
      if (p) pen.push_back(i);
      if (r) nor.push_back(i);
    }
    thread_ghosts_[t] = std::move(buf);
    thread_penetrated_[t] = std::move(pen);
    thread_no_root_[t] = std::move(nor);
    thread_corners_[t] = std::move(cor);
#pragma omp barrier
#pragma omp single
    {
      used_threads = T;
      offsets_[0] = 0;
      for (int k = 0; k < T; ++k) offsets_[k + 1] = offsets_[k] + thread_ghosts_[k].size();
      const std::size_t m = offsets_[T];
      x.resize(m);
      v.resize(m);
      if (options.velocity == GhostVelocity::no_slip)
        v_slip.resize(m);
      else
        v_slip.clear();
      beta.resize(m);
      source.resize(m);
      wall.resize(m);
      depth.resize(m);
      source_depth.resize(m);
      foot.resize(m);
      normal.resize(m);
      reflections.resize(m);
    }
    std::size_t o = offsets_[t];
    for (const Record& r : thread_ghosts_[t]) {
      x[o] = r.x;
      v[o] = r.v;
      if (!v_slip.empty()) v_slip[o] = r.v_slip;
      beta[o] = r.beta;
      source[o] = r.source;
      wall[o] = r.wall;
      depth[o] = r.depth;
      source_depth[o] = r.source_depth;
      foot[o] = r.foot;
      normal[o] = r.normal;
      reflections[o] = r.reflections;
      ++o;
    }
  }
  penetrated.clear();
  no_root.clear();
  corners.clear();
  for (int k = 0; k < used_threads; ++k) {
    for (Corner c : thread_corners_[k]) {
      c.ghost += static_cast<Index>(offsets_[k]);
      corners.push_back(c);
    }
    penetrated.insert(penetrated.end(), thread_penetrated_[k].begin(), thread_penetrated_[k].end());
    no_root.insert(no_root.end(), thread_no_root_[k].begin(), thread_no_root_[k].end());
  }
}

template <int D>
void check_ghost_walls(GhostMapKind map, const WallSet<D>& walls, Real support,
                       const std::vector<Vec<D>>& x_f, const std::string& file) {
  const Index n = static_cast<Index>(x_f.size());
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const Wall<D>& w = walls[k];
    const std::string key = fmt::format("walls.{}", k);
    const double rmin = w.min_radius_of_curvature();
    if (n == 0) {
      // No sample: the convex worst case of the smallest radius of curvature.
      const double kk = rmin < std::numeric_limits<double>::infinity() ? -1.0 / rmin : 0.0;
      check_ghost_support(map, kk, D == 3 ? kk : 0.0, support, rmin, w.describe(), file, key);
      continue;
    }
    // The tightest sample: the one whose largest admissible depth is smallest.
    std::vector<double> dmax(n), concave(n);
    std::vector<std::array<double, 2>> kappa(n);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      const WallPoint<D> p = w.closest(x_f[i].template cast<double>());
      kappa[i] = {p.k1, p.k2};
      dmax[i] = ghost_max_depth(map, p.k1, p.k2);
      // The largest concave curvature among the feet of particles within the support.
      concave[i] = p.distance > 0 && p.distance < support ? std::max(p.k1, p.k2) : 0.0;
    }
    Index worst = 0, tightest = 0;
    for (Index i = 1; i < n; ++i) {
      if (dmax[i] < dmax[worst]) worst = i;
      if (concave[i] > concave[tightest]) tightest = i;
    }
    check_ghost_support(map, kappa[worst][0], kappa[worst][1], support, rmin, w.describe(), file,
                        key);
    check_concave_support(kappa[tightest][0], kappa[tightest][1], support, w.describe(), file, key);
  }
}

template class GhostSet<2>;
template class GhostSet<3>;
template void check_ghost_walls<2>(GhostMapKind, const WallSet<2>&, Real,
                                   const std::vector<Vec<2>>&, const std::string&);
template void check_ghost_walls<3>(GhostMapKind, const WallSet<3>&, Real,
                                   const std::vector<Vec<3>>&, const std::string&);

}  // namespace curvsph
