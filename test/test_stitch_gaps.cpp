// stitch_gaps (thesis 4.2, 4.3.1): gaps, overlaps and non-matching nodes closed within tolerance,
// nothing merged beyond it.
#include "stitch_test_meshes.h"

#include <CGAL/Mesh_repair/remove_overlaps.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace {
using namespace stitch_test;
namespace MR = CGAL::Mesh_repair;
namespace PMP = CGAL::Polygon_mesh_processing;

void expect_closed_manifold_valid(const Mesh& mesh, const MR::Stitch_result& result) {
  EXPECT_TRUE(result.valid);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh)) << border_cycle_count(mesh) << " border cycles left";
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
}

TEST(StitchGaps, CubeOfSixSeparateFacesWithGapsBecomesClosedWithSharpEdges) {
  const double inset = 0.01;
  Mesh cube = to_mesh(cube_of_separate_faces(inset, {3, 4, 5, 4, 3, 6}));
  ASSERT_EQ(border_cycle_count(cube), 6u);
  const MR::Stitch_result result = MR::stitch_gaps(cube);
  expect_closed_manifold_valid(cube, result);
  EXPECT_GT(result.t_junctions_split, 0u);
  EXPECT_TRUE(result.tolerance_derived);
  EXPECT_FALSE(self_intersects(cube));
  // The tangent-plane rule puts seam nodes on the cube's edges: every vertex on the unit cube.
  for (auto v : vertices(cube)) {
    const Point& p = cube.point(v);
    const double to_surface =
        std::min({std::abs(p.x()), std::abs(p.y()), std::abs(p.z()), std::abs(1 - p.x()),
                  std::abs(1 - p.y()), std::abs(1 - p.z())});
    EXPECT_LT(to_surface, 1e-9) << p;
  }
  // Non-matching nodes within tolerance slide along the seam; no move exceeds the tolerance.
  EXPECT_LE(result.max_displacement, result.merge_tolerance);
}

TEST(StitchGaps, CubeGapAboveToleranceMergesNothing) {
  Mesh cube = to_mesh(cube_of_separate_faces(0.05, {3, 4, 5, 4, 3, 6}));
  const std::size_t faces_before = cube.number_of_faces();
  const MR::Stitch_result result = MR::stitch_gaps(cube, MR::parameters::merge_tolerance(0.05));
  EXPECT_EQ(result.node_merges, 0u);
  EXPECT_EQ(result.t_junctions_split, 0u);
  EXPECT_EQ(border_cycle_count(cube), 6u);
  EXPECT_EQ(cube.number_of_faces(), faces_before);
  EXPECT_EQ(result.max_displacement, 0.0);
}

TEST(StitchGaps, ExactlyCoincidentBordersAreGluedByStitchBordersFirst) {
  Mesh cube = to_mesh(cube_of_separate_faces(0.0, {3, 3, 3, 3, 3, 3}));
  ASSERT_EQ(border_cycle_count(cube), 6u);
  const MR::Stitch_result result = MR::stitch_gaps(cube);
  EXPECT_GT(result.coincident_edges_stitched, 0u);
  expect_closed_manifold_valid(cube, result);
  EXPECT_EQ(result.max_displacement, 0.0);
}

TEST(StitchGaps, CurvedPatchesWithDifferentNodeCountsJoinAlongTheCurve) {
  const double gap = 0.01;
  Mesh patches = to_mesh(curved_patches(7, 11, gap));
  ASSERT_EQ(border_cycle_count(patches), 2u);
  const MR::Stitch_result result = MR::stitch_gaps(patches);
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(border_cycle_count(patches), 1u);
  EXPECT_EQ(non_manifold_vertex_count(patches), 0u);
  EXPECT_FALSE(self_intersects(patches));
  // Nodes moved onto the seam stay on the surface z = 0.3 sin(2x) within the gap width.
  for (auto v : vertices(patches)) {
    const Point& p = patches.point(v);
    EXPECT_LT(std::abs(p.z() - 0.3 * std::sin(2 * p.x())), gap) << p;
  }
}

