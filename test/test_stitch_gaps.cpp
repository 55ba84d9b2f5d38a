// stitch_gaps (thesis 4.2, 4.3.1): gaps, overlaps and non-matching nodes closed within tolerance,
// nothing merged beyond it.
#include "support/cgal_calls.h"
#include "support/stitch_test_meshes.h"

#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/remove_overlaps.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

namespace {
using namespace stitch_test;
namespace MR = CGAL::Mesh_repair;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace support = mesh_repair_test;

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
  if (!std::filesystem::exists(path) || !support::read_polygon_mesh(path, elephant))
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
  const double distance = support::max_distance_to_triangle_mesh(points, elephant);
  EXPECT_LT(distance, gap);
}

TEST(StitchGaps, QuadsToStitchDemoMeshLosesBorders) {
  const std::string path = std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/quads_to_stitch.off";
  Mesh quads;
  if (!std::filesystem::exists(path) || !support::read_polygon_mesh(path, quads))
    GTEST_SKIP() << "libcgal-demo mesh " << path << " absent (scripts/fetch_demo_data.sh)";
  support::triangulate_faces(quads);
  const std::size_t borders_before = border_cycle_count(quads);
  const MR::Stitch_result result = MR::stitch_gaps(quads);
  EXPECT_TRUE(result.valid);
  EXPECT_LT(border_cycle_count(quads), borders_before);
  EXPECT_EQ(non_manifold_vertex_count(quads), 0u);
}

TEST(StitchGaps, CubeWithCoincidentAndNearSeamsIsClosedWithoutLosingFaces) {
  // Five faces share their borders exactly (glued by CGAL's stitch_borders, then the nodes are
  // collected again); the top face is lifted by 0.003, so its four seams are only near.
  Soup soup = cube_of_separate_faces(0.0, {4, 4, 4, 4, 4, 4});
  const std::size_t top_points = 5 * 5;
  for (std::size_t i = soup.points.size() - top_points; i < soup.points.size(); ++i)
    soup.points[i] = soup.points[i] + Vector(0, 0, 0.003);
  Mesh cube = to_mesh(soup);
  ASSERT_EQ(border_cycle_count(cube), 6u);
  const std::size_t faces_before = cube.number_of_faces();
  const MR::Stitch_result result = MR::stitch_gaps(cube, MR::parameters::merge_tolerance(0.01));
  expect_closed_manifold_valid(cube, result);
  EXPECT_GT(result.coincident_edges_stitched, 0u);
  EXPECT_GT(result.node_merges, 0u);
  EXPECT_EQ(result.border_edges_after, 0u);
  EXPECT_EQ(cube.number_of_faces(), faces_before);
  EXPECT_LE(result.max_displacement, 0.01);
  EXPECT_FALSE(self_intersects(cube));
}

/// Each vertex's position and half its shortest incident edge: the move bound of the derived
/// tolerance.
std::vector<std::pair<Point, double>> positions_and_move_bounds(const Mesh& mesh) {
  std::vector<std::pair<Point, double>> out;
  for (vertex_descriptor v : vertices(mesh)) {
    double shortest = std::numeric_limits<double>::infinity();
    for (halfedge_descriptor h : halfedges_around_target(v, mesh))
      shortest = std::min(
          shortest, std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(source(h, mesh)))));
    out.emplace_back(mesh.point(v), 0.5 * shortest);
  }
  return out;
}

/// Every vertex of `before` that is still in `after` (stitching only removes glued copies and
/// appends T-junction nodes) moved by at most its bound; returns the largest move.
double expect_moves_within_bounds(const std::vector<std::pair<Point, double>>& before,
                                  const Mesh& after) {
  double largest = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const vertex_descriptor v(static_cast<Mesh::size_type>(i));
    if (after.is_removed(v)) continue;
    const double move = std::sqrt(CGAL::squared_distance(before[i].first, after.point(v)));
    EXPECT_LE(move, before[i].second * (1 + 1e-12)) << "vertex " << i;
    largest = std::max(largest, move);
  }
  return largest;
}

