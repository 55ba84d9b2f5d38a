// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_DEFORM_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_DEFORM_H

// Pernot 6: the single deformation step that shapes every inner mesh of the mesh at once.
// Unconstrained: H x_f = -M^T C with H = M^T M (force_density_system.h). With k point
// constraints A x_f = t (6.4) the Lagrange conditions H x + M^T C + A^T lambda = 0, A x = t are
// solved through the Schur complement S = A H^-1 A^T (k x k, small): x = x0 - H^-1 A^T lambda,
// S lambda = A x0 - t. H^-1 A^T costs k solves with the factorisation already computed, so the
// constrained problem still needs ONE sparse factorisation.

#include <CGAL/Mesh_repair/internal/curvature_variation/constraints.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/force_density_system.h>

#include <Eigen/QR>

#include <chrono>
#include <limits>
#include <string>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Rows of A (and the blocked part moved to t) for each target attached to its closest point on
/// the inner meshes positioned at X0. Targets attached only to blocked vertices are dropped.
template <class System, class PolygonMesh>
void attach_constraints(const System& system, const PolygonMesh& pm,
                        const std::vector<Fill_patch<PolygonMesh>>& patches,
                        const Eigen::MatrixXd& X0, const std::vector<Vec3>& targets,
                        std::vector<Linear_row>& rows, std::vector<Vec3>& right_hand_sides,
                        Curvature_deformation_report& report) {
  auto position = [&](auto v) {
    const int i = system.free_index(v);
    if (i < 0) return system.position(v);
    return Vec3{X0(i, 0), X0(i, 1), X0(i, 2)};
  };
  for (const Vec3& goal : targets) {
    double best = std::numeric_limits<double>::infinity();
    Linear_row best_row;
    for (const auto& patch : patches) {
      for (auto f : patch.faces) {
        auto h = halfedge(f, pm);
        const std::array<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, 3> v{
            source(h, pm), target(h, pm), target(next(h, pm), pm)};
        const Vec3 a = position(v[0]), b = position(v[1]), c = position(v[2]);
        const Vec3 w = closest_barycentric(goal, a, b, c);
        Vec3 q;
        for (int k = 0; k < 3; ++k) q[k] = w[0] * a[k] + w[1] * b[k] + w[2] * c[k];
        const double d = dot3(q - goal, q - goal);
        if (d >= best) continue;
        best = d;
        best_row = Linear_row();
        for (int j = 0; j < 3; ++j) {
          const int i = system.free_index(v[std::size_t(j)]);
          if (w[std::size_t(j)] == 0) continue;
          if (i >= 0) {
            best_row.free_terms.emplace_back(i, w[std::size_t(j)]);
          } else {
            const Vec3 p = system.position(v[std::size_t(j)]);
            for (int k = 0; k < 3; ++k) best_row.constant[k] += w[std::size_t(j)] * p[k];
          }
        }
      }
    }
    if (best_row.free_terms.empty()) {
      ++report.constraints_dropped;
      continue;
    }
    rows.push_back(best_row);
    right_hand_sides.push_back(goal - best_row.constant);
  }
  report.constraints_applied = rows.size();
}

/// Applies the constraints to the unconstrained solution X0 with the factorisation of H.
template <class Solver>
Eigen::MatrixXd apply_constraints(const Solver& solver, Eigen::Index free_count,
                                  const std::vector<Linear_row>& rows,
                                  const std::vector<Vec3>& targets, const Eigen::MatrixXd& X0,
                                  double& max_residual) {
  const Eigen::Index k = Eigen::Index(rows.size());
  Eigen::SparseMatrix<double> A(k, free_count);
  std::vector<Eigen::Triplet<double>> triplets;
  for (Eigen::Index r = 0; r < k; ++r)
    for (const auto& [column, weight] : rows[std::size_t(r)].free_terms)
      triplets.emplace_back(int(r), column, weight);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::MatrixXd T(k, 3);
  for (Eigen::Index r = 0; r < k; ++r)
    for (int c = 0; c < 3; ++c) T(r, c) = targets[std::size_t(r)][std::size_t(c)];
  const Eigen::MatrixXd At = Eigen::MatrixXd(A.transpose());
  const Eigen::MatrixXd Y = solver.solve(At);  // H^-1 A^T, free_count x k
  const Eigen::MatrixXd S = A * Y;
  // Two constraints attached to the same point make S singular: the least-squares multipliers of
  // the complete orthogonal decomposition then satisfy them in the least-squares sense.
  const Eigen::MatrixXd lambda = S.completeOrthogonalDecomposition().solve(A * X0 - T);
  Eigen::MatrixXd X = X0 - Y * lambda;
  max_residual = k > 0 ? (A * X - T).rowwise().norm().maxCoeff() : 0.0;
  return X;
}

/// Shapes the free vertices of every patch in one solve. The mesh is modified only on success.
template <class PolygonMesh, class VertexPointMap, class Visitor>
Curvature_deformation_report deform_patches(PolygonMesh& pm, VertexPointMap vpm,
                                            const std::vector<Fill_patch<PolygonMesh>>& patches,
                                            const System_options& options,
                                            const std::vector<Vec3>& constraint_targets,
                                            Visitor& visitor) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  Curvature_deformation_report report;
  auto start = std::chrono::steady_clock::now();
  visitor.start_step("curvature variation: assembly");
  Force_density_system<PolygonMesh, VertexPointMap> system(pm, vpm, patches, options);
  report.free_vertices = system.free_count();
  report.contour_vertices = system.contour_count();
  if (system.free_count() == 0) {
    visitor.end_step("curvature variation: assembly");
    report.solved = true;  // nothing to move: the patches have no interior vertex
    return report;
  }
  Eigen::SparseMatrix<double> M;
  Eigen::MatrixXd C;
  system.assemble(M, C);
  report.objective_terms = std::size_t(M.rows());
  const Eigen::SparseMatrix<double> Mt = M.transpose();
  const Eigen::SparseMatrix<double> H = Mt * M;
  const Eigen::MatrixXd B = -(Mt * C);
  report.system_nonzeros = std::size_t(H.nonZeros());
  report.assembly_seconds = seconds_since(start);
  visitor.end_step("curvature variation: assembly");
  if (!visitor.progress(1.0)) {
    report.cancelled = true;
    return report;
  }

  visitor.start_step("curvature variation: factorisation");
  start = std::chrono::steady_clock::now();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(H);
  report.factorizations = 1;
  report.factorization_seconds = seconds_since(start);
  visitor.end_step("curvature variation: factorisation");
  if (solver.info() != Eigen::Success) {
    report.failure = "the sparse factorisation failed (singular system)";
    return report;
  }
  start = std::chrono::steady_clock::now();
  Eigen::MatrixXd X = solver.solve(B);
  if (!constraint_targets.empty()) {
    std::vector<Linear_row> rows;
    std::vector<Vec3> targets;
    attach_constraints(system, pm, patches, X, constraint_targets, rows, targets, report);
    if (!rows.empty())
      X = apply_constraints(solver, Eigen::Index(system.free_count()), rows, targets, X,
                            report.max_constraint_residual);
  }
  report.solve_seconds = seconds_since(start);
  if (!X.allFinite()) {
    report.failure = "the solve produced non-finite positions";
    return report;
  }
  const auto& free = system.free_vertices();
  for (std::size_t i = 0; i < free.size(); ++i)
    put(vpm, free[i], Point(X(Eigen::Index(i), 0), X(Eigen::Index(i), 1), X(Eigen::Index(i), 2)));
  report.solved = true;
  return report;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_DEFORM_H
