// Pernot 4: cleaning the contour of a hole (clean_hole_contour.h).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/clean_hole_contour.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include "support/cgal_calls.h"

#include <array>
#include <cmath>
#include <vector>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using halfedge_descriptor = boost::graph_traits<Mesh>::halfedge_descriptor;
namespace MR = CGAL::Mesh_repair;

Mesh from_soup(const std::vector<Point>& points,
               const std::vector<std::array<std::size_t, 3>>& faces) {
  Mesh mesh;
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& f : faces) polygons.push_back({f[0], f[1], f[2]});
  mesh_repair_test::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}

halfedge_descriptor any_border(const Mesh& mesh) {
  for (auto h : halfedges(mesh))
    if (is_border(h, mesh)) return h;
  return boost::graph_traits<Mesh>::null_halfedge();
}

auto only_badly_oriented(bool preserve) {
  return MR::parameters::treat_degenerate_triangles(false)
      .homogenize_edge_lengths(false)
      .preserve_contour_details(preserve);
}
auto only_degenerate() {
  return MR::parameters::remove_badly_oriented_triangles(false).homogenize_edge_lengths(false);
}

// A 4 x 4 planar grid (z = 0) with one spike triangle (two border edges, apex lifted) on the
// middle of its lower side, and optionally a second spike on the first one.
Mesh grid_with_spikes(int spikes) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, 0, 4, 0, 4, 4, 4, [](double, double) { return 0.0; });
  halfedge_descriptor b = boost::graph_traits<Mesh>::null_halfedge();
  for (auto h : halfedges(mesh)) {
    const Point s = mesh.point(source(h, mesh)), t = mesh.point(target(h, mesh));
    if (is_border(h, mesh) && s.y() == 0 && t.y() == 0 && std::min(s.x(), t.x()) == 2) b = h;
  }
  auto u = source(b, mesh), w = target(b, mesh);
  auto p1 = mesh.add_vertex(Point(2.5, -0.8, 0.9));
  mesh.add_face(u, w, p1);
  if (spikes == 2) {
    auto p2 = mesh.add_vertex(Point(3.2, -1.2, 1.5));
    // the border halfedge p1 -> w of the first spike carries the second one
    mesh.add_face(p1, w, p2);
  }
  return mesh;
}

