#pragma once
// Ghost images at the edges where flat faces meet at any angle: faces of different walls (two
// `plane` walls, a plane and a polygon's side, the plane lid that setup.relax holds on a free
// surface), the faces of a box and the planar faces of one CAD solid. The polygon's own corners
// are facet_images.hpp's; this is its construction carried over to edges between flat faces
// in 2-D and 3-D (in 3-D the plane normal to the edge line sees the same 2-D corner).
//
// Two faces A and B within the support of a particle x, both concave towards the fluid (the
// fluid lies on the positive side of both, so it fills the wedge between them), meet along an
// edge with interior angle theta, cos theta = -n_A.n_B. In the plane normal to the edge, put
// the fluid at polar angles (0, theta) from the edge, A along angle 0. The words of the two
// reflections, written in the order applied, map the wedge onto sectors of width theta that
// wind round the exterior (2 pi - theta) from both faces: those ending with B onto
// (k theta, (k + 1) theta) (B, AB, BAB, ... for k = 1, 2, 3, ...), those ending with A onto
// (-k theta, -(k - 1) theta). The exterior bisector (angle pi + theta/2, s_A = s_B, s the
// signed distance to a face's plane) splits the exterior into B's side (s_B <= s_A) and A's
// side (s_A <= s_B), each of angle pi - theta/2: the words ending with a face, of length
// 1 .. K with K = ceil(pi/theta - 1/2), cover that face's side, and each image point is kept
// only on its last face's side. Every exterior direction is then covered exactly once: the
// fluid and its kept images tile the plane around the edge at any angle, so the support of
// every particle near the edge is full (the images are isometries of the wedge).
//  - theta = pi/n (n = 2 .. 6: 90, 60, 45, 36, 30 degrees): K = n and no word crosses the
//    bisector but the two of length n, which are one map (the dihedral group of 2n elements
//    tiles space, "multiple mirroring"): emitted once and whole, the 2n - 3 words AB, BA,
//    ABA, ... beyond the singles. 90 degrees: AB, the double reflection of box corners;
//  - 2 pi/3 < theta < pi: K = 1, the singles alone, each cut at the bisector (as
//    facet_images.hpp does at a polygon's corners);
//  - other theta (2 pi/3 itself: K = 1, no cut): the words up to length K on both sides,
//    those of length K cut at the bisector (100 degrees: A, B, AB, BA; 50 degrees: up to
//    length 4). Below about 24 degrees K would pass the word's 7 reflections: K is capped
//    there and a gap stays round the exterior bisector.
// A face C perpendicular to both A and B adds every image of the pair reflected across C (the
// group is the dihedral one times C's reflection; three mutually perpendicular faces: the
// triple reflection of a box corner), once per triple; C's reflection keeps s_A and s_B, so
// a cut image stays cut, and the double image AC of a single A cut at the edge A-B goes too.
// Three faces meeting at a vertex, none perpendicular to both others (a tetrahedron's vertex,
// a V trough's edge meeting a leaning end wall): no product of groups tiles space there, and
// the pairs' images leave the region behind the vertex short (a sum of 0.66 instead of 1 at
// a regular tetrahedron's vertex). Every point y outside the fluid cone has a canonical word:
// fold y back, reflecting it across the face it lies deepest behind until it is in front of
// all three, and read the reflections backwards. The images of x under every word over the
// three faces (up to 8 letters; the tetrahedron's cone needs 6) are kept only where the word
// is the canonical one of the image, and the pairs' words and singles among these faces that
// are not canonical go: each outside point is then covered once. For two faces the fold is
// the bisector rule above (the side of the exterior bisector says which face is deeper).
// The edge counts only where it is a real edge of the fluid region: some of it lies on the
// fluid side of every other face in the list (two lines that meet behind a third face make no
// corner). Faces of one polygon (same `group`) are skipped: facet_images.hpp
// has their corners.
#include <array>
#include <cstdint>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

// A flat face a particle has a single image across.
template <int D>
struct FlatFace {
  VecD<D> foot, normal;  // a point of the face's plane (x's foot), its unit normal into the fluid
  std::int32_t wall;     // index in the WallSet
  std::int32_t group;    // >= 0: the faces of one polygon (facet_images.hpp's corners); -1 else
  Index image;           // that single image's index in the ghost buffer (-1: none emitted)
};

// A sequence of reflections across faces (indices into the face list), applied in order.
struct ReflectionWord {
  std::array<std::int8_t, 8> face{};
  int length = 0;
};

// The corner images of x from its flat faces f[0..n): the words to emit, in a fixed order
// (pairs a < b ascending, each pair's words by length, then the triples with a third face),
// and in drop[k] whether face k's single image overlaps its neighbour's and must go. Images
// farther than `support` behind the faces of their word are not listed.
template <int D>
void flat_corner_images(const VecD<D>& x, const FlatFace<D>* f, int n, double support,
                        std::vector<ReflectionWord>& words, std::vector<char>& drop);

// The image of x under word w (the faces' reflections applied in order).
template <int D>
VecD<D> reflect_word(const VecD<D>& x, const FlatFace<D>* f, const ReflectionWord& w);

}  // namespace curvsph