TEST(StitchGaps, CubicCurvesKeepInsertedNodesCloserToTheCurvedSeam) {
  auto seam_error = [](bool curves) {
    Mesh patches = to_mesh(curved_patches(4, 9, 0.004));
    MR::stitch_gaps(patches, MR::parameters::use_cubic_curves(curves));
    double worst = 0;
    for (auto v : vertices(patches)) {
      const Point& p = patches.point(v);
      worst = std::max(worst, std::abs(p.z() - 0.3 * std::sin(2 * p.x())));
    }
    return worst;
  };
  EXPECT_LT(seam_error(true), seam_error(false));
}

TEST(StitchGaps, CutAndJitteredSphereIsRestoredWithinTheGapWidth) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  for (unsigned seed : {1u, 2u, 3u}) {
    const double gap = 0.02;
    Mesh pieces = to_mesh(cut_and_jitter(sphere, 6, gap, seed));
    ASSERT_GT(border_cycle_count(pieces), 1u);
    const MR::Stitch_result result = MR::stitch_gaps(pieces, MR::parameters::merge_tolerance(gap));
    expect_closed_manifold_valid(pieces, result);
    EXPECT_EQ(pieces.number_of_faces(), sphere.number_of_faces()) << "seed " << seed;
    EXPECT_LT(max_distance_to_unit_sphere(pieces), gap) << "seed " << seed;
    EXPECT_FALSE(self_intersects(pieces)) << "seed " << seed;
  }
}

TEST(StitchGaps, CutSphereWithNonMatchingNodesIsRestoredByTJunctionSplits) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  const double gap = 0.01;
  Mesh pieces = to_mesh(cut_and_jitter(sphere, 5, gap, 7));
  const std::size_t inserted = split_border_edges(pieces, 3);
  ASSERT_GT(inserted, 0u);
  const MR::Stitch_result result = MR::stitch_gaps(pieces, MR::parameters::merge_tolerance(gap));
  expect_closed_manifold_valid(pieces, result);
  EXPECT_GE(result.t_junctions_split, inserted);
  EXPECT_LT(max_distance_to_unit_sphere(pieces), gap);
  EXPECT_FALSE(self_intersects(pieces));
}

TEST(StitchGaps, SphereSoupWithGapsOverlapsTJointsAndHolesKeepsOnlyTheHoles) {
  // Figure 4.17: jittered cuts give gaps and overlaps, split edges give T-joints, removed faces
  // give holes far wider than the tolerance, which must stay open.
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  const double gap = 0.015;
  Mesh soup = to_mesh(cut_and_jitter(sphere, 8, gap, 11));
  split_border_edges(soup, 4);
  std::vector<face_descriptor> interior;
  for (face_descriptor f : faces(soup)) {
    bool touches_border = false;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, soup), soup))
      for (halfedge_descriptor h : halfedges_around_target(v, soup))
        if (is_border(h, soup) || is_border(opposite(h, soup), soup)) touches_border = true;
    if (!touches_border) interior.push_back(f);
  }
  ASSERT_GT(interior.size(), 200u);
  // Two holes: one face each, far apart inside patches.
  CGAL::Euler::remove_face(halfedge(interior[0], soup), soup);
  CGAL::Euler::remove_face(halfedge(interior[interior.size() - 1], soup), soup);
  const MR::Stitch_result result = MR::stitch_gaps(soup, MR::parameters::merge_tolerance(gap));
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(border_cycle_count(soup), 2u);
  EXPECT_EQ(non_manifold_vertex_count(soup), 0u);
  EXPECT_LT(max_distance_to_unit_sphere(soup), gap);
}

TEST(StitchGaps, RelativeToleranceIsAFractionOfTheBoundingBoxDiagonal) {
  Mesh cube = to_mesh(cube_of_separate_faces(0.01, {3, 3, 3, 3, 3, 3}));
  const MR::Stitch_result result = MR::stitch_gaps(cube, MR::parameters::relative_tolerance(0.02));
  EXPECT_NEAR(result.merge_tolerance, 0.02 * std::sqrt(3.0), 1e-9);
  EXPECT_FALSE(result.tolerance_derived);
  expect_closed_manifold_valid(cube, result);
}

