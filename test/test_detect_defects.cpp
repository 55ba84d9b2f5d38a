// detect_defects: one synthetic mesh per kind of defect with its exact expected count, the
// combination with the soup stage of read_mesh, and real meshes against CGAL's own counts.
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "support/cgal_calls.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace MR = CGAL::Mesh_repair;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Soup = MR::Polygon_soup<Point>;

/// A mesh built face by face (no soup repair), each face on its own list of point indices.
Mesh mesh_from(const std::vector<Point>& points,
               const std::vector<std::vector<std::size_t>>& polygons) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertices;
  for (const Point& p : points) vertices.push_back(mesh.add_vertex(p));
  for (const auto& polygon : polygons) {
    std::vector<Mesh::Vertex_index> face;
    for (std::size_t i : polygon) face.push_back(vertices[i]);
    EXPECT_NE(mesh.add_face(face), Mesh::null_face());
  }
  return mesh;
}

/// The `check` pipeline on an in-memory soup: soup repair, mesh, detection, combination.
MR::Defect_report check_soup(const std::vector<Point>& points,
                             const std::vector<std::vector<std::size_t>>& polygons,
                             double tolerance = -1) {
  Soup soup{points, polygons};
  MR::Soup_repair_report soup_report = MR::repair_polygon_soup(soup);
  Mesh mesh;
  EXPECT_EQ(MR::soup_to_mesh(soup, mesh, true, soup_report), "");
  MR::Defect_report report = MR::detect_defects(mesh, MR::parameters::merge_tolerance(tolerance));
  MR::add_soup_repair_report(report, soup_report, mesh);
  return report;
}

/// Unit cube [0,1]^3 as 12 outward triangles; `skip_top` leaves the two triangles of z = 1 out.
std::pair<std::vector<Point>, std::vector<std::vector<std::size_t>>> cube(bool skip_top) {
  std::vector<Point> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<std::vector<std::size_t>> faces = {
      {0, 2, 3}, {0, 3, 1},  // z = 0
      {0, 1, 5}, {0, 5, 4},  // y = 0
      {1, 3, 7}, {1, 7, 5},  // x = 1
      {3, 2, 6}, {3, 6, 7},  // y = 1
      {2, 0, 4}, {2, 4, 6},  // x = 0
  };
  if (!skip_top) {
    faces.push_back({4, 5, 7});
    faces.push_back({4, 7, 6});
  }
  return {points, faces};
}

/// A planar n x n grid of unit-spacing `step` squares split into triangles, offset by `origin`,
/// appended to points/faces.
void add_grid(std::vector<Point>& points, std::vector<std::vector<std::size_t>>& faces, double x0,
              double y0, double step, int n) {
  const std::size_t first = points.size();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) points.emplace_back(x0 + i * step, y0 + j * step, 0);
  auto id = [&](int i, int j) { return first + std::size_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
}

MR::Defect_counts counts_of(const MR::Defect_report& r) {
  return MR::counts(r);
}

TEST(DetectDefects, ClosedCubeHasNoDefectAndOutwardVolume) {
  const auto c = cube(false);
  const Mesh mesh = mesh_from(c.first, c.second);
  const auto report = MR::detect_defects(mesh);
  EXPECT_TRUE(report.closed);
  EXPECT_FALSE(counts_of(report).any());
  ASSERT_EQ(report.components.size(), 1u);
  EXPECT_EQ(report.components[0].faces, 12u);
  EXPECT_EQ(report.components[0].orientation, MR::Volume_orientation::outward);
  EXPECT_TRUE(report.self_intersections_checked);
}

TEST(DetectDefects, ReversedCubeBoundsAnInwardVolume) {
  auto c = cube(false);
  for (auto& f : c.second) std::swap(f[1], f[2]);
  const auto report = MR::detect_defects(mesh_from(c.first, c.second));
  ASSERT_EQ(report.components.size(), 1u);
  EXPECT_EQ(report.components[0].orientation, MR::Volume_orientation::inward);
}

