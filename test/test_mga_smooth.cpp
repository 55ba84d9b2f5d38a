// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/internal/c1_surface/clough_tocher.h>
#include <CGAL/Mesh_repair/mga_smooth.h>
#include <CGAL/Mesh_repair/triangles_to_quads.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include "support/cgal_calls.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

double mean_alpha(const Mesh& mesh) {
  return MR::quality_statistics(mesh).mean_alpha;
}

// A planar grid whose interior nodes are displaced in the plane by up to 35% of a cell.
Mesh jittered_plane(int n, unsigned seed) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, 0, 1, 0, 1, n, n, [](double, double) { return 0.0; });
  CGAL::Random random(seed);
  const double cell = 1.0 / n;
  for (auto v : vertices(mesh)) {
    if (is_border(v, mesh)) continue;
    const Point& p = mesh.point(v);
    mesh.point(v) = Point(p.x() + random.get_double(-0.35, 0.35) * cell,
                          p.y() + random.get_double(-0.35, 0.35) * cell, 0);
  }
  return mesh;
}

// An icosphere whose vertices are moved tangentially, then put back on the sphere.
Mesh jittered_sphere(double radius, unsigned seed) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), radius, 3);
  CGAL::Random random(seed);
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    const double dx = random.get_double(-0.04, 0.04) * radius;
    const double dy = random.get_double(-0.04, 0.04) * radius;
    const double dz = random.get_double(-0.04, 0.04) * radius;
    const Point q(p.x() + dx, p.y() + dy, p.z() + dz);
    const double scale = radius / std::sqrt(CGAL::to_double((q - CGAL::ORIGIN).squared_length()));
    mesh.point(v) = Point(q.x() * scale, q.y() * scale, q.z() * scale);
  }
  return mesh;
}

TEST(MgaSmooth, PlaneMeshStaysInThePlaneAndImproves) {
  Mesh mesh = jittered_plane(12, 7);
  const double before = mean_alpha(mesh);
  const auto result = MR::mga_smooth(mesh, CGAL::parameters::random_seed(3));
  EXPECT_GT(result.moves, 0u);
  for (auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v).z(), 0.0);
  EXPECT_GT(mean_alpha(mesh), before + 0.01);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

// The largest distance from `mesh`'s vertices to `input`'s triangles, and CGAL's smoothing as
// `mesh_repair smooth --method cgal` runs it (test-support library).
using mesh_repair_test::cgal_smooth;
using mesh_repair_test::max_distance_to;

// The paper's mapping: every node on the full G1 surface (tangent scale 1). On this sphere the
// Walton-Meek patches lie within 2.5e-5 R of the sphere; the bound leaves room for the estimated
// normals of other seeds.
TEST(MgaSmooth, SphereMeshOnTheFullG1SurfaceStaysWithinOneTenThousandthOfTheRadius) {
  const double radius = 2.0;
  Mesh mesh = jittered_sphere(radius, 11);
  const double before = mean_alpha(mesh);
  MR::mga_smooth(mesh, MR::parameters::random_seed(5).surface_tangent_scale(1.0));
  for (auto v : vertices(mesh)) {
    const double distance =
        std::sqrt(CGAL::to_double((mesh.point(v) - CGAL::ORIGIN).squared_length()));
    EXPECT_LT(std::abs(distance - radius), 1e-4 * radius);
  }
  EXPECT_GT(mean_alpha(mesh), before);
}

// `cubic_surface_weight` is the deprecated name of `surface_tangent_scale`: same mesh.
TEST(MgaSmooth, DeprecatedCubicSurfaceWeightIsTheTangentScale) {
  const Mesh input = jittered_sphere(1.0, 3);
  Mesh old_name = input, new_name = input;
  MR::mga_smooth(old_name, MR::parameters::random_seed(2).cubic_surface_weight(0.8));
  MR::mga_smooth(new_name, MR::parameters::random_seed(2).surface_tangent_scale(0.8));
  for (auto v : vertices(input)) EXPECT_EQ(old_name.point(v), new_name.point(v));
}

