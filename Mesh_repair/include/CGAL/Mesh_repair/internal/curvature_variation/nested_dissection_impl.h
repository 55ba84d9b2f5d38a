// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_NESTED_DISSECTION_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_NESTED_DISSECTION_IMPL_H

#include <CGAL/Mesh_repair/internal/curvature_variation/nested_dissection.h>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

CGAL_MESH_REPAIR_CORE_INLINE Nested_dissection
nested_dissection(const Eigen::SparseMatrix<double>& H,
                  const std::vector<std::array<double, 3>>& positions, std::size_t leaf_size) {
  const int n = int(H.cols());
  Nested_dissection result;
  std::vector<int>& order = result.order;
  order.reserve(std::size_t(n));
  std::vector<Nested_dissection::Node> tree;  // indexed by task; renumbered in post-order below
  std::vector<int> post_order;
  std::vector<int> label(std::size_t(n), -1);  // which half of the current split a vertex is in
  int next_label = 0;

  struct Task {
    std::vector<int> vertices;
    bool emit_only;  // a separator waiting for its turn
    int node;
  };
  // Depth-first with an explicit stack: push the separator first so that it pops last.
  std::vector<Task> stack;
  std::vector<int> everything(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) everything[std::size_t(i)] = i;
  tree.emplace_back();
  stack.push_back({std::move(everything), false, 0});
  while (!stack.empty()) {
    Task task = std::move(stack.back());
    stack.pop_back();
    std::vector<int>& set = task.vertices;
    if (task.emit_only || set.size() <= leaf_size) {
      tree[std::size_t(task.node)].begin = int(order.size());
      order.insert(order.end(), set.begin(), set.end());
      tree[std::size_t(task.node)].end = int(order.size());
      post_order.push_back(task.node);
      continue;
    }
    std::array<double, 3> low = positions[std::size_t(set[0])], high = low;
    for (int v : set)
      for (int k = 0; k < 3; ++k) {
        low[std::size_t(k)] =
            std::min(low[std::size_t(k)], positions[std::size_t(v)][std::size_t(k)]);
        high[std::size_t(k)] =
            std::max(high[std::size_t(k)], positions[std::size_t(v)][std::size_t(k)]);
      }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (high[std::size_t(k)] - low[std::size_t(k)] >
          high[std::size_t(axis)] - low[std::size_t(axis)])
        axis = k;
    const std::size_t half = set.size() / 2;
    std::nth_element(set.begin(), set.begin() + std::ptrdiff_t(half), set.end(), [&](int a, int b) {
      return positions[std::size_t(a)][std::size_t(axis)] <
             positions[std::size_t(b)][std::size_t(axis)];
    });
    const int first = next_label++, second = next_label++;
    for (std::size_t i = 0; i < set.size(); ++i)
      label[std::size_t(set[i])] = i < half ? first : second;
    // The vertices of each side with a neighbour on the other side; the smaller set separates.
    std::array<std::vector<int>, 2> border;
    for (int v : set) {
      const int mine = label[std::size_t(v)];
      const int other = mine == first ? second : first;
      for (Eigen::SparseMatrix<double>::InnerIterator it(H, v); it; ++it)
        if (label[std::size_t(it.index())] == other) {
          border[mine == first ? 0 : 1].push_back(v);
          break;
        }
    }
    const int cut = border[0].size() <= border[1].size() ? 0 : 1;
    for (int v : border[std::size_t(cut)]) label[std::size_t(v)] = -2;  // separator
    std::array<std::vector<int>, 2> sides;
    for (int v : set) {
      const int l = label[std::size_t(v)];
      if (l == first)
        sides[0].push_back(v);
      else if (l == second)
        sides[1].push_back(v);
    }
    stack.push_back({std::move(border[std::size_t(cut)]), true, task.node});
    for (auto& side : sides)
      if (!side.empty()) {
        tree.emplace_back();
        tree.back().parent = task.node;
        ++tree[std::size_t(task.node)].children;
        stack.push_back({std::move(side), false, int(tree.size()) - 1});
      }
  }
  // Renumber the nodes in post-order (the order they were emitted in).
  std::vector<int> renumbered(tree.size());
  for (std::size_t k = 0; k < post_order.size(); ++k)
    renumbered[std::size_t(post_order[k])] = int(k);
  result.nodes.resize(tree.size());
  for (std::size_t t = 0; t < tree.size(); ++t) {
    Nested_dissection::Node node = tree[t];
    if (node.parent >= 0) node.parent = renumbered[std::size_t(node.parent)];
    result.nodes[std::size_t(renumbered[t])] = node;
  }
  return result;
}

CGAL_MESH_REPAIR_CORE_INLINE std::vector<int> nested_dissection_order(
    const Eigen::SparseMatrix<double>& H, const std::vector<std::array<double, 3>>& positions,
    std::size_t leaf_size) {
  return nested_dissection(H, positions, leaf_size).order;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_NESTED_DISSECTION_IMPL_H
