// The outer surface of a self-intersecting part whose union touches itself along an edge or at
// a corner (touching_fans.h, self_union_impl.h): the faces around each touching edge are paired
// as the wedges of the solids, each fan gets a point of its own, moved about 1e-6 of the
// diagonal into its own side, and the result is closed, valid, free of intersections, bounds the
// union's volume and lies within that distance of the input. Where the rounding of the result to
// doubles folds faces across others, the thin solids of the arrangement that cross are dropped
// (thin_solids.h).
#include <CGAL/Mesh_repair/internal/automatic_repair/self_union.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/solid_soup.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/thin_solids.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/touching_fans.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>
#include <gtest/gtest.h>

#include <array>
#include <iostream>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {
namespace MRI = CGAL::Mesh_repair::internal;
using Soup = MRI::Triangle_soup;
using Mesh = MRI::Core_mesh;
using Point = Mesh::Point;

/// Appends the closed, outward box [lo, hi] with points of its own.
void add_box(Soup& soup, const Point& lo, const Point& hi) {
  const std::size_t first = soup.points.size();
  for (int i = 0; i < 8; ++i)
    soup.points.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(),
                             (i & 4) ? hi.z() : lo.z());
  const std::array<std::array<std::size_t, 3>, 12> faces{{{0, 2, 1},
                                                          {1, 2, 3},
                                                          {4, 5, 6},
                                                          {5, 7, 6},
                                                          {0, 1, 4},
                                                          {1, 5, 4},
                                                          {2, 6, 3},
                                                          {3, 6, 7},
                                                          {0, 4, 2},
                                                          {2, 4, 6},
                                                          {1, 3, 5},
                                                          {3, 7, 5}}};
  for (const auto& f : faces) soup.polygons.push_back({first + f[0], first + f[1], first + f[2]});
}

/// A unit cube crossed by a slab (the part intersects itself), and a third box that meets the
/// cube along its edge x = y = 1 (`along_edge`) or at its corner (1, 1, 1).
Soup part_touching_itself(bool along_edge) {
  Soup soup;
  add_box(soup, Point(0, 0, 0), Point(1, 1, 1));
  add_box(soup, Point(0.5, -0.5, 0.25), Point(1.5, 0.5, 0.75));
  add_box(soup, Point(1, 1, along_edge ? 0 : 1), Point(2, 2, along_edge ? 1 : 2));
  return soup;
}

struct Checked {
  std::string why;
  MRI::Solid_autorefinement measures;
  Mesh mesh;
  double farthest_from_input = 0;
};

Checked outer_surface(const Soup& part) {
  Checked checked;
  Soup out;
  checked.why = MRI::outer_surface_of_solid(part, out, checked.measures);
  if (checked.why.empty()) {
    EXPECT_EQ(MRI::solid_union::to_closed_mesh(out, checked.mesh), "");
    // Every point of the result on the input's surface, up to the moves (about 1e-6 of the
    // diagonal, 3.2).
    Mesh input;
    EXPECT_EQ(MRI::solid_union::to_closed_mesh(part, input), "");
    checked.farthest_from_input =
        CGAL::Polygon_mesh_processing::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(
            checked.mesh.points(), input);
  }
  return checked;
}

void expect_two_separate_solids(const Checked& checked) {
  const Mesh& mesh = checked.mesh;
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(mesh.is_valid(false));
  EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(mesh));
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::does_bound_a_volume(mesh));
  std::vector<std::size_t> component(mesh.number_of_faces());
  EXPECT_EQ(
      CGAL::Polygon_mesh_processing::connected_components(mesh, CGAL::make_property_map(component)),
      2u);
  // Cube 1 + the slab outside it 0.375 + the third box 1.
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(mesh), 2.375, 1e-4);
  EXPECT_LT(checked.farthest_from_input, 1e-5);
  // No two vertices at one point: a reader that merges coincident points sees the same mesh.
  const std::set<Point> points(mesh.points().begin(), mesh.points().end());
  EXPECT_EQ(points.size(), mesh.number_of_vertices());
}

TEST(TouchingFans, FacesAroundAnEdgeWhereTwoBoxesMeetArePairedBoxByBox) {
  Soup soup;
  add_box(soup, Point(0, 0, 0), Point(1, 1, 1));
  add_box(soup, Point(1, 1, 0), Point(2, 2, 1));
  // The second box's points on the edge x = y = 1 are the first box's.
  for (auto& polygon : soup.polygons)
    for (std::size_t& v : polygon) {
      if (v == 8) v = 3;   // (1, 1, 0)
      if (v == 12) v = 7;  // (1, 1, 1)
    }
  const MRI::touching_fans::Touching touching = MRI::touching_fans::find_touching(soup);
  const auto& triangles = touching.triangles_on_edge.at({3, 7});
  ASSERT_EQ(triangles.size(), 4u);
  const auto& wedges = touching.joined.at({3, 7});
  ASSERT_EQ(wedges.size(), 2u);
  for (const auto& [f, g] : wedges) EXPECT_EQ(f < 12, g < 12) << f << " with " << g;
  // Both ends of the edge touch, each with one fan per box.
  ASSERT_EQ(touching.points.size(), 2u);
  for (const auto& point : touching.points) EXPECT_EQ(point.second.size(), 2u);
}

TEST(TouchingFans, AUnionTouchingItselfAlongAnEdgeBecomesTwoSolidsApart) {
  const Checked checked = outer_surface(part_touching_itself(true));
  ASSERT_EQ(checked.why, "");
  EXPECT_EQ(checked.measures.touching_vertices_separated, 2u);
  expect_two_separate_solids(checked);
}

