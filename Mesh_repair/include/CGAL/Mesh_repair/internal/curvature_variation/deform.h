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
#include <CGAL/Mesh_repair/internal/curvature_variation/measures.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/multifrontal_cholesky.h>

#include <Eigen/QR>

#include <chrono>
#include <memory>
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
  auto position = [&](auto v) -> Vec3 {
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
        const double d = dot(q - goal, q - goal);
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

/// H x = B for a matrix H close to the one `factor` factorised: conjugate gradients, column by
/// column, preconditioned with that factorisation (so H^-1 costs a few solves, no new
/// factorisation). Converged when the relative residual is below 1e-12 or the last step moved
/// x by less than 1e-13 of its size.
class Preconditioned_solver {
 public:
  Preconditioned_solver(const Eigen::SparseMatrix<double>& H, const Multifrontal_cholesky& factor)
      : H_(H), factor_(factor) {}

  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const {
    return solve(B, Eigen::MatrixXd(factor_.solve(B)));
  }

  Eigen::MatrixXd solve(const Eigen::MatrixXd& B, Eigen::MatrixXd X) const {
    for (Eigen::Index c = 0; c < B.cols(); ++c) {
      Eigen::VectorXd x = X.col(c);
      const Eigen::VectorXd b = B.col(c);
      const double b_norm = b.norm();
      Eigen::VectorXd r = b - H_ * x;
      Eigen::VectorXd z = factor_.solve(r);
      Eigen::VectorXd d = z;
      double rz = r.dot(z);
      bool done = b_norm == 0 || r.norm() <= 1e-12 * b_norm;
      for (int k = 0; k < maximum_iterations && !done; ++k) {
        const Eigen::VectorXd q = H_ * d;
        const double curvature = d.dot(q);
        if (!(curvature > 0)) break;
        const double alpha = rz / curvature;
        x += alpha * d;
        r -= alpha * q;
        ++iterations_;
        done = r.norm() <= 1e-12 * b_norm || std::abs(alpha) * d.lpNorm<Eigen::Infinity>() <=
                                                 1e-13 * std::max(1.0, x.lpNorm<Eigen::Infinity>());
        z = factor_.solve(r);
        const double rz_next = r.dot(z);
        d = z + (rz_next / rz) * d;
        rz = rz_next;
      }
      converged_ = converged_ && done;
      X.col(c) = x;
    }
    return X;
  }

  bool converged() const { return converged_; }
  std::size_t iterations() const { return iterations_; }

  static constexpr int maximum_iterations = 200;

 private:
  const Eigen::SparseMatrix<double>& H_;
  const Multifrontal_cholesky& factor_;
  mutable bool converged_ = true;
  mutable std::size_t iterations_ = 0;
};

/// Tangential relaxation of the free vertices (Jacobi steps): each moves towards the centroid of
/// its neighbours, within the plane orthogonal to the area-weighted normal of its faces. The
/// blocked vertices (the contour and beyond) do not move. On a planar grid the vertices stay in
/// the plane; it only evens out the triangle shapes on which the cotangent densities and the
/// vertex areas are measured.
template <class PolygonMesh, class VertexPointMap>
void relax_tangentially(
    PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& free,
    int steps) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  std::vector<Vec3> moved(free.size());
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < free.size(); ++i) {
      const Vec3 x = to_array(get(vpm, free[i]));
      Vec3 centroid{0, 0, 0}, normal{0, 0, 0};
      int neighbours = 0;
      for (auto h : CGAL::halfedges_around_target(halfedge(free[i], pm), pm)) {
        const Vec3 u = to_array(get(vpm, source(h, pm)));
        for (int d = 0; d < 3; ++d) centroid[d] += u[d];
        ++neighbours;
        if (is_border(h, pm)) continue;
        const Vec3 w = to_array(get(vpm, target(next(h, pm), pm)));
        const Vec3 n = cross(sub(x, u), sub(w, u));
        for (int d = 0; d < 3; ++d) normal[d] += n[d];
      }
      Vec3 step_vector{0, 0, 0};
      if (neighbours > 0)
        for (int d = 0; d < 3; ++d) step_vector[d] = centroid[d] / neighbours - x[d];
      const double squared_normal = dot(normal, normal);
      if (squared_normal > 0) {
        const double t = dot(step_vector, normal) / squared_normal;
        for (int d = 0; d < 3; ++d) step_vector[d] -= t * normal[d];
      }
      moved[i] = {x[0] + step_vector[0], x[1] + step_vector[1], x[2] + step_vector[2]};
    }
    for (std::size_t i = 0; i < free.size(); ++i)
      put(vpm, free[i], Point(moved[i][0], moved[i][1], moved[i][2]));
  }
}

