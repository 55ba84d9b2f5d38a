// repair_t_junctions (thesis 4.3, Figures 4.4-4.6): border nodes inside other border edges split
// them and are merged; several nodes on one edge; nothing beyond the tolerance.
#include "support/stitch_test_meshes.h"

#include <CGAL/Mesh_repair/repair_t_junctions.h>
#include <gtest/gtest.h>

namespace {
using namespace stitch_test;
namespace MR = CGAL::Mesh_repair;

/// Patch above y = 0 with `cells_above` cells along the seam, patch below with `cells_below`;
/// interior seam nodes of the lower patch are moved down by `offset` (ends stay coincident).
Mesh two_patches(int cells_above, int cells_below, double offset) {
  Soup soup;
  add_grid_patch(soup, Point(0, 0, 0), Vector(1, 0, 0), Vector(0, 1, 0), cells_above, 2);
  const std::size_t below = soup.points.size();
  add_grid_patch(soup, Point(0, -1, 0), Vector(1, 0, 0), Vector(0, 1, 0), cells_below, 2);
  for (std::size_t i = below; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (p.y() == 0 && p.x() > 0 && p.x() < 1) soup.points[i] = Point(p.x(), -offset, p.z());
  }
  return to_mesh(soup);
}

TEST(TJunctions, NonConformingSeamIsMadeConformingAndClosed) {
  Mesh mesh = two_patches(2, 5, 0.0);
  const std::size_t faces_before = mesh.number_of_faces();
  ASSERT_EQ(border_cycle_count(mesh), 2u);
  const MR::Stitch_result result = MR::repair_t_junctions(mesh);
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(result.t_junctions_split, 5u);  // 1 node of the upper patch, 4 of the lower
  EXPECT_EQ(mesh.number_of_faces(), faces_before + 5);
  EXPECT_EQ(border_cycle_count(mesh), 1u);
  EXPECT_EQ(non_manifold_vertex_count(mesh), 0u);
  EXPECT_LT(result.max_displacement, 1e-12);  // coplanar seam on one line: nothing moves
}

TEST(TJunctions, SeveralNodesOnOneEdgeSplitItOnceEach) {
  Mesh mesh = two_patches(1, 6, 0.0);
  const MR::Stitch_result result = MR::repair_t_junctions(mesh);
  EXPECT_EQ(result.t_junctions_split, 5u);
  EXPECT_EQ(border_cycle_count(mesh), 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  // Every seam node is now shared by both patches: 7 vertices on y = 0.
  std::size_t on_seam = 0;
  for (auto v : vertices(mesh))
    if (mesh.point(v).y() == 0) ++on_seam;
  EXPECT_EQ(on_seam, 7u);
}

TEST(TJunctions, NodesWithinToleranceOfTheEdgeAreInsertedAndMerged) {
  const double offset = 0.01;
  Mesh mesh = two_patches(3, 4, offset);
  const MR::Stitch_result result =
      MR::repair_t_junctions(mesh, MR::parameters::merge_tolerance(0.02));
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(border_cycle_count(mesh), 1u);
  EXPECT_FALSE(self_intersects(mesh));
  EXPECT_LE(result.max_displacement, offset);
}

TEST(TJunctions, NodesFartherThanToleranceAreLeftAlone) {
  Mesh mesh = two_patches(3, 4, 0.05);
  const std::size_t faces_before = mesh.number_of_faces();
  const MR::Stitch_result result =
      MR::repair_t_junctions(mesh, MR::parameters::merge_tolerance(0.02));
  EXPECT_EQ(result.t_junctions_split, 0u);
  EXPECT_EQ(mesh.number_of_faces(), faces_before);
  EXPECT_EQ(border_cycle_count(mesh), 2u);
}

TEST(TJunctions, FoldedSeamNodesLandOnThePlanesIntersection) {
  // Two perpendicular patches (z = 0 and x = 0) meeting along the y axis, with non-matching
  // nodes and the vertical patch lifted by a small gap: inserted nodes merge onto the axis.
  Soup soup;
  add_grid_patch(soup, Point(0, 0, 0), Vector(0, 1, 0), Vector(1, 0, 0), 3, 2);
  add_grid_patch(soup, Point(0, 0, 0.005), Vector(0, 0, 1), Vector(0, 1, 0), 2, 5);
  Mesh mesh = to_mesh(soup);
  const MR::Stitch_result result =
      MR::repair_t_junctions(mesh, MR::parameters::merge_tolerance(0.01));
  EXPECT_GT(result.t_junctions_split, 0u);
  EXPECT_GT(result.tangent_plane_merges, 0u);
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    if (p.x() < 1e-9 && std::abs(p.z()) < 0.004) {
      EXPECT_NEAR(p.z(), 0.0, 1e-12) << p;
    }
  }
}

}  // namespace
