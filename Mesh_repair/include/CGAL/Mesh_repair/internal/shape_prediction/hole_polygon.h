// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_HOLE_POLYGON_H
#define CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_HOLE_POLYGON_H

// Reads a hole's border polygon off a mesh: node positions in border-halfedge order, the node
// normals of eq. 5.30 (angle-weighted, via cubic_curves.h eq. 4.1) and the normal of the face
// across each border edge.

#include <CGAL/Mesh_repair/internal/cubic_curves.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/shape_estimate.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <utility>
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

/// The border polygon of the hole of `border_halfedge` and its vertices, in order.
template <class Kernel, class PolygonMesh, class VertexPointMap>
Hole_polygon<Kernel> read_hole_polygon(
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    const PolygonMesh& pm, VertexPointMap vpm,
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& vertices) {
  using Vector_3 = typename Kernel::Vector_3;
  Hole_polygon<Kernel> hole;
  vertices.clear();
  for (auto h : halfedges_around_face(border_halfedge, pm)) {
    const auto v = source(h, pm);
    vertices.push_back(v);
    const auto& p = get(vpm, v);
    hole.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                             CGAL::to_double(p.z()));
    hole.normals.push_back(vertex_normal<Kernel>(v, pm, vpm));
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