TEST(DetectDefects, CubeMissingOneFaceHasOneSquareBorderCycle) {
  const auto c = cube(true);
  const auto report = MR::detect_defects(mesh_from(c.first, c.second));
  EXPECT_FALSE(report.closed);
  ASSERT_EQ(report.border_cycles.size(), 1u);
  EXPECT_EQ(report.border_cycles[0].edges, 4u);
  EXPECT_DOUBLE_EQ(report.border_cycles[0].perimeter, 4.0);
  EXPECT_NEAR(report.border_cycles[0].area, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(report.border_cycles[0].bbox.min[2], 1.0);
  EXPECT_EQ(report.border_cycles[0].island_of, -1);
  const auto n = counts_of(report);
  EXPECT_EQ(n.small_gaps + n.t_junctions + n.overlaps + n.self_intersections + n.slivers +
                n.degenerate_faces + n.needles + n.caps + n.non_manifold_edges +
                n.non_manifold_vertices,
            0u);
  EXPECT_EQ(report.components[0].orientation, MR::Volume_orientation::not_closed);
}

// Two 4 x 4 grids of spacing 0.1 side by side, 0.01 apart: the 5 vertex pairs across the gap.
std::pair<std::vector<Point>, std::vector<std::vector<std::size_t>>> two_patches(double gap) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  add_grid(points, faces, 0, 0, 0.1, 4);
  add_grid(points, faces, 0.4 + gap, 0, 0.1, 4);
  return {points, faces};
}

TEST(DetectDefects, GapOfKnownWidthGivesOnePairPerFacingVertex) {
  const auto p = two_patches(0.01);
  const Mesh mesh = mesh_from(p.first, p.second);
  const auto within = MR::detect_defects(mesh, MR::parameters::merge_tolerance(0.02));
  EXPECT_EQ(within.small_gaps.size(), 5u);
  for (const auto& gap : within.small_gaps) {
    EXPECT_NEAR(gap.distance, 0.01, 1e-12);
    EXPECT_FALSE(gap.same_cycle);
  }
  EXPECT_EQ(within.t_junctions.size(), 0u);
  EXPECT_EQ(within.border_cycles.size(), 2u);
  EXPECT_EQ(within.components.size(), 2u);
  const auto below = MR::detect_defects(mesh, MR::parameters::merge_tolerance(0.005));
  EXPECT_EQ(below.small_gaps.size(), 0u);
}

TEST(DetectDefects, DefaultToleranceIsAQuarterOfTheMeanBorderEdge) {
  const auto p = two_patches(0.01);
  const auto report = MR::detect_defects(mesh_from(p.first, p.second));
  EXPECT_TRUE(report.tolerance_derived);
  EXPECT_NEAR(report.tolerance, 0.025, 1e-12);
  EXPECT_EQ(report.small_gaps.size(), 5u);
}

TEST(DetectDefects, ToleranceRelativeToTheDiagonal) {
  const auto p = two_patches(0.01);
  const auto report =
      MR::detect_defects(mesh_from(p.first, p.second), MR::parameters::relative_tolerance(0.001));
  EXPECT_NEAR(report.tolerance, 0.001 * std::sqrt(0.81 * 0.81 + 0.4 * 0.4), 1e-12);
  EXPECT_EQ(report.small_gaps.size(), 0u);
}

// Left square [0,1]^2 (two triangles); right square [1,2] x [0,1] whose left side has a vertex
// at (1, 0.5): that vertex lies on the interior of the left square's right edge.
TEST(DetectDefects, TJunctionStripHasOneTJunction) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0},   {1, 1, 0}, {0, 1, 0},  // left
                                     {1, 0, 0}, {1, 0.5, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  const std::vector<std::vector<std::size_t>> faces = {
      {0, 1, 2}, {0, 2, 3}, {4, 7, 5}, {5, 7, 8}, {5, 8, 6}};
  const auto report =
      MR::detect_defects(mesh_from(points, faces), MR::parameters::merge_tolerance(0.01));
  ASSERT_EQ(report.t_junctions.size(), 1u);
  EXPECT_EQ(report.t_junctions[0].vertex, 5u);
  EXPECT_DOUBLE_EQ(report.t_junctions[0].distance, 0.0);
  EXPECT_DOUBLE_EQ(report.t_junctions[0].foot[1], 0.5);
  // The two corners where the squares touch without sharing an edge are pinched (CGAL's
  // definition); they are reported there, not as zero-width gaps.
  EXPECT_EQ(report.non_manifold_vertices.size(), 2u);
  EXPECT_EQ(report.small_gaps.size(), 0u);
}

// Two triangles sharing only one vertex.
const std::vector<Point> bow_tie_points = {
    {0, 0, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}};
const std::vector<std::vector<std::size_t>> bow_tie_faces = {{0, 1, 2}, {0, 3, 4}};

