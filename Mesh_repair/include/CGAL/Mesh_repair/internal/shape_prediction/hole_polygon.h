// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_HOLE_POLYGON_H
#define CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_HOLE_POLYGON_H

// Reads a hole's border polygon off a mesh: node positions in border-halfedge order, the node
// normals of eq. 5.30 (angle-weighted, via cubic_curves.h eq. 4.1) and the normal of the face
// across each border edge.

#include <CGAL/Mesh_repair/internal/cubic_curves.h>
#include <CGAL/Mesh_repair/internal/least_squares.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/shape_estimate.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <utility>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace shape_prediction {

template <class Kernel, class Point>
typename Kernel::Vector_3 face_unit_normal(const Point& a, const Point& b, const Point& c) {
  const typename Kernel::Vector_3 n = CGAL::cross_product(b - a, c - a);
  const double l = std::sqrt(CGAL::to_double(n.squared_length()));
  return l > 0 ? n / l : typename Kernel::Vector_3(0, 0, 0);
}

/// Eq. 5.30: unit normal of vertex `v`, the mean of its faces' unit normals weighted by the
/// angle each face subtends at `v`.
template <class Kernel, class PolygonMesh, class VertexPointMap>
typename Kernel::Vector_3 vertex_normal(
    typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm,
    VertexPointMap vpm) {
  using Vector_3 = typename Kernel::Vector_3;
  std::vector<std::pair<Vector_3, double>> faces;
  for (auto h : halfedges_around_target(halfedge(v, pm), pm)) {
    if (is_border(h, pm)) continue;
    const auto& p = get(vpm, v);
    const auto& a = get(vpm, source(h, pm));
    const auto& b = get(vpm, target(next(h, pm), pm));
    const Vector_3 n = face_unit_normal<Kernel>(a, p, b);
    const Vector_3 e1 = a - p, e2 = b - p;
    const double l1 = std::sqrt(CGAL::to_double(e1.squared_length()));
    const double l2 = std::sqrt(CGAL::to_double(e2.squared_length()));
    if (l1 == 0 || l2 == 0) continue;
    const double c = std::max(-1.0, std::min(1.0, CGAL::to_double(e1 * e2) / (l1 * l2)));
    faces.emplace_back(n, std::acos(c));
  }
  return angle_weighted_normal<Vector_3>(faces);
}

