// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_TEST_HOLE_PUNCHING_H
#define MESH_REPAIR_TEST_HOLE_PUNCHING_H

// Test helpers: punch a disc of faces around a point or remove a plane's faces, so tests can
// fill a hole whose truth is known, and count border cycles. Compiled once in the test-support
// library (hole_punching.cpp).

#include "support/cgal_calls.h"

#include <cstddef>

namespace mesh_repair_test {

/// Removes a disc of faces around `center` (the library's one puncher, see
/// `internal::hole_benchmark::punch_ball_hole`). Returns the number of faces removed.
std::size_t punch_hole(Support_mesh& mesh, const Support_point& center, double radius);

/// Removes every face whose corners all lie in the plane z = `z` (exact comparison): a box
/// loses its bottom. Returns the number of faces removed; the mesh is garbage-collected.
std::size_t remove_faces_in_plane_z(Support_mesh& mesh, double z);

/// The border cycles of `mesh` as the library counts them (`internal::border_cycles`).
std::size_t count_border_cycles(const Support_mesh& mesh);

}  // namespace mesh_repair_test

#endif  // MESH_REPAIR_TEST_HOLE_PUNCHING_H
