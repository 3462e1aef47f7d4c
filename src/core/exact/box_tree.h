// A bounding-box tree over a solid's faces or edges: which boxes lie within a distance of a point,
// without scanning them all (a plate with 248 holes: 3,700 edges and 1,000 faces per radius).
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <vector>

#include "../types.h"

namespace cadmedial {

using Box = std::array<double, 6>;  ///< min x y z, max x y z; empty when min x > max x

/// Squared distance from p to the box (0 inside); infinite for an empty box.
inline double sq_distance(const Box& b, const Point3& p) {
  if (b[0] > b[3]) return std::numeric_limits<double>::infinity();
  double s = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max({b[k] - p[k], 0.0, p[k] - b[k + 3]});
    s += d * d;
  }
  return s;
}

class BoxTree {
 public:
  BoxTree() = default;
  explicit BoxTree(const std::vector<Box>& boxes) : boxes_(boxes) {
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0);
    // Empty boxes are never near anything: left out.
    order_.erase(std::remove_if(order_.begin(), order_.end(), [&](int i) { return boxes[i][0] > boxes[i][3]; }),
                 order_.end());
    if (!order_.empty()) build(0, order_.size());
  }

  /// The indices of the boxes closer to p than sqrt(d2) (squared distance below d2), ascending.
  void near(const Point3& p, double d2, std::vector<int>& out) const {
    out.clear();
    if (nodes_.empty()) return;
    int stack[128];  // a balanced tree: depth at most log2 of the boxes' count, plus one
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!(sq_distance(n.box, p) < d2)) continue;
      if (n.left < 0) {
        for (std::size_t k = n.begin; k < n.end; ++k)
          if (sq_distance(boxes_[order_[k]], p) < d2) out.push_back(order_[k]);
      } else {
        stack[top++] = n.left;
        stack[top++] = n.right;
      }
    }
    std::sort(out.begin(), out.end());
  }

 private:
  struct Node {
    Box box;
    std::size_t begin = 0, end = 0;
    int left = -1, right = -1;  // children; -1 for a leaf
  };

  // Median split on the longest side of the boxes' centres, down to 4 boxes a leaf (depth about
  // log2(n / 4)).
  int build(std::size_t begin, std::size_t end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Box b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    Box c = b;  // the centres' box
    for (std::size_t k = begin; k < end; ++k) {
      const Box& x = boxes_[order_[k]];
      for (int a = 0; a < 3; ++a) {
        b[a] = std::min(b[a], x[a]);
        b[a + 3] = std::max(b[a + 3], x[a + 3]);
        const double m = 0.5 * (x[a] + x[a + 3]);
        c[a] = std::min(c[a], m);
        c[a + 3] = std::max(c[a + 3], m);
      }
    }
    nodes_[id].box = b;
    nodes_[id].begin = begin;
    nodes_[id].end = end;
    if (end - begin <= 4) return id;
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (c[a + 3] - c[a] > c[axis + 3] - c[axis]) axis = a;
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](int i, int j) {
      return boxes_[i][axis] + boxes_[i][axis + 3] < boxes_[j][axis] + boxes_[j][axis + 3];
    });
    const int left = build(begin, mid);
    const int right = build(mid, end);
    nodes_[id].left = left;
    nodes_[id].right = right;
    return id;
  }

  std::vector<Box> boxes_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace cadmedial