/// The normal at border vertex `v` of the surface the hole cuts: the tangent plane at `v` of a
/// quadric height field z = c1 x + c2 y + c3 x^2 + c4 xy + c5 y^2 through `v`, over the plane of
/// the eq. 5.30 normal `n0`, fitted to the vertices within two rings of `v`.
/// At a border vertex every face lies on one side, so eq. 5.30 averages normals taken half a
/// ring away from `v`, on the far side from the hole: an error of the order of the edge length
/// times the curvature, which tilts every boundary curve of the patches. The quadric's normal at
/// `v` has no such one-sided bias. The fit is weighted least squares, Gaussian in the distance
/// (width: the mean one-ring edge), made robust by iteratively reweighted least squares (Cauchy
/// weights on the residuals, scaled by their median absolute deviation), so that the vertices
/// across a crease (CAD models) do not tilt the plane of the smooth side. Returns `n0` when the
/// fit is under-determined (fewer than 8 neighbours or rank below 5) or its normal faces away
/// from `n0`.
template <class Kernel, class PolygonMesh, class VertexPointMap>
typename Kernel::Vector_3 fitted_vertex_normal(
    typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
    const typename Kernel::Vector_3& n0, const PolygonMesh& pm, VertexPointMap vpm) {
  using Vector_3 = typename Kernel::Vector_3;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  if (n0.squared_length() == 0) return n0;
  // At most `max_fit_vertices`: next to the centre of a fan of n triangles the two rings hold
  // the whole fan, and n border vertices would cost O(n^2).
  constexpr std::size_t max_fit_vertices = 256;
  std::vector<vertex_descriptor> ring{v};
  std::unordered_set<vertex_descriptor> in_ring{v};
  for (std::size_t begin = 0, depth = 0; depth < 2; ++depth) {
    const std::size_t end = ring.size();
    for (std::size_t k = begin; k < end && ring.size() < max_fit_vertices; ++k) {
      for (auto w : vertices_around_target(halfedge(ring[k], pm), pm)) {
        if (ring.size() == max_fit_vertices) break;
        if (in_ring.insert(w).second) ring.push_back(w);
      }
    }
    begin = end;
  }
  if (ring.size() < 9) return n0;
  const auto& pv = get(vpm, v);
  const Vec3 n = to_array(n0);
  Vec3 u, w;
  tangent_frame(n, u, w);
  std::vector<std::array<double, 3>> local;
  double extent = 0;
  for (std::size_t k = 1; k < ring.size(); ++k) {
    const auto& q = get(vpm, ring[k]);
    const double d[3] = {CGAL::to_double(q.x() - pv.x()), CGAL::to_double(q.y() - pv.y()),
                         CGAL::to_double(q.z() - pv.z())};
    local.push_back({d[0] * u[0] + d[1] * u[1] + d[2] * u[2],
                     d[0] * w[0] + d[1] * w[1] + d[2] * w[2],
                     d[0] * n[0] + d[1] * n[1] + d[2] * n[2]});
    extent = std::max(extent, std::hypot(local.back()[0], local.back()[1]));
  }
  if (!(extent > 0)) return n0;
  Eigen::MatrixXd design(local.size(), 5);
  Eigen::VectorXd heights(local.size());
  double near = 0;  // mean distance of the one-ring
  std::size_t ring1 = 0;
  for (auto w1 : vertices_around_target(halfedge(v, pm), pm)) {
    near += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, w1), pv)));
    ++ring1;
  }
  near = ring1 > 0 ? near / double(ring1) : extent;
  for (std::size_t k = 0; k < local.size(); ++k) {
    const double x = local[k][0] / extent, y = local[k][1] / extent;
    const double d2 = (local[k][0] * local[k][0] + local[k][1] * local[k][1]) / (near * near);
    const double weight = std::exp(-0.5 * d2);
    design.row(Eigen::Index(k)) << weight * x, weight * y, weight * x * x, weight * x * y,
        weight * y * y;
    heights(Eigen::Index(k)) = weight * local[k][2] / extent;
  }
  Eigen::VectorXd c;
  if (!solve_least_squares(design, heights, 5, c)) return n0;
  {
    // Iteratively reweighted least squares with Cauchy weights on the residuals, scaled by
    // their median absolute deviation (1.4826 MAD estimates the standard deviation; 2.385 is
    // Cauchy's constant for 95% efficiency under Gaussian noise).
    const Eigen::MatrixXd base_design = design;
    const Eigen::VectorXd base_heights = heights;
    for (int iteration = 0; iteration < 4 && c.allFinite(); ++iteration) {
      const Eigen::VectorXd residual = base_design * c - base_heights;
      std::vector<double> magnitudes(std::size_t(residual.size()));
      for (Eigen::Index k = 0; k < residual.size(); ++k)
        magnitudes[std::size_t(k)] = std::abs(residual(k));
      std::nth_element(magnitudes.begin(), magnitudes.begin() + magnitudes.size() / 2,
                       magnitudes.end());
      const double scale = 1.4826 * magnitudes[magnitudes.size() / 2];
      if (!(scale > 0)) break;  // the majority fits exactly
      Eigen::MatrixXd weighted = base_design;
      Eigen::VectorXd weighted_heights = base_heights;
      for (Eigen::Index k = 0; k < residual.size(); ++k) {
        const double u = residual(k) / (2.385 * scale);
        const double weight = 1.0 / std::sqrt(1.0 + u * u);  // square root of Cauchy's weight
        weighted.row(k) *= weight;
        weighted_heights(k) *= weight;
      }
      if (!solve_least_squares(weighted, weighted_heights, 5, c)) break;
    }
  }
  if (!c.allFinite()) return n0;
  // Tangent plane at v: n0 - c1 u - c2 w (the scale cancels in the slopes).
  const Vector_3 fitted(n[0] - c(0) * u[0] - c(1) * w[0], n[1] - c(0) * u[1] - c(1) * w[1],
                        n[2] - c(0) * u[2] - c(1) * w[2]);
  const double l = std::sqrt(CGAL::to_double(fitted.squared_length()));
  if (!(l > 0) || CGAL::to_double(fitted * n0) <= 0) return n0;
  return fitted / l;
}

/// The border polygon of the hole of `border_halfedge` and its vertices, in order.
template <class Kernel, class PolygonMesh, class VertexPointMap>
Hole_polygon<Kernel> read_hole_polygon(
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    const PolygonMesh& pm, VertexPointMap vpm,
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& vertices,
    bool fit_normals = true) {
  using Vector_3 = typename Kernel::Vector_3;
  Hole_polygon<Kernel> hole;
  vertices.clear();
  for (auto h : halfedges_around_face(border_halfedge, pm)) {
    const auto v = source(h, pm);
    vertices.push_back(v);
    const auto& p = get(vpm, v);
    hole.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                             CGAL::to_double(p.z()));
    const Vector_3 n0 = vertex_normal<Kernel>(v, pm, vpm);
    hole.face_normals.push_back(n0);
    hole.normals.push_back(fit_normals ? fitted_vertex_normal<Kernel>(v, n0, pm, vpm) : n0);
    const auto o = opposite(h, pm);
    hole.outside.push_back(is_border(o, pm) ? Vector_3(0, 0, 0)
                                            : face_unit_normal<Kernel>(
                                                  get(vpm, source(o, pm)), get(vpm, target(o, pm)),
                                                  get(vpm, target(next(o, pm), pm))));
  }
  return hole;
}

}  // namespace shape_prediction
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_HOLE_POLYGON_H
