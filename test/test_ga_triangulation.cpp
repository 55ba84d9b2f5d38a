// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The genetic-algorithm triangulation of closed 3D polygons (thesis 5.4, 7.x).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/internal/genetic/ga_triangulation.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace ga = CGAL::Mesh_repair::internal::genetic;

// A closed polygon on the saddle z = a (x^2 - y^2), counterclockwise seen from +z, and the
// normals of the saddle at the middle of each edge (the "existing faces" across the edges).
void saddle_polygon(int n, double a, std::vector<Point>& points, std::vector<Vector>& outside) {
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    const double r = 1 + 0.25 * std::cos(3 * t);
    const double x = r * std::cos(t), y = r * std::sin(t);
    points.emplace_back(x, y, a * (x * x - y * y));
  }
  for (int i = 0; i < n; ++i) {
    const Point m = CGAL::midpoint(points[i], points[(i + 1) % n]);
    Vector nrm(-2 * a * m.x(), 2 * a * m.y(), 1);
    outside.push_back(nrm / std::sqrt(nrm.squared_length()));
  }
}

// Every polygon edge in one triangle, every chord in two, n-2 triangles.
void expect_triangulation(int n, const std::vector<ga::Triangle>& triangles) {
  ASSERT_EQ(int(triangles.size()), n - 2);
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : triangles) {
    EXPECT_TRUE(t[0] < t[1] && t[1] < t[2]);
    ++count[{t[0], t[1]}];
    ++count[{t[1], t[2]}];
    ++count[{t[0], t[2]}];
  }
  for (const auto& [edge, c] : count) {
    const bool polygon_edge =
        edge.second == edge.first + 1 || (edge.first == 0 && edge.second == n - 1);
    EXPECT_EQ(c, polygon_edge ? 1 : 2);
  }
}

TEST(GaTriangulation, NumberOfCandidateChordsIsEq58ForAConvexPolygon) {
  for (int n : {4, 5, 6, 7, 8, 20}) {
    std::vector<Point> points;
    for (int i = 0; i < n; ++i)
      points.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0);
    const ga::Chord_table table = ga::valid_chords<K>(points);
    EXPECT_TRUE(table.planar);
    EXPECT_EQ(int(table.chords.size()), (n - 3) + (n - 3) * (n - 2) / 2) << n;
  }
}

TEST(GaTriangulation, ChordOutsideANonConvexPolygonIsInvalid) {
  // Thesis Figure 5.6(a): six nodes, the chord between nodes 2 and 6 leaves the polygon.
  const std::vector<Point> points = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0},
                                     {1, 1, 0}, {0, 2, 0}, {-1, 1, 0}};
  const ga::Chord_table table = ga::valid_chords<K>(points);
  EXPECT_FALSE(table.is_valid(2, 4));  // passes outside through the notch at node 3
  EXPECT_TRUE(table.is_valid(1, 3));
  EXPECT_TRUE(table.is_valid(0, 3));
}

TEST(GaTriangulation, CrossingChordsAreRejected) {
  EXPECT_TRUE(ga::detail::interleave({1, 4}, {3, 5}));
  EXPECT_FALSE(ga::detail::interleave({1, 4}, {4, 6}));
  EXPECT_FALSE(ga::detail::interleave({1, 5}, {2, 4}));
  ga::detail::Chord_set_builder builder(8);
  EXPECT_TRUE(builder.try_add({1, 4}));
  EXPECT_FALSE(builder.try_add({3, 5}));
  EXPECT_FALSE(builder.try_add({0, 2}));  // 0 < 1 < 2 < 4
  EXPECT_TRUE(builder.try_add({4, 7}));
  EXPECT_FALSE(builder.try_add({4, 7}));  // no duplicate
  EXPECT_FALSE(builder.try_add({2, 6}));
  EXPECT_TRUE(builder.try_add({1, 7}));  // shares end nodes only
}

