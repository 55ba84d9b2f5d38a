// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_BOX_HIERARCHY_H
#define CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_BOX_HIERARCHY_H

// A bounding-box hierarchy over the flat triangles of the patch network, for eq. 5.31's "nearest
// triangle" of every new front node. A linear scan costs O(triangles) per node, O(n^3) for a
// hole of n border edges (n^2 new nodes over n triangles); the hierarchy answers in about
// O(log n). The distance is the caller's own (not CGAL's exact closest point: the network's
// `projected_distance` clamps barycentric coordinates), and among equal distances the lowest
// index wins, so the answer is the one of the linear scan it replaces, bit for bit. CGAL's
// AABB_tree would need Triangle_3 primitives and its undocumented traversal traits for that.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace shape_prediction {

class Box_hierarchy {
 public:
  using Box = std::array<double, 6>;  ///< lo x, y, z, hi x, y, z

  Box_hierarchy() = default;  ///< empty: `nearest` returns `size()`

  /// Builds the hierarchy over `boxes` (one per item). Every box is widened by a billionth of
  /// the whole extent, so that a distance the caller computes with rounding errors (a point of
  /// the triangle that rounds just outside its box) is never pruned.
  explicit Box_hierarchy(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
    if (boxes_.empty()) return;
    Box all = boxes_.front();
    for (const Box& b : boxes_) all = merged(all, b);
    double extent = 0;
    for (int d = 0; d < 3; ++d) extent = std::max(extent, all[d + 3] - all[d]);
    const double margin = 1e-9 * extent;
    for (Box& b : boxes_)
      for (int d = 0; d < 3; ++d) b[d] -= margin, b[d + 3] += margin;
    order_.resize(boxes_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
    nodes_.reserve(2 * boxes_.size() / leaf_size + 2);
    build(0, order_.size());
  }

  /// The item nearest to `p` for `distance(item)` (a squared distance that is never below the
  /// squared distance from p to the item's box), the lowest index among equal distances;
  /// `best_distance` receives its distance. Items whose distance is not finite are never
  /// returned; returns `size()` when no item has a finite distance.
  template <class Distance>
  std::size_t nearest(const double* p, const Distance& distance, double& best_distance) const {
    std::size_t best = boxes_.size();
    best_distance = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best;
    std::size_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (squared_distance_to_box(p, node.box) > best_distance) continue;
      if (node.leaf) {
        for (std::size_t k = node.first; k < node.last; ++k) {
          const std::size_t item = order_[k];
          const double d = distance(item);
          if (d < best_distance || (d == best_distance && item < best)) {
            best_distance = d;
            best = item;
          }
        }
        continue;
      }
      // The nearer child on top of the stack: it is searched first and prunes the other.
      const std::size_t near = node.first, far = node.last;
      const bool swap = squared_distance_to_box(p, nodes_[near].box) >
                        squared_distance_to_box(p, nodes_[far].box);
      stack[top++] = swap ? near : far;
      stack[top++] = swap ? far : near;
    }
    return best;
  }

  std::size_t size() const { return boxes_.size(); }

 private:
  static constexpr std::size_t leaf_size = 4;
  struct Node {
    Box box;
    bool leaf;
    std::size_t first, last;  // leaf: range of order_; inner: the two children
  };

  static Box merged(const Box& a, const Box& b) {
    return {std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2]),
            std::max(a[3], b[3]), std::max(a[4], b[4]), std::max(a[5], b[5])};
  }

  static double squared_distance_to_box(const double* p, const Box& b) {
    double d = 0;
    for (int k = 0; k < 3; ++k) {
      const double below = b[k] - p[k], above = p[k] - b[k + 3];
      if (below > 0) d += below * below;
      if (above > 0) d += above * above;
    }
    return d;
  }

  // Median split of order_[first, last) along the longest axis of the box centres. The depth
  // is about log2(n / leaf_size), far below the query stack's 64 entries.
  std::size_t build(std::size_t first, std::size_t last) {
    const std::size_t index = nodes_.size();
    nodes_.push_back(Node{boxes_[order_[first]], true, first, last});
    for (std::size_t k = first; k < last; ++k)
      nodes_[index].box = merged(nodes_[index].box, boxes_[order_[k]]);
    if (last - first <= leaf_size) return index;
    Box centres{std::numeric_limits<double>::infinity(),  std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity(),  -std::numeric_limits<double>::infinity(),
                -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (std::size_t k = first; k < last; ++k) {
      for (int d = 0; d < 3; ++d) {
        const double c = centre(order_[k], d);
        centres[d] = std::min(centres[d], c);
        centres[d + 3] = std::max(centres[d + 3], c);
      }
    }
    int axis = 0;
    for (int d = 1; d < 3; ++d)
      if (centres[d + 3] - centres[d] > centres[axis + 3] - centres[axis]) axis = d;
    const std::size_t middle = first + (last - first) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + middle, order_.begin() + last,
                     [&](std::size_t a, std::size_t b) {
                       return centre(a, axis) < centre(b, axis) ||
                              (centre(a, axis) == centre(b, axis) && a < b);
                     });
    const std::size_t left = build(first, middle);
    const std::size_t right = build(middle, last);
    nodes_[index].leaf = false;
    nodes_[index].first = left;
    nodes_[index].last = right;
    return index;
  }

  double centre(std::size_t item, int axis) const {
    return 0.5 * (boxes_[item][axis] + boxes_[item][axis + 3]);
  }

  std::vector<Box> boxes_;
  std::vector<std::size_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace shape_prediction
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_BOX_HIERARCHY_H
