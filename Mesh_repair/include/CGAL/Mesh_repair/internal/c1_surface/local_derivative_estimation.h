// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_H
#define CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_H

// Local derivative estimation at a data point (Chen et al. 2.2, after Goodman, Said, Chang 1995):
// the gradient of the unknown function at a vertex is that of a local quadratic fitted to the
// neighbouring data by least squares, with weights 1/d^2 so that the nearest neighbours dominate.
// The same routine serves scattered functional data (u, v = x, y; h = f - f0) and surface meshes
// (u, v in the tangent plane of a first normal estimate, h the height above it).

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// One neighbour of the centre, in the centre's local coordinates: offset (u, v), height h.
struct Height_sample {
  double u, v, h;
};

/// Gradient (dh/du, dh/dv) at the origin of a weighted least-squares fit of
/// h = a u + b v + c u^2 + d u v + e v^2 (five or more samples) or of the plane h = a u + b v
/// (two to four samples). Returns {0, 0} without samples or when the fit is singular.
inline std::array<double, 2> estimate_gradient(const std::vector<Height_sample>& samples) {
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

#endif  // CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_H
