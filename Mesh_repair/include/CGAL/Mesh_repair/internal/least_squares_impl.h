// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_LEAST_SQUARES_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_LEAST_SQUARES_IMPL_H

#include <CGAL/Mesh_repair/internal/least_squares.h>

#include <Eigen/QR>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

CGAL_MESH_REPAIR_CORE_INLINE bool solve_least_squares(const Eigen::MatrixXd& design,
                                                      const Eigen::VectorXd& rhs,
                                                      Eigen::Index min_rank,
                                                      Eigen::VectorXd& solution) {
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < min_rank) return false;
  solution = qr.solve(rhs);
  return true;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_LEAST_SQUARES_IMPL_H