TEST(DetectDefects, BowTieInAHalfedgeMeshIsOneNonManifoldVertex) {
  const auto report = MR::detect_defects(mesh_from(bow_tie_points, bow_tie_faces));
  ASSERT_EQ(report.non_manifold_vertices.size(), 1u);
  EXPECT_EQ(report.non_manifold_vertices[0].point, (MR::Coordinates{0, 0, 0}));
  EXPECT_EQ(report.non_manifold_edges.size(), 0u);
  EXPECT_EQ(report.small_gaps.size(), 0u);
}

TEST(DetectDefects, BowTieSplitBySoupStageIsCountedOnce) {
  const auto report = check_soup(bow_tie_points, bow_tie_faces);
  EXPECT_EQ(report.soup_stage.non_manifold_vertices, 1u);
  EXPECT_EQ(counts_of(report).non_manifold_vertices, 1u);
  EXPECT_EQ(counts_of(report).small_gaps, 0u);
}

// Three triangles around the edge (0,0,0)-(1,0,0).
const std::vector<Point> fin_points = {
    {0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
const std::vector<std::vector<std::size_t>> fin_faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};

TEST(DetectDefects, EdgeSharedByThreeTrianglesIsOneNonManifoldEdge) {
  const auto report = check_soup(fin_points, fin_faces);
  EXPECT_EQ(report.soup_stage.non_manifold_edges, 1u);
  const auto n = counts_of(report);
  EXPECT_EQ(n.non_manifold_edges, 1u);
  // Its two ends are non-manifold vertices too (the faces around them form three fans).
  EXPECT_EQ(n.non_manifold_vertices, 2u);
  EXPECT_EQ(n.small_gaps, 0u);
  ASSERT_FALSE(report.non_manifold_edges.empty());
  // Found again in the split mesh, at the same place: listed once.
  EXPECT_FALSE(report.non_manifold_edges[0].from_soup_stage);
  EXPECT_EQ(report.non_manifold_edges[0].face_sides, 3u);
}

TEST(DetectDefects, DuplicatedFaceOfASoupIsCounted) {
  auto c = cube(false);
  c.second.push_back(c.second.front());
  const auto report = check_soup(c.first, c.second);
  EXPECT_EQ(counts_of(report).duplicated_faces, 1u);
  EXPECT_TRUE(report.closed);
}

TEST(DetectDefects, TwoFacesOnTheSameVerticesAreDuplicates) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {0, 2, 1}}));
  EXPECT_EQ(report.duplicated_faces.size(), 1u);
  EXPECT_EQ(report.overlaps.size(), 0u);  // reported as a duplicate, not again as an overlap
}

TEST(DetectDefects, DuplicatedFaceOnCoincidentVerticesIsFound) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                     {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(report.duplicated_faces.size(), 1u);
}

TEST(DetectDefects, FlippedFaceOfASoupIsCounted) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  add_grid(points, faces, 0, 0, 1, 2);
  std::swap(faces[3][1], faces[3][2]);
  const auto report = check_soup(points, faces);
  EXPECT_EQ(report.soup_stage.polygons_reversed, 1u);
  EXPECT_EQ(counts_of(report).inconsistent_orientation, 1u);
}

TEST(DetectDefects, FlippedFaceOnCoincidentVerticesIsInconsistentOrientation) {
  // Two triangles along the segment (1,0,0)-(0,1,0), each with its own vertices; the second runs
  // the common segment the same way as the first.
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                     {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(report.inconsistently_oriented_faces.size(), 1u);
  EXPECT_TRUE(report.orientable);
  EXPECT_EQ(report.non_manifold_vertices.size(), 0u);
}

std::size_t degenerate_of_kind(const MR::Defect_report& r, MR::Degeneracy kind) {
  std::size_t n = 0;
  for (const auto& d : r.badly_shaped_faces) n += d.kind == kind ? 1 : 0;
  return n;
}

// Needles and caps have an area: they are counted as such, never as degenerate faces.
TEST(DetectDefects, NeedleIsCountedAsANeedleNotAsADegenerateFace) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {1, 0.01, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}}));
  EXPECT_EQ(report.badly_shaped_faces.size(), 1u);
  EXPECT_EQ(degenerate_of_kind(report, MR::Degeneracy::needle), 1u);
  EXPECT_EQ(report.slivers.size(), 0u);
  const auto c = MR::counts(report);
  EXPECT_EQ(c.needles, 1u);
  EXPECT_EQ(c.caps, 0u);
  EXPECT_EQ(c.degenerate_faces, 0u);
}

