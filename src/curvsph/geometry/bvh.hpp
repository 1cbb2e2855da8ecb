#pragma once
// Bounding-volume hierarchy of axis-aligned boxes for nearest-object queries: NURBS Bezier
// segments/patches (the closest-point certificate) and mesh triangles. Built once by median
// splits; queries walk it with a fixed-size stack, near child first, so they never allocate.
#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
struct Aabb {
  VecD<D> lo = VecD<D>::Constant(std::numeric_limits<double>::infinity());
  VecD<D> hi = VecD<D>::Constant(-std::numeric_limits<double>::infinity());
  void extend(const VecD<D>& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void extend(const Aabb& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  // Euclidean distance from x to the box (0 inside): a lower bound for anything inside.
  double distance(const VecD<D>& x) const {
    const VecD<D> d = (lo - x).cwiseMax(x - hi).cwiseMax(0.0);
    return d.norm();
  }
  double diagonal() const { return (hi - lo).norm(); }
};

template <int D>
class Bvh {
 public:
  void build(const std::vector<Aabb<D>>& boxes, int leaf_size = 2) {
    items_.resize(boxes.size());
    std::iota(items_.begin(), items_.end(), 0);
    nodes_.clear();
    if (!boxes.empty()) build_node(boxes, 0, static_cast<int>(boxes.size()), leaf_size);
  }

  // Calls leaf(item) for every item whose box is nearer to x than threshold(), which is
  // re-read after each leaf so the caller can tighten it (branch and bound).
  template <class Threshold, class Leaf>
  void visit(const VecD<D>& x, Threshold&& threshold, Leaf&& leaf) const {
    if (nodes_.empty()) return;
    int stack[96];
    double stack_d[96];
    int top = 0;
    stack[top] = 0;
    stack_d[top++] = nodes_[0].box.distance(x);
    while (top > 0) {
      --top;
      const int ni = stack[top];
      if (stack_d[top] >= threshold()) continue;
      const Node& n = nodes_[ni];
      if (n.count > 0) {
        for (int k = 0; k < n.count; ++k) leaf(items_[n.first + k]);
        continue;
      }
      const double dl = nodes_[n.left].box.distance(x);
      const double dr = nodes_[n.right].box.distance(x);
      // Push the far child first so the near one is popped next.
      if (dl <= dr) {
        stack[top] = n.right, stack_d[top++] = dr;
        stack[top] = n.left, stack_d[top++] = dl;
      } else {
        stack[top] = n.left, stack_d[top++] = dl;
        stack[top] = n.right, stack_d[top++] = dr;
      }
    }
  }

  bool empty() const { return nodes_.empty(); }

 private:
  struct Node {
    Aabb<D> box;
    int left = -1, right = -1;
    int first = 0, count = 0;  // leaf when count > 0
  };

  int build_node(const std::vector<Aabb<D>>& boxes, int first, int last, int leaf_size) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Aabb<D> box, centers;
    for (int i = first; i < last; ++i) {
      box.extend(boxes[items_[i]]);
      centers.extend(VecD<D>(0.5 * (boxes[items_[i]].lo + boxes[items_[i]].hi)));
    }
    nodes_[id].box = box;
    if (last - first <= leaf_size) {
      nodes_[id].first = first;
      nodes_[id].count = last - first;
      return id;
    }
    int axis = 0;
    (centers.hi - centers.lo).maxCoeff(&axis);
    const int mid = (first + last) / 2;
    std::nth_element(
        items_.begin() + first, items_.begin() + mid, items_.begin() + last, [&](int a, int b) {
          return boxes[a].lo[axis] + boxes[a].hi[axis] < boxes[b].lo[axis] + boxes[b].hi[axis];
        });
    const int l = build_node(boxes, first, mid, leaf_size);
    const int r = build_node(boxes, mid, last, leaf_size);
    nodes_[id].left = l;
    nodes_[id].right = r;
    return id;
  }

  std::vector<Node> nodes_;
  std::vector<int> items_;
};

}  // namespace curvsph
