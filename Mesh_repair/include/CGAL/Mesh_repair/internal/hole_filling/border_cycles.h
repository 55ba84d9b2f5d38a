// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_BORDER_CYCLES_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_BORDER_CYCLES_H

// Walking border cycles (closed loops of border halfedges) and describing them, shared by every
// hole-filling method, the dispatcher and the benchmarks.

#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// One halfedge per border cycle of `pm`, in the order of the halfedge iteration: CGAL's
/// `extract_boundary_cycles`, the one border-cycle enumeration of the library (detection,
/// filling, repair and the tool all call this).
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> border_cycles(
    const PolygonMesh& pm) {
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(pm, std::back_inserter(cycles));
  return cycles;
}

/// The border halfedges of the cycle of `h`, in order.
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> cycle_halfedges(
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm) {
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> cycle;
  for (auto c : halfedges_around_face(h, pm)) cycle.push_back(c);
  return cycle;
}

/// The border halfedges of the whole mesh (the border edges).
template <class PolygonMesh>
std::size_t count_border_halfedges(const PolygonMesh& pm) {
  std::size_t n = 0;
  for (auto h : halfedges(pm)) n += is_border(h, pm) ? 1 : 0;
  return n;
}

/// Geometry of a border cycle: what selection predicates and reports need.
struct Border_cycle_geometry {
  std::size_t edges = 0;
  double perimeter = 0;
  double mean_edge_length = 0;
  double diameter = 0;        ///< bounding-box diagonal of the cycle's vertices
  Vec3 centroid{0, 0, 0};     ///< of the vertices
  Vec3 vector_area{0, 0, 0};  ///< Newell's vector area: normal times projected area
  Vec3 ring_normal{0, 0, 0};  ///< sum of the unit normals of the faces along the cycle
};

template <class Point>
Vec3 triangle_normal(const Point& a, const Point& b, const Point& c) {
  return cross(sub(to_array(b), to_array(a)), sub(to_array(c), to_array(a)));
}

template <class PolygonMesh, class VertexPointMap>
Border_cycle_geometry cycle_geometry(
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm,
    VertexPointMap vpm) {
  Border_cycle_geometry g;
  Vec3 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
           std::numeric_limits<double>::max()};
  Vec3 high = scale(low, -1);
  for (auto c : halfedges_around_face(h, pm)) {
    const Vec3 p = to_array(get(vpm, source(c, pm))), q = to_array(get(vpm, target(c, pm)));
    ++g.edges;
    g.perimeter += norm(sub(q, p));
    g.centroid = add(g.centroid, p);
    g.vector_area = add(g.vector_area, scale(cross(p, q), 0.5));
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
    const auto o = opposite(c, pm);
    if (!is_border(o, pm)) {
      const auto n = normalized(triangle_normal(get(vpm, source(o, pm)), get(vpm, target(o, pm)),
                                                get(vpm, target(next(o, pm), pm))));
      g.ring_normal = add(g.ring_normal, n);
    }
  }
  if (g.edges > 0) {
    g.centroid = scale(g.centroid, 1.0 / double(g.edges));
    g.mean_edge_length = g.perimeter / double(g.edges);
    g.diameter = norm(sub(high, low));
  }
  return g;
}

/// Bounding-box diagonal of the whole mesh.
template <class PolygonMesh, class VertexPointMap>
double mesh_bbox_diagonal(const PolygonMesh& pm, VertexPointMap vpm) {
  Vec3 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
           std::numeric_limits<double>::max()};
  Vec3 high = scale(low, -1);
  bool any = false;
  for (auto v : vertices(pm)) {
    const Vec3 p = to_array(get(vpm, v));
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
    any = true;
  }
  return any ? norm(sub(high, low)) : 0.0;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_BORDER_CYCLES_H
