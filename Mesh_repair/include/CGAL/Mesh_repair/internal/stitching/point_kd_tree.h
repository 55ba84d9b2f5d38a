// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_STITCHING_POINT_KD_TREE_H
#define CGAL_MESH_REPAIR_INTERNAL_STITCHING_POINT_KD_TREE_H

// A static kd-tree over 3D points for the fixed-radius searches of the node pairing (thesis 4.2).
//
// CGAL's `Kd_tree` with a `Search_traits_adapter` reaches the points through a property map and
// each `Fuzzy_sphere` query writes into an output iterator; on a million border nodes that cost
// more than the rest of the pairing. This tree keeps copies of the points next to their ids in one
// array, reordered in place by median splits along the widest extent (`std::nth_element`), so a
// subtree is a contiguous slice: linear memory, O(n log n) construction, no allocation per query.

#include <CGAL/Mesh_repair/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

class Point_kd_tree {
 public:
  using Point = Vec3;
  struct Item {
    Point point;
    std::size_t id;
  };

  explicit Point_kd_tree(const std::vector<Point>& points) : items_(points.size()) {
    for (std::size_t i = 0; i < points.size(); ++i) items_[i] = Item{points[i], i};
    if (!items_.empty()) build(0, items_.size());
  }

  /// The points in tree order (neighbouring items are close in space).
  const std::vector<Item>& items() const { return items_; }

  /// Calls `f(id, squared_distance)` for every point within distance `radius` of `q`
  /// (squared distance <= radius^2, boundary included).
  template <class F>
  void for_each_within(const Point& q, double radius, F&& f) const {
    if (items_.empty() || !(radius >= 0)) return;
    const double r2 = radius * radius;
    std::size_t stack[128];
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (node.dim < 0) {
        for (std::size_t k = node.begin; k < node.end; ++k) {
          const Point& p = items_[k].point;
          const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
          const double d2 = dx * dx + dy * dy + dz * dz;
          if (d2 <= r2) f(items_[k].id, d2);
        }
        continue;
      }
      const double offset = q[node.dim] - node.split;
      // Left points have coordinate <= split, right points >= split.
      if (offset - radius <= 0) stack[top++] = node.left;
      if (offset + radius >= 0) stack[top++] = node.left + 1;
    }
  }

 private:
  static constexpr std::size_t leaf_size = 16;
  struct Node {
    std::size_t begin, end;
    std::size_t left;  // children at left and left + 1
    int dim;           // -1: leaf
    double split;
  };

  void build(std::size_t begin, std::size_t end) {
    // Breadth-first: nodes_ grows as children are appended. Each node splits its cell (the
    // points' bounding box cut by the splits above it) along the widest side.
    Point lo = items_[begin].point, hi = lo;
    for (std::size_t i = begin; i < end; ++i)
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], items_[i].point[d]);
        hi[d] = std::max(hi[d], items_[i].point[d]);
      }
    nodes_.reserve(4 * (items_.size() / leaf_size + 1));
    std::vector<std::array<Point, 2>> cells;
    nodes_.push_back(Node{begin, end, 0, -1, 0});
    cells.push_back({lo, hi});
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      const std::size_t b = nodes_[k].begin, e = nodes_[k].end;
      if (e - b <= leaf_size) continue;
      const std::array<Point, 2> cell = cells[k];
      int dim = 0;
      for (int d = 1; d < 3; ++d)
        if (cell[1][d] - cell[0][d] > cell[1][dim] - cell[0][dim]) dim = d;
      const std::size_t mid = b + (e - b) / 2;
      std::nth_element(items_.begin() + b, items_.begin() + mid, items_.begin() + e,
                       [dim](const Item& x, const Item& y) { return x.point[dim] < y.point[dim]; });
      const double split = items_[mid].point[dim];
      if (!(split >= cell[0][dim] && split <= cell[1][dim])) continue;  // NaN: a leaf
      nodes_[k].dim = dim;
      nodes_[k].split = split;
      nodes_[k].left = nodes_.size();
      nodes_.push_back(Node{b, mid, 0, -1, 0});
      nodes_.push_back(Node{mid, e, 0, -1, 0});
      std::array<Point, 2> left = cell, right = cell;
      left[1][dim] = split;
      right[0][dim] = split;
      cells.push_back(left);
      cells.push_back(right);
    }
  }

  std::vector<Item> items_;
  std::vector<Node> nodes_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_STITCHING_POINT_KD_TREE_H
