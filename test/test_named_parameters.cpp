// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Every named parameter that no other test, example, command or benchmark sets is set here, and
// each test checks that the parameter changes what its operator does in the documented way.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/clean_hole_contour.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/hole_filling/shape_prediction.h>
#include <CGAL/Mesh_repair/optimize_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "support/cgal_calls.h"
#include "support/sliver_grid.h"

#include <array>
#include <cmath>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using halfedge_descriptor = boost::graph_traits<Mesh>::halfedge_descriptor;
namespace MR = CGAL::Mesh_repair;

Mesh from_soup(const std::vector<Point>& points, const std::vector<std::vector<std::size_t>>& f) {
  Mesh mesh;
  mesh_repair_test::polygon_soup_to_polygon_mesh(points, f, mesh);
  return mesh;
}

std::size_t count(const MR::Defect_report& report, MR::Degeneracy kind) {
  std::size_t n = 0;
  for (const auto& d : report.badly_shaped_faces) n += d.kind == kind ? 1 : 0;
  return n;
}

// One needle (edges 1 : 1 : 0.05, ratio 20) and one cap (largest angle about 169 degrees).
TEST(NamedParameters, NeedleAndCapThresholdsDecideWhatIsDegenerate) {
  const Mesh needle = from_soup({{0, 0, 0}, {1, 0, 0}, {0.5, 0.05, 0}}, {{0, 1, 2}});
  EXPECT_EQ(count(MR::detect_defects(needle), MR::Degeneracy::needle), 0u)
      << "a 1 : 0.05 triangle is a cap by its angles, not a needle";
  const Mesh thin = from_soup({{0, 0, 0}, {1, 0, 0}, {1, 0.05, 0}}, {{0, 1, 2}});
  EXPECT_EQ(count(MR::detect_defects(thin), MR::Degeneracy::needle), 1u);
  EXPECT_EQ(count(MR::detect_defects(thin, MR::parameters::needle_threshold(30.0)),
                  MR::Degeneracy::needle),
            0u);

  const Mesh cap = from_soup({{0, 0, 0}, {1, 0, 0}, {0.5, 0.05, 0}}, {{0, 1, 2}});
  EXPECT_EQ(count(MR::detect_defects(cap), MR::Degeneracy::cap), 1u);
  EXPECT_EQ(
      count(MR::detect_defects(cap, MR::parameters::cap_threshold_deg(175.0)), MR::Degeneracy::cap),
      0u);
}

// A ring of 16 border edges around a hole, one of them split in two halves: the short halves
// are collapsed below 0.7 x the mean length, not below 0.4 x.
Mesh annulus_with_split_edge() {
  std::vector<Point> points;
  const int n = 16;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * CGAL_PI * k / n;
    points.emplace_back(std::cos(a), std::sin(a), 0);
  }
  for (int k = 0; k < n; ++k) {
    const double a = 2 * CGAL_PI * k / n;
    points.emplace_back(2 * std::cos(a), 2 * std::sin(a), 0);
  }
  const double half = CGAL_PI / n;  // the middle of the inner edge 0-1
  points.emplace_back(std::cos(half), std::sin(half), 0);
  std::vector<std::vector<std::size_t>> faces;
  for (int k = 0; k < n; ++k) {
    const std::size_t k1 = (k + 1) % n;
    faces.push_back({std::size_t(n + k), std::size_t(n) + k1, k1});
    if (k == 0) {
      faces.push_back({std::size_t(n), std::size_t(2 * n), 0});
      faces.push_back({std::size_t(n), k1, std::size_t(2 * n)});
    } else {
      faces.push_back({std::size_t(n + k), k1, std::size_t(k)});
    }
  }
  return from_soup(points, faces);
}

halfedge_descriptor inner_border(const Mesh& mesh) {
  for (auto h : halfedges(mesh))
    if (is_border(h, mesh) &&
        CGAL::squared_distance(mesh.point(target(h, mesh)), Point(0, 0, 0)) < 2)
      return h;
  return boost::graph_traits<Mesh>::null_halfedge();
}

