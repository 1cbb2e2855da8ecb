#include "curvsph/boundary/ghost/facet_images.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace curvsph {
namespace {

using Mat2 = Eigen::Matrix2d;

double segment_distance(const Vec2d& y, const WallFacet<2>& f) {
  const Vec2d t = f.b - f.a;
  const double u = std::clamp((y - f.a).dot(t) / t.squaredNorm(), 0.0, 1.0);
  return (y - (f.a + u * t)).norm();
}

Mat2 reflection(const Vec2d& n) {
  return Mat2::Identity() - 2.0 * n * n.transpose();
}

// Two faces meeting at a shared end point v.
struct Corner {
  Vec2d v;
  Vec2d ea, eb;  // unit directions from v along each face
  bool concave;  // interior (fluid) angle < pi
  double theta;  // interior angle
};

bool shared_vertex(const WallFacet<2>& A, const WallFacet<2>& B, double tol, Corner& c) {
  const std::array<Vec2d, 2> pa{A.a, A.b}, pb{B.a, B.b};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      if ((pa[i] - pb[j]).norm() > tol) continue;
      c.v = pa[i];
      c.ea = (pa[1 - i] - pa[i]).normalized();
      c.eb = (pb[1 - j] - pb[j]).normalized();
      c.concave = c.eb.dot(A.normal) > 0;  // B rises into A's fluid side
      const double open = std::acos(std::clamp(c.ea.dot(c.eb), -1.0, 1.0));
      c.theta = c.concave ? open : 2.0 * std::numbers::pi - open;
      return true;
    }
  return false;
}

// The vertex member's factor. Where the solid is acute (alpha < 90 degrees) the particles
// beyond both faces have no share of a face's image (their reflections land in the fluid), and
// the point image gives them one: it takes most of the solid near the vertex there, the faces'
// members the rest. Elsewhere the faces share the solid alone. Chosen by the step and ramp
// tanks of docs/geometry.md (factors 0, 1, 2, 4, 8, 20, 40, 100 measured).
constexpr double kVertexFactor = 40;
double vertex_factor(const Corner& c) {
  return 2.0 * std::numbers::pi - c.theta < 0.5 * std::numbers::pi - 1e-9 ? kVertexFactor : 0.0;
}

// The three members' shares at a point y of the solid wedge of the convex corner c.
struct ConvexShares {
  double a, b, v;
};
ConvexShares convex_shares(const Vec2d& y, const WallFacet<2>& A, const WallFacet<2>& B,
                           const Corner& c, double support) {
  const double fa = convex_share(segment_distance(y, A), support);
  const double fb = convex_share(segment_distance(y, B), support);
  const double fv = vertex_factor(c) * convex_share((y - c.v).norm(), support);
  const double sum = fa + fb + fv;
  if (!(sum > 0)) return {0, 0, 0};
  return {fa / sum, fb / sum, fv / sum};
}

bool same_line(const WallFacet<2>& A, const WallFacet<2>& B, double tol) {
  return A.normal.dot(B.normal) > 1.0 - 1e-12 && std::abs((B.a - A.a).dot(A.normal)) <= tol;
}

}  // namespace

// The convex corners' partition of unity (facet_images.hpp): the raw share of an image at
// distance D from the member's face segment (or from the vertex), q^2 / D^2 with
// q = 1 - D / support, none beyond the support. 1/D^2 makes the shares depend on the angle
// alone close to the vertex and gives the face an image sits on all of it; q^2 takes a
// member's share to 0 where its source leaves the support of the wall.
double convex_share(double D, double support) {
  if (!(D < support)) return 0;
  const double q = 1 - D / support;
  const double Dm = std::max(D, 1e-12 * support);
  return q * q / (Dm * Dm);
}

