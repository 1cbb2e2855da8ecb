#pragma once
// Ghost images at the edges where flat faces meet at any angle: faces of different walls (two
// `plane` walls, a plane and a polygon's side, the plane lid that setup.relax holds on a free
// surface), the faces of a box and the planar faces of one CAD solid. The polygon's own corners
// are facet_images.hpp's; this is its construction carried over to edges between flat faces
// in 2-D and 3-D (in 3-D the plane normal to the edge line sees the same 2-D corner).
//
// Two faces A and B within the support of a particle x, both concave towards the fluid (the
// fluid lies on the positive side of both, so it fills the wedge between them), meet along an
// edge with interior angle theta, cos theta = -n_A.n_B:
//  - theta = pi/n (n = 2 .. 6: 90, 60, 45, 36, 30 degrees): the dihedral group of the two
//    reflections tiles space with 2n images of the wedge ("multiple mirroring"); the 2n - 3
//    beyond x and its two single images are the alternating words AB, BA, ABA, ... of length 2
//    to n (the two words of length n are the same map: one of them). 90 degrees: AB, the
//    double reflection of box corners;
//  - 2 pi/3 < theta < pi: the single images overlap around the exterior bisector; each is kept
//    only on its own face's side of it (s_A(y) <= s_B(y), s the signed distance to a face's
//    plane), as facet_images.hpp does at a polygon's corners;
//  - other theta: the single images alone (theta = 2 pi/3 they tile; below it a gap of
//    2 pi - 3 theta stays empty).
// A face C perpendicular to both A and B adds every image of the pair reflected across C (the
// group is the dihedral one times C's reflection; three mutually perpendicular faces: the
// triple reflection of a box corner), once per triple.
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
