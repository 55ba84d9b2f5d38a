// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_LEAST_SQUARES_H
#define CGAL_MESH_REPAIR_INTERNAL_LEAST_SQUARES_H

// Dense least squares by Eigen's column-pivoting Householder QR, the one solver of the local
// surface fits (shape prediction's tangent planes, the advancing front's quadric height field).
// Compiled once in the core (internal/core_inline.h).

#include <CGAL/Mesh_repair/internal/core_inline.h>

#include <Eigen/Core>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Solves `design` c = `rhs` in the least-squares sense into `solution`. Returns false, leaving
/// `solution` unchanged, when the numerical rank of `design` is below `min_rank` (the fit is
/// under-determined).
CGAL_MESH_REPAIR_CORE_INLINE bool solve_least_squares(const Eigen::MatrixXd& design,
                                                      const Eigen::VectorXd& rhs,
                                                      Eigen::Index min_rank,
                                                      Eigen::VectorXd& solution);

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/least_squares_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_LEAST_SQUARES_H
