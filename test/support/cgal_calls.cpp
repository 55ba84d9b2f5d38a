// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The one instantiation, for the suites, of the CGAL calls they repeat (cgal_calls.h).
#include "support/cgal_calls.h"

// io.h declares the compiled core's instantiation of PMP::triangulate_faces for this mesh type.
#include <CGAL/Mesh_repair/io.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace mesh_repair_test {

namespace PMP = CGAL::Polygon_mesh_processing;

bool does_self_intersect(const Support_mesh& mesh) {
  return PMP::does_self_intersect(mesh);
}

std::vector<Face_pair> self_intersections(const Support_mesh& mesh) {
  std::vector<Face_pair> pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  return pairs;
}

std::vector<Support_mesh::Halfedge_index> boundary_cycles(const Support_mesh& mesh) {
  std::vector<Support_mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  return cycles;
}

std::size_t connected_components(const Support_mesh& mesh) {
  std::vector<std::size_t> component(num_faces(mesh) + mesh.number_of_removed_faces());
  return PMP::connected_components(mesh, CGAL::make_property_map(component));
}

std::size_t non_manifold_vertex_count(const Support_mesh& mesh) {
  std::size_t count = 0;
  for (Support_mesh::Vertex_index v : vertices(mesh))
    if (PMP::is_non_manifold_vertex(v, mesh)) ++count;
  return count;
}

bool read_polygon_mesh(const std::string& path, Support_mesh& mesh) {
  return CGAL::IO::read_polygon_mesh(path, mesh);
}

bool read_repaired_polygon_mesh(const std::string& path, Support_mesh& mesh) {
  return PMP::IO::read_polygon_mesh(path, mesh);
}

void polygon_soup_to_polygon_mesh(const std::vector<Support_point>& points,
                                  const std::vector<std::vector<std::size_t>>& polygons,
                                  Support_mesh& mesh) {
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
}

void polygon_soup_to_polygon_mesh(const std::vector<Support_point>& points,
                                  const std::vector<std::array<std::size_t, 3>>& polygons,
                                  Support_mesh& mesh) {
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
}

bool triangulate_faces(Support_mesh& mesh) {
  return PMP::triangulate_faces(mesh);
}

void triangulate_and_refine_hole(Support_mesh& mesh, Support_mesh::Halfedge_index border,
                                 std::vector<Support_mesh::Face_index>& faces,
                                 std::vector<Support_mesh::Vertex_index>& vertices) {
  PMP::triangulate_and_refine_hole(mesh, border, std::back_inserter(faces),
                                   std::back_inserter(vertices));
}

bool triangulate_refine_and_fair_hole(Support_mesh& mesh, Support_mesh::Halfedge_index border,
                                      std::vector<Support_mesh::Face_index>& faces,
                                      std::vector<Support_mesh::Vertex_index>& vertices) {
  return std::get<0>(PMP::triangulate_refine_and_fair_hole(mesh, border, std::back_inserter(faces),
                                                           std::back_inserter(vertices)));
}

std::size_t stitch_borders(
    Support_mesh& mesh,
    const std::vector<std::pair<Support_mesh::Halfedge_index, Support_mesh::Halfedge_index>>&
        pairs) {
  return PMP::stitch_borders(mesh, pairs);
}

double max_distance_to_triangle_mesh(const std::vector<Support_point>& points,
                                     const Support_mesh& mesh) {
  return PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(points, mesh);
}

double approximate_Hausdorff_distance(const Support_mesh& from, const Support_mesh& to,
                                      double points_per_area_unit) {
  return PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
      from, to, PMP::parameters::number_of_points_per_area_unit(points_per_area_unit));
}

double area(const Support_mesh& mesh) {
  return PMP::area(mesh);
}

void cgal_smooth(Support_mesh& mesh) {
  PMP::angle_and_area_smoothing(mesh);
  PMP::tangential_relaxation(mesh);
}

double max_distance_to(const Support_mesh& mesh, const Support_mesh& input) {
  using Tree = CGAL::AABB_tree<
      CGAL::AABB_traits<Support_kernel, CGAL::AABB_face_graph_triangle_primitive<Support_mesh>>>;
  Tree tree(faces(input).first, faces(input).second, input);
  tree.accelerate_distance_queries();
  double largest = 0;
  for (auto v : vertices(mesh))
    largest = std::max(largest, std::sqrt(tree.squared_distance(mesh.point(v))));
  return largest;
}

}  // namespace mesh_repair_test