/// The builder's range queries accept exactly the chords that cross no accepted chord and are
/// not accepted already (brute force with `interleave`), on random sequences, across clears;
/// and a full set is a triangulation (n - 3 chords).
TEST(GaTriangulation, ChordSetBuilderAgreesWithTheBruteForceCrossingTest) {
  CGAL::Random random(11);
  for (int n : {4, 5, 9, 31, 64, 100}) {
    ga::detail::Chord_set_builder builder(n);
    for (int round = 0; round < 20; ++round) {
      builder.clear();
      std::vector<ga::Chord> accepted;
      for (int attempt = 0; attempt < 6 * n; ++attempt) {
        int a = random.get_int(0, n), b = random.get_int(0, n);
        if (a > b) std::swap(a, b);
        if (b - a < 2 || (a == 0 && b == n - 1)) continue;  // polygon edges are not chords
        bool expected =
            std::find(accepted.begin(), accepted.end(), ga::Chord(a, b)) == accepted.end();
        for (const ga::Chord& c : accepted)
          expected = expected && !ga::detail::interleave(c, ga::Chord(a, b));
        ASSERT_EQ(builder.try_add({a, b}), expected) << n << ": " << a << "-" << b;
        if (expected) accepted.emplace_back(a, b);
      }
      EXPECT_LE(int(accepted.size()), n - 3);
      EXPECT_EQ(builder.full(), int(accepted.size()) == n - 3);
    }
  }
}

TEST(GaTriangulation, ResultIsAValidTriangulationNeverWorseThanItsSeed) {
  std::vector<Point> points;
  std::vector<Vector> outside;
  saddle_polygon(24, 0.6, points, outside);
  const ga::Chord_table table = ga::valid_chords<K>(points);
  ga::Ga_options options;
  options.target_fitness = 1.0;  // never reached: run all generations
  options.max_generations = 200;
  options.stall_generations = 0;  // run every generation
  options.random_seed = 7;
  const ga::Ga_result r =
      ga::ga_triangulate<K>(points, outside, table, ga::Smoothness_fitness(), options);
  ASSERT_TRUE(r.found);
  expect_triangulation(24, r.triangles);
  EXPECT_GE(r.fitness, r.seed_fitness);
  EXPECT_EQ(r.generations, 200);
  const auto seed = ga::min_dihedral_triangulation<K>(points, outside, table);
  ASSERT_TRUE(seed);
  expect_triangulation(24, *seed);
  EXPECT_DOUBLE_EQ(
      ga::evaluate_triangulation<K>(points, outside, table, *seed, ga::Smoothness_fitness()),
      r.seed_fitness);
}

TEST(GaTriangulation, StallCountsOnlyImprovementsOfAtLeastTheStallImprovement) {
  std::vector<Point> points;
  std::vector<Vector> outside;
  saddle_polygon(40, 0.8, points, outside);
  const ga::Chord_table table = ga::valid_chords<K>(points);
  ga::Ga_options options;
  options.target_fitness = 1.0;  // never reached
  options.max_generations = 300;
  options.stall_generations = 8;
  options.random_seed = 3;
  const ga::Ga_result every =
      ga::ga_triangulate<K>(points, outside, table, ga::Smoothness_fitness(), options);
  // No improvement can exceed the whole fitness range: the run stops after exactly the stall
  // count, and the stall rule is the only thing that changed.
  options.stall_improvement = 1.0;
  const ga::Ga_result none =
      ga::ga_triangulate<K>(points, outside, table, ga::Smoothness_fitness(), options);
  EXPECT_EQ(none.generations, options.stall_generations);
  EXPECT_GT(every.generations, none.generations);
  EXPECT_GE(none.fitness, none.seed_fitness);  // elitism still keeps the best
  expect_triangulation(40, none.triangles);
  // A threshold between the two stops in between, and keeps the best triangulation it saw.
  options.stall_improvement = 0.002;
  const ga::Ga_result some =
      ga::ga_triangulate<K>(points, outside, table, ga::Smoothness_fitness(), options);
  EXPECT_GE(some.generations, none.generations);
  EXPECT_LE(some.generations, every.generations);
  EXPECT_GE(some.fitness, none.fitness);
}