TEST(DetectDefects, CapIsCountedAsACapNotAsADegenerateFace) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.01, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}}));
  EXPECT_EQ(report.badly_shaped_faces.size(), 1u);
  EXPECT_EQ(degenerate_of_kind(report, MR::Degeneracy::cap), 1u);
  EXPECT_GT(report.badly_shaped_faces[0].max_angle_deg, 160.0);
  const auto c = MR::counts(report);
  EXPECT_EQ(c.caps, 1u);
  EXPECT_EQ(c.needles, 0u);
  EXPECT_EQ(c.degenerate_faces, 0u);
}

TEST(DetectDefects, CollinearTriangleHasExactlyZeroArea) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}}));
  EXPECT_EQ(degenerate_of_kind(report, MR::Degeneracy::zero_area), 1u);
  EXPECT_EQ(MR::counts(report).degenerate_faces, 1u);
}

TEST(DetectDefects, ObtuseTriangleIsASliverByShapeFactor) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.2, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}}));
  ASSERT_EQ(report.slivers.size(), 1u);
  EXPECT_LT(report.slivers[0].shape_factor, 0.7);
  EXPECT_EQ(report.badly_shaped_faces.size(), 0u);
  const auto strict =
      MR::detect_defects(mesh_from(points, {{0, 1, 2}}),
                         MR::parameters::shape_factor_threshold(0.5).aspect_ratio_threshold(0.1));
  EXPECT_EQ(strict.slivers.size(), 0u);
}

TEST(DetectDefects, OverlappingCoplanarTrianglesAreOneOverlap) {
  const std::vector<Point> points = {{0, 0, 0},     {2, 0, 0},     {0, 2, 0},
                                     {0.5, 0.5, 0}, {2.5, 0.5, 0}, {0.5, 2.5, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(report.overlaps.size(), 1u);
  EXPECT_EQ(report.self_intersections.size(), 1u);
}

TEST(DetectDefects, CoplanarTrianglesTouchingAlongAnEdgeDoNotOverlap) {
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {2, 1, 3}}));
  EXPECT_EQ(report.overlaps.size(), 0u);
  EXPECT_EQ(report.self_intersections.size(), 0u);
}

TEST(DetectDefects, FoldedNeighbourOverlapsExactly) {
  // The second triangle is folded back onto the first across their common edge.
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 0}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {2, 1, 3}}));
  EXPECT_EQ(report.overlaps.size(), 1u);
}

TEST(DetectDefects, CrossingTrianglesAreOneSelfIntersection) {
  const std::vector<Point> points = {{0, 0, 0},      {2, 0, 0},     {0, 2, 0},
                                     {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 0.5, 0.2}};
  const auto report = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(report.self_intersections.size(), 1u);
  EXPECT_EQ(report.overlaps.size(), 0u);
  const auto skipped = MR::detect_defects(mesh_from(points, {{0, 1, 2}, {3, 4, 5}}),
                                          MR::parameters::detect_self_intersections(false));
  EXPECT_FALSE(skipped.self_intersections_checked);
  EXPECT_EQ(skipped.self_intersections.size(), 0u);
}

// A 6 x 6 grid with the middle 2 x 2 squares removed, and a small square patch floating inside
// that hole: a ring hole whose island is the patch.
TEST(DetectDefects, PatchInsideAHoleIsAnIslandOfThatHole) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  add_grid(points, faces, 0, 0, 1, 6);
  std::vector<std::vector<std::size_t>> kept;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const int cell = int(f / 2), i = cell % 6, j = cell / 6;
    if (!(i >= 2 && i < 4 && j >= 2 && j < 4)) kept.push_back(faces[f]);
  }
  add_grid(points, kept, 2.5, 2.5, 1, 1);
  const auto report = MR::detect_defects(mesh_from(points, kept));
  ASSERT_EQ(report.border_cycles.size(), 3u);
  EXPECT_EQ(counts_of(report).ring_hole_islands, 1u);
  for (const auto& cycle : report.border_cycles) {
    if (cycle.island_of < 0) continue;
    EXPECT_EQ(cycle.edges, 4u);                                               // the island
    EXPECT_EQ(report.border_cycles[std::size_t(cycle.island_of)].edges, 8u);  // the hole
  }
}

