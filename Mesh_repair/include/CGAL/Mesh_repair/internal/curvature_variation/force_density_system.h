// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_FORCE_DENSITY_SYSTEM_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_FORCE_DENSITY_SYSTEM_H

// Pernot 6.1-6.3. A bar network on the whole mesh: node i is in equilibrium under the external
// force f_i = sum_j q_ij (x_i - x_j) (eq. 2, the rows of D = C^T Q C). The patch vertices are the
// free nodes, every other vertex is blocked (6.2). The objective is quadratic in the free
// positions: phi = |M x_f + c|^2, one term per squared force (eq. 8) or per squared difference
// of the forces of two connected nodes (eq. 9), each term a sparse row of D or a difference of
// two rows. We assemble it in the free POSITIONS rather than in the free forces F of the paper:
// the two are related by the affine bijection F = D_f x_f + D_bf x_b (eq. 3, D_f is
// non-singular as soon as every patch touches a blocked node), so the minimisers are the same,
// but in positions the normal matrix H = M^T M stays sparse (a 3-ring stencil), while in forces
// the contour terms need D_f^-1 (eq. 6), which is dense. One sparse Cholesky factorisation of H
// (multifrontal_cholesky.h)
// serves the three coordinates, every hole of the mesh, and the constraint multipliers.

#include <CGAL/Mesh_repair/hole_filling/curvature_variation_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

struct System_options {
  Curvature_objective objective = Curvature_objective::force_variation;
  Objective_nodes nodes = Objective_nodes::free_and_contour_nodes;
  Force_density density = Force_density::uniform;
  bool area_normalized = false;  // sum f_i / A_i (a pressure) instead of f_i
  // Re-measure the densities and areas on the first solution and solve again (deform.h). Off in
  // the public functions: it helps on smooth analytic surfaces, it hurts on scans (see
  // doc/curvature_variation.md, "Initial grid").
  bool remeasure_weights = true;
  // Jacobi steps of tangential relaxation of the free vertices before the densities and areas are
  // measured on the initial grid (deform.h). 0: the grid as inserted.
  int initial_grid_relaxation = 0;
};

/// A sparse linear combination of node positions.
struct Linear_row {
  std::vector<std::pair<int, double>> free_terms;  // (free index, weight)
  std::array<double, 3> constant{0, 0, 0};         // sum of the blocked terms
};

// Cotangent force densities are clamped here (the mean of (cot a + cot b) / 2 is about 0.58 on a
// regular mesh): keeps every bar in tension, so D stays a positive weighted Laplacian.
constexpr double minimum_cotangent_density = 0.03;

// Steps of tangential relaxation of the initial grid in the public functions (deform.h).
constexpr int default_initial_grid_relaxation = 3;

template <class PolygonMesh, class VertexPointMap>
class Force_density_system {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Index_map =
      typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<int>>::const_type;

 public:
  Force_density_system(const PolygonMesh& pm, VertexPointMap vpm,
                       const std::vector<Fill_patch<PolygonMesh>>& patches,
                       const System_options& options)
      : pm_(pm),
        vpm_(vpm),
        options_(options),
        free_index_(get(CGAL::dynamic_vertex_property_t<int>(), pm)),
        contour_mark_(get(CGAL::dynamic_vertex_property_t<int>(), pm)) {
    for (auto v : vertices(pm)) {
      put(free_index_, v, -1);
      put(contour_mark_, v, -1);
    }
    for (std::size_t p = 0; p < patches.size(); ++p) {
      for (auto v : patches[p].vertices) {
        put(free_index_, v, int(free_.size()));
        free_.push_back(v);
        patch_of_free_.push_back(p);
      }
    }
    patch_bar_density_.assign(patches.size(), 1.0);
    for (std::size_t p = 0; p < patches.size(); ++p) collect_contour(patches[p], p);
  }

  std::size_t free_count() const { return free_.size(); }
  std::size_t contour_count() const { return contour_.size(); }
  const std::vector<vertex_descriptor>& free_vertices() const { return free_; }
  int free_index(vertex_descriptor v) const { return get(free_index_, v); }

  /// Builds M (one row per objective term with a free part) and the constant part C.
  void assemble(Eigen::SparseMatrix<double>& M, Eigen::MatrixXd& C) const {
    std::vector<Linear_row> terms;
    auto add_term = [&](Linear_row&& row) {
      if (!row.free_terms.empty()) terms.push_back(std::move(row));
    };
    auto for_each_summed_node = [&](auto&& f) {
      for (auto v : free_) f(v);
      if (options_.nodes == Objective_nodes::free_and_contour_nodes)
        for (auto v : contour_) f(v);
    };
    for_each_summed_node([&](vertex_descriptor i) {
      if (options_.objective == Curvature_objective::forces) {
        add_term(force_row(i));
        return;
      }
      const Linear_row fi = force_row(i);
      for (auto j : CGAL::vertices_around_target(halfedge(i, pm_), pm_))
        add_term(difference(fi, force_row(j)));
    });
    std::vector<Eigen::Triplet<double>> triplets;
    C.resize(Eigen::Index(terms.size()), 3);
    for (std::size_t r = 0; r < terms.size(); ++r) {
      for (const auto& [column, weight] : terms[r].free_terms)
        triplets.emplace_back(int(r), column, weight);
      for (int k = 0; k < 3; ++k) C(Eigen::Index(r), k) = terms[r].constant[k];
    }
    M.resize(Eigen::Index(terms.size()), Eigen::Index(free_.size()));
    M.setFromTriplets(triplets.begin(), triplets.end());
  }