// The default shortens the boundary curves' tangents to 0.45: the surface bulges 0.45 times as
// far off the input triangles as the full one, so a node is off the sphere by at most about half
// the input's largest gap to the sphere (its sagitta at a triangle's centroid) plus the full
// surface's own error (< 1e-4 R, previous test).
TEST(MgaSmooth, SphereMeshByDefaultStaysWithinHalfTheInputsSagitta) {
  const double radius = 2.0;
  const Mesh input = jittered_sphere(radius, 11);
  Mesh mesh = input;
  double sagitta = 0;
  for (auto f : faces(input)) {
    std::vector<Point> c;
    for (auto v : vertices_around_face(halfedge(f, input), input)) c.push_back(input.point(v));
    const Point centroid = CGAL::centroid(c[0], c[1], c[2]);
    sagitta = std::max(
        sagitta, radius - std::sqrt(CGAL::to_double((centroid - CGAL::ORIGIN).squared_length())));
  }
  MR::mga_smooth(mesh, CGAL::parameters::random_seed(5));
  for (auto v : vertices(mesh)) {
    const double distance =
        std::sqrt(CGAL::to_double((mesh.point(v) - CGAL::ORIGIN).squared_length()));
    EXPECT_LT(std::abs(distance - radius), 0.5 * sagitta + 1e-3 * radius);
  }
  EXPECT_GT(mean_alpha(mesh), mean_alpha(input));
}

// A saddle z = x^2/10 - y^2/4 sampled by a jittered grid: the default's nodes stay closer to
// the input triangles than CGAL's smoothing leaves them, with a higher mean alpha.
TEST(MgaSmooth, SaddleEndsCloserToTheInputThanCgalWithHigherMeanAlpha) {
  auto height = [](double x, double y) { return x * x / 10 - y * y / 4; };
  Mesh input;
  MR::make_height_field<Mesh, Point>(input, -2, 2, -2, 2, 16, 16, height);
  CGAL::Random random(17);
  const double cell = 4.0 / 16;
  for (auto v : vertices(input)) {
    if (is_border(v, input)) continue;
    const Point& p = input.point(v);
    const double x = p.x() + random.get_double(-0.35, 0.35) * cell;
    const double y = p.y() + random.get_double(-0.35, 0.35) * cell;
    input.point(v) = Point(x, y, height(x, y));
  }
  Mesh ours = input, cgal = input;
  MR::mga_smooth(ours, CGAL::parameters::random_seed(1));
  cgal_smooth(cgal);
  EXPECT_LT(max_distance_to(ours, input), max_distance_to(cgal, input));
  EXPECT_GT(mean_alpha(ours), mean_alpha(cgal));
  EXPECT_GT(mean_alpha(ours), mean_alpha(input) + 0.02);
}

// Real meshes: a noisy scan (femur: its short sharp spurs are noise, not features) and a CAD
// part (fandisk). Mean alpha at least CGAL's, maximum distance off the input below CGAL's.
class MgaRealMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(MgaRealMesh, MeanAlphaAtLeastCgalsAndMaxDistanceBelowCgals) {
  const std::string path = std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/" + GetParam();
  if (!std::filesystem::exists(path))
    GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh input;
  ASSERT_TRUE(mesh_repair_test::read_repaired_polygon_mesh(path, input));
  Mesh ours = input, cgal = input;
  const auto result = MR::mga_smooth(ours, MR::parameters::number_of_threads(2).random_seed(1));
  cgal_smooth(cgal);
  EXPECT_GE(mean_alpha(ours), mean_alpha(cgal));
  EXPECT_LT(max_distance_to(ours, input), max_distance_to(cgal, input));
  EXPECT_LT(result.feature_nodes, input.number_of_vertices() / 4);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(ours));
}

INSTANTIATE_TEST_SUITE_P(Demo, MgaRealMesh, ::testing::Values("femur.off", "fandisk.off"));

