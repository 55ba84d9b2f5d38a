// remove_slivers (thesis 4.5, Figures 4.13-4.14): short-edge slivers collapse, others flip,
// features stay, and no change folds, pinches or self-intersects the mesh.
#include "support/stitch_test_meshes.h"

#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/remove_slivers.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>
#include <gtest/gtest.h>

namespace {
using namespace stitch_test;
namespace MR = CGAL::Mesh_repair;

Mesh flat_grid(int n) {
  Soup soup;
  add_grid_patch(soup, Point(0, 0, 0), Vector(n, 0, 0), Vector(0, n, 0), n, n);
  return to_mesh(soup);
}

vertex_descriptor vertex_at(const Mesh& mesh, double x, double y) {
  for (vertex_descriptor v : vertices(mesh))
    if (mesh.point(v).x() == x && mesh.point(v).y() == y) return v;
  return Mesh::null_vertex();
}

void expect_valid_manifold_unfolded(const Mesh& mesh, const MR::Sliver_result& result) {
  EXPECT_TRUE(result.valid);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_triangle_mesh(mesh));
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
  EXPECT_FALSE(self_intersects(mesh));
}

TEST(RemoveSlivers, ShortEdgeSliversAreCollapsedAtTheMidpointOnASmoothSurface) {
  // Figure 4.13(d): an interior node pushed next to its neighbour makes slivers with a short edge.
  Mesh grid = flat_grid(6);
  const vertex_descriptor moved = vertex_at(grid, 3, 3);
  grid.point(moved) = Point(3.97, 3.0, 0);
  const std::size_t faces_before = grid.number_of_faces();
  const MR::Sliver_result result = MR::remove_slivers(grid);
  expect_valid_manifold_unfolded(grid, result);
  EXPECT_GT(result.slivers_before, 0u);
  EXPECT_GE(result.collapsed, 1u);
  EXPECT_EQ(result.slivers_after, 0u);
  EXPECT_EQ(grid.number_of_faces(), faces_before - 2 * result.collapsed);
  EXPECT_EQ(border_cycle_count(grid), 1u);
  for (vertex_descriptor v : vertices(grid)) EXPECT_EQ(grid.point(v).z(), 0.0);
}

TEST(RemoveSlivers, CapSliverIsRemovedByAnEdgeSwap) {
  // Figure 4.14(b): a node pushed almost onto the opposite diagonal makes a cap with no short edge.
  Mesh grid = flat_grid(4);
  grid.point(vertex_at(grid, 2, 2)) = Point(2.45, 1.55, 0);
  const MR::Sliver_result result =
      MR::remove_slivers(grid, MR::parameters::tolerance_edge_length(0.1));
  expect_valid_manifold_unfolded(grid, result);
  EXPECT_GE(result.flipped, 1u);
  EXPECT_EQ(result.collapsed, 0u);
  EXPECT_GT(result.min_shape_factor_after, result.min_shape_factor_before);
}

TEST(RemoveSlivers, FeatureLinesOfACubeSurviveSliverRemoval) {
  Mesh cube;
  MR::make_subdivided_cube<Mesh, Point>(cube, 1.0, 4);
  // Slide nodes along a cube edge and inside a face towards their neighbours.
  for (vertex_descriptor v : vertices(cube)) {
    const Point& p = cube.point(v);
    if (p.x() == 0.5 && p.y() == 0 && p.z() == 0) cube.point(v) = Point(0.73, 0, 0);
    if (p.x() == 0.5 && p.y() == 0.5 && p.z() == 1) cube.point(v) = Point(0.5, 0.72, 1);
  }
  const MR::Sliver_result result = MR::remove_slivers(cube);
  expect_valid_manifold_unfolded(cube, result);
  EXPECT_TRUE(CGAL::is_closed(cube));
  EXPECT_GT(result.collapsed + result.flipped, 0u);
  std::size_t corners = 0;
  for (vertex_descriptor v : vertices(cube)) {
    const Point& p = cube.point(v);
    const double to_surface =
        std::min({std::abs(p.x()), std::abs(p.y()), std::abs(p.z()), std::abs(1 - p.x()),
                  std::abs(1 - p.y()), std::abs(1 - p.z())});
    EXPECT_LT(to_surface, 1e-12) << p;
    const auto at_bound = [](double c) { return c == 0 || c == 1; };
    if (at_bound(p.x()) && at_bound(p.y()) && at_bound(p.z())) ++corners;
  }
  EXPECT_EQ(corners, 8u);
}

TEST(RemoveSlivers, JitteredSphereLosesSliversWithoutFoldsOrSelfIntersections) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  CGAL::Random random(3);
  for (vertex_descriptor v : vertices(sphere)) {
    if (random.get_double() > 0.3) continue;
    const Point& p = sphere.point(v);
    const Vector shift(random.get_double(-1, 1), random.get_double(-1, 1),
                       random.get_double(-1, 1));
    const Point q = p + 0.06 * shift;
    sphere.point(v) =
        CGAL::ORIGIN + (q - CGAL::ORIGIN) / std::sqrt((q - CGAL::ORIGIN).squared_length());
  }
  ASSERT_FALSE(self_intersects(sphere));
  const MR::Sliver_result result = MR::remove_slivers(sphere);
  expect_valid_manifold_unfolded(sphere, result);
  EXPECT_TRUE(CGAL::is_closed(sphere));
  EXPECT_GT(result.slivers_before, 0u);
  EXPECT_LT(result.slivers_after, result.slivers_before);
  EXPECT_LT(max_distance_to_unit_sphere(sphere), 0.01);
}

TEST(RemoveSlivers, SliversLeftByTJunctionStitchingAreReduced) {
  Mesh cube = to_mesh(cube_of_separate_faces(0.01, {3, 4, 5, 4, 3, 6}));
  MR::stitch_gaps(cube);
  ASSERT_TRUE(CGAL::is_closed(cube));
  const MR::Sliver_result result = MR::remove_slivers(cube);
  expect_valid_manifold_unfolded(cube, result);
  EXPECT_TRUE(CGAL::is_closed(cube));
  EXPECT_LE(result.slivers_after, result.slivers_before);
}

TEST(RemoveSlivers, ThresholdZeroChangesNothing) {
  Mesh grid = flat_grid(6);
  grid.point(vertex_at(grid, 3, 3)) = Point(3.97, 3.0, 0);
  const std::size_t faces_before = grid.number_of_faces();
  const MR::Sliver_result result =
      MR::remove_slivers(grid, MR::parameters::shape_factor_threshold(0.0));
  EXPECT_EQ(result.slivers_before, 0u);
  EXPECT_EQ(result.collapsed + result.flipped, 0u);
  EXPECT_EQ(grid.number_of_faces(), faces_before);
}

}  // namespace