TEST(StitchGaps, DerivedToleranceMovesNoVertexByMoreThanHalfItsShortestEdge) {
  // A coarse sheet facing a thin strip (cells 1 x 0.05) across a gap of 0.2, nodes offset by
  // 0.3: half the border edges (0.5) would pair them; half the strip's shortest edge does not.
  Soup soup;
  add_grid_patch(soup, Point(0, -2, 0), Vector(10, 0, 0), Vector(0, 2, 0), 10, 2);
  add_grid_patch(soup, Point(0.3, 0.2, 0), Vector(9, 0, 0), Vector(0, 0.05, 0), 9, 1);
  Mesh strip = to_mesh(soup);
  const auto strip_before = positions_and_move_bounds(strip);
  const MR::Stitch_result strip_result = MR::stitch_gaps(strip);
  EXPECT_TRUE(strip_result.valid);
  EXPECT_LE(strip_result.max_move_to_shortest_edge, 0.5);
  expect_moves_within_bounds(strip_before, strip);
  EXPECT_EQ(border_cycle_count(strip), 2u);  // the gap is left to hole filling
  // Cut spheres whose two sides are jittered (seeds not used elsewhere): every move within its
  // bound, and none larger than the reported one.
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  for (unsigned seed : {11u, 12u, 13u}) {
    Mesh pieces = to_mesh(cut_and_jitter(sphere, 6, 0.02, seed));
    const auto before = positions_and_move_bounds(pieces);
    const MR::Stitch_result result = MR::stitch_gaps(pieces);
    EXPECT_TRUE(result.valid);
    EXPECT_GT(result.node_merges, 20u);
    EXPECT_LE(result.max_move_to_shortest_edge, 0.5);
    // The kept vertex of a glued pair moved at most as far as the removed one (reported too).
    const double measured = expect_moves_within_bounds(before, pieces);
    EXPECT_GT(measured, 0.0);
    EXPECT_LE(measured, result.max_displacement + 1e-12);
  }
}

TEST(StitchGaps, ANodePairThatGluesNoEdgeStaysWhereItWas) {
  // Two triangles whose corners are 0.001 apart: the pair is within tolerance, but no border
  // edge pair matches, so merging would only leave two distinct vertices at one point.
  Soup soup;
  soup.points = {Point(0, 0, 0),      Point(1, 0, 0),     Point(0, 1, 0),
                 Point(-0.001, 0, 0), Point(-1, -0.5, 0), Point(-0.5, -1, 0)};
  soup.faces = {{0, 1, 2}, {3, 5, 4}};
  Mesh mesh = to_mesh(soup);
  const MR::Stitch_result result = MR::stitch_gaps(mesh);
  EXPECT_EQ(result.node_merges, 1u);
  EXPECT_EQ(result.edges_stitched, 0u);
  EXPECT_EQ(result.unstitched_clusters, 1u);
  EXPECT_EQ(result.unglued_nodes_restored, 2u);
  EXPECT_EQ(result.max_displacement, 0.0);
  for (std::size_t i = 0; i < soup.points.size(); ++i)
    EXPECT_EQ(mesh.point(vertex_descriptor(static_cast<Mesh::size_type>(i))), soup.points[i]);
}

TEST(StitchGaps, TheFarCornersOfAFlapFoldedOntoItsNeighbourAreNotMerged) {
  // Two triangles on one edge, the second folded back over the first (a folded scan border):
  // their far corners are 0.05 apart, within the tolerance, far apart along the border and of
  // no common face. Merged and glued, the two faces would be one face twice, a closed pillow
  // whose duplicated face any reader removes, leaving a border.
  Soup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0), Point(0.5, 1, 0.05)};
  soup.faces = {{0, 1, 2}, {1, 0, 3}};
  Mesh mesh = to_mesh(soup);
  const MR::Stitch_result result = MR::stitch_gaps(mesh, MR::parameters::merge_tolerance(0.1));
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(result.node_merges, 0u);
  EXPECT_EQ(result.rejected_folded_flap, 1u);
  EXPECT_EQ(result.edges_stitched, 0u);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(border_cycle_count(mesh), 1u);
  for (std::size_t i = 0; i < soup.points.size(); ++i)
    EXPECT_EQ(mesh.point(vertex_descriptor(static_cast<Mesh::size_type>(i))), soup.points[i]);
}