TEST(NamedParameters, SplitAndCollapseRatiosBoundTheContourEdgeLengths) {
  const auto only_lengths =
      MR::parameters::remove_badly_oriented_triangles(false).treat_degenerate_triangles(false);
  Mesh collapsed = annulus_with_split_edge();
  const auto by_default = MR::clean_hole_contour(collapsed, inner_border(collapsed), only_lengths);
  EXPECT_EQ(by_default.border_edges_before, 17u);
  EXPECT_EQ(by_default.edges_collapsed, 1u);
  EXPECT_EQ(by_default.border_edges_after, 16u);

  Mesh kept = annulus_with_split_edge();
  const auto tolerant =
      MR::clean_hole_contour(kept, inner_border(kept), only_lengths.collapse_length_ratio(0.4));
  EXPECT_EQ(tolerant.edges_collapsed, 0u);
  EXPECT_EQ(tolerant.border_edges_after, 17u);

  // Every full edge is 1.06 x the mean: a split ratio of 1.02 splits them, 1.5 does not.
  Mesh split = annulus_with_split_edge();
  const auto strict = MR::clean_hole_contour(
      split, inner_border(split), only_lengths.collapse_length_ratio(0.4).split_length_ratio(1.02));
  EXPECT_GT(strict.edges_split, 0u);
  EXPECT_EQ(tolerant.edges_split, 0u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(split));
}

// A sphere with a cap removed: the hole of the shape-prediction tests.
halfedge_descriptor sphere_with_hole(Mesh& mesh) {
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 3);
  std::vector<boost::graph_traits<Mesh>::face_descriptor> doomed;
  for (auto f : faces(mesh)) {
    double z = 0;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) z += mesh.point(v).z() / 3;
    if (z > 0.8) doomed.push_back(f);
  }
  for (auto f : doomed) CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
  for (auto h : halfedges(mesh))
    if (is_border(h, mesh)) return h;
  return boost::graph_traits<Mesh>::null_halfedge();
}

template <class NamedParameters>
std::vector<Point> shape_prediction_patch(const NamedParameters& np) {
  Mesh mesh;
  const halfedge_descriptor h = sphere_with_hole(mesh);
  MR::Fill_patch<Mesh> patch;
  const auto report = MR::fill_hole_shape_prediction(mesh, h, patch, np.random_seed(2u));
  EXPECT_TRUE(report.filled) << report.failure;
  std::vector<Point> points;
  for (auto v : patch.vertices) points.push_back(mesh.point(v));
  return points;
}

// Each smoothing parameter of shape prediction changes the patch (same seed); the GA's parameters
// reach the GA's options. (On this cap the patch is the same for a population of 2 or 30 and for
// weights {1, 0, 0}, with the target fitness out of reach and no simplification: the GA does not
// improve on its seed, the minimum-dihedral triangulation, so they cannot be seen in the patch.)
TEST(NamedParameters, ShapePredictionParametersChangeThePatch) {
  const auto base = MR::parameters::max_generations(40);
  const std::vector<Point> reference = shape_prediction_patch(base);
  ASSERT_FALSE(reference.empty());
  EXPECT_EQ(shape_prediction_patch(base), reference);  // reproducible, so a change is the cause
  EXPECT_NE(shape_prediction_patch(base.boundary_smoothing_iterations(4)), reference);
  EXPECT_NE(shape_prediction_patch(base.curvature_flow_iterations(0)), reference);
  EXPECT_NE(shape_prediction_patch(base.use_rough_set_simplification(false)), reference);
  const auto options = MR::internal::shape_prediction_options_from(
      base.population_size(2).target_fitness(1.0).fitness_weights(
          std::array<double, 3>{1.0, 0.0, 0.0}));
  EXPECT_EQ(options.max_generations, 40);
  EXPECT_EQ(options.population_size, 2);
  EXPECT_EQ(options.target_fitness, 1.0);
  EXPECT_EQ(options.fitness_weights, (std::array<double, 3>{1.0, 0.0, 0.0}));
}

// The weights of eq. 7.9 change which re-triangulations the quality mode keeps on a curved grid
// of slivers.
TEST(NamedParameters, OptimizationWeightsChangeTheQualityModeResult) {
  auto run = [](double shape, double smoothness, double surrounding) {
    Mesh mesh = sliver_grid(12, 0.3);
    const auto result =
        MR::optimize_mesh(mesh, MR::parameters::optimization_mode(MR::Optimization_mode::quality)
                                    .shape_weight(shape)
                                    .smoothness_weight(smoothness)
                                    .surrounding_weight(surrounding)
                                    .random_seed(1u));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    EXPECT_GT(result.regions_replaced, 0u);
    mesh.collect_garbage();
    std::vector<Point> points;
    for (auto f : faces(mesh))
      for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) points.push_back(mesh.point(v));
    return std::make_pair(result.regions_replaced, points);
  };
  const auto balanced = run(1.0 / 3, 1.0 / 3, 1.0 / 3);
  EXPECT_NE(run(1, 0, 0), balanced);
  EXPECT_NE(run(0, 1, 0), balanced);
  EXPECT_NE(run(0, 0, 1), balanced);
}

}  // namespace
