// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_TEST_SUPPORT_CGAL_CALLS_H
#define MESH_REPAIR_TEST_SUPPORT_CGAL_CALLS_H

// The CGAL calls the suites repeat, on Surface_mesh<Epick> only, as plain functions compiled once
// in the test-support library (test/support/cgal_calls.cpp). Each one is CGAL's function with
// the arguments the suites gave it (default named parameters unless said otherwise): a suite that
// calls `PMP::does_self_intersect` itself compiles Box_intersection_d, the triangle-triangle tests
// and their exact fallback again (a few seconds of CPU per call site type), and one that calls
// `CGAL::IO::read_polygon_mesh` compiles every reader; here they are compiled once for all suites.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace mesh_repair_test {

using Support_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Support_point = Support_kernel::Point_3;
using Support_mesh = CGAL::Surface_mesh<Support_point>;
using Face_pair = std::pair<Support_mesh::Face_index, Support_mesh::Face_index>;

/// `PMP::does_self_intersect(mesh)`.
bool does_self_intersect(const Support_mesh& mesh);

/// The pairs `PMP::self_intersections(mesh, out)` reports, in its order.
std::vector<Face_pair> self_intersections(const Support_mesh& mesh);

/// One halfedge per border cycle, as `PMP::extract_boundary_cycles` gives them.
std::vector<Support_mesh::Halfedge_index> boundary_cycles(const Support_mesh& mesh);

/// The number of connected components, `PMP::connected_components` with a face-index map.
std::size_t connected_components(const Support_mesh& mesh);

/// `PMP::is_non_manifold_vertex(v, mesh)` counted over the vertices.
std::size_t non_manifold_vertex_count(const Support_mesh& mesh);

/// `CGAL::IO::read_polygon_mesh(path, mesh)`: CGAL's reader as is (no soup repair).
bool read_polygon_mesh(const std::string& path, Support_mesh& mesh);

/// `PMP::IO::read_polygon_mesh(path, mesh)`: the soup repaired and oriented, then built.
bool read_repaired_polygon_mesh(const std::string& path, Support_mesh& mesh);

/// `PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh)`.
void polygon_soup_to_polygon_mesh(const std::vector<Support_point>& points,
                                  const std::vector<std::vector<std::size_t>>& polygons,
                                  Support_mesh& mesh);
void polygon_soup_to_polygon_mesh(const std::vector<Support_point>& points,
                                  const std::vector<std::array<std::size_t, 3>>& polygons,
                                  Support_mesh& mesh);

/// `PMP::triangulate_faces(mesh)`.
bool triangulate_faces(Support_mesh& mesh);

/// `PMP::triangulate_and_refine_hole(mesh, border, faces, vertices)`: the new faces and
/// vertices appended to `faces` and `vertices`.
void triangulate_and_refine_hole(Support_mesh& mesh, Support_mesh::Halfedge_index border,
                                 std::vector<Support_mesh::Face_index>& faces,
                                 std::vector<Support_mesh::Vertex_index>& vertices);

/// `PMP::triangulate_refine_and_fair_hole(mesh, border, faces, vertices)`; its success flag.
bool triangulate_refine_and_fair_hole(Support_mesh& mesh, Support_mesh::Halfedge_index border,
                                      std::vector<Support_mesh::Face_index>& faces,
                                      std::vector<Support_mesh::Vertex_index>& vertices);

/// `PMP::stitch_borders(mesh, pairs)`: the number of pairs stitched.
std::size_t stitch_borders(
    Support_mesh& mesh,
    const std::vector<std::pair<Support_mesh::Halfedge_index, Support_mesh::Halfedge_index>>&
        pairs);

/// `PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(points, mesh)`.
double max_distance_to_triangle_mesh(const std::vector<Support_point>& points,
                                     const Support_mesh& mesh);

/// `PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(from, to,
/// PMP::parameters::number_of_points_per_area_unit(points_per_area_unit))`.
double approximate_Hausdorff_distance(const Support_mesh& from, const Support_mesh& to,
                                      double points_per_area_unit);

/// `PMP::area(mesh)`.
double area(const Support_mesh& mesh);

/// CGAL's smoothing as `mesh_repair smooth --method cgal` runs it:
/// `PMP::angle_and_area_smoothing(mesh)` then `PMP::tangential_relaxation(mesh)`.
void cgal_smooth(Support_mesh& mesh);

/// The largest distance from `mesh`'s vertices to `input`'s triangles (an AABB tree of
/// `input`'s faces with accelerated distance queries).
double max_distance_to(const Support_mesh& mesh, const Support_mesh& input);

}  // namespace mesh_repair_test

#endif  // MESH_REPAIR_TEST_SUPPORT_CGAL_CALLS_H
