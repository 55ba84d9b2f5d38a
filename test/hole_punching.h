// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_TEST_HOLE_PUNCHING_H
#define MESH_REPAIR_TEST_HOLE_PUNCHING_H

// Test helpers: punch a disc of faces around a point, so tests can fill a hole whose truth is
// known, and count border cycles.

#include <CGAL/Mesh_repair/internal/hole_benchmark/punch.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

#include <cstddef>

namespace mesh_repair_test {

/// Removes a disc of faces around `center` (the library's one puncher, see
/// `internal::hole_benchmark::punch_ball_hole`). Returns the number of faces removed.
template <class Mesh, class Point>
std::size_t punch_hole(Mesh& mesh, const Point& center, double radius) {
  std::size_t removed = 0;
  CGAL::Mesh_repair::internal::hole_benchmark::punch_ball_hole(mesh, center, radius, &removed);
  return removed;
}

template <class Mesh>
std::size_t count_border_cycles(const Mesh& mesh) {
  return CGAL::Mesh_repair::internal::border_cycles(mesh).size();
}

}  // namespace mesh_repair_test

#endif  // MESH_REPAIR_TEST_HOLE_PUNCHING_H
