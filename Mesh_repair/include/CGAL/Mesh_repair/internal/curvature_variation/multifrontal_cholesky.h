// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MULTIFRONTAL_CHOLESKY_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MULTIFRONTAL_CHOLESKY_H

// Sparse Cholesky factorisation H = L L^T of the force-density normal matrix, multifrontal along
// the separator tree of a geometric nested dissection.
//
// Why not Eigen's SimplicialLDLT: it updates one column at a time, so on H (a 3-ring stencil, a
// factor of 29 M non-zeros at 100,000 free vertices) it runs at about 1.7 GFlop/s and the
// factorisation was 90 % of the solve. Eigen has no supernodal Cholesky (CHOLMOD is not among our
// dependencies) and its supernodal SparseLU does twice the work. Here every node of the tree
// (a separator, or a leaf of the dissection) is one dense frontal matrix: its own unknowns plus
// those of its ancestors that they couple to. The node's rows of H and its children's update
// matrices are added in, its own columns are factorised with Eigen's dense kernels (LLT, a
// triangular solve, a symmetric rank-k update), and what is left (the Schur complement on the
// ancestors) goes up to the parent. Same factor as a column-by-column Cholesky in this order, up
// to rounding, but computed in dense blocks.

#include <CGAL/Mesh_repair/internal/core_inline.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/nested_dissection.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

/// L L^T of a symmetric positive definite `H` (both triangles stored) in a nested-dissection
/// order of the unknowns at `positions`; solves in the original numbering.
class Multifrontal_cholesky {
 public:
  CGAL_MESH_REPAIR_CORE_INLINE Multifrontal_cholesky(
      const Eigen::SparseMatrix<double>& H, const std::vector<std::array<double, 3>>& positions);

  Eigen::ComputationInfo info() const { return info_; }

  CGAL_MESH_REPAIR_CORE_INLINE Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

  /// Non-zeros of the factor L (a measure of the ordering's quality).
  std::size_t factor_nonzeros() const {
    std::size_t count = 0;
    for (const Front& front : fronts_) {
      const std::size_t k = std::size_t(front.end - front.begin), s = front.rows.size();
      count += k * s - k * (k - 1) / 2;
    }
    return count;
  }

 private:
  // Measured at 100,000 free vertices: leaves of 64 unknowns factorise in 1.94 s, of 128 in
  // 2.04 s, of 512 in 2.67 s (larger leaves are denser fronts with more fill).
  static constexpr std::size_t leaf_size = 64;

  struct Front {
    int begin = 0, end = 0;  // own unknowns, in the new numbering
    std::vector<int> rows;   // own unknowns, then the ancestors' they couple to (ascending)
    Eigen::MatrixXd L;       // rows.size() x (end - begin): this front's columns of L
  };

  // Symbolic step: the rows of each front are its own unknowns, their neighbours in H that come
  // later in the order, and the rows its children pass up.
  CGAL_MESH_REPAIR_CORE_INLINE void find_front_rows(const Eigen::SparseMatrix<double>& H,
                                                    const Nested_dissection& dissection);

  // Numeric step, in post-order: a node's children have pushed their update matrices on a stack,
  // in the order they were factorised, just before the node itself.
  CGAL_MESH_REPAIR_CORE_INLINE void factorise(const Eigen::SparseMatrix<double>& H,
                                              const Nested_dissection& dissection);

  std::vector<int> order_, new_index_;
  std::vector<Front> fronts_;
  Eigen::ComputationInfo info_ = Eigen::NumericalIssue;
};

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/curvature_variation/multifrontal_cholesky_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MULTIFRONTAL_CHOLESKY_H