// A 12 x 12 grid with three 2 x 2 holes, a patch floating in two of them, a patch above the
// third (farther from its plane than the hole is wide) and 400 patches far from the grid: each
// patch border is an island cycle, and only the two inside a hole are that hole's islands.
TEST(DetectDefects, IslandsAmongHundredsOfSeparatePatchesGoToTheHoleAroundThem) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  add_grid(points, faces, 0, 0, 1, 12);
  const std::vector<std::pair<int, int>> hole_corners = {{2, 2}, {7, 3}, {4, 8}};
  std::vector<std::vector<std::size_t>> kept;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const int cell = int(f / 2), i = cell % 12, j = cell / 12;
    const bool in_hole = std::any_of(hole_corners.begin(), hole_corners.end(), [&](auto c) {
      return i >= c.first && i < c.first + 2 && j >= c.second && j < c.second + 2;
    });
    if (!in_hole) kept.push_back(faces[f]);
  }
  add_grid(points, kept, 2.5, 2.5, 1, 1);
  add_grid(points, kept, 7.5, 3.5, 1, 1);
  const std::size_t above = points.size();
  add_grid(points, kept, 4.5, 8.5, 1, 1);
  for (std::size_t v = above; v < points.size(); ++v)
    points[v] = Point(points[v].x(), points[v].y(), 5.0);
  for (int k = 0; k < 400; ++k) add_grid(points, kept, 100 + 2 * (k % 20), 2 * (k / 20), 1, 1);
  const auto report =
      MR::detect_defects(mesh_from(points, kept), MR::parameters::detect_self_intersections(false));
  ASSERT_EQ(report.border_cycles.size(), 1u + 3u + 3u + 400u);
  EXPECT_EQ(counts_of(report).ring_hole_islands, 2u);
  for (const auto& cycle : report.border_cycles) {
    if (cycle.island_of < 0) continue;
    EXPECT_EQ(cycle.edges, 4u);
    EXPECT_EQ(report.border_cycles[std::size_t(cycle.island_of)].edges, 8u);
  }
}

TEST(DetectDefects, AnnulusHasNoIsland) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  add_grid(points, faces, 0, 0, 1, 4);
  std::vector<std::vector<std::size_t>> kept;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const int cell = int(f / 2), i = cell % 4, j = cell / 4;
    if (!(i >= 1 && i < 3 && j >= 1 && j < 3)) kept.push_back(faces[f]);
  }
  const auto report = MR::detect_defects(mesh_from(points, kept));
  EXPECT_EQ(report.border_cycles.size(), 2u);
  EXPECT_EQ(counts_of(report).ring_hole_islands, 0u);
}

TEST(DetectDefects, QualityHistogramsCoverEveryTriangle) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 2);
  const auto report = MR::detect_defects(sphere, MR::parameters::histogram_bins(5));
  EXPECT_EQ(report.quality.triangles, sphere.number_of_faces());
  ASSERT_EQ(report.quality.shape_factor_histogram.size(), 5u);
  std::size_t total = 0;
  for (std::size_t n : report.quality.shape_factor_histogram) total += n;
  EXPECT_EQ(total, sphere.number_of_faces());
  EXPECT_TRUE(report.closed);
  EXPECT_FALSE(counts_of(report).any());
}

struct Counting_visitor : MR::Default_visitor {
  int steps = 0;
  bool cancel_at_third = false;
  void start_step(const char*) { ++steps; }
  bool progress(double) { return !(cancel_at_third && steps >= 3); }
};

TEST(DetectDefects, VisitorSeesEveryStepAndCanCancel) {
  const auto c = cube(true);
  const Mesh mesh = mesh_from(c.first, c.second);
  Counting_visitor all;
  const auto full = MR::detect_defects(mesh, CGAL::parameters::visitor(std::ref(all)));
  EXPECT_EQ(all.steps, 8);
  EXPECT_FALSE(full.cancelled);
  Counting_visitor stopper;
  stopper.cancel_at_third = true;
  const auto partial = MR::detect_defects(mesh, CGAL::parameters::visitor(std::ref(stopper)));
  EXPECT_TRUE(partial.cancelled);
  EXPECT_EQ(partial.border_cycles.size(), 1u);  // steps before the cancellation are kept

  // By value the visitor is copied: it runs, and the caller's object stays as it was.
  Counting_visitor copied;
  copied.cancel_at_third = true;
  const auto by_value = MR::detect_defects(mesh, CGAL::parameters::visitor(copied));
  EXPECT_TRUE(by_value.cancelled);
  EXPECT_EQ(copied.steps, 0);
}

