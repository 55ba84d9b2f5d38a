// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/optimize_mesh.h>
#include <CGAL/Mesh_repair/quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/internal/genetic/ga_triangulation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include "support/cgal_calls.h"
#include "support/sliver_grid.h"

#include <cmath>
#include <set>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;
namespace support = mesh_repair_test;

void expect_valid(Mesh& mesh, bool closed) {
  mesh.collect_garbage();
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_triangle_mesh(mesh));
  if (closed) {
    EXPECT_TRUE(CGAL::is_closed(mesh));
  }
  EXPECT_FALSE(support::does_self_intersect(mesh));
}

bool on_cube_edge(const Point& p, double size) {
  int extreme = 0;
  for (int k = 0; k < 3; ++k) extreme += (p[k] == 0 || p[k] == size);
  return extreme >= 2;
}

TEST(OptimizeMesh, SubdividedCubeKeepsEightCornersAndTwelveFeatureLines) {
  const double size = 1;
  Mesh cube;
  MR::make_subdivided_cube<Mesh, Point>(cube, size, 8);
  const std::size_t input_faces = cube.number_of_faces();
  const auto result = MR::optimize_mesh(cube, MR::parameters::target_face_ratio(0.1));
  expect_valid(cube, true);
  EXPECT_LT(cube.number_of_faces(), input_faces / 2);
  EXPECT_EQ(result.corner_nodes, 8u);

  std::set<std::array<double, 3>> corners;
  for (auto v : cube.vertices()) {
    const Point& p = cube.point(v);
    int extreme = 0;
    for (int k = 0; k < 3; ++k) extreme += (p[k] == 0 || p[k] == size);
    if (extreme == 3) corners.insert({p.x(), p.y(), p.z()});
  }
  EXPECT_EQ(corners.size(), 8u);

  // Every face stays inside one side of the cube (no face cuts a feature line), and the
  // feature edges (on two cube planes at once) add up to the twelve edges of the cube.
  for (auto f : cube.faces()) {
    int common_planes = 0;
    for (int k = 0; k < 3; ++k)
      for (double value : {0.0, size}) {
        bool all = true;
        for (auto v : vertices_around_face(cube.halfedge(f), cube))
          all &= cube.point(v)[k] == value;
        common_planes += all;
      }
    EXPECT_EQ(common_planes, 1);
  }
  double feature_length = 0;
  for (auto e : cube.edges()) {
    const Point& a = cube.point(cube.vertex(e, 0));
    const Point& b = cube.point(cube.vertex(e, 1));
    if (on_cube_edge(a, size) && on_cube_edge(b, size) && on_cube_edge(CGAL::midpoint(a, b), size))
      feature_length += std::sqrt(CGAL::squared_distance(a, b));
  }
  EXPECT_NEAR(feature_length, 12 * size, 1e-12);
}

TEST(OptimizeMesh, PlanarGridReducesToFewTrianglesWithZeroHausdorffError) {
  Mesh grid;
  MR::make_height_field<Mesh, Point>(grid, 0, 1, 0, 1, 20, 20, [](double, double) { return 0.0; });
  const Mesh input = grid;
  MR::optimize_mesh(grid, MR::parameters::target_face_ratio(0.01));
  expect_valid(grid, false);
  EXPECT_LE(grid.number_of_faces(), 40u);
  const double there = support::approximate_Hausdorff_distance(grid, input, 4000);
  const double back = support::approximate_Hausdorff_distance(input, grid, 4000);
  EXPECT_EQ(there, 0.0);
  EXPECT_EQ(back, 0.0);
  EXPECT_NEAR(support::area(grid), 1.0, 1e-12);
}

TEST(OptimizeMesh, QualityModeRaisesMinimumAngleOfSliversAtConstantFaceCount) {
  Mesh mesh = sliver_grid(12);
  const auto before = MR::quality_statistics(mesh);
  const std::size_t faces = mesh.number_of_faces();
  const auto result =
      MR::optimize_mesh(mesh, MR::parameters::optimization_mode(MR::Optimization_mode::quality));
  expect_valid(mesh, false);
  const auto after = MR::quality_statistics(mesh);
  EXPECT_GT(result.regions_replaced, 0u);
  EXPECT_LE(std::abs(double(mesh.number_of_faces()) - double(faces)), 0.05 * faces);
  EXPECT_GT(after.mean_alpha, before.mean_alpha);
  EXPECT_GT(after.min_angle_deg, before.min_angle_deg);
}

TEST(OptimizeMesh, ClosedSphereStaysClosedValidAndIntersectionFree) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 4);
  const auto result =
      MR::optimize_mesh(sphere, MR::parameters::target_face_ratio(0.3).random_seed(3u));
  expect_valid(sphere, true);
  EXPECT_GT(result.regions_replaced, 0u);
  EXPECT_LT(sphere.number_of_faces(), result.input_faces);
}