TEST(MgaSmooth, MeanAlphaNeverDecreasesSweepAfterSweep) {
  Mesh mesh = jittered_sphere(1.0, 23);
  double previous = mean_alpha(mesh);
  for (int sweep = 0; sweep < 4; ++sweep) {
    const auto result =
        MR::mga_smooth(mesh, CGAL::parameters::random_seed(sweep).number_of_iterations(1));
    EXPECT_GE(result.mean_quality_after, result.mean_quality_before);
    const double now = mean_alpha(mesh);
    EXPECT_GE(now, previous - 1e-12);
    previous = now;
  }
}

TEST(MgaSmooth, FixedBorderFeatureAndConstrainedNodesNeverMove) {
  Mesh mesh;
  MR::make_subdivided_cube<Mesh, Point>(mesh, 1.0, 6);
  CGAL::Random random(5);
  for (auto v : vertices(mesh)) {  // jitter inside each cube face, keeping it planar
    Point p = mesh.point(v);
    double c[3] = {p.x(), p.y(), p.z()};
    for (double& x : c)
      if (x > 1e-9 && x < 1 - 1e-9) x += random.get_double(-0.04, 0.04);
    mesh.point(v) = Point(c[0], c[1], c[2]);
  }
  auto constrained = mesh.add_property_map<Mesh::Vertex_index, bool>("v:constrained", false).first;
  const auto pinned = *vertices(mesh).begin();
  std::vector<Point> before;
  for (auto v : vertices(mesh)) before.push_back(mesh.point(v));
  std::size_t interior_pinned = 0;
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    const bool inside = p.x() > 1e-9 && p.x() < 1 - 1e-9 && p.y() > 1e-9 && p.y() < 1 - 1e-9;
    if (inside && p.z() == 0 && interior_pinned++ == 0) put(constrained, v, true);
  }
  put(constrained, pinned, true);
  const auto result = MR::mga_smooth(mesh, MR::parameters::feature_angle_deg(135.0)
                                               .vertex_is_constrained_map(constrained)
                                               .random_seed(1));
  EXPECT_GT(result.feature_nodes, 0u);
  EXPECT_GE(result.constrained_nodes, 1u);
  std::size_t i = 0;
  for (auto v : vertices(mesh)) {
    const Point& p = before[i++];
    auto on = [](double x) { return x == 0 || x == 1; };
    const int edge_coordinates = on(p.x()) + on(p.y()) + on(p.z());
    if (edge_coordinates >= 2 || get(constrained, v)) {
      EXPECT_EQ(mesh.point(v), p);
    }
  }
}

// A roof z = 0.8 |x - 0.5| (faces 77 degrees apart across the ridge): the ridge is a feature line
// that runs from border to border, so spur pruning must not eat it from its ends; its nodes stay.
TEST(MgaSmooth, CreaseThatRunsToTheBorderStaysFixed) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, 0, 1, 0, 1, 8, 8,
                                     [](double x, double) { return 0.8 * std::abs(x - 0.5); });
  CGAL::Random random(3);
  for (auto v : vertices(mesh)) {  // jitter the flat parts along y, keeping the ridge straight
    const Point p = mesh.point(v);
    if (is_border(v, mesh) || std::abs(p.x() - 0.5) < 1e-9) continue;
    mesh.point(v) = Point(p.x(), p.y() + random.get_double(-0.04, 0.04), p.z());
  }
  std::vector<Point> ridge;
  for (auto v : vertices(mesh))
    if (std::abs(mesh.point(v).x() - 0.5) < 1e-9) ridge.push_back(mesh.point(v));
  const auto result = MR::mga_smooth(mesh, CGAL::parameters::random_seed(2));
  EXPECT_EQ(result.feature_nodes, 7u);  // the ridge's interior nodes
  EXPECT_GT(result.moves, 0u);
  std::size_t on_ridge = 0;
  for (auto v : vertices(mesh))
    on_ridge += std::find(ridge.begin(), ridge.end(), mesh.point(v)) != ridge.end();
  EXPECT_EQ(on_ridge, ridge.size());
}