TEST(CleanHoleContour, SpikeTriangleWithTwoBorderEdgesIsDeleted) {
  Mesh mesh = grid_with_spikes(1);
  const std::size_t faces_before = mesh.number_of_faces();
  const auto result = MR::clean_hole_contour(mesh, any_border(mesh), only_badly_oriented(true));
  EXPECT_EQ(result.badly_oriented_removed, 1u);
  EXPECT_EQ(mesh.number_of_faces(), faces_before - 1);
  EXPECT_EQ(result.border_edges_after, 16u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST(CleanHoleContour, DetailConditionKeepsASpikeRestingOnAnotherSpike) {
  Mesh kept = grid_with_spikes(2);
  const auto preserved = MR::clean_hole_contour(kept, any_border(kept), only_badly_oriented(true));
  EXPECT_EQ(preserved.badly_oriented_removed, 0u);
  EXPECT_EQ(preserved.badly_oriented_kept, 1u);
  Mesh removed = grid_with_spikes(2);
  const auto recursive =
      MR::clean_hole_contour(removed, any_border(removed), only_badly_oriented(false));
  EXPECT_EQ(recursive.badly_oriented_removed, 2u);  // the outer spike, then the one below it
  EXPECT_EQ(recursive.border_edges_after, 16u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(removed));
}

// A fan of four triangles around c; the outer border is the hole. a(0,0) b(2,0) e(2,1) f(0,1).
Mesh fan(const Point& c) {
  return from_soup({Point(0, 0, 0), Point(2, 0, 0), c, Point(2, 1, 0), Point(0, 1, 0)},
                   {{0, 1, 2}, {1, 3, 2}, {3, 4, 2}, {4, 0, 2}});
}

double worst_quality(const Mesh& mesh) {
  double worst = 1;
  for (auto f : faces(mesh)) {
    auto h = halfedge(f, mesh);
    worst =
        std::min(worst, MR::aspect_ratio(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                         mesh.point(target(next(h, mesh), mesh))));
  }
  return worst;
}

TEST(CleanHoleContour, NeedleAtTheContourHasItsSmallEdgeCollapsed) {
  Mesh mesh = fan(Point(0.04, 0.02, 0));
  ASSERT_LT(worst_quality(mesh), 0.25);
  const auto result = MR::clean_hole_contour(mesh, any_border(mesh), only_degenerate());
  EXPECT_EQ(result.degenerate_collapsed, 1u);
  EXPECT_EQ(result.degenerate_left, 0u);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_GE(worst_quality(mesh), 0.25);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST(CleanHoleContour, CapWhoseLongestEdgeIsOnTheBorderIsDeleted) {
  Mesh mesh = fan(Point(1, 0.05, 0));
  const auto result = MR::clean_hole_contour(mesh, any_border(mesh), only_degenerate());
  EXPECT_EQ(result.degenerate_removed, 1u);
  EXPECT_EQ(result.degenerate_left, 0u);
  EXPECT_EQ(mesh.number_of_faces(), 3u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST(CleanHoleContour, CapWhoseLongestEdgeIsInteriorHasItFlipped) {
  // Two triangles: the cap (a, b, c) and (b, a, d); ab is the cap's longest, interior, edge.
  Mesh mesh = from_soup({Point(0, 0, 0), Point(2, 0, 0), Point(1, 0.05, 0), Point(1, -1, 0)},
                        {{0, 1, 2}, {1, 0, 3}});
  const auto result = MR::clean_hole_contour(mesh, any_border(mesh), only_degenerate());
  EXPECT_EQ(result.degenerate_flipped, 1u);
  EXPECT_GT(worst_quality(mesh), 0.05);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST(CleanHoleContour, FlipThatWouldFoldIsRefused) {
  // The same pair with d beyond b, nearly on line ab: the quad a d b c is reflex at b, so the
  // flipped triangle (d, b, c) would be folded over (a, d, c).
  Mesh mesh = from_soup({Point(0, 0, 0), Point(2, 0, 0), Point(1, 0.05, 0), Point(3, -0.01, 0)},
                        {{0, 1, 2}, {1, 0, 3}});
  const auto result = MR::clean_hole_contour(mesh, any_border(mesh), only_degenerate());
  EXPECT_EQ(result.degenerate_flipped, 0u);
  EXPECT_GE(result.degenerate_left, 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

// An annulus of 16 quads (split in two) around a polygonal hole whose vertex 5 is moved
// towards vertex 6: border edge 4-5 is long (1.8 x mean), 5-6 short (0.2 x mean).
Mesh annulus_with_uneven_hole() {
  std::vector<Point> points;
  const int n = 16;
  for (int k = 0; k < n; ++k) {
    double angle = 2 * CGAL_PI * k / n;
    if (k == 5) angle = 2 * CGAL_PI * 5.8 / n;
    points.emplace_back(std::cos(angle), std::sin(angle), 0);
  }
  for (int k = 0; k < n; ++k)
    points.emplace_back(2 * std::cos(2 * CGAL_PI * k / n), 2 * std::sin(2 * CGAL_PI * k / n), 0);
  std::vector<std::array<std::size_t, 3>> faces;
  for (std::size_t k = 0; k < std::size_t(n); ++k) {
    const std::size_t k1 = (k + 1) % n;
    faces.push_back({k, n + k, n + k1});
    faces.push_back({k, n + k1, k1});
  }
  return from_soup(points, faces);
}

TEST(CleanHoleContour, LongBorderEdgeIsSplitAndShortOneCollapsed) {
  Mesh mesh = annulus_with_uneven_hole();
  halfedge_descriptor inner = boost::graph_traits<Mesh>::null_halfedge();
  for (auto h : halfedges(mesh))
    if (is_border(h, mesh) &&
        CGAL::squared_distance(mesh.point(target(h, mesh)), Point(0, 0, 0)) < 2)
      inner = h;
  const auto result = MR::clean_hole_contour(
      mesh, inner,
      MR::parameters::remove_badly_oriented_triangles(false).treat_degenerate_triangles(false));
  EXPECT_EQ(result.edges_split, 1u);
  EXPECT_EQ(result.edges_collapsed, 1u);
  EXPECT_EQ(result.border_edges_after, 16u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  const double mean = 2 * CGAL_PI / 16;  // about the chord length
  for (auto h : CGAL::halfedges_around_face(result.border_halfedge, mesh)) {
    const double length = std::sqrt(CGAL::to_double(
        CGAL::squared_distance(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)))));
    EXPECT_GT(length, 0.5 * mean);
    EXPECT_LT(length, 1.5 * mean);
  }
}

}  // namespace
