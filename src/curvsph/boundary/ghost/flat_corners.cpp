#include "curvsph/boundary/ghost/flat_corners.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>

namespace curvsph {
namespace {

template <int D>
double signed_distance(const VecD<D>& y, const FlatFace<D>& f) {
  return (y - f.foot).dot(f.normal);
}

template <int D>
bool perpendicular(const FlatFace<D>& a, const FlatFace<D>& b) {
  return std::abs(a.normal.dot(b.normal)) < 1e-9;
}

// The point of the edge line of faces a and b nearest x: x - alpha n_a - beta n_b on both
// planes, [1 c; c 1] (alpha, beta) = (s_a, s_b) with c = n_a.n_b.
template <int D>
VecD<D> edge_point(const VecD<D>& x, const FlatFace<D>& a, const FlatFace<D>& b) {
  const double c = a.normal.dot(b.normal);
  const double sa = signed_distance<D>(x, a), sb = signed_distance<D>(x, b);
  const double det = 1.0 - c * c;
  const double alpha = (sa - c * sb) / det, beta = (sb - c * sa) / det;
  return x - alpha * a.normal - beta * b.normal;
}

// Whether the edge of faces a and b is a real edge of the fluid: some of it lies on the fluid
// side of every other face. 2-D: the edge is the point where the lines meet; 3-D: the line
// e0 + tau t (t = n_a x n_b), clipped by each other face k to s_k(e0) + tau t.n_k >= 0, must
// keep a piece (a wedge's edge ending at a third face perpendicular to it still counts for
// the particles beyond that end: their double image across the wedge's faces is needed too).
template <int D>
bool real_edge(const VecD<D>& x, const FlatFace<D>* f, int n, int a, int b, double tol) {
  const VecD<D> e = edge_point<D>(x, f[a], f[b]);
  if constexpr (D == 2) {
    for (int k = 0; k < n; ++k)
      if (k != a && k != b && signed_distance<D>(e, f[k]) < -tol) return false;
    return true;
  } else {
    const Vec3d t = f[a].normal.cross(f[b].normal).normalized();
    double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k < n; ++k) {
      if (k == a || k == b) continue;
      const double s = signed_distance<D>(e, f[k]), c = t.dot(f[k].normal);
      if (std::abs(c) < 1e-12) {
        if (s < -tol) return false;
      } else if (c > 0) {
        lo = std::max(lo, -(s + tol) / c);
      } else {
        hi = std::min(hi, -(s + tol) / c);
      }
    }
    return lo <= hi;
  }
}

constexpr int kMaxWordLength = static_cast<int>(std::tuple_size_v<decltype(ReflectionWord::face)>);

// Deepest point of y behind the faces of word w: a lower bound of its distance to the fluid.
template <int D>
double behind(const VecD<D>& y, const FlatFace<D>* f, const ReflectionWord& w) {
  double d = 0;
  for (int k = 0; k < w.length; ++k) d = std::max(d, -signed_distance<D>(y, f[w.face[k]]));
  return d;
}

// Whether w is the canonical word of its image y = w(x) among the faces t[0..3): folding y back
// (reflecting it across the face it lies deepest behind, until it is in front of all three)
// undoes w letter by letter. Every point outside the cone of the three faces has one such
// word, so the images kept by this test cover the outside once (flat_corners.hpp).
template <int D>
bool canonical(const VecD<D>& y, const FlatFace<D>* f, const std::array<int, 3>& t,
               const ReflectionWord& w, double tol) {
  VecD<D> z = y;
  for (int step = 0;; ++step) {
    int deepest = -1;
    double s_min = -tol;
    for (const int q : t) {
      const double s = signed_distance<D>(z, f[q]);
      if (s < s_min) {
        s_min = s;
        deepest = q;
      }
    }
    if (deepest < 0) return step == w.length;
    if (step >= w.length || w.face[static_cast<std::size_t>(w.length - 1 - step)] != deepest)
      return false;
    z -= 2.0 * s_min * f[deepest].normal;
  }
}

// Corners of three faces a, b, c none of which is perpendicular to both others (a box corner,
// or a wedge's edge meeting an end wall at right angles, is the product construction above):
// the images of every word over the three (no letter twice in a row, up to kMaxWordLength
// letters), each kept only when canonical; the pairs' words and singles of these faces that
// are not canonical go. 3-D only (three lines of a plane have no common point).
template <int D>
void trihedral_corners(const VecD<D>& x, const FlatFace<D>* f, int n, double support,
                       std::vector<ReflectionWord>& words, std::vector<char>& drop) {
  if constexpr (D == 3) {
    const double tol = 1e-9 * support;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        for (int c = b + 1; c < n; ++c) {
          const std::array<int, 3> t{a, b, c};
          bool skip = false;
          for (int q = 0; q < 3 && !skip; ++q) {
            const FlatFace<D>& P = f[t[static_cast<std::size_t>(q)]];
            const FlatFace<D>& Q = f[t[static_cast<std::size_t>((q + 1) % 3)]];
            const FlatFace<D>& R = f[t[static_cast<std::size_t>((q + 2) % 3)]];
            skip = (P.group >= 0 && P.group == Q.group) ||
                   std::abs(P.normal.dot(Q.normal)) > 1.0 - 1e-12 ||
                   (perpendicular<D>(P, Q) && perpendicular<D>(P, R));
          }
          if (skip) continue;
          // The vertex: the three planes' common point, a real corner of the fluid (on the
          // fluid side of every other face) and within reach (images keep |y - v| = |x - v|).
          Eigen::Matrix3d N;
          Eigen::Vector3d rhs;
          for (int q = 0; q < 3; ++q) {
            const FlatFace<D>& F = f[t[static_cast<std::size_t>(q)]];
            N.row(q) = F.normal.transpose();
            rhs[q] = F.normal.dot(F.foot);
          }
          if (std::abs(N.determinant()) < 1e-6) continue;
          const Vec3d v = N.partialPivLu().solve(rhs);
          if ((x - v).norm() > 2.0 * support) continue;
          bool real = true;
          for (int k = 0; k < n && real; ++k)
            if (k != a && k != b && k != c) real = signed_distance<D>(v, f[k]) >= -tol;
          if (!real) continue;
          const auto within = [&](const ReflectionWord& w) {
            for (int k = 0; k < w.length; ++k)
              if (w.face[static_cast<std::size_t>(k)] != a &&
                  w.face[static_cast<std::size_t>(k)] != b &&
                  w.face[static_cast<std::size_t>(k)] != c)
                return false;
            return true;
          };
          // The pairs' words among these faces are replaced by the canonical ones.
          words.erase(std::remove_if(words.begin(), words.end(), within), words.end());
          for (const int q : t) {
            ReflectionWord w;
            w.length = 1;
            w.face[0] = static_cast<std::int8_t>(q);
            if (!canonical<D>(reflect_word<D>(x, f, w), f, t, w, tol))
              drop[static_cast<std::size_t>(q)] = 1;
          }
          // Words of length 2 .. kMaxWordLength, depth first in lexicographic order. The fold
          // of a canonical word's image passes through its prefix's image (its first step
          // undoes the last letter), so the prefix is canonical too: a word that is not
          // canonical is not extended.
          std::array<int, kMaxWordLength> letter{};
          ReflectionWord w;
          w.length = 1;
          letter[0] = 0;
          while (w.length > 0) {
            const std::size_t top = static_cast<std::size_t>(w.length - 1);
            if (letter[top] >= 3) {  // exhausted: back up
              --w.length;
              if (w.length > 0) ++letter[static_cast<std::size_t>(w.length - 1)];
              continue;
            }
            if (top > 0 && letter[top] == letter[top - 1]) {
              ++letter[top];
              continue;
            }
            w.face[top] = static_cast<std::int8_t>(t[static_cast<std::size_t>(letter[top])]);
            const VecD<D> y = reflect_word<D>(x, f, w);
            const bool ok = canonical<D>(y, f, t, w, tol);
            if (ok && w.length >= 2 && behind<D>(y, f, w) < support) words.push_back(w);
            if (ok && w.length < kMaxWordLength) {
              letter[static_cast<std::size_t>(w.length)] = 0;
              ++w.length;
            } else {
              ++letter[top];
            }
          }
        }
  }
}

}  // namespace

