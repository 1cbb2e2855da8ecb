#pragma once
// The ownership tree of the orthogonal recursive bisection (parallel/decomposition.hpp): each
// inner node cuts its region across one axis, each leaf is a rank. Every rank holds the same
// tree, so the owner of a position is the same log2(ranks) descent on every rank — which is
// what lets the midpoint rule (parallel/pair_rule.hpp) decide, without communication, which
// rank computes a pair.
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
struct OrbTree {
  struct Node {
    int axis = 0;
    Real cut = 0;
    int child[2] = {-1, -1};
    int rank = -1;  // leaf: the owning rank
  };
  std::vector<Node> nodes{Node{0, 0, {-1, -1}, 0}};

  // The rank whose box holds x: [lo, cut) goes to the first child, [cut, hi) to the second.
  int owner(const Vec<D>& x) const {
    int k = 0;
    while (nodes[static_cast<std::size_t>(k)].rank < 0) {
      const Node& n = nodes[static_cast<std::size_t>(k)];
      k = n.child[x[n.axis] < n.cut ? 0 : 1];
    }
    return nodes[static_cast<std::size_t>(k)].rank;
  }
};

}  // namespace curvsph
