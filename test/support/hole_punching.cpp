// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The hole-punching helpers (hole_punching.h), compiled once for the suites.
#include "support/hole_punching.h"

#include <CGAL/Mesh_repair/internal/hole_benchmark/punch.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <vector>

namespace mesh_repair_test {

std::size_t punch_hole(Support_mesh& mesh, const Support_point& center, double radius) {
  std::size_t removed = 0;
  CGAL::Mesh_repair::internal::hole_benchmark::punch_ball_hole(mesh, center, radius, &removed);
  return removed;
}

std::size_t remove_faces_in_plane_z(Support_mesh& mesh, double z) {
  std::vector<Support_mesh::Face_index> in_plane;
  for (auto f : mesh.faces()) {
    bool all = true;
    for (auto v : vertices_around_face(mesh.halfedge(f), mesh)) all = all && mesh.point(v).z() == z;
    if (all) in_plane.push_back(f);
  }
  for (auto f : in_plane) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  mesh.collect_garbage();
  return in_plane.size();
}

std::size_t count_border_cycles(const Support_mesh& mesh) {
  return CGAL::Mesh_repair::internal::border_cycles(mesh).size();
}

}  // namespace mesh_repair_test