// A roof z = 0.8 |x| (a straight crease along x = 0, dihedral angle 103 degrees) whose crease
// nodes are jittered along the crease: with `slide_feature_nodes` they move, but only along the
// crease (x and z stay 0 up to rounding), while the crease's end nodes on the border stay fixed;
// the mean alpha rises above that of the paper's fixed feature nodes.
TEST(MgaSmooth, SlidingFeatureNodesMoveOnlyAlongTheirCrease) {
  Mesh input;
  MR::make_height_field<Mesh, Point>(input, -1, 1, -1, 1, 10, 10,
                                     [](double x, double) { return 0.8 * std::abs(x); });
  CGAL::Random random(9);
  const double cell = 2.0 / 10;
  for (auto v : vertices(input)) {
    if (is_border(v, input)) continue;
    const Point& p = input.point(v);
    const bool on_crease = std::abs(p.x()) < 1e-12;
    const double x = on_crease ? 0.0 : p.x() + random.get_double(-0.1, 0.1) * cell;
    const double y = p.y() + random.get_double(-0.35, 0.35) * cell;
    input.point(v) = Point(x, y, 0.8 * std::abs(x));
  }
  Mesh fixed_crease = input, sliding = input;
  const auto paper = MR::mga_smooth(fixed_crease, CGAL::parameters::random_seed(4));
  const auto result =
      MR::mga_smooth(sliding, MR::parameters::random_seed(4).slide_feature_nodes(true));
  EXPECT_EQ(paper.sliding_nodes, 0u);
  EXPECT_EQ(result.sliding_nodes, 9u);  // the 9 interior crease nodes
  EXPECT_EQ(result.feature_nodes + result.sliding_nodes, paper.feature_nodes);
  int crease_moves = 0;
  for (auto v : vertices(input)) {
    const Point &before = input.point(v), &after = sliding.point(v);
    if (std::abs(before.x()) > 1e-12) continue;  // not on the crease
    EXPECT_LT(std::abs(after.x()), 1e-12);
    EXPECT_LT(std::abs(after.z()), 1e-12);
    if (is_border(v, input)) {
      EXPECT_EQ(before, after);
    }
    if (before != after) ++crease_moves;
  }
  EXPECT_GT(crease_moves, 3);
  EXPECT_GT(mean_alpha(sliding), mean_alpha(fixed_crease));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(sliding));
}

TEST(MgaSmooth, SameSeedGivesSameMeshAndThreadsDoNotChangeIt) {
  const Mesh input = jittered_sphere(1.0, 99);
  Mesh serial = input, again = input, parallel = input, other_seed = input;
  MR::mga_smooth(serial, CGAL::parameters::random_seed(42).number_of_iterations(3));
  MR::mga_smooth(again, CGAL::parameters::random_seed(42).number_of_iterations(3));
  MR::mga_smooth(parallel,
                 MR::parameters::number_of_threads(2).random_seed(42).number_of_iterations(3));
  MR::mga_smooth(other_seed, CGAL::parameters::random_seed(43).number_of_iterations(3));
  bool differs = false;
  for (auto v : vertices(input)) {
    EXPECT_EQ(serial.point(v), again.point(v));
    EXPECT_EQ(serial.point(v), parallel.point(v));
    differs = differs || serial.point(v) != other_seed.point(v);
  }
  EXPECT_TRUE(differs);
}

TEST(ConjugateGradientSmooth, PlaneMeshImprovesWithoutLeavingThePlane) {
  Mesh mesh = jittered_plane(12, 8);
  const double before = mean_alpha(mesh);
  MR::conjugate_gradient_smooth(mesh);
  for (auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v).z(), 0.0);
  EXPECT_GT(mean_alpha(mesh), before + 0.01);
}

