// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_SOUP_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_SOUP_H

// Closed parts as triangle soups and back, for the units that compute unions and outer surfaces
// (solid_union_impl.h, self_union_impl.h).

#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

namespace solid_union {

/// `soup` as a closed mesh; an empty string, or why it is not one.
inline std::string to_closed_mesh(const Triangle_soup& soup, Core_mesh& mesh) {
  std::vector<Core_mesh::Vertex_index> vertices;
  vertices.reserve(soup.points.size());
  for (const auto& p : soup.points) vertices.push_back(mesh.add_vertex(p));
  for (const auto& t : soup.polygons)
    if (t.size() != 3 ||
        mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) == Core_mesh::null_face())
      return "a part is not a manifold triangle mesh";
  if (!CGAL::is_closed(mesh)) return "a part is not closed";
  return {};
}

/// `soup` as a mesh; an empty string, or why it is not a solid that corefinement accepts.
inline std::string to_solid(const Triangle_soup& soup, Core_mesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const std::string why = to_closed_mesh(soup, mesh);
  if (!why.empty()) return why;
  if (PMP::does_self_intersect(mesh)) return "a part intersects itself";
  // An inward part (the soup's orientation is only consistent) is turned outward.
  PMP::orient_to_bound_a_volume(mesh);
  if (!PMP::does_bound_a_volume(mesh)) return "a part does not bound a volume";
  return {};
}

/// `mesh` as a soup; where the surface touches itself at a vertex (two fans of faces around one
/// vertex, which corefinement can leave), each fan gets a point of its own, so that the soup can
/// be rebuilt face by face. Points and triangles are sorted (each triangle from its smallest
/// index): CGAL's corefinement and autorefinement number their output in an order that depends
/// on memory addresses, and the rebuilt part would otherwise differ from run to run.
inline void to_soup(Core_mesh& mesh, Triangle_soup& soup) {
  CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(mesh);
  soup = Triangle_soup();
  std::vector<Core_mesh::Vertex_index> by_point(mesh.vertices().begin(), mesh.vertices().end());
  std::stable_sort(by_point.begin(), by_point.end(),
                   [&](auto a, auto b) { return mesh.point(a) < mesh.point(b); });
  std::vector<std::size_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  for (auto v : by_point) {
    index[v] = soup.points.size();
    soup.points.push_back(mesh.point(v));
  }
  for (auto f : mesh.faces()) {
    std::vector<std::size_t> triangle;
    for (auto v : vertices_around_face(mesh.halfedge(f), mesh)) triangle.push_back(index[v]);
    std::rotate(triangle.begin(), std::min_element(triangle.begin(), triangle.end()),
                triangle.end());
    soup.polygons.push_back(std::move(triangle));
  }
  std::sort(soup.polygons.begin(), soup.polygons.end());
}

}  // namespace solid_union

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_SOUP_H