/// The normal system H x = B of the objective, with the force densities and areas measured on
/// the current positions of the mesh.
template <class PolygonMesh, class VertexPointMap>
void assemble_normal_system(const Force_density_system<PolygonMesh, VertexPointMap>& system,
                            Eigen::SparseMatrix<double>& H, Eigen::MatrixXd& B,
                            std::size_t& terms) {
  Eigen::SparseMatrix<double> M;
  Eigen::MatrixXd C;
  system.assemble(M, C);
  terms = std::size_t(M.rows());
  const Eigen::SparseMatrix<double> Mt = M.transpose();
  H = Mt * M;
  B = -(Mt * C);
}

/// Shapes the free vertices of every patch with one sparse factorisation. The mesh is modified
/// only on success.
///
/// The cotangent force densities and the vertex areas depend on the positions, and the initial
/// grid is flat (or a stretched disc): measured there they describe a flattened patch, whose
/// triangles are compressed along the slope of the final surface (by 1 - cos(slope), 9 % for a
/// 24 degree cap), and the curvature the objective matches across the contour is biased. So the
/// system is solved twice: once with the densities of the initial grid, then with the densities
/// re-measured on that first shape. The second system differs from the first only by these
/// re-measured weights, so it is solved by conjugate gradients preconditioned with the first
/// factorisation (a few solves, no second factorisation; one is made only if that does not
/// converge, and reported).
template <class PolygonMesh, class VertexPointMap, class Visitor>
Curvature_deformation_report deform_patches(PolygonMesh& pm, VertexPointMap vpm,
                                            const std::vector<Fill_patch<PolygonMesh>>& patches,
                                            const System_options& options,
                                            const std::vector<Vec3>& constraint_targets,
                                            Visitor& visitor) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using System = Force_density_system<PolygonMesh, VertexPointMap>;
  Curvature_deformation_report report;
  auto start = std::chrono::steady_clock::now();
  visitor.start_step("curvature variation: assembly");
  // The relaxation moves the free vertices before the solve: they are put back on failure.
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> all_free;
  std::vector<Point> inserted;
  if (options.initial_grid_relaxation > 0) {
    for (const auto& patch : patches)
      all_free.insert(all_free.end(), patch.vertices.begin(), patch.vertices.end());
    for (auto v : all_free) inserted.push_back(get(vpm, v));
    relax_tangentially(pm, vpm, all_free, options.initial_grid_relaxation);
  }
  struct Restore_on_failure {
    PolygonMesh& pm;
    VertexPointMap vpm;
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& vertices;
    const std::vector<Point>& points;
    const Curvature_deformation_report& report;
    ~Restore_on_failure() {
      if (!report.solved)
        for (std::size_t i = 0; i < points.size(); ++i) put(vpm, vertices[i], points[i]);
    }
  } restore{pm, vpm, all_free, inserted, report};
  System system(pm, vpm, patches, options);
  report.free_vertices = system.free_count();
  report.contour_vertices = system.contour_count();
  if (system.free_count() == 0) {
    visitor.end_step("curvature variation: assembly");
    report.solved = true;  // nothing to move: the patches have no interior vertex
    return report;
  }
  Eigen::SparseMatrix<double> H;
  Eigen::MatrixXd B;
  assemble_normal_system(system, H, B, report.objective_terms);
  report.system_nonzeros = std::size_t(H.nonZeros());
  report.assembly_seconds = seconds_since(start);
  visitor.end_step("curvature variation: assembly");
  if (!visitor.progress(1.0)) {
    report.cancelled = true;
    return report;
  }

  visitor.start_step("curvature variation: factorisation");
  start = std::chrono::steady_clock::now();
  std::vector<std::array<double, 3>> positions;
  positions.reserve(system.free_count());
  for (auto v : system.free_vertices()) positions.push_back(system.position(v));
  const Multifrontal_cholesky factor(H, positions);
  report.factorizations = 1;
  report.factor_nonzeros = factor.factor_nonzeros();
  report.factorization_seconds = seconds_since(start);
  visitor.end_step("curvature variation: factorisation");
  if (factor.info() != Eigen::Success) {
    report.failure = "the sparse factorisation failed (singular system)";
    return report;
  }
  start = std::chrono::steady_clock::now();
  Eigen::MatrixXd X = factor.solve(B);
  const auto& free = system.free_vertices();
  auto put_free = [&](const Eigen::MatrixXd& Y) {
    for (std::size_t i = 0; i < free.size(); ++i)
      put(vpm, free[i], Point(Y(Eigen::Index(i), 0), Y(Eigen::Index(i), 1), Y(Eigen::Index(i), 2)));
  };
  const bool weights_move = options.remeasure_weights && X.allFinite() &&
                            (options.density != Force_density::uniform || options.area_normalized);
  if (!weights_move) {
    if (!constraint_targets.empty()) {
      std::vector<Linear_row> rows;
      std::vector<Vec3> targets;
      attach_constraints(system, pm, patches, X, constraint_targets, rows, targets, report);
      if (!rows.empty())
        X = apply_constraints(factor, Eigen::Index(free.size()), rows, targets, X,
                              report.max_constraint_residual);
    }
  } else {
    std::vector<Point> initial;
    initial.reserve(free.size());
    for (auto v : free) initial.push_back(get(vpm, v));
    put_free(X);  // the densities and areas are read from the mesh
    const auto assembly_start = std::chrono::steady_clock::now();
    const System remeasured(pm, vpm, patches, options);
    Eigen::SparseMatrix<double> H2;
    Eigen::MatrixXd B2;
    std::size_t terms = 0;
    assemble_normal_system(remeasured, H2, B2, terms);
    report.assembly_seconds += seconds_since(assembly_start);
    std::unique_ptr<Multifrontal_cholesky> refactorised;
    Preconditioned_solver iterative(H2, factor);
    X = iterative.solve(B2, X);
    report.weight_remeasurements = 1;
    report.preconditioned_iterations = iterative.iterations();
    if (!iterative.converged()) {
      const auto factor_start = std::chrono::steady_clock::now();
      refactorised = std::make_unique<Multifrontal_cholesky>(H2, positions);
      ++report.factorizations;
      report.factorization_seconds += seconds_since(factor_start);
      if (refactorised->info() == Eigen::Success) X = refactorised->solve(B2);
    }
    if (!constraint_targets.empty()) {
      std::vector<Linear_row> rows;
      std::vector<Vec3> targets;
      attach_constraints(remeasured, pm, patches, X, constraint_targets, rows, targets, report);
      if (!rows.empty()) {
        if (refactorised)
          X = apply_constraints(*refactorised, Eigen::Index(free.size()), rows, targets, X,
                                report.max_constraint_residual);
        else
          X = apply_constraints(iterative, Eigen::Index(free.size()), rows, targets, X,
                                report.max_constraint_residual);
      }
    }
    for (std::size_t i = 0; i < free.size(); ++i) put(vpm, free[i], initial[i]);
  }
  report.solve_seconds = seconds_since(start);
  if (!X.allFinite()) {
    report.failure = "the solve produced non-finite positions";
    return report;
  }
  put_free(X);
  report.solved = true;
  return report;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_DEFORM_H