TEST(TrianglesToQuads, RegularTriangleGridBecomesAllQuads) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, 0, 1, 0, 1, 8, 8, [](double, double) { return 0.0; });
  const auto result = MR::triangles_to_quads(mesh);
  EXPECT_EQ(result.remaining_triangles, 0u);
  EXPECT_EQ(result.quads, 64u);
  for (auto f : faces(mesh)) EXPECT_EQ(degree(f, mesh), 4u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST(TrianglesToQuads, QuadSmoothingRaisesMeanBetaAndKeepsPlane) {
  Mesh mesh = jittered_plane(10, 3);
  MR::triangles_to_quads(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  const auto result = MR::mga_smooth(mesh, CGAL::parameters::random_seed(2));
  EXPECT_GT(result.mean_quality_after, result.mean_quality_before);
  EXPECT_GT(result.worst_quality_after, 0.0);
  for (auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v).z(), 0.0);
}

// A 6 x 6 grid of unit quads in the plane z = 0 whose central quad (2,2)-(3,3) is squashed
// along its diagonal: its corners (2,2) and (3,3) are pulled to (2.45,2.45) and (2.55,2.55).
Mesh grid_with_squashed_quad(std::vector<Mesh::Vertex_index>& vertex) {
  Mesh mesh;
  const int n = 6;
  vertex.clear();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) vertex.push_back(mesh.add_vertex(Point(i, j, 0)));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      mesh.add_face(vertex[a], vertex[a + 1], vertex[a + n + 2], vertex[a + n + 1]);
    }
  mesh.point(vertex[3 * (n + 1) + 3]) = Point(2.55, 2.55, 0);
  mesh.point(vertex[2 * (n + 1) + 2]) = Point(2.45, 2.45, 0);
  return mesh;
}

double worst_beta(const Mesh& mesh) {
  double worst = 1;
  for (auto f : faces(mesh)) {
    std::vector<Point> c;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) c.push_back(mesh.point(v));
    worst = std::min(
        worst, c.size() == 4 ? MR::quad_beta(c[0], c[1], c[2], c[3]) : MR::alpha(c[0], c[1], c[2]));
  }
  return worst;
}

TEST(TrianglesToQuads, ElementCollapseRemovesASquashedQuadAndRaisesTheWorstBeta) {
  std::vector<Mesh::Vertex_index> vertex;
  Mesh mesh = grid_with_squashed_quad(vertex);
  const double before = worst_beta(mesh);
  ASSERT_LT(before, 0.2);  // the squashed quad
  const auto result = MR::triangles_to_quads(mesh);
  EXPECT_EQ(result.collapsed_elements, 1u);
  EXPECT_EQ(result.quads, 35u);
  EXPECT_EQ(mesh.number_of_faces(), 35u);
  EXPECT_EQ(mesh.number_of_vertices(), 48u);  // the two ends of the diagonal became one node
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_GT(worst_beta(mesh), before + 0.2);
  // Every element keeps its upward orientation (exact test) and stays convex.
  for (auto f : faces(mesh)) {
    std::vector<Point> c;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) c.push_back(mesh.point(v));
    ASSERT_EQ(c.size(), 4u);
    for (int i = 0; i < 4; ++i)
      EXPECT_EQ(CGAL::orientation(Kernel::Point_2(c[i].x(), c[i].y()),
                                  Kernel::Point_2(c[(i + 1) % 4].x(), c[(i + 1) % 4].y()),
                                  Kernel::Point_2(c[(i + 2) % 4].x(), c[(i + 2) % 4].y())),
                CGAL::LEFT_TURN);
  }
  // The merged node sits at the midpoint of the old diagonal.
  bool found = false;
  for (auto v : vertices(mesh)) found = found || mesh.point(v) == Point(2.5, 2.5, 0);
  EXPECT_TRUE(found);
}

TEST(TrianglesToQuads, ElementCollapseLeavesGoodQuadsAndBordersAlone) {
  std::vector<Mesh::Vertex_index> vertex;
  Mesh mesh = grid_with_squashed_quad(vertex);
  // Squash a border quad instead: its diagonal ends are on the border, so it must stay.
  mesh.point(vertex[3 * 7 + 3]) = Point(3, 3, 0);
  mesh.point(vertex[2 * 7 + 2]) = Point(2, 2, 0);
  mesh.point(vertex[0]) = Point(0.45, 0.45, 0);
  mesh.point(vertex[8]) = Point(0.55, 0.55, 0);
  const auto result = MR::triangles_to_quads(mesh);
  EXPECT_EQ(result.collapsed_elements, 0u);
  EXPECT_EQ(mesh.number_of_faces(), 36u);
  // A regular grid has no poor quad: nothing collapses.
  Mesh regular;
  MR::make_height_field<Mesh, Point>(regular, 0, 1, 0, 1, 8, 8, [](double, double) { return 0.0; });
  EXPECT_EQ(MR::triangles_to_quads(regular).collapsed_elements, 0u);
}