TEST(DetectDefects, JsonHasTheTopLevelCounts) {
  const auto c = cube(true);
  const auto report = MR::detect_defects(mesh_from(c.first, c.second));
  std::ostringstream text;
  MR::Json_writer json(text);
  MR::write_json(json, report);
  for (const char* key :
       {"\"vertices\": 8", "\"faces\": 10", "\"border_cycles\": 1", "\"non_manifold_edges\": 0",
        "\"closed\": false", "\"self_intersections\": 0", "\"connected_components\": 1"})
    EXPECT_NE(text.str().find(key), std::string::npos) << key;
  EXPECT_NE(MR::summary(report).find("border cycles:          1"), std::string::npos);
}

TEST(DetectDefects, PolyhedronGivesTheSameReportAsSurfaceMesh) {
  const auto c = cube(true);
  const Mesh mesh = mesh_from(c.first, c.second);
  CGAL::Polyhedron_3<Kernel> polyhedron;
  CGAL::copy_face_graph(mesh, polyhedron);
  const auto from_polyhedron = counts_of(MR::detect_defects(polyhedron));
  const auto from_surface_mesh = counts_of(MR::detect_defects(mesh));
  EXPECT_EQ(from_polyhedron.border_cycles, 1u);
  EXPECT_EQ(from_polyhedron.border_cycles, from_surface_mesh.border_cycles);
  EXPECT_EQ(from_polyhedron.connected_components, 1u);
  EXPECT_EQ(from_polyhedron.slivers, from_surface_mesh.slivers);
  EXPECT_EQ(from_polyhedron.overlaps + from_polyhedron.self_intersections, 0u);
}

// Real meshes of libcgal-demo.
std::string demo_mesh(const std::string& name) {
  return std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/" + name;
}

/// The {n/step} star polygon on the unit circle, triangulated as a fan from its first corner
/// (what read_mesh makes of such a polygon): every fan triangle overlaps many others.
Mesh fan_of_star_polygon(std::size_t n, std::size_t step) {
  const double pi = 3.14159265358979323846;
  std::vector<Point> points;
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = 2 * pi * double((k * step) % n) / double(n);
    points.emplace_back(std::cos(angle), std::sin(angle), 0);
  }
  std::vector<std::vector<std::size_t>> fan;
  for (std::size_t k = 1; k + 1 < n; ++k) fan.push_back({0, k, k + 1});
  return mesh_from(points, fan);
}

/// detect_defects on plain options, with the pair limit the public function leaves at default.
MR::Defect_report detect_with_pair_limit(const Mesh& mesh, std::size_t pair_limit,
                                         bool self_intersections = true) {
  MR::internal::detect::Options options;
  options.pair_limit = pair_limit;
  options.self_intersections = self_intersections;
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  const auto fim = CGAL::get_initialized_face_index_map(mesh);
  const auto him = CGAL::get_initialized_halfedge_index_map(mesh);
  using Access =
      MR::internal::detect::Mesh_access<Mesh, Mesh::Property_map<Mesh::Vertex_index, Point>, Kernel,
                                        std::decay_t<decltype(vim)>, std::decay_t<decltype(fim)>,
                                        std::decay_t<decltype(him)>>;
  MR::Default_visitor quiet;
  return MR::internal::detect::run_detection(Access{mesh, mesh.points(), Kernel(), vim, fim, him},
                                             options, MR::Any_visitor(quiet));
}

