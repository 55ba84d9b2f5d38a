// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SOUP_TO_MESH_H
#define CGAL_MESH_REPAIR_INTERNAL_SOUP_TO_MESH_H

// A polygon soup that is a polygon mesh (`is_polygon_soup_a_polygon_mesh`) into a FaceGraph in
// time linear in its size. CGAL 5.5's `polygon_soup_to_polygon_mesh` adds each face with
// `Euler::add_face`, which walks around each corner vertex: quadratic in a vertex's degree
// (a fan of 100,000 triangles around one vertex took 17 s to read, 10^6 about half an hour).
// Same result otherwise: vertex i is point i, face k is polygon k.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

template <class PointRange, class PolygonRange, class PolygonMesh>
void polygon_mesh_soup_to_mesh(const PointRange& points, const PolygonRange& polygons,
                               PolygonMesh& pm) {
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  auto vpm = get(CGAL::vertex_point, pm);
  using Mesh_point = typename boost::property_traits<decltype(vpm)>::value_type;
  std::vector<vertex_descriptor> vertices;
  vertices.reserve(points.size());
  for (const auto& p : points) {
    const vertex_descriptor v = add_vertex(pm);
    put(vpm, v, Mesh_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    vertices.push_back(v);
  }
  // The halfedge of each directed soup edge u -> w, keyed u * n + w.
  const std::uint64_t n = points.size();
  std::unordered_map<std::uint64_t, halfedge_descriptor> directed;
  std::vector<halfedge_descriptor> around;
  for (const auto& polygon : polygons) {
    const std::size_t k = polygon.size();
    around.clear();
    for (std::size_t i = 0; i < k; ++i) {
      const std::uint64_t u = polygon[i], w = polygon[(i + 1) % k];
      const auto reverse = directed.find(w * n + u);
      halfedge_descriptor h;
      if (reverse != directed.end()) {
        h = opposite(reverse->second, pm);
      } else {
        h = halfedge(add_edge(pm), pm);
        set_target(h, vertices[w], pm);
        set_target(opposite(h, pm), vertices[u], pm);
        set_face(opposite(h, pm), GT::null_face(), pm);
      }
      directed.emplace(u * n + w, h);
      around.push_back(h);
    }
    const auto f = add_face(pm);
    for (std::size_t i = 0; i < k; ++i) {
      set_next(around[i], around[(i + 1) % k], pm);
      set_face(around[i], f, pm);
      set_halfedge(target(around[i], pm), around[i], pm);
    }
    set_halfedge(f, around[k - 1], pm);  // the face starts at the polygon's first vertex
  }
  // Border halfedges: the opposites of soup edges used once. Each vertex of a polygon mesh has
  // at most one outgoing border halfedge, which follows the one coming in; a border vertex's
  // halfedge is its incoming border halfedge (CGAL's convention).
  std::vector<halfedge_descriptor> border_from(vertices.size(), GT::null_halfedge());
  std::vector<std::pair<halfedge_descriptor, std::uint64_t>> borders;  // and its target
  for (const auto& [key, h] : directed) {
    const std::uint64_t u = key / n, w = key % n;
    if (directed.count(w * n + u)) continue;
    border_from[w] = opposite(h, pm);
    borders.emplace_back(opposite(h, pm), u);
  }
  for (const auto& [b, to] : borders) {
    set_next(b, border_from[to], pm);
    set_halfedge(vertices[to], b, pm);
  }
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SOUP_TO_MESH_H