TEST(GaTriangulation, SameSeedGivesTheSameTriangulation) {
  std::vector<Point> points;
  std::vector<Vector> outside;
  saddle_polygon(30, 0.8, points, outside);
  const ga::Chord_table table = ga::valid_chords<K>(points);
  ga::Ga_options options;
  options.target_fitness = 1.0;
  options.max_generations = 100;
  options.random_seed = 42;
  const auto a =
      ga::ga_triangulate<K>(points, outside, table, ga::Shape_smoothness_fitness(), options);
  const auto b =
      ga::ga_triangulate<K>(points, outside, table, ga::Shape_smoothness_fitness(), options);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.fitness, b.fitness);
  expect_triangulation(30, a.triangles);
}

TEST(GaTriangulation, NoTwoChordsOfThePlanarResultCross) {
  std::vector<Point> points;
  std::vector<Vector> outside;
  saddle_polygon(40, 0.0, points, outside);  // flat, non-convex star
  const ga::Chord_table table = ga::valid_chords<K>(points);
  ga::Ga_options options;
  options.target_fitness = 1.0;
  options.max_generations = 50;
  const auto r =
      ga::ga_triangulate<K>(points, outside, table, ga::Shape_smoothness_fitness(), options);
  ASSERT_TRUE(r.found);
  expect_triangulation(40, r.triangles);
  std::set<std::pair<int, int>> chords;
  for (const auto& t : r.triangles)
    for (auto e :
         {std::make_pair(t[0], t[1]), std::make_pair(t[1], t[2]), std::make_pair(t[0], t[2])})
      if (e.second != e.first + 1 && !(e.first == 0 && e.second == 39)) chords.insert(e);
  for (const auto& c : chords) {
    EXPECT_TRUE(table.is_valid(c.first, c.second));
    const K::Segment_2 s(K::Point_2(points[c.first].x(), points[c.first].y()),
                         K::Point_2(points[c.second].x(), points[c.second].y()));
    for (const auto& d : chords) {
      if (d.first == c.first || d.first == c.second || d.second == c.first || d.second == c.second)
        continue;
      const K::Segment_2 t(K::Point_2(points[d.first].x(), points[d.first].y()),
                           K::Point_2(points[d.second].x(), points[d.second].y()));
      EXPECT_FALSE(CGAL::do_intersect(s, t));
    }
  }
}

TEST(GaTriangulation, HundredsOfNodesAreTriangulated) {
  std::vector<Point> points;
  std::vector<Vector> outside;
  saddle_polygon(300, 0.3, points, outside);
  const ga::Chord_table table = ga::valid_chords<K>(points);
  ga::Ga_options options;
  options.target_fitness = 1.0;
  options.max_generations = 100;
  const auto r = ga::ga_triangulate<K>(points, outside, table, ga::Smoothness_fitness(), options);
  ASSERT_TRUE(r.found);
  expect_triangulation(300, r.triangles);
  EXPECT_GE(r.fitness, r.seed_fitness);
}

TEST(GaTriangulation, FoldedPolygonUsesTheProjectionFreeTestAndIsTriangulated) {
  // A band around a cylinder wrapping 300 degrees, closed by a vertical edge: its projection
  // onto any plane overlaps itself.
  std::vector<Point> points;
  std::vector<Vector> normals;
  const int half = 12;
  for (int k = 0; k <= half; ++k) {
    const double t = 300.0 / 180 * M_PI * k / half;
    points.emplace_back(std::cos(t), std::sin(t), 0);
    normals.emplace_back(std::cos(t), std::sin(t), 0);
  }
  for (int k = half; k >= 0; --k) {
    const double t = 300.0 / 180 * M_PI * k / half;
    points.emplace_back(std::cos(t), std::sin(t), 0.6);
    normals.emplace_back(std::cos(t), std::sin(t), 0);
  }
  const ga::Chord_table table = ga::valid_chords<K>(points, normals);
  EXPECT_FALSE(table.planar);
  const auto r = ga::ga_triangulate<K>(points, {}, table, ga::Smoothness_fitness());
  ASSERT_TRUE(r.found);
  expect_triangulation(int(points.size()), r.triangles);
}

}  // namespace