TEST(TrianglesToQuads, ElementCollapseRefusesAFold) {
  // The squashed quad's other corners are moved to (2.66, 2.08) and (2.29, 3.16): every element
  // is still convex, but with either diagonal collapsed to its midpoint or to either end, some
  // element around it would turn reflex or fold. No collapse may happen.
  std::vector<Mesh::Vertex_index> vertex;
  Mesh mesh = grid_with_squashed_quad(vertex);
  mesh.point(vertex[2 * 7 + 3]) = Point(2.66, 2.08, 0);
  mesh.point(vertex[3 * 7 + 2]) = Point(2.29, 3.16, 0);
  ASSERT_LT(worst_beta(mesh), 0.3);
  const auto result = MR::triangles_to_quads(mesh);
  EXPECT_EQ(result.collapsed_elements, 0u);
  EXPECT_EQ(mesh.number_of_vertices(), 49u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  for (auto f : faces(mesh)) {
    std::vector<Point> c;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) c.push_back(mesh.point(v));
    for (std::size_t i = 0; i < c.size(); ++i)
      EXPECT_EQ(
          CGAL::orientation(Kernel::Point_2(c[i].x(), c[i].y()),
                            Kernel::Point_2(c[(i + 1) % c.size()].x(), c[(i + 1) % c.size()].y()),
                            Kernel::Point_2(c[(i + 2) % c.size()].x(), c[(i + 2) % c.size()].y())),
          CGAL::LEFT_TURN);
  }
}

TEST(FlipEdgesForQuality, WorstAlphaOfAJitteredPlaneDoesNotDecrease) {
  Mesh mesh = jittered_plane(10, 5);
  const double before = MR::quality_statistics(mesh).min_alpha;
  const auto result = MR::flip_edges_for_quality(mesh);
  EXPECT_GT(result.flips, 0u);
  EXPECT_GE(MR::quality_statistics(mesh).min_alpha, before);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

// A 5 x 5 grid of the unit square, each cell split along its rising diagonal.
MR::internal::Clough_tocher_interpolant grid_interpolant(
    const std::function<double(double, double)>& f) {
  std::vector<std::array<double, 2>> sites;
  std::vector<double> values;
  const int n = 5;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      sites.push_back({double(i) / n, double(j) / n});
      values.push_back(f(double(i) / n, double(j) / n));
    }
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      triangles.push_back({a, a + 1, a + n + 2});
      triangles.push_back({a, a + n + 2, a + n + 1});
    }
  return MR::internal::Clough_tocher_interpolant(sites, values, triangles);
}

// ---- The G1 surface the nodes are mapped onto --------------------------------------------

using MR::internal::G1_surface;
using MR::internal::Vec3;

G1_surface g1_surface_of(const Mesh& mesh, double tangent_scale) {
  std::vector<Vec3> points;
  for (auto v : vertices(mesh))
    points.emplace_back(CGAL::to_double(mesh.point(v).x()), CGAL::to_double(mesh.point(v).y()),
                        CGAL::to_double(mesh.point(v).z()));
  std::vector<std::array<int, 3>> triangles;
  for (auto f : faces(mesh)) {
    std::array<int, 3> t;
    int i = 0;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) t[i++] = int(v.idx());
    triangles.push_back(t);
  }
  return G1_surface(points, triangles, 120.0, tangent_scale);
}

// The point of triangle t's patch at (1 - k) ((1 - u) a + u b) + k c, a b c its vertices.
Vec3 patch_point(const G1_surface& surface, int t, int a, int b, int c, double u, double k) {
  G1_surface::Location at;
  at.triangle = t;
  const auto& corners = surface.triangles()[t];
  auto corner = [&](int v) { return corners[0] == v ? 0 : (corners[1] == v ? 1 : 2); };
  at.b[corner(a)] = (1 - k) * (1 - u), at.b[corner(b)] = (1 - k) * u, at.b[corner(c)] = k;
  return surface.evaluate(at);
}

