// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_NESTED_DISSECTION_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_NESTED_DISSECTION_H

// A fill-reducing ordering for the normal matrix H of the force-density system, with the
// separator tree that multifrontal_cholesky.h factorises along.
//
// H has a 3-ring stencil on a surface mesh (about 37 non-zeros per row). Eigen's default
// minimum-degree ordering (AMD) is good for small systems but, on a large surface patch, its
// factor grows much faster than that of a nested dissection: at 100,000 free vertices the
// factorisation took 80 % of a 271 s solve. The free vertices have positions, so a geometric
// nested dissection is cheap and reliable: split the vertex set at the median of its longest
// bounding-box axis, take as separator the vertices of the smaller side that have a neighbour in
// H on the other side (so the two remaining halves are disconnected in H, whatever the geometry),
// order the two halves recursively and the separator last. Small sets are left to AMD-free
// natural order. The geometry only affects the quality of the ordering, never its validity.

#include <CGAL/Mesh_repair/internal/core_inline.h>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

/// A nested-dissection elimination order with its separator tree. Each tree node owns a
/// contiguous range [begin, end) of the order: a leaf its vertices, an inner node its separator,
/// emitted after both of its subtrees (so `nodes` is in post-order, children before parents).
struct Nested_dissection {
  struct Node {
    int begin = 0, end = 0;  // range of the order that this node eliminates
    int children = 0;        // 0 (leaf) or the number of non-empty halves
    int parent = -1;
  };
  std::vector<int> order;  // new position -> old index
  std::vector<Node> nodes;
};

/// Elimination order and separator tree of the symmetric pattern `H` by geometric nested
/// dissection on `positions` (one row per unknown).
CGAL_MESH_REPAIR_CORE_INLINE Nested_dissection
nested_dissection(const Eigen::SparseMatrix<double>& H,
                  const std::vector<std::array<double, 3>>& positions, std::size_t leaf_size = 48);

/// Elimination order (new position -> old index) of the symmetric pattern `H` by geometric
/// nested dissection on `positions` (one row per unknown).
CGAL_MESH_REPAIR_CORE_INLINE std::vector<int> nested_dissection_order(
    const Eigen::SparseMatrix<double>& H, const std::vector<std::array<double, 3>>& positions,
    std::size_t leaf_size = 48);

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/curvature_variation/nested_dissection_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_NESTED_DISSECTION_H