TEST(TouchingFans, AUnionTouchingItselfAtACornerBecomesTwoSolidsApart) {
  const Checked checked = outer_surface(part_touching_itself(false));
  ASSERT_EQ(checked.why, "");
  EXPECT_EQ(checked.measures.touching_vertices_separated, 1u);
  expect_two_separate_solids(checked);
}

TEST(TouchingFans, APartWhoseFacesOnlyTouchIsLeftToThePatches) {
  // Two boxes meeting along an edge and nothing crossing: no face to cut.
  Soup soup;
  add_box(soup, Point(0, 0, 0), Point(1, 1, 1));
  add_box(soup, Point(1, 1, 0), Point(2, 2, 1));
  const Checked checked = outer_surface(soup);
  EXPECT_EQ(checked.why, "its faces only touch one another");
}

// Boxes on a coarse integer grid, so that they meet corner to corner, edge to edge and face to
// face, and cross: whatever the arrangement accepts is closed, valid, free of intersections,
// bounds a volume and lies on the input's surface up to the moves; and most configurations are
// accepted.
TEST(TouchingFans, EveryAcceptedOuterSurfaceOfRandomGridBoxesIsASolid) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> corner(0, 3), size(1, 2);
  int accepted = 0, separated = 0;
  const int configurations = 60;
  for (int c = 0; c < configurations; ++c) {
    Soup soup;
    for (int b = 0; b < 4; ++b) {
      const int x = corner(random), y = corner(random), z = corner(random);
      add_box(soup, Point(x, y, z), Point(x + size(random), y + size(random), z + size(random)));
    }
    const Checked checked = outer_surface(soup);
    if (!checked.why.empty()) continue;
    ++accepted;
    separated += checked.measures.touching_vertices_separated > 0;
    const Mesh& mesh = checked.mesh;
    EXPECT_TRUE(CGAL::is_closed(mesh)) << c;
    EXPECT_TRUE(mesh.is_valid(false)) << c;
    EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(mesh)) << c;
    EXPECT_TRUE(CGAL::Polygon_mesh_processing::does_bound_a_volume(mesh)) << c;
    EXPECT_LT(checked.farthest_from_input, 1e-5) << c;
  }
  EXPECT_GE(accepted, configurations * 3 / 4);
  EXPECT_GT(separated, 0);
  std::cout << accepted << " of " << configurations << " accepted, " << separated
            << " with touching points moved apart\n";
}

/// The unit cube and a tetrahedron of height `height` over the triangle (0.5, 0.2, 0.5),
/// (1.5, 0.5, 0.5), (0.5, 0.8, 0.5), which crosses the cube's face x = 1: two components.
Mesh cube_crossed_by_tetrahedron(double height) {
  Soup soup;
  add_box(soup, Point(0, 0, 0), Point(1, 1, 1));
  const std::size_t a = soup.points.size();
  soup.points.insert(soup.points.end(), {Point(0.5, 0.2, 0.5), Point(1.5, 0.5, 0.5),
                                         Point(0.5, 0.8, 0.5), Point(0.8, 0.5, 0.5 + height)});
  const std::size_t b = a + 1, c = a + 2, d = a + 3;
  soup.polygons.insert(soup.polygons.end(), {{a, c, b}, {a, b, d}, {b, c, d}, {c, a, d}});
  Mesh mesh;
  EXPECT_EQ(MRI::solid_union::to_closed_mesh(soup, mesh), "");
  return mesh;
}

MRI::self_union::Face_pairs crossing_pairs(const Mesh& mesh) {
  MRI::self_union::Face_pairs pairs;
  CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
  return pairs;
}

TEST(ThinSolids, AThinSolidCrossingAnotherPartIsDroppedAndTheRestKept) {
  const Mesh mesh = cube_crossed_by_tetrahedron(1e-7);
  const auto crossing = crossing_pairs(mesh);
  ASSERT_FALSE(crossing.empty());
  EXPECT_TRUE(MRI::self_union::crosses_between_components(mesh, crossing));
  Soup out;
  EXPECT_EQ(MRI::self_union::drop_thin_crossing_components(mesh, crossing, 1e-6, out), 1u);
  Mesh kept;
  ASSERT_EQ(MRI::solid_union::to_closed_mesh(out, kept), "");
  EXPECT_EQ(kept.number_of_faces(), 12u);
  EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(kept));
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(kept), 1.0, 1e-12);
}

TEST(ThinSolids, ASolidThickerThanTheDistanceIsKept) {
  const Mesh mesh = cube_crossed_by_tetrahedron(0.3);
  const auto crossing = crossing_pairs(mesh);
  ASSERT_FALSE(crossing.empty());
  Soup out;
  EXPECT_EQ(MRI::self_union::drop_thin_crossing_components(mesh, crossing, 1e-6, out), 0u);
  EXPECT_TRUE(out.polygons.empty());
  // Thinner than a larger distance: its volume (0.03) is below its area (about 1.0) times 0.1.
  EXPECT_EQ(MRI::self_union::drop_thin_crossing_components(mesh, crossing, 0.1, out), 1u);
}

TEST(ThinSolids, CrossingsInsideOneComponentAreNotBetweenComponents) {
  Soup soup;
  add_box(soup, Point(0, 0, 0), Point(1, 1, 1));
  soup.points[7] = Point(0.5, 0.5, -0.5);  // the corner (1, 1, 1) pushed through the bottom
  Mesh mesh;
  ASSERT_EQ(MRI::solid_union::to_closed_mesh(soup, mesh), "");
  const auto crossing = crossing_pairs(mesh);
  ASSERT_FALSE(crossing.empty());
  EXPECT_FALSE(MRI::self_union::crosses_between_components(mesh, crossing));
}

}  // namespace