// Unit normal of triangle t's patch at the point u of its edge a-b: central differences along
// the edge, second-order one-sided differences towards c (error O(h^2) = 1e-8, rounding 1e-12).
Vec3 normal_on_edge(const G1_surface& surface, int t, int a, int b, int c, double u) {
  const double h = 1e-4;
  auto at = [&](double s, double k) { return patch_point(surface, t, a, b, c, s, k); };
  const Vec3 along = (0.5 / h) * (at(u + h, 0) - at(u - h, 0));
  const Vec3 inward = (0.5 / h) * (-3.0 * at(u, 0) + 4.0 * at(u, h) - 1.0 * at(u, 2 * h));
  return MR::internal::normalized(MR::internal::cross(along, inward));
}

struct Edge_continuity {
  double largest_gap = 0, largest_sine = 0;
  int edges = 0;
};

// Over every edge shared by two triangles, at 9 points along it: the gap between the two
// patches and the sine of the angle between their normals.
Edge_continuity edge_continuity(const Mesh& mesh, const G1_surface& surface) {
  Edge_continuity result;
  for (auto e : edges(mesh)) {
    if (is_border(e, mesh)) continue;
    const auto h = halfedge(e, mesh), o = opposite(h, mesh);
    const int a = int(source(h, mesh).idx()), b = int(target(h, mesh).idx());
    const int t0 = int(face(h, mesh).idx()), t1 = int(face(o, mesh).idx());
    const int c0 = int(target(next(h, mesh), mesh).idx());
    const int c1 = int(target(next(o, mesh), mesh).idx());
    ++result.edges;
    for (double u = 0.1; u < 0.95; u += 0.1) {
      const Vec3 gap =
          patch_point(surface, t0, a, b, c0, u, 0) - patch_point(surface, t1, a, b, c1, u, 0);
      result.largest_gap = std::max(result.largest_gap, MR::internal::norm(gap));
      const Vec3 n0 = normal_on_edge(surface, t0, a, b, c0, u);
      const Vec3 n1 = normal_on_edge(surface, t1, a, b, c1, u);
      result.largest_sine =
          std::max(result.largest_sine, MR::internal::norm(MR::internal::cross(n0, n1)));
    }
  }
  return result;
}

// Tangent-plane continuity across every primary edge of a curved mesh in space, at the default
// tangent scale and at the full one: the two patches of an edge meet without a crack and with
// the same tangent plane (measured 1e-7 or less, the finite differences' own error, which
// quarters when h is halved). The
// same measurement on the flat input triangles (scale 0) sees their kinks, so it can fail.
TEST(G1Surface, NeighbouringPatchesShareTheTangentPlaneAlongEveryEdgeOfACurvedMesh) {
  const Mesh sphere = jittered_sphere(1.0, 11);
  for (double scale : {MR::internal::default_surface_tangent_scale, 1.0}) {
    const Edge_continuity c = edge_continuity(sphere, g1_surface_of(sphere, scale));
    EXPECT_EQ(c.edges, int(sphere.number_of_edges()));
    EXPECT_LT(c.largest_gap, 1e-14) << "scale " << scale;
    EXPECT_LT(c.largest_sine, 1e-6) << "scale " << scale;
  }
  const Edge_continuity flat = edge_continuity(sphere, g1_surface_of(sphere, 0.0));
  EXPECT_GT(flat.largest_sine, 0.05);
}