TEST(DetectDefects, SelfOverlappingStarStopsAtThePairLimitAndSaysTheCountIsALowerBound) {
  const Mesh star = fan_of_star_polygon(101, 40);
  const MR::Defect_report full = MR::detect_defects(star);
  ASSERT_TRUE(full.self_intersections_checked);
  EXPECT_FALSE(full.self_intersections_truncated);
  EXPECT_FALSE(full.overlaps_truncated);
  ASSERT_GT(full.self_intersections.size(), 200u);  // quadratic in the 99 fan triangles

  const std::size_t limit = 50;
  const MR::Defect_report bounded = detect_with_pair_limit(star, limit);
  EXPECT_TRUE(bounded.self_intersections_truncated);
  EXPECT_EQ(bounded.self_intersections.size(), limit);
  EXPECT_TRUE(bounded.overlaps_truncated);
  EXPECT_LE(bounded.overlaps.size(), limit);
  EXPECT_TRUE(bounded.small_gaps_truncated);
  EXPECT_EQ(bounded.small_gaps.size(), limit);
  EXPECT_TRUE(bounded.t_junctions_truncated);
  EXPECT_EQ(bounded.t_junctions.size(), limit);
  EXPECT_FALSE(bounded.cancelled);
  // Every pair kept is a true intersection, and the text and JSON say "at least".
  for (const auto& pair : bounded.self_intersections) EXPECT_NE(pair.first, pair.second);
  EXPECT_NE(MR::summary(bounded).find("at least 50 face pair(s)"), std::string::npos);
  std::ostringstream text;
  MR::Json_writer json(text);
  MR::write_json(json, bounded);
  EXPECT_NE(text.str().find("\"self_intersections_truncated\": true"), std::string::npos);

  // Without self-intersections, the coplanar-overlap pass stops at the limit too.
  const MR::Defect_report coplanar = detect_with_pair_limit(star, limit, false);
  EXPECT_FALSE(coplanar.self_intersections_checked);
  EXPECT_TRUE(coplanar.overlaps_truncated);
  EXPECT_EQ(coplanar.overlaps.size(), limit);
}

// A {2000/3} star fanned: 1998 thin triangles whose boxes nearly all meet one another (about
// 2 million box pairs) though far fewer triangles intersect. The box passes stop after ten
// times the pair limit of candidates, below the pair limit of pairs, and say the count is a
// lower bound.
TEST(DetectDefects, BoxPassesStopAtTheCandidateLimitOnAFanOfThinTriangles) {
  const Mesh star = fan_of_star_polygon(2000, 3);
  const std::size_t pair_limit = MR::internal::default_pair_limit(num_faces(star));
  ASSERT_EQ(pair_limit, 100000u);
  const MR::Defect_report report = MR::detect_defects(star);
  ASSERT_TRUE(report.self_intersections_checked);
  EXPECT_TRUE(report.self_intersections_truncated);
  EXPECT_GT(report.self_intersections.size(), 0u);
  EXPECT_LT(report.self_intersections.size(), pair_limit);  // stopped by the candidates
  for (const auto& pair : report.self_intersections) EXPECT_NE(pair.first, pair.second);
  const MR::Defect_report coplanar = detect_with_pair_limit(star, 0, false);
  EXPECT_TRUE(coplanar.overlaps_truncated);
  EXPECT_LT(coplanar.overlaps.size(), pair_limit);
}

class RealMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(RealMesh, BorderCycleCountEqualsCgalExtractBoundaryCycles) {
  const std::string path = demo_mesh(GetParam());
  if (!std::filesystem::exists(path))
    GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh mesh;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path, mesh, soup), "");
  const std::vector<Mesh::Halfedge_index> cycles = mesh_repair_test::boundary_cycles(mesh);
  const auto report = MR::detect_defects(mesh, MR::parameters::detect_self_intersections(false));
  EXPECT_EQ(report.border_cycles.size(), cycles.size());
  EXPECT_GT(cycles.size(), 0u);
  std::size_t border_halfedges = 0;
  for (auto h : halfedges(mesh)) border_halfedges += is_border(h, mesh) ? 1 : 0;
  std::size_t edges_in_cycles = 0;
  for (const auto& c : report.border_cycles) edges_in_cycles += c.edges;
  EXPECT_EQ(edges_in_cycles, border_halfedges);
}

INSTANTIATE_TEST_SUITE_P(DemoMeshesWithHoles, RealMesh,
                         ::testing::Values("elephant-with-holes.off", "mech-holes-shark.off",
                                           "holes.off", "mesh_with_border.off"));

class ClosedRealMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(ClosedRealMesh, ReportsNoBorderAndAnOutwardVolume) {
  const std::string path = demo_mesh(GetParam());
  if (!std::filesystem::exists(path))
    GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh mesh;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path, mesh, soup), "");
  const auto report = MR::detect_defects(mesh);
  EXPECT_EQ(report.border_cycles.size(), 0u);
  EXPECT_TRUE(report.closed);
  for (const auto& c : report.components) EXPECT_EQ(c.orientation, MR::Volume_orientation::outward);
}

INSTANTIATE_TEST_SUITE_P(DemoClosedMeshes, ClosedRealMesh,
                         ::testing::Values("elephant.off", "bunny00.off", "fandisk.off"));

}  // namespace