TEST(OptimizeMesh, SameSeedGivesSameMesh) {
  Mesh a, b;
  MR::make_sphere(a, Point(0, 0, 0), 1.0, 3);
  MR::make_sphere(b, Point(0, 0, 0), 1.0, 3);
  MR::optimize_mesh(a, MR::parameters::target_face_ratio(0.4).random_seed(11u));
  MR::optimize_mesh(b, MR::parameters::target_face_ratio(0.4).random_seed(11u));
  a.collect_garbage();
  b.collect_garbage();
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  auto fa = a.faces().begin();
  for (auto f : b.faces()) {
    auto ha = a.halfedge(*fa++), hb = b.halfedge(f);
    EXPECT_EQ(a.point(a.target(ha)), b.point(b.target(hb)));
  }
}

// The exact shortcut for small regions: every triangulation of a convex hexagon (Catalan(4) = 14)
// once, best fitness first; the GA, which searches the same space, cannot do better.
TEST(OptimizeMesh, SmallPolygonsEnumerateAllTriangulationsBestFirst) {
  namespace G = MR::internal::genetic;
  std::vector<Point> hexagon;
  for (int i = 0; i < 6; ++i)
    hexagon.emplace_back(std::cos(i * CGAL_PI / 3) * (1 + 0.3 * (i % 2)), std::sin(i * CGAL_PI / 3),
                         0.05 * (i % 3));
  const std::vector<Kernel::Vector_3> outside;
  const G::Chord_table table = G::valid_chords<Kernel>(hexagon);
  G::Shape_smoothness_fitness fitness;
  const auto all = G::all_triangulations_by_fitness<Kernel>(hexagon, outside, table, fitness);
  ASSERT_EQ(all.size(), 14u);
  std::set<std::vector<G::Triangle>> distinct;
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_EQ(all[k].second.size(), 4u);
    if (k > 0) {
      EXPECT_LE(all[k].first, all[k - 1].first);
    }
    auto sorted = all[k].second;
    std::sort(sorted.begin(), sorted.end());
    distinct.insert(sorted);
  }
  EXPECT_EQ(distinct.size(), 14u);
  G::Ga_options options;
  options.population_size = 20;
  options.max_generations = 50;
  const G::Ga_result ga = G::ga_triangulate<Kernel>(hexagon, outside, table, fitness, options);
  ASSERT_TRUE(ga.found);
  EXPECT_LE(ga.fitness, all.front().first);

  // A reflex node (index 3 pushed inside): chords leaving the polygon are never enumerated.
  std::vector<Point> dented = {Point(0, 0, 0),   Point(2, 0, 0), Point(2, 2, 0),
                               Point(1, 0.5, 0), Point(0, 2, 0), Point(-0.5, 1, 0)};
  const G::Chord_table dented_table = G::valid_chords<Kernel>(dented);
  const auto valid =
      G::all_triangulations_by_fitness<Kernel>(dented, outside, dented_table, fitness);
  EXPECT_GT(valid.size(), 0u);
  EXPECT_LT(valid.size(), 14u);
  for (const auto& t : valid)
    for (const G::Triangle& tri : t.second)
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(dented_table.is_valid(tri[c], tri[(c + 1) % 3]));
}

// Distance control: with the removed input nodes tracked and the distance bound, the input nodes
// end up closer to the reduced surface than with the thesis' ranking alone.
double reduced_vertex_error(bool error_tracking) {
  Mesh bump;
  MR::make_height_field<Mesh, Point>(bump, -1, 1, -1, 1, 40, 40, [](double x, double y) {
    return 0.4 * std::exp(-4 * (x * x + y * y)) + 0.05 * x * y;
  });
  const Mesh input = bump;
  auto options = MR::internal::optimize::options_from_parameters(
      bump, MR::parameters::target_face_ratio(0.15));
  options.error_tracking = error_tracking;
  MR::Default_visitor visitor;
  using Optimizer =
      MR::internal::optimize::Optimizer<Mesh, Mesh::Property_map<Mesh::Vertex_index, Point>, Kernel,
                                        MR::Default_visitor>;
  Optimizer optimizer(bump, bump.points(), Kernel(), options, visitor);
  const auto result = optimizer.run();
  EXPECT_TRUE(result.target_reached);
  expect_valid(bump, false);
  std::vector<Point> points;
  for (auto v : input.vertices()) points.push_back(input.point(v));
  return support::max_distance_to_triangle_mesh(points, bump);
}

TEST(OptimizeMesh, DistanceControlKeepsInputNodesCloserToTheReducedSurface) {
  const double tracked = reduced_vertex_error(true);
  const double untracked = reduced_vertex_error(false);
  EXPECT_GT(tracked, 0.0);
  EXPECT_LT(tracked, untracked);
}

}  // namespace
