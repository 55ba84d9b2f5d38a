// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_TEST_HOLE_PUNCHING_H
#define MESH_REPAIR_TEST_HOLE_PUNCHING_H

// Test helper: removes a connected disc of faces around a point, so tests can fill a hole whose
// truth is known.

#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <queue>
#include <set>
#include <vector>

namespace mesh_repair_test {

/// Removes the faces reachable from the face nearest to `center` whose vertices all lie within
/// `radius` of it; then removes faces left hanging (two border edges), so the hole's border is
/// one simple cycle in the usual cases. Returns the number of faces removed.
template <class Mesh, class Point>
std::size_t punch_hole(Mesh& mesh, const Point& center, double radius) {
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  auto inside = [&](face_descriptor f) {
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) {
      if (CGAL::squared_distance(mesh.point(v), center) > radius * radius) return false;
    }
    return true;
  };
  std::set<face_descriptor> region;
  std::queue<face_descriptor> queue;
  for (auto f : faces(mesh)) {
    if (inside(f)) {
      queue.push(f);
      region.insert(f);
      break;
    }
  }
  while (!queue.empty()) {
    const face_descriptor f = queue.front();
    queue.pop();
    for (auto h : halfedges_around_face(halfedge(f, mesh), mesh)) {
      const face_descriptor g = face(opposite(h, mesh), mesh);
      if (g != boost::graph_traits<Mesh>::null_face() && !region.count(g) && inside(g)) {
        region.insert(g);
        queue.push(g);
      }
    }
  }
  for (face_descriptor f : region) CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
  std::size_t removed = region.size();
  for (bool again = true; again;) {
    again = false;
    for (auto f : faces(mesh)) {
      int border_edges = 0;
      for (auto h : halfedges_around_face(halfedge(f, mesh), mesh))
        border_edges += is_border(opposite(h, mesh), mesh) ? 1 : 0;
      if (border_edges >= 2) {
        CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
        ++removed;
        again = true;
        break;
      }
    }
  }
  return removed;
}

template <class Mesh>
std::size_t count_border_cycles(const Mesh& mesh) {
  std::set<typename boost::graph_traits<Mesh>::halfedge_descriptor> seen;
  std::size_t cycles = 0;
  for (auto h : halfedges(mesh)) {
    if (!is_border(h, mesh) || seen.count(h)) continue;
    ++cycles;
    for (auto c : halfedges_around_face(h, mesh)) seen.insert(c);
  }
  return cycles;
}

}  // namespace mesh_repair_test

#endif  // MESH_REPAIR_TEST_HOLE_PUNCHING_H
