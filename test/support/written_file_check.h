// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_TEST_WRITTEN_FILE_CHECK_H
#define MESH_REPAIR_TEST_WRITTEN_FILE_CHECK_H

// The written file against its report, for the CLI suites: the output is read back with CGAL's
// own reader (`Polygon_mesh_processing::IO::read_polygon_mesh`: the soup repaired, coincident
// points merged, oriented, then built), not with ours, and the report of `mesh_repair repair`
// must say what that reading shows. Compiled once in the test-support library
// (written_file_check.cpp).

#include <cstddef>
#include <string>

namespace mesh_repair_test {

/// What CGAL's reading of a mesh file shows.
struct Cgal_reading {
  bool readable = false;
  std::size_t points = 0, polygons = 0;  ///< in the file
  std::size_t coincident_points = 0;     ///< points of the file at the position of another
  std::size_t duplicated_polygons = 0;   ///< after merging points, either orientation
  std::size_t vertices = 0, faces = 0, border_cycles = 0;
  std::size_t non_manifold_edges = 0, non_manifold_vertices = 0;
  std::size_t self_intersections = 0;  ///< pairs CGAL finds in the mesh it read
  bool valid = false, closed = false, manifold = false;
};

/// Reads `path` as CGAL's `Polygon_mesh_processing::IO::read_polygon_mesh` does (the same calls,
/// with a visitor that counts the non-manifold elements the orientation splits), and checks that
/// the mesh built is the one `read_polygon_mesh` itself builds.
Cgal_reading read_like_cgal(const std::string& path);

std::string file_text(const std::string& path);

/// The text of the object `"key": {...}` that is a member of the report's top-level object.
std::string member_object(const std::string& json, const std::string& key);

/// The value (number, true/false or a quoted string's content) of a direct member of an
/// object returned by `member_object`; empty if absent.
std::string member_value(const std::string& object, const std::string& key);

long long member_integer(const std::string& object, const std::string& key);

/// The report of `mesh_repair repair` says what CGAL's reading of the written file shows, and
/// the exit status is the report's status. `name` labels the failures.
void expect_report_is_the_reading(const std::string& report_path, const Cgal_reading& read,
                                  int exit_status, const std::string& name);

}  // namespace mesh_repair_test

#endif  // MESH_REPAIR_TEST_WRITTEN_FILE_CHECK_H
