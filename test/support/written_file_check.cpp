// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The written file against its report (written_file_check.h), compiled once for the CLI suites.
#include "support/written_file_check.h"

#include "support/cgal_calls.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace mesh_repair_test {

namespace {
struct Non_manifold {
  std::set<std::pair<std::size_t, std::size_t>> edges;
  std::set<std::size_t> vertices;
};
// CGAL copies the visitor: the sets live outside.
struct Orientation_visitor : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  Non_manifold* found;
  explicit Orientation_visitor(Non_manifold* f) : found(f) {}
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t) {
    found->edges.insert(std::minmax(a, b));
  }
  void non_manifold_vertex(std::size_t v, std::size_t) { found->vertices.insert(v); }
};
}  // namespace

Cgal_reading read_like_cgal(const std::string& path) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  Cgal_reading r;
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, points, polygons)) return r;
  r.points = points.size();
  r.polygons = polygons.size();
  r.coincident_points = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  std::vector<std::vector<std::size_t>> merged = polygons;
  r.duplicated_polygons = PMP::merge_duplicate_polygons_in_polygon_soup(points, merged);
  PMP::repair_polygon_soup(points, polygons);
  Non_manifold found;
  PMP::orient_polygon_soup(points, polygons,
                           CGAL::parameters::visitor(Orientation_visitor(&found)));
  Mesh mesh;
  if (!read_repaired_polygon_mesh(path, mesh)) return r;
  r.readable = true;
  r.vertices = mesh.number_of_vertices();
  r.faces = mesh.number_of_faces();
  r.valid = CGAL::is_valid_polygon_mesh(mesh);
  const std::vector<Mesh::Halfedge_index> cycles = boundary_cycles(mesh);
  std::vector<Mesh::Halfedge_index> pinched;
  PMP::non_manifold_vertices(mesh, std::back_inserter(pinched));
  r.border_cycles = cycles.size();
  r.closed = r.faces > 0 && cycles.empty();
  r.non_manifold_edges = found.edges.size();
  r.non_manifold_vertices = found.vertices.size() + pinched.size();
  r.manifold = r.non_manifold_edges + r.non_manifold_vertices == 0;
  r.self_intersections = self_intersections(mesh).size();
  // The calls above are those of read_polygon_mesh: the same soup gives the same mesh.
  EXPECT_EQ(polygons.size(), r.faces) << path;
  return r;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string member_object(const std::string& json, const std::string& key) {
  const std::string opening = "\n  \"" + key + "\": {";
  const std::size_t start = json.find(opening);
  if (start == std::string::npos) return {};
  const std::size_t end = json.find("\n  }", start);
  return json.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

std::string member_value(const std::string& object, const std::string& key) {
  const std::regex pattern("\n    \"" + key + "\": (\"([^\"]*)\"|[^,\n]+)");
  std::smatch match;
  if (!std::regex_search(object, match, pattern)) return {};
  return match[2].matched ? std::string(match[2]) : std::string(match[1]);
}

long long member_integer(const std::string& object, const std::string& key) {
  const std::string value = member_value(object, key);
  return value.empty() ? -1 : std::stoll(value);
}

namespace {
const char* boolean(bool b) {
  return b ? "true" : "false";
}
}  // namespace

void expect_report_is_the_reading(const std::string& report_path, const Cgal_reading& read,
                                  int exit_status, const std::string& name) {
  const std::string json = file_text(report_path);
  const std::string repair = member_object(json, "repair");
  const std::string written = member_object(json, "written_file");
  const std::string after = member_object(json, "defects_after");
  ASSERT_FALSE(repair.empty()) << name << ": no repair object in " << report_path;
  ASSERT_FALSE(written.empty()) << name << ": no written_file object";
  ASSERT_TRUE(read.readable) << name << ": CGAL cannot read the output back";
  EXPECT_EQ(member_value(repair, "valid"), boolean(read.valid)) << name;
  EXPECT_EQ(member_value(repair, "closed"), boolean(read.closed)) << name;
  EXPECT_EQ(member_value(repair, "manifold"), boolean(read.manifold)) << name;
  EXPECT_EQ(member_integer(repair, "border_cycles_left"), (long long)read.border_cycles) << name;
  EXPECT_EQ(member_integer(written, "vertices"), (long long)read.vertices) << name;
  EXPECT_EQ(member_integer(written, "faces"), (long long)read.faces) << name;
  EXPECT_EQ(member_integer(written, "non_manifold_edges"), (long long)read.non_manifold_edges)
      << name;
  EXPECT_EQ(member_integer(written, "non_manifold_vertices"), (long long)read.non_manifold_vertices)
      << name;
  // The pairs a user of the file finds: where the reading splits non-manifold vertices and
  // edges, faces that met there become separate faces that touch.
  if (member_value(repair, "self_intersections_checked") == "true" &&
      member_value(repair, "self_intersections_output_truncated") == "false") {
    EXPECT_EQ(member_integer(repair, "self_intersections_output"),
              (long long)read.self_intersections)
        << name;
  }
  EXPECT_EQ(member_integer(written, "duplicated_faces_removed"),
            (long long)read.duplicated_polygons)
      << name;
  // defects_after is the defect report of that reading: one definition of manifold.
  EXPECT_EQ(member_integer(after, "non_manifold_vertices") +
                    member_integer(after, "non_manifold_edges") ==
                0,
            read.manifold)
      << name;
  EXPECT_EQ(member_integer(after, "border_cycles"), (long long)read.border_cycles) << name;
  EXPECT_EQ(member_integer(after, "faces"), (long long)read.faces) << name;
  // Coincident distinct vertices only where the surface is non-manifold, and then said so.
  if (read.coincident_points > 0 && read.points != read.polygons * 3) {  // not an STL soup
    EXPECT_FALSE(read.manifold) << name << ": " << read.coincident_points
                                << " coincident distinct vertices in a manifold output";
  }
  const std::string status = member_value(repair, "status");
  const int expected = status == "complete"               ? 0
                       : status == "complete_except_kept" ? 3
                       : status == "incomplete"           ? 1
                                                          : -1;
  EXPECT_EQ(exit_status, expected) << name << ": status " << status;
  if (status != "incomplete") {
    EXPECT_TRUE(read.valid) << name;
    // Non-manifold only where separate parts touch, kept on purpose and said so.
    if (member_value(repair, "non_manifold_only_between_components") != "true") {
      EXPECT_TRUE(read.manifold) << name;
    }
  }
}

}  // namespace mesh_repair_test