TEST(StitchGaps, NodesAlongOneBorderSideAreNotMergedEvenWithALargeTolerance) {
  // One open sheet, border edges of 1, tolerance 2.5: nodes two edges apart along the border
  // share no face and are within tolerance, but merging them would fold the border onto itself.
  Soup soup;
  add_grid_patch(soup, Point(0, 0, 0), Vector(8, 0, 0), Vector(0, 8, 0), 8, 8);
  Mesh sheet = to_mesh(soup);
  const double area_before = PMP::area(sheet);
  const MR::Stitch_result result = MR::stitch_gaps(sheet, MR::parameters::merge_tolerance(2.5));
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(result.node_merges, 0u);
  EXPECT_GT(result.rejected_same_side, 0u);
  EXPECT_EQ(result.max_displacement, 0.0);
  EXPECT_EQ(border_cycle_count(sheet), 1u);
  EXPECT_NEAR(PMP::area(sheet), area_before, 1e-9);
  EXPECT_FALSE(self_intersects(sheet));
}

std::size_t border_edge_count(const Mesh& mesh) {
  std::size_t count = 0;
  for (halfedge_descriptor h : halfedges(mesh)) count += is_border(h, mesh);
  return count;
}

// A crack wider than the edges along it (a sphere of 5,120 faces cut across, the sides 0.07
// apart, every third border edge split), stitched with twice the gap: merging nodes whose
// partners lie along the seam pushes faces through their neighbours. With
// `check_self_intersections` the vertices of those faces are left unstitched and nothing
// intersects, while the rest of the seam is still stitched.
TEST(StitchGaps, ACheckedStitchAcrossAWideCrackAddsNoSelfIntersection) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 4);
  const Vector normal = Vector(0.3, -0.5, 0.8) / std::sqrt(0.98);
  const double gap = 0.07;
  Mesh cracked = to_mesh(crack_across(sphere, normal, gap));
  ASSERT_GT(split_border_edges(cracked, 3), 0u);
  ASSERT_FALSE(self_intersects(cracked));
  const std::size_t border_before = border_edge_count(cracked);

  Mesh unchecked = cracked;
  MR::stitch_gaps(unchecked, MR::parameters::merge_tolerance(2 * gap));
  ASSERT_TRUE(self_intersects(unchecked)) << "the case no longer needs the check";

  const MR::Stitch_result result = MR::stitch_gaps(
      cracked, MR::parameters::merge_tolerance(2 * gap).check_self_intersections(true));
  EXPECT_TRUE(result.valid);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(cracked));
  EXPECT_FALSE(self_intersects(cracked));
  EXPECT_FALSE(result.check_failed);
  EXPECT_GT(result.frozen_vertices, 0u);
  EXPECT_GT(result.self_intersections_avoided, 0u);
  EXPECT_GE(result.self_intersection_rounds, 2u);
  EXPECT_GT(result.node_merges, 0u);
  // The frozen vertices stay open; the rest of the seam is stitched (283 border edges -> 185).
  EXPECT_LT(border_edge_count(cracked), border_before * 3 / 4);
  EXPECT_GE(border_edge_count(cracked), border_edge_count(unchecked));
}

/// Pairs of border halfedges whose end points coincide in opposite directions, each halfedge in
/// at most one pair (the input of a `stitch_borders(pm, pairs)` call).
std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> coincident_border_pairs(
    const Mesh& mesh) {
  std::map<std::pair<Point, Point>, std::vector<halfedge_descriptor>> by_ends;
  for (halfedge_descriptor h : halfedges(mesh))
    if (is_border(h, mesh))
      by_ends[{mesh.point(source(h, mesh)), mesh.point(target(h, mesh))}].push_back(h);
  std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> pairs;
  for (const auto& [ends, hs] : by_ends) {
    if (!(ends.first < ends.second) || hs.size() != 1) continue;
    auto other = by_ends.find({ends.second, ends.first});
    if (other != by_ends.end() && other->second.size() == 1)
      pairs.emplace_back(hs.front(), other->second.front());
  }
  return pairs;
}

/// Same elements, slot by slot (what CGAL's stitching and ours keep, link and remove).
void expect_same_connectivity(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  ASSERT_EQ(a.number_of_halfedges(), b.number_of_halfedges());
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  for (halfedge_descriptor h : halfedges(a)) {
    ASSERT_FALSE(b.is_removed(h));
    EXPECT_EQ(a.target(h), b.target(h));
    EXPECT_EQ(a.next(h), b.next(h));
    EXPECT_EQ(a.face(h), b.face(h));
  }
  for (vertex_descriptor v : vertices(a)) {
    ASSERT_FALSE(b.is_removed(v));
    EXPECT_EQ(a.halfedge(v), b.halfedge(v));
  }
}