// The same on an open saddle with a jittered grid (vertex normals from the quadratic fit).
TEST(G1Surface, SaddlePatchesShareTheTangentPlaneAlongEveryInteriorEdge) {
  auto height = [](double x, double y) { return x * x / 10 - y * y / 4; };
  Mesh saddle;
  MR::make_height_field<Mesh, Point>(saddle, -2, 2, -2, 2, 12, 12, height);
  CGAL::Random random(5);
  for (auto v : vertices(saddle)) {
    if (is_border(v, saddle)) continue;
    const Point& p = saddle.point(v);
    const double x = p.x() + random.get_double(-0.3, 0.3) / 3;
    const double y = p.y() + random.get_double(-0.3, 0.3) / 3;
    saddle.point(v) = Point(x, y, height(x, y));
  }
  const Edge_continuity c =
      edge_continuity(saddle, g1_surface_of(saddle, MR::internal::default_surface_tangent_scale));
  EXPECT_GT(c.edges, 300);
  EXPECT_LT(c.largest_gap, 1e-14);
  EXPECT_LT(c.largest_sine, 1e-6);
}

// Shortening the tangents keeps the vertex normals and scales the bulge: at scale s the patches
// stray s times as far off their flat triangles as at scale 1 (measured: 0.500 at s = 0.5).
TEST(G1Surface, ShorterTangentsBulgeProportionallyLess) {
  const Mesh sphere = jittered_sphere(1.0, 11);
  auto largest_height = [&](double scale) {
    const G1_surface surface = g1_surface_of(sphere, scale);
    double largest = 0;
    for (int t = 0; t < int(surface.triangles().size()); ++t) {
      const auto& c = surface.triangles()[t];
      const Vec3 &p0 = surface.points()[c[0]], &p1 = surface.points()[c[1]],
                 &p2 = surface.points()[c[2]];
      const Vec3 n = MR::internal::normalized(MR::internal::cross(p1 - p0, p2 - p0));
      for (int i = 0; i <= 8; ++i)
        for (int j = 0; i + j <= 8; ++j) {
          G1_surface::Location at;
          at.triangle = t;
          at.b[0] = i / 8.0, at.b[1] = j / 8.0, at.b[2] = (8 - i - j) / 8.0;
          largest = std::max(largest, std::abs(MR::internal::dot(surface.evaluate(at) - p0, n)));
        }
    }
    return largest;
  };
  const double full = largest_height(1.0);
  EXPECT_GT(full, 1e-3);  // the icosphere's triangles do bulge
  for (double scale : {0.25, 0.5, 0.75}) {
    EXPECT_NEAR(largest_height(scale) / full, scale, 0.05 * scale);
  }
  EXPECT_LT(largest_height(0.0), 1e-15);
}

TEST(CloughTocher, ReproducesQuadraticsExactly) {
  // The gradient fit is exact on quadratics, and so are the cubic patches built from it.
  auto f = [](double x, double y) { return 1 + 2 * x - y + 0.5 * x * x + x * y - 2 * y * y; };
  const auto interpolant = grid_interpolant(f);
  for (double x = 0.03; x < 1; x += 0.11)
    for (double y = 0.05; y < 1; y += 0.13) EXPECT_NEAR(interpolant.value(x, y), f(x, y), 1e-9);
}

TEST(CloughTocher, GradientIsContinuousAcrossTriangleEdges) {
  const auto interpolant =
      grid_interpolant([](double x, double y) { return std::exp(x) * std::sin(3 * y); });
  const double h = 1e-6;
  // Midpoints and quarter points of interior edges: a diagonal (normal (1,-1)/sqrt 2) and a
  // vertical cell side (normal (1, 0)); one-sided slopes across the edge must agree.
  struct Probe {
    double x, y, nx, ny;
  };
  const double s = 1 / std::sqrt(2.0);
  const Probe probes[] = {
      {0.5, 0.5, s, -s}, {0.45, 0.45, s, -s}, {0.4, 0.3, 1, 0}, {0.4, 0.35, 1, 0}};
  for (const Probe& p : probes) {
    const double centre = interpolant.value(p.x, p.y);
    const double ahead = (interpolant.value(p.x + h * p.nx, p.y + h * p.ny) - centre) / h;
    const double behind = (centre - interpolant.value(p.x - h * p.nx, p.y - h * p.ny)) / h;
    EXPECT_NEAR(ahead, behind, 1e-4) << "at (" << p.x << ", " << p.y << ")";
  }
}

}  // namespace
