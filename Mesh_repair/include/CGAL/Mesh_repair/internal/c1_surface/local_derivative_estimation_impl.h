// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_IMPL_H

#include <CGAL/Mesh_repair/internal/c1_surface/local_derivative_estimation.h>

#include <Eigen/Dense>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

CGAL_MESH_REPAIR_CORE_INLINE std::array<double, 2> estimate_gradient(
    const std::vector<Height_sample>& samples) {
  const bool quadratic = samples.size() >= 5;
  const int unknowns = quadratic ? 5 : 2;
  if (samples.size() < 2) return {0, 0};
  Eigen::Matrix<double, 5, 5> normal_matrix = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> right_side = Eigen::Matrix<double, 5, 1>::Zero();
  for (const Height_sample& s : samples) {
    const double squared_distance = s.u * s.u + s.v * s.v;
    if (squared_distance == 0) continue;
    const double weight = 1.0 / squared_distance;
    const double row[5] = {s.u, s.v, s.u * s.u, s.u * s.v, s.v * s.v};
    for (int i = 0; i < unknowns; ++i) {
      right_side(i) += weight * row[i] * s.h;
      for (int j = 0; j < unknowns; ++j) normal_matrix(i, j) += weight * row[i] * row[j];
    }
  }
  const auto block = normal_matrix.topLeftCorner(unknowns, unknowns);
  Eigen::LDLT<Eigen::MatrixXd> solver(block);
  if (solver.info() != Eigen::Success || !solver.isPositive()) return {0, 0};
  const Eigen::VectorXd solution = solver.solve(right_side.head(unknowns));
  if (!solution.allFinite()) return {0, 0};
  return {solution(0), solution(1)};
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_IMPL_H