  std::array<double, 3> position(vertex_descriptor v) const {
    const auto& p = get(vpm_, v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }

 private:
  void collect_contour(const Fill_patch<PolygonMesh>& patch, std::size_t p) {
    double length_sum = 0;
    std::size_t length_count = 0;
    for (auto f : patch.faces) {
      for (auto h : CGAL::halfedges_around_face(halfedge(f, pm_), pm_)) {
        const vertex_descriptor v = target(h, pm_);
        if (get(free_index_, v) < 0 && get(contour_mark_, v) < 0) {
          put(contour_mark_, v, int(contour_.size()));
          contour_.push_back(v);
        }
        if (get(free_index_, v) < 0 && get(free_index_, source(h, pm_)) < 0) {
          length_sum += bar_length(source(h, pm_), v);
          ++length_count;
        }
      }
    }
    if (length_count > 0 && length_sum > 0)
      patch_bar_density_[p] = double(length_count) / length_sum;
  }

  double bar_length(vertex_descriptor a, vertex_descriptor b) const {
    const auto pa = position(a), pb = position(b);
    return std::sqrt((pa[0] - pb[0]) * (pa[0] - pb[0]) + (pa[1] - pb[1]) * (pa[1] - pb[1]) +
                     (pa[2] - pb[2]) * (pa[2] - pb[2]));
  }

  double force_density(vertex_descriptor a, vertex_descriptor b) const {
    if (options_.density == Force_density::uniform) return 1.0;
    if (options_.density == Force_density::cotangent) return cotangent_density(a, b);
    const int fa = get(free_index_, a), fb = get(free_index_, b);
    if (fa >= 0) return patch_bar_density_[patch_of_free_[std::size_t(fa)]];
    if (fb >= 0) return patch_bar_density_[patch_of_free_[std::size_t(fb)]];
    const double length = bar_length(a, b);
    return length > 0 ? 1.0 / length : 1.0;
  }

  /// (cot a + cot b) / 2 of the bar ab on the current positions, clamped below so that obtuse
  /// triangles never give a non-positive force density.
  double cotangent_density(vertex_descriptor a, vertex_descriptor b) const {
    const auto h = halfedge(a, b, pm_).first;
    double weight = 0;
    for (auto g : {h, opposite(h, pm_)}) {
      if (is_border(g, pm_)) continue;
      const auto pa = position(a), pb = position(b), pc = position(target(next(g, pm_), pm_));
      const std::array<double, 3> u{pa[0] - pc[0], pa[1] - pc[1], pa[2] - pc[2]};
      const std::array<double, 3> v{pb[0] - pc[0], pb[1] - pc[1], pb[2] - pc[2]};
      const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                    u[0] * v[1] - u[1] * v[0]};
      const double sine = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double cosine = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      if (sine > 0) weight += 0.5 * cosine / sine;
    }
    return std::max(weight, minimum_cotangent_density);
  }

  /// A third of the area of the faces around v, on the current positions.
  double vertex_area(vertex_descriptor v) const {
    double area = 0;
    for (auto h : CGAL::halfedges_around_target(halfedge(v, pm_), pm_)) {
      if (is_border(h, pm_)) continue;
      const auto a = position(source(h, pm_)), b = position(v),
                 c = position(target(next(h, pm_), pm_));
      const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const std::array<double, 3> w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                                    u[0] * w[1] - u[1] * w[0]};
      area += std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 6.0;
    }
    return area > 0 ? area : 1.0;
  }

  void add(Linear_row& row, vertex_descriptor v, double weight) const {
    const int index = get(free_index_, v);
    if (index >= 0) {
      row.free_terms.emplace_back(index, weight);
      return;
    }
    const auto p = position(v);
    for (int k = 0; k < 3; ++k) row.constant[k] += weight * p[k];
  }

  /// Row i of eq. 2: f_i = sum_j q_ij (x_i - x_j).
  Linear_row force_row(vertex_descriptor i) const {
    Linear_row row;
    const double scale = options_.area_normalized ? 1.0 / vertex_area(i) : 1.0;
    double diagonal = 0;
    for (auto j : CGAL::vertices_around_target(halfedge(i, pm_), pm_)) {
      const double q = scale * force_density(i, j);
      diagonal += q;
      add(row, j, -q);
    }
    add(row, i, diagonal);
    return row;
  }

  static Linear_row difference(const Linear_row& a, const Linear_row& b) {
    Linear_row row = a;
    for (const auto& [column, weight] : b.free_terms) row.free_terms.emplace_back(column, -weight);
    for (int k = 0; k < 3; ++k) row.constant[k] -= b.constant[k];
    return row;
  }

  const PolygonMesh& pm_;
  VertexPointMap vpm_;
  System_options options_;
  Index_map free_index_, contour_mark_;
  std::vector<vertex_descriptor> free_, contour_;
  std::vector<std::size_t> patch_of_free_;
  std::vector<double> patch_bar_density_;
};

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_FORCE_DENSITY_SYSTEM_H
