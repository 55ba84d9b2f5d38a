// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_FRONT_MESH_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_FRONT_MESH_H

// Between a mesh and the advancing front: the front's input read from a border cycle, and the
// front's triangulation written back into the mesh. Any method that meshes a hole with the front
// (advancing_front, shape_prediction) uses these two functions.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/advancing_front_core.h>
#include <CGAL/Mesh_repair/internal/hole_filling/patch_check.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// The front's input for the border cycle of `h`, and the mesh vertex of each input point.
/// `near_faces`, when given (the dispatcher's cache of face boxes), replaces the pass over every
/// face of the mesh that finds the faces near the hole: one scan of boxes instead of geometry.
template <class PolygonMesh, class VertexPointMap>
Front_input front_input_from_border(
    const PolygonMesh& pm, VertexPointMap vpm,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& point_vertices,
    const Face_box_cache<PolygonMesh, VertexPointMap>* near_faces = nullptr) {
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
  // The faces within two rings of the border: no new triangle may meet them.
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::unordered_map<vertex_descriptor, std::size_t> context_index(index);
  std::vector<vertex_descriptor> layer(point_vertices), reached(point_vertices);
  std::unordered_map<vertex_descriptor, bool> in_ring;
  for (vertex_descriptor v : layer) in_ring[v] = true;
  {
    std::vector<vertex_descriptor> next_layer;
    for (vertex_descriptor v : layer) {
      for (auto around : halfedges_around_target(v, pm)) {
        if (in_ring.emplace(source(around, pm), true).second)
          next_layer.push_back(source(around, pm));
      }
    }
    reached.insert(reached.end(), next_layer.begin(), next_layer.end());
  }
  std::unordered_map<face_descriptor, bool> seen_face;
  bool all_triangles = true;
  const auto add_context_face = [&](face_descriptor f) {
    if (f == boost::graph_traits<PolygonMesh>::null_face() || !seen_face.emplace(f, true).second)
      return;
    std::array<std::size_t, 3> corners{0, 0, 0};
    int count = 0;
    for (auto c : halfedges_around_face(halfedge(f, pm), pm)) {
      const vertex_descriptor w = target(c, pm);
      auto found = context_index.find(w);
      if (found == context_index.end()) {
        found = context_index.emplace(w, input.points.size() + input.context_points.size()).first;
        input.context_points.push_back(to_array(get(vpm, w)));
      }
      if (count < 3) corners[std::size_t(count)] = found->second;
      ++count;
    }
    if (count == 3)
      input.context_triangles.push_back(corners);
    else
      all_triangles = false;  // not tested by the front: the caller's own check must run
  };
  for (vertex_descriptor v : reached) {
    for (face_descriptor f : faces_around_target(halfedge(v, pm), pm)) add_context_face(f);
  }
  // Any other face of the mesh that a patch bulging by up to half the border's diameter could
  // meet (a thin part of the mesh facing the hole, another patch): one pass over the faces.
  Vec3 lo = input.points.front(), hi = lo;
  for (const Vec3& p : input.points) {
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], p[d]);
      hi[d] = std::max(hi[d], p[d]);
    }
  }
  const double margin = 0.5 * norm(sub(hi, lo));
  for (int d = 0; d < 3; ++d) {
    lo[d] -= margin;
    hi[d] += margin;
  }
  // Every face whose box overlaps [lo, hi] is in the context (below), so a patch inside that
  // box whose triangles all passed the front's exact test meets no face of the mesh.
  input.context_lo = lo;
  input.context_hi = hi;
  if (near_faces != nullptr) {
    const CGAL::Bbox_3 box(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    for (face_descriptor f : near_faces->overlapping(box, seen_face)) add_context_face(f);
    input.context_complete = all_triangles;
    return input;
  }
  for (face_descriptor f : faces(pm)) {
    if (seen_face.count(f)) continue;
    bool overlaps = true;
    Vec3 flo{0, 0, 0}, fhi{0, 0, 0};
    bool first = true;
    for (auto c : halfedges_around_face(halfedge(f, pm), pm)) {
      const Vec3 p = to_array(get(vpm, target(c, pm)));
      for (int d = 0; d < 3; ++d) {
        flo[d] = first ? p[d] : std::min(flo[d], p[d]);
        fhi[d] = first ? p[d] : std::max(fhi[d], p[d]);
      }
      first = false;
    }
    for (int d = 0; d < 3; ++d) overlaps = overlaps && flo[d] <= hi[d] && fhi[d] >= lo[d];
    if (overlaps) add_context_face(f);
  }
  input.context_complete = all_triangles;
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