TEST(GlueBorderPairs, GluesLikeCgalStitchBordersAndClosesTheMesh) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  for (unsigned seed : {1u, 2u}) {
    // Gap 0: every patch has its own copies of the cut vertices, at the same places.
    const Mesh pieces = to_mesh(cut_and_jitter(sphere, 7, 0.0, seed));
    const auto pairs = coincident_border_pairs(pieces);
    ASSERT_GT(pairs.size(), 20u);
    Mesh ours = pieces, cgal = pieces;
    EXPECT_EQ(MR::internal::glue_border_halfedge_pairs(ours, pairs), pairs.size());
    EXPECT_EQ(support::stitch_borders(cgal, pairs), pairs.size());
    expect_same_connectivity(ours, cgal);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(ours));
    EXPECT_TRUE(CGAL::is_closed(ours));
    EXPECT_EQ(non_manifold_vertex_count(ours), 0u);
    EXPECT_EQ(ours.number_of_faces(), sphere.number_of_faces());
    EXPECT_EQ(ours.number_of_vertices(), sphere.number_of_vertices());
  }
}

TEST(GlueBorderPairs, RefusesAPairThatWouldDuplicateAnInteriorEdge) {
  // A fan of three triangles around o. Gluing border edge v1-v2 to v2-v3 (a zip at v2) would
  // merge v1 and v3, making the border edge o-v1 and the interior edge o-v3 one edge with three
  // faces, and the vertex non-manifold: refused, as CGAL does; the mesh is left as it was.
  Mesh fan;
  const vertex_descriptor o = fan.add_vertex(Point(0, 0, 0));
  std::vector<vertex_descriptor> v;
  for (int k = 0; k < 4; ++k)
    v.push_back(fan.add_vertex(Point(std::cos(0.5 * k), std::sin(0.5 * k), 0)));
  for (int k = 0; k < 3; ++k) fan.add_face(o, v[k], v[k + 1]);
  halfedge_descriptor v3_to_v2, v2_to_v1;
  for (halfedge_descriptor h : halfedges(fan)) {
    if (!is_border(h, fan)) continue;
    if (source(h, fan) == v[2] && target(h, fan) == v[1]) v2_to_v1 = h;
    if (source(h, fan) == v[3] && target(h, fan) == v[2]) v3_to_v2 = h;
  }
  const std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> pairs = {
      {v3_to_v2, v2_to_v1}};
  Mesh ours = fan, cgal = fan;
  EXPECT_EQ(MR::internal::glue_border_halfedge_pairs(ours, pairs), 0u);
  EXPECT_EQ(support::stitch_borders(cgal, pairs), 0u);
  expect_same_connectivity(ours, fan);
  expect_same_connectivity(ours, cgal);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(ours));
  EXPECT_EQ(non_manifold_vertex_count(ours), 0u);
  EXPECT_EQ(ours.number_of_faces(), 3u);
  EXPECT_EQ(border_cycle_count(ours), 1u);
}

TEST(PointKdTree, FindsExactlyThePointsWithinTheRadius) {
  CGAL::Random random(4);
  std::vector<MR::internal::Point_kd_tree::Point> points;
  for (int i = 0; i < 3000; ++i)
    points.push_back({random.get_double(0, 10), random.get_double(0, 1), 0.5 * (i % 3)});
  points.push_back(points[17]);  // a duplicate
  const MR::internal::Point_kd_tree tree(points);
  for (std::size_t q = 0; q < points.size(); q += 7) {
    const double radius = 0.05 + 0.3 * double(q % 5);
    std::vector<std::size_t> found, expected;
    tree.for_each_within(points[q], radius, [&](std::size_t j, double) { found.push_back(j); });
    for (std::size_t j = 0; j < points.size(); ++j) {
      const double dx = points[j][0] - points[q][0], dy = points[j][1] - points[q][1],
                   dz = points[j][2] - points[q][2];
      if (dx * dx + dy * dy + dz * dz <= radius * radius) expected.push_back(j);
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "query " << q;
  }
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
