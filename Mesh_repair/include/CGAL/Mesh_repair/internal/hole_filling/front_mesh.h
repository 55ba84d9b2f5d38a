// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_FRONT_MESH_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_FRONT_MESH_H

// Between a mesh and the advancing front: the front's input read from a border cycle, and the
// front's triangulation written back into the mesh. Any method that meshes a hole with the front
// (advancing_front, shape_prediction) uses these two functions.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/advancing_front_core.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// The front's input for the border cycle of `h`, and the mesh vertex of each input point.
template <class PolygonMesh, class VertexPointMap>
Front_input front_input_from_border(
    const PolygonMesh& pm, VertexPointMap vpm,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& point_vertices) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  Front_input input;
  std::unordered_map<vertex_descriptor, std::size_t> index;
  point_vertices.clear();
  for (auto c : halfedges_around_face(h, pm)) {
    const vertex_descriptor v = source(c, pm);
    auto inserted = index.emplace(v, point_vertices.size());
    if (inserted.second) {
      point_vertices.push_back(v);
      input.points.push_back(to_array(get(vpm, v)));
      Vec3 normal_sum{0, 0, 0};
      for (auto f : faces_around_target(halfedge(v, pm), pm)) {
        if (f == boost::graph_traits<PolygonMesh>::null_face()) continue;
        const auto fh = halfedge(f, pm);
        normal_sum =
            add(normal_sum,
                normalized(triangle_normal(get(vpm, source(fh, pm)), get(vpm, target(fh, pm)),
                                           get(vpm, target(next(fh, pm), pm)))));
      }
      input.normals.push_back(normal_sum);
    }
    input.cycle.push_back(inserted.first->second);
  }
  for (std::size_t k = 0; k < point_vertices.size(); ++k) {
    for (auto around : halfedges_around_target(point_vertices[k], pm)) {
      const auto other = index.find(source(around, pm));
      if (other != index.end() && other->second > k)
        input.existing_edges.emplace_back(k, other->second);
    }
  }
  return input;
}

/// Adds the front's new points and triangles to the mesh (triangles in creation order, so each
/// one is attached to the current border); records them in `patch`. False when the mesh refuses
/// a face (the caller rolls back `patch`).
template <class PolygonMesh, class VertexPointMap>
bool insert_front_triangulation(
    PolygonMesh& pm, VertexPointMap vpm, const Front_triangulation& triangulation,
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& point_vertices,
    Fill_patch<PolygonMesh>& patch) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  std::vector<vertex_descriptor> vertex_of(point_vertices);
  for (std::size_t k = triangulation.border_points; k < triangulation.points.size(); ++k) {
    const Vec3& p = triangulation.points[k];
    const vertex_descriptor v = add_vertex(pm);
    put(vpm, v, Point(p[0], p[1], p[2]));
    patch.vertices.push_back(v);
    vertex_of.push_back(v);
  }
  for (const auto& t : triangulation.triangles) {
    const std::array<vertex_descriptor, 3> face{vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]};
    const auto f = CGAL::Euler::add_face(face, pm);
    if (f == boost::graph_traits<PolygonMesh>::null_face()) return false;
    patch.faces.push_back(f);
  }
  return true;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_FRONT_MESH_H