template <int D>
VecD<D> reflect_word(const VecD<D>& x, const FlatFace<D>* f, const ReflectionWord& w) {
  VecD<D> y = x;
  for (int k = 0; k < w.length; ++k) {
    const FlatFace<D>& F = f[w.face[k]];
    y -= 2.0 * signed_distance<D>(y, F) * F.normal;
  }
  return y;
}

template <int D>
void flat_corner_images(const VecD<D>& x, const FlatFace<D>* f, int n, double support,
                        std::vector<ReflectionWord>& words, std::vector<char>& drop) {
  words.clear();
  drop.assign(static_cast<std::size_t>(n), 0);
  const double tol = 1e-9 * support;
  // clip >= 0: the word's image is kept only on its last face's side of the exterior
  // bisector of the edge of faces (last, other), s_last(y) <= s_other(y) (flat_corners.hpp).
  const auto keep = [&](const ReflectionWord& w, int other) {
    const VecD<D> y = reflect_word<D>(x, f, w);
    if (other >= 0) {
      const FlatFace<D>& L = f[w.face[static_cast<std::size_t>(w.length - 1)]];
      if (signed_distance<D>(y, L) > signed_distance<D>(y, f[other]) + tol) return;
    }
    if (behind<D>(y, f, w) < support) words.push_back(w);
  };
  // Faces whose single image went at an edge with a face: (face, that face).
  std::array<std::pair<int, int>, 16> dropped{};
  int ndropped = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      const FlatFace<D>& A = f[a];
      const FlatFace<D>& B = f[b];
      if (A.group >= 0 && A.group == B.group) continue;  // a polygon's own corner
      const double c = A.normal.dot(B.normal);
      if (std::abs(c) > 1.0 - 1e-12) continue;  // parallel: no edge
      if (!real_edge<D>(x, f, n, a, b, tol)) continue;
      const double theta = std::acos(std::clamp(-c, -1.0, 1.0));
      if (theta > 2.0 * std::numbers::pi / 3.0 + 1e-9) {
        // Overlapping singles: each kept on its own side of the exterior bisector.
        const VecD<D> ya = x - 2.0 * signed_distance<D>(x, A) * A.normal;
        const VecD<D> yb = x - 2.0 * signed_distance<D>(x, B) * B.normal;
        if (signed_distance<D>(ya, A) > signed_distance<D>(ya, B) + tol) {
          drop[a] = 1;
          if (ndropped < 16) dropped[static_cast<std::size_t>(ndropped++)] = {a, b};
        }
        if (signed_distance<D>(yb, B) > signed_distance<D>(yb, A) + tol) {
          drop[b] = 1;
          if (ndropped < 16) dropped[static_cast<std::size_t>(ndropped++)] = {b, a};
        }
        continue;
      }
      // Words up to length `order` on each side: pi/n tiles (the two longest words are one
      // map, emitted once and whole); any other angle clips the words at the bisector.
      const double nd = std::numbers::pi / theta;
      const int nearest = static_cast<int>(std::lround(nd));
      const bool tiles = nearest >= 2 && nearest <= 6 && std::abs(nd - nearest) <= 1e-6 * nearest;
      const int order =
          tiles ? nearest
                : std::min(kMaxWordLength - 1, static_cast<int>(std::ceil(nd - 0.5 - 1e-9)));
      const std::size_t pair_begin = words.size();
      for (int len = 2; len <= order; ++len)
        for (int start = 0; start < (len < order || !tiles ? 2 : 1); ++start) {
          ReflectionWord w;
          w.length = len;
          for (int k = 0; k < len; ++k)
            w.face[static_cast<std::size_t>(k)] =
                static_cast<std::int8_t>(((k + start) % 2 == 0) ? a : b);
          keep(w, tiles ? -1 : (w.face[static_cast<std::size_t>(len - 1)] == a ? b : a));
        }
      const std::size_t pair_end = words.size();
      if constexpr (D == 3) {
        // A third face perpendicular to both: each image of the pair reflected across it
        // (a perpendicular pair takes only c > b, so that a box corner's triple comes once).
        // Reflecting across it leaves s_a and s_b as they were: the clip carries over.
        for (int k = tiles && order == 2 ? b + 1 : 0; k < n; ++k) {
          if (k == a || k == b || !perpendicular<D>(f[k], A) || !perpendicular<D>(f[k], B))
            continue;
          for (std::size_t q = pair_begin; q < pair_end; ++q) {
            ReflectionWord w = words[q];
            if (w.length >= kMaxWordLength) continue;
            w.face[static_cast<std::size_t>(w.length++)] = static_cast<std::int8_t>(k);
            keep(w, -1);
          }
        }
      }
    }
  // A single dropped at an edge (a, b) takes its image across a face k perpendicular to both
  // with it: the double word {a, k} of that perpendicular pair (the edge a-b meeting a floor k
  // at right angles: the floor's reflection of the clipped single is clipped alike).
  if (ndropped > 0)
    words.erase(std::remove_if(words.begin(), words.end(),
                               [&](const ReflectionWord& w) {
                                 if (w.length != 2) return false;
                                 for (int q = 0; q < ndropped; ++q) {
                                   const auto [p, other] = dropped[static_cast<std::size_t>(q)];
                                   for (int e = 0; e < 2; ++e) {
                                     const int k = w.face[static_cast<std::size_t>(1 - e)];
                                     if (w.face[static_cast<std::size_t>(e)] == p && k != other &&
                                         perpendicular<D>(f[k], f[p]) &&
                                         perpendicular<D>(f[k], f[other]))
                                       return true;
                                   }
                                 }
                                 return false;
                               }),
                words.end());
  trihedral_corners<D>(x, f, n, support, words, drop);
}

template void flat_corner_images<2>(const Vec2d&, const FlatFace<2>*, int, double,
                                    std::vector<ReflectionWord>&, std::vector<char>&);
template void flat_corner_images<3>(const Vec3d&, const FlatFace<3>*, int, double,
                                    std::vector<ReflectionWord>&, std::vector<char>&);
template Vec2d reflect_word<2>(const Vec2d&, const FlatFace<2>*, const ReflectionWord&);
template Vec3d reflect_word<3>(const Vec3d&, const FlatFace<3>*, const ReflectionWord&);

}  // namespace curvsph