template <>
int facet_images<2>(const Vec2d& x, const WallFacet<2>* faces, int nfaces, double support,
                    FacetImage<2>* out, int max) {
  constexpr int kMax = 16;
  std::array<int, kMax> keep{};
  int m = 0;
  double scale = 0;
  for (int k = 0; k < nfaces; ++k) scale = std::max(scale, (faces[k].b - faces[k].a).norm());
  const double tol = 1e-9 * scale;
  // Collinear neighbours are one face: one image, no corner.
  for (int k = 0; k < nfaces && m < kMax; ++k) {
    bool dup = false;
    for (int q = 0; q < m; ++q) dup |= same_line(faces[keep[q]], faces[k], tol);
    if (!dup) keep[m++] = k;
  }
  int n = 0;
  auto push = [&](const FacetImage<2>& im) {
    if (n < max) out[n++] = im;
  };

  // Single images, each checked against the corners of its face.
  for (int q = 0; q < m; ++q) {
    const WallFacet<2>& A = faces[keep[q]];
    const double d = (x - A.a).dot(A.normal);
    if (!(d > 0 && d < support)) continue;
    const Vec2d y = x - 2.0 * d * A.normal;
    bool ok = true;
    double weight = 1;
    for (int r = 0; r < m && ok; ++r) {
      if (r == q) continue;
      const WallFacet<2>& B = faces[keep[r]];
      Corner c;
      if (!shared_vertex(A, B, tol, c)) continue;
      if (c.concave) {
        ok = (y - c.v).dot(A.normal) <= (y - c.v).dot(B.normal) + tol;  // A's side of the bisector
        continue;
      }
      // Convex: A's share of the solid wedge at y, none outside it (y in the fluid beyond B).
      if ((y - c.v).dot(B.normal) > tol)
        weight = 0;
      else
        weight *= convex_shares(y, A, B, c, support).a;
    }
    if (!ok) continue;
    if (!(weight > 0)) {
      // No share, but x projects onto A: a guard of no volume (facet_images.hpp).
      const Vec2d t = A.b - A.a;
      const double u = (x - A.a).dot(t) / t.squaredNorm();
      if (!(u >= 0 && u <= 1)) continue;
      weight = 0;
    }
    FacetImage<2> im;
    im.x = y;
    im.M = reflection(A.normal);
    im.foot = x - d * A.normal;
    im.normal = A.normal;
    im.depth = im.source_depth = d;
    im.reflections = 1;
    im.weight = weight;
    push(im);
  }

  // Corners: the vertex image of convex ones, the dihedral orbit of concave pi/n ones.
  for (int q = 0; q < m; ++q)
    for (int r = q + 1; r < m; ++r) {
      const WallFacet<2>& A = faces[keep[q]];
      const WallFacet<2>& B = faces[keep[r]];
      Corner c;
      if (!shared_vertex(A, B, tol, c)) continue;
      const Vec2d rel = x - c.v;
      const double dist = rel.norm();
      if (!c.concave) {
        // The point image: the vertex member's share where it lies in the solid; beyond both
        // faces (the vertex x's closest point) a guard of no volume where it does not.
        const Vec2d y = c.v - rel;
        const bool solid = (y - c.v).dot(A.normal) <= tol && (y - c.v).dot(B.normal) <= tol;
        const bool beyond = rel.dot(c.ea) < 0 && rel.dot(c.eb) < 0;
        const double wv = solid ? convex_shares(y, A, B, c, support).v : 0.0;
        if (dist > 0 && dist < support && (wv > 0 || beyond)) {
          FacetImage<2> im;
          im.x = y;
          im.M = -Mat2::Identity();
          im.foot = c.v;
          im.normal = rel / dist;
          im.depth = im.source_depth = dist;
          im.reflections = 1;
          im.weight = wv;
          push(im);
        }
        continue;
      }
      // A corner image y = c.v + M (x - c.v) of x, kept if within the support of either face.
      const auto corner_image = [&](const Vec2d& y, const Mat2& M, int reflections) {
        if (!(std::min(segment_distance(y, A), segment_distance(y, B)) < support)) return;
        FacetImage<2> im;
        im.x = y;
        im.M = M;
        im.foot = c.v;
        im.normal = A.normal;
        im.depth = im.source_depth = dist;
        im.reflections = reflections;
        push(im);
      };
      const double nd = std::numbers::pi / c.theta;
      const int order = static_cast<int>(std::lround(nd));
      if (order < 2 || order > 6 || std::abs(nd - order) > 1e-6 * order) {
        // Any other angle below 2 pi/3: the words of the two reflections up to length
        // K = ceil(pi/theta - 1/2) on both sides, each image kept on its last face's side of
        // the exterior bisector (flat_corners.hpp): the exterior covered once.
        const int K = std::min(7, static_cast<int>(std::ceil(nd - 0.5 - 1e-9)));
        const std::array<Mat2, 2> R{reflection(A.normal), reflection(B.normal)};
        const std::array<Vec2d, 2> nrm{A.normal, B.normal};
        for (int len = 2; len <= K; ++len)
          for (int start = 0; start < 2; ++start) {
            Mat2 M = Mat2::Identity();
            int last = 0;
            for (int k = 0; k < len; ++k) {
              last = (k + start) % 2;
              M = R[static_cast<std::size_t>(last)] * M;
            }
            const Vec2d y = c.v + M * rel;
            if ((y - c.v).dot(nrm[static_cast<std::size_t>(last)]) >
                (y - c.v).dot(nrm[static_cast<std::size_t>(1 - last)]) + tol)
              continue;
            corner_image(y, M, len % 2 == 0 ? 2 : 3);
          }
        continue;
      }
      // The group generated by the two reflections: rotations by 2 k theta and those composed
      // with A's reflection; the identity and the two singles are already there.
      const Mat2 RA = reflection(A.normal), RB = reflection(B.normal);
      const Mat2 rot = RB * RA;  // rotation by twice the angle between the lines
      Mat2 Rk = Mat2::Identity();
      for (int k = 0; k < order; ++k) {
        for (int refl = 0; refl < 2; ++refl) {
          const Mat2 M = refl ? Mat2(Rk * RA) : Rk;
          if ((M - Mat2::Identity()).norm() < 1e-9 || (M - RA).norm() < 1e-9 ||
              (M - RB).norm() < 1e-9)
            continue;
          const Vec2d y = c.v + M * rel;
          corner_image(y, M, refl ? 3 : 2);
        }
        Rk = rot * Rk;
      }
    }
  return n;
}

template <>
int facet_images<3>(const Vec3d&, const WallFacet<3>*, int, double, FacetImage<3>*, int) {
  return 0;
}

}  // namespace curvsph