TEST(StitchGaps, RealMeshCutAndJitteredIsRestored) {
  const std::string path = std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/elephant.off";
  Mesh elephant;
  if (!std::filesystem::exists(path) || !CGAL::IO::read_polygon_mesh(path, elephant))
    GTEST_SKIP() << "libcgal-demo mesh " << path << " absent (scripts/fetch_demo_data.sh)";
  ASSERT_TRUE(CGAL::is_closed(elephant));
  double shortest = std::numeric_limits<double>::infinity();
  for (auto e : edges(elephant))
    shortest =
        std::min(shortest, std::sqrt(CGAL::to_double(PMP::squared_edge_length(e, elephant))));
  const double gap = 0.3 * shortest;
  Mesh pieces = to_mesh(cut_and_jitter(elephant, 6, gap, 5));
  const MR::Stitch_result result = MR::stitch_gaps(pieces, MR::parameters::merge_tolerance(gap));
  expect_closed_manifold_valid(pieces, result);
  EXPECT_EQ(pieces.number_of_faces(), elephant.number_of_faces());
  std::vector<Point> points;
  for (auto v : vertices(pieces)) points.push_back(pieces.point(v));
  const double distance =
      PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(points, elephant);
  EXPECT_LT(distance, gap);
}

TEST(StitchGaps, QuadsToStitchDemoMeshLosesBorders) {
  const std::string path = std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/quads_to_stitch.off";
  Mesh quads;
  if (!std::filesystem::exists(path) || !CGAL::IO::read_polygon_mesh(path, quads))
    GTEST_SKIP() << "libcgal-demo mesh " << path << " absent (scripts/fetch_demo_data.sh)";
  PMP::triangulate_faces(quads);
  const std::size_t borders_before = border_cycle_count(quads);
  const MR::Stitch_result result = MR::stitch_gaps(quads);
  EXPECT_TRUE(result.valid);
  EXPECT_LT(border_cycle_count(quads), borders_before);
  EXPECT_EQ(non_manifold_vertex_count(quads), 0u);
}

TEST(RemoveOverlaps, DuplicatedFacesAreRemovedAndTheSphereStaysClosed) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 2);
  Soup soup;
  std::map<vertex_descriptor, std::size_t> index;
  for (vertex_descriptor v : vertices(sphere)) {
    index[v] = soup.points.size();
    soup.points.push_back(sphere.point(v));
  }
  std::size_t copied = 0;
  for (face_descriptor f : faces(sphere)) {
    std::vector<std::size_t> polygon;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, sphere), sphere))
      polygon.push_back(index[v]);
    soup.faces.push_back(polygon);
    if (copied < 10 && soup.faces.size() % 7 == 0) {
      // A duplicated face with its own copies of the points (a stray second layer).
      std::vector<std::size_t> duplicate;
      for (std::size_t i : polygon) {
        duplicate.push_back(soup.points.size());
        soup.points.push_back(soup.points[i]);
      }
      soup.faces.push_back(duplicate);
      ++copied;
    }
  }
  Mesh mesh = to_mesh(soup);
  const MR::Overlap_result result = MR::remove_overlaps(mesh);
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(result.duplicated_faces_removed, copied);
  EXPECT_EQ(mesh.number_of_faces(), sphere.number_of_faces());
  EXPECT_TRUE(CGAL::is_closed(mesh));
}

TEST(RemoveOverlaps, CoplanarOverlappingPatchIsRemovedKeepingTheLargerLayer) {
  Soup soup;
  add_grid_patch(soup, Point(0, 0, 0), Vector(2, 0, 0), Vector(0, 1, 0), 4, 2);
  add_grid_patch(soup, Point(0.5, 0.2, 0), Vector(1, 0, 0), Vector(0, 0.6, 0), 2, 2);
  Mesh mesh = to_mesh(soup);
  const MR::Overlap_result result = MR::remove_overlaps(mesh);
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(result.overlapping_faces_removed, 8u);
  EXPECT_EQ(mesh.number_of_faces(), 16u);
  EXPECT_EQ(border_cycle_count(mesh), 1u);
}

TEST(RemoveOverlaps, FacesTouchingAlongEdgesAreNotOverlaps) {
  Soup soup;
  add_grid_patch(soup, Point(0, 0, 0), Vector(1, 0, 0), Vector(0, 1, 0), 5, 5);
  Mesh mesh = to_mesh(soup);
  const MR::Overlap_result result = MR::remove_overlaps(mesh);
  EXPECT_GT(result.candidate_pairs, 0u);
  EXPECT_EQ(result.duplicated_faces_removed + result.overlapping_faces_removed, 0u);
  EXPECT_EQ(mesh.number_of_faces(), 50u);
}

}  // namespace
