// automatic_repair: the whole pipeline on synthetic defective meshes and real ones.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/internal/child_process.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <gtest/gtest.h>

#include "support/cgal_calls.h"
#include "support/hole_punching.h"
#include "support/stitch_test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;
namespace support = mesh_repair_test;

using mesh_repair_test::count_border_cycles;
using mesh_repair_test::punch_hole;

/// The libcgal-demo mesh `name` read into `mesh`; false when the package is absent (the test
/// then skips).
bool read_demo_mesh(const std::string& name, Mesh& mesh) {
  const std::string path = std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/" + name;
  if (!std::filesystem::exists(path)) return false;
  MR::Soup_repair_report soup;
  EXPECT_EQ(MR::read_mesh(path, mesh, soup), "") << name;
  return true;
}

Mesh sphere_with_holes() {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 4);
  punch_hole(sphere, Point(1, 0, 0), 0.3);
  punch_hole(sphere, Point(-1, 0, 0), 0.25);
  punch_hole(sphere, Point(0, 0, 1), 0.35);
  sphere.collect_garbage();
  return sphere;
}

/// CGAL 5.5's experimental autorefinement runs in a child process (child_process.h): a crash
/// there ends the child only, and the caller learns the signal; a child that finishes hands its
/// bytes back whole, however many.
TEST(AutomaticRepair, ACrashInAChildProcessEndsOnlyTheChild) {
  namespace MI = CGAL::Mesh_repair::internal;
  const MI::Child_outcome crashed = MI::run_in_child_process([]() -> std::string {
    std::raise(SIGSEGV);
    return "never";
  });
  EXPECT_FALSE(crashed.finished);
  EXPECT_EQ(crashed.signal, SIGSEGV);
  EXPECT_TRUE(crashed.bytes.empty());
  const MI::Child_outcome done =
      MI::run_in_child_process([] { return std::string(1 << 20, 'x') + "end"; });
  EXPECT_TRUE(done.finished);
  EXPECT_EQ(done.bytes.size(), (1u << 20) + 3);
  EXPECT_EQ(done.bytes.substr(done.bytes.size() - 3), "end");
}

TEST(AutomaticRepair, SphereWithThreeHolesBecomesClosedAndValid) {
  Mesh mesh = sphere_with_holes();
  ASSERT_EQ(count_border_cycles(mesh), 3u);
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(result.complete()) << (result.remaining.empty() ? "" : result.remaining.front());
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(result.holes.filled, 3u);
  EXPECT_EQ(result.self_intersections_output, 0u);
  // The patches follow the sphere: every vertex within 5% of the radius.
  for (auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p, Point(0, 0, 0))), 1.0, 0.05);
  }
}

// Records the steps a visitor sees: every start has its end, in nesting order.
struct Step_log {
  std::vector<std::string> open;
  std::size_t starts = 0, ends = 0, unbalanced = 0, progress_calls = 0;
  std::size_t cancel_after = std::size_t(-1);
  void start_step(const char* name) {
    open.push_back(name);
    ++starts;
  }
  bool progress(double) { return ++progress_calls < cancel_after; }
  void end_step(const char* name) {
    ++ends;
    if (open.empty() || open.back() != name) ++unbalanced;
    if (!open.empty()) open.pop_back();
  }
};

TEST(AutomaticRepair, EveryStepReachesTheVisitorBalancedEvenWhenCancelled) {
  Mesh mesh = sphere_with_holes();
  Step_log log;
  const auto result = MR::automatic_repair(mesh, MR::parameters::visitor(std::ref(log)));
  EXPECT_GE(log.starts, result.steps.size());  // each step, and the operators' own steps inside
  EXPECT_EQ(log.starts, log.ends);
  EXPECT_EQ(log.unbalanced, 0u);
  EXPECT_TRUE(log.open.empty());

  Mesh cancelled_mesh = sphere_with_holes();
  Step_log stopper;
  stopper.cancel_after = 2;
  const auto cancelled =
      MR::automatic_repair(cancelled_mesh, MR::parameters::visitor(std::ref(stopper)));
  EXPECT_TRUE(cancelled.cancelled);
  EXPECT_FALSE(cancelled.complete());
  EXPECT_EQ(stopper.starts, stopper.ends);
  EXPECT_EQ(stopper.unbalanced, 0u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(cancelled_mesh));
}

// A visitor passed by value is copied (the caller's object does not change); by std::ref it is
// used in place.
TEST(AutomaticRepair, VisitorsWorkByValueAndByReference) {
  Mesh by_value = sphere_with_holes();
  Step_log copied;
  MR::automatic_repair(by_value, MR::parameters::visitor(copied));
  EXPECT_EQ(copied.starts, 0u);
  EXPECT_TRUE(CGAL::is_closed(by_value));

  Mesh by_reference = sphere_with_holes();
  Step_log used;
  MR::automatic_repair(by_reference, MR::parameters::visitor(std::ref(used)));
  EXPECT_GT(used.starts, 0u);
  EXPECT_TRUE(CGAL::is_closed(by_reference));
}

TEST(AutomaticRepair, HolesOverTheSizeLimitAreLeftOpenAndListed) {
  Mesh mesh = sphere_with_holes();
  const auto result = MR::automatic_repair(mesh, MR::parameters::max_hole_size(0.2));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_GT(result.holes_too_large, 0u);
  EXPECT_FALSE(result.complete());
  // Left open as asked: kept, not incomplete.
  EXPECT_EQ(result.status(), MR::Repair_status::complete_except_kept);
  EXPECT_TRUE(result.remaining.empty()) << result.remaining.front();
  ASSERT_EQ(result.kept.size(), 1u);
  EXPECT_NE(result.kept[0].find("larger than the size limit"), std::string::npos);
  EXPECT_EQ(count_border_cycles(mesh), result.holes_too_large);
}

TEST(AutomaticRepair, KeepsEveryComponentUnlessAskedAndCountsRemovals) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 2);
  MR::make_sphere(mesh, Point(5, 0, 0), 0.5, 1);
  Mesh kept = mesh;
  MR::automatic_repair(kept);
  EXPECT_EQ(support::connected_components(kept), 2u);
  const auto result = MR::automatic_repair(mesh, MR::parameters::keep_largest_component(true));
  EXPECT_EQ(result.components_removed, 1u);
  EXPECT_EQ(result.faces_removed_with_components, 80u);
  EXPECT_EQ(mesh.number_of_faces(), 320u);
}

TEST(AutomaticRepair, BundledDefectivePartBecomesClosedAndValid) {
  const std::string path = std::string(MESH_REPAIR_SOURCE_DIR) + "/data/demo/defective_part.off";
  Mesh mesh;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path, mesh, soup), "");
  EXPECT_GT(soup.points_merged, 0u);
  EXPECT_EQ(soup.duplicated_polygons_removed, 1u);
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  // The detached zero-area triangle is removed as degenerate; the block is closed.
  EXPECT_TRUE(CGAL::is_closed(mesh)) << count_border_cycles(mesh) << " border cycles left";
  EXPECT_TRUE(result.complete()) << (result.remaining.empty() ? "" : result.remaining.front());
}

// Two unit spheres whose balls overlap, each with the part inside the other's (slightly larger)
// ball removed: the input does not self-intersect, but any patch that follows the curvature
// of one hole crosses the other sphere's patch or its border region.
Mesh overlapping_spheres_with_facing_holes() {
  Mesh mesh;
  const Point a(-0.95, 0, 0), b(0.95, 0, 0);
  MR::make_sphere(mesh, a, 1.0, 4);
  MR::make_sphere(mesh, b, 1.0, 4);
  std::vector<Mesh::Face_index> doomed;
  for (auto f : mesh.faces()) {
    for (auto v : vertices_around_face(mesh.halfedge(f), mesh)) {
      const Point& p = mesh.point(v);
      const Point& other = p.x() < 0 ? b : a;
      if (CGAL::squared_distance(p, other) < 1.05 * 1.05) {
        doomed.push_back(f);
        break;
      }
    }
  }
  for (auto f : doomed) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  mesh.collect_garbage();
  return mesh;
}

/// Same vertex positions and same faces (corners by index), element for element.
void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  for (auto v : a.vertices()) EXPECT_EQ(a.point(v), b.point(v));
  for (auto f : a.faces()) {
    auto corner = vertices_around_face(b.halfedge(f), b).begin();
    for (auto v : vertices_around_face(a.halfedge(f), a)) EXPECT_EQ(v, *corner++);
  }
}

TEST(AutomaticRepair, TwoThreadsGiveTheSameMeshAsOne) {
  Mesh serial = sphere_with_holes();
  Mesh parallel = serial;
  const auto one = MR::automatic_repair(serial, MR::parameters::number_of_threads(1));
  const auto two = MR::automatic_repair(parallel, MR::parameters::number_of_threads(2));
  EXPECT_EQ(one.holes.filled, 3u);
  EXPECT_EQ(two.holes.filled, 3u);
  expect_same_mesh(serial, parallel);
}

// elephant-with-holes has 40 pinched holes (two holes meeting at a vertex): the patches welded in
// the copies cannot be spliced and are filled in place; the others come from the copies.
TEST(AutomaticRepair, RealScanGivesTheSameMeshWithTwoThreads) {
  Mesh serial;
  if (!read_demo_mesh("elephant-with-holes.off", serial))
    GTEST_SKIP() << "libcgal-demo meshes absent";
  Mesh parallel = serial;
  const auto one = MR::automatic_repair(serial, MR::parameters::number_of_threads(1));
  const auto two = MR::automatic_repair(parallel, MR::parameters::number_of_threads(2));
  EXPECT_EQ(one.holes.failed, 0u);
  EXPECT_EQ(two.holes.filled, one.holes.filled);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(parallel) && CGAL::is_closed(parallel));
  EXPECT_TRUE(two.manifold);
  expect_same_mesh(serial, parallel);
}

std::size_t self_intersection_count(const Mesh& mesh) {
  return support::self_intersections(mesh).size();
}

/// A sphere where two vertices were pushed through the surface, each along a chord (the two
/// chords do not meet) until just past the far side (the first one `depth` below the centre):
/// each spike pierces the sphere there.
Mesh sphere_with_spikes(int subdivisions = 4, std::size_t count = 2, double depth = 1.1) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, subdivisions);
  const std::pair<Point, Point> spikes[] = {{Point(0, 0, 1), Point(0, 0, -depth)},
                                            {Point(0.6, 0.8, 0), Point(0.6, -0.9, 0)}};
  for (std::size_t i = 0; i < count; ++i) {
    const auto& spike = spikes[i];
    Mesh::Vertex_index v = *mesh.vertices().begin();
    for (auto w : mesh.vertices())
      if (CGAL::squared_distance(mesh.point(w), spike.first) <
          CGAL::squared_distance(mesh.point(v), spike.first))
        v = w;
    mesh.point(v) = spike.second;
  }
  return mesh;
}

const MR::Repair_step_report* find_step(const MR::Repair_result& result, const std::string& name) {
  for (const auto& step : result.steps)
    if (step.name == name) return &step;
  return nullptr;
}

TEST(AutomaticRepair, SelfIntersectionsInsideAComponentAreReplacedByDefault) {
  Mesh mesh = sphere_with_spikes();
  const std::size_t before = self_intersection_count(mesh);
  ASSERT_GT(before, 0u);
  const auto result = MR::automatic_repair(mesh);
  EXPECT_EQ(result.self_intersections_input, before);
  EXPECT_EQ(result.self_intersections_output, 0u);
  EXPECT_EQ(self_intersection_count(mesh), 0u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(result.complete()) << (result.remaining.empty() ? "" : result.remaining.front());
  const auto* step = find_step(result, "self-intersection removal");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("pairs_within_components_before"), double(before));
  EXPECT_EQ(step->count("pairs_within_components_after"), 0.0);
  EXPECT_GT(step->count("faces_removed"), 0.0);
  EXPECT_GT(step->count("faces_added"), 0.0);
  // The spikes are gone: every vertex is back near the unit sphere.
  for (auto v : mesh.vertices())
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(mesh.point(v), Point(0, 0, 0))), 1.0, 0.1);

  Mesh kept = sphere_with_spikes();
  const auto without = MR::automatic_repair(kept, MR::parameters::repair_self_intersections(false));
  EXPECT_EQ(without.self_intersections_output, before);
  EXPECT_EQ(find_step(without, "self-intersection removal"), nullptr);
  // Not asked to remove them: the input's own self-intersections are kept, listed in `kept`.
  EXPECT_EQ(without.status(), MR::Repair_status::complete_except_kept);
  EXPECT_TRUE(without.remaining.empty()) << without.remaining.front();
}

// On a coarse part (an 80-face sphere), the rings around a spike reach most of the part:
// replacing them would rebuild the part, not repair its defect, so the self-intersection is kept
// and reported. The same spike on a 320-face sphere is a region of 15% of the faces, replaced
// (`SelfIntersectionsInsideAComponentAreReplacedByDefault` has it on 5,120 faces). The spike
// goes on 2.5 radii past the far side, too far from its neighbours (about 8 of their spacings)
// to be taken for a vertex thrown off the surface and moved back (the next test).
TEST(AutomaticRepair, ASelfIntersectionOfACoarsePartIsKeptRatherThanThePartRebuilt) {
  Mesh mesh = sphere_with_spikes(1, 1, 3.5);
  const std::size_t faces = mesh.number_of_faces();
  const std::vector<Point> points(mesh.points().begin(), mesh.points().end());
  const std::size_t before = self_intersection_count(mesh);
  ASSERT_GT(before, 0u);
  const auto result = MR::automatic_repair(mesh);
  const auto* step = find_step(result, "self-intersection removal");
  ASSERT_NE(step, nullptr);
  EXPECT_GT(step->count("regions_too_large"), 0.0);
  EXPECT_EQ(step->count("faces_removed"), 0.0);
  EXPECT_EQ(step->count("pairs_within_components_after"), double(before));
  EXPECT_EQ(result.self_intersections_output, before);
  EXPECT_EQ(result.status(), MR::Repair_status::incomplete);
  // Nothing replaced: the same faces on the same points, the spike included.
  EXPECT_EQ(mesh.number_of_faces(), faces);
  ASSERT_EQ(mesh.number_of_vertices(), points.size());
  std::size_t moved = 0;
  for (auto v : mesh.vertices()) moved += mesh.point(v) != points[std::size_t(v)];
  EXPECT_EQ(moved, 0u);
  EXPECT_TRUE(CGAL::is_closed(mesh));
}

// Vertices thrown off their place by one and a half spacings (a scan's outliers), beside a hole
// and away from it, on the flat sides of a subdivided cube: their fans overlap the faces around
// them, and a patch of the hole would meet the one beside it. Each is moved back to the centre
// of its neighbours before the holes are filled: no face is removed, and each is back near its
// grid point.
TEST(AutomaticRepair, SpikesBesideHolesAreMovedBackAndEveryFaceIsKept) {
  Mesh mesh;
  MR::make_subdivided_cube<Mesh, Point>(mesh, 1.0, 10);
  punch_hole(mesh, Point(0.5, 0.5, 1), 0.2);
  mesh.collect_garbage();
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  // Grid point, and the push within its side of the cube (1.5 spacings of 0.1).
  const std::pair<Point, Kernel::Vector_3> spikes[] = {
      {Point(0.5, 0.8, 1), Kernel::Vector_3(0.12, -0.09, 0)},  // one ring beside the hole
      {Point(0.3, 0.6, 0), Kernel::Vector_3(0.09, 0.12, 0)},
      {Point(0.5, 0, 0.4), Kernel::Vector_3(-0.12, 0, 0.09)}};
  std::vector<std::pair<Mesh::Vertex_index, Point>> moved;
  for (const auto& spike : spikes)
    for (auto v : mesh.vertices())
      if (CGAL::squared_distance(mesh.point(v), spike.first) < 1e-12) {
        mesh.point(v) = spike.first + spike.second;
        moved.emplace_back(v, spike.first);
      }
  ASSERT_EQ(moved.size(), 3u);
  ASSERT_GT(self_intersection_count(mesh), 0u);
  const std::size_t faces = mesh.number_of_faces();
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(result.complete()) << (result.remaining.empty() ? "" : result.remaining.front());
  EXPECT_EQ(self_intersection_count(mesh), 0u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(result.holes.filled, 1u);
  const auto* spike_step = find_step(result, "spikes");
  ASSERT_NE(spike_step, nullptr);
  EXPECT_EQ(spike_step->count("spike_vertices_moved"), 3.0);
  EXPECT_GT(spike_step->count("spike_largest_move"), 0.1);
  const auto* removal = find_step(result, "self-intersection removal");
  if (removal) {
    EXPECT_EQ(removal->count("faces_removed"), 0.0);
  }
  const auto* filling = find_step(result, "hole filling");
  ASSERT_NE(filling, nullptr);
  EXPECT_EQ(mesh.number_of_faces(), faces + std::size_t(filling->count("faces_added")));
  for (const auto& entry : moved)
    EXPECT_LT(std::sqrt(CGAL::squared_distance(mesh.point(entry.first), entry.second)), 0.025);
}

// An assembly of two closed solids that pass through each other: each is a solid of its own and
// the intersections between them are kept, nothing removed.
TEST(AutomaticRepair, SelfIntersectionsBetweenComponentsAreKept) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 3);
  MR::make_sphere(mesh, Point(1.2, 0.1, 0), 1.0, 3);
  const std::size_t faces = mesh.number_of_faces();
  const std::size_t before = self_intersection_count(mesh);
  ASSERT_GT(before, 0u);
  const auto result = MR::automatic_repair(mesh);
  EXPECT_EQ(result.self_intersections_output, before);
  EXPECT_EQ(mesh.number_of_faces(), faces);
  const auto* step = find_step(result, "self-intersection removal");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("pairs_between_components_kept"), double(before));
  EXPECT_EQ(step->count("pairs_within_components_before"), 0.0);
  EXPECT_EQ(step->count("faces_removed"), 0.0);
  EXPECT_EQ(result.self_intersections_between_components, before);
  // A documented choice, not a failure: listed in `kept`.
  EXPECT_EQ(result.status(), MR::Repair_status::complete_except_kept)
      << (result.remaining.empty() ? "" : result.remaining.front());
  ASSERT_EQ(result.kept.size(), 1u);
  EXPECT_NE(result.kept[0].find("between separate components"), std::string::npos);
}

/// A closed tube of radius `radius` around a figure-eight (Gerono's lemniscate x = sin t,
/// y = sin t cos t, z = 0): one connected part that crosses itself once, at the origin.
Mesh figure_eight_tube(double radius, int rings, int sides) {
  const double pi = std::acos(-1.0);
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for (int i = 0; i < rings; ++i) {
    const double t = 2 * pi * (i + 0.5) / rings;  // no ring centred on the crossing
    const double tx = std::cos(t), ty = std::cos(2 * t), norm = std::hypot(tx, ty);
    for (int j = 0; j < sides; ++j) {
      const double a = 2 * pi * j / sides, side = radius * std::cos(a);
      v.push_back(mesh.add_vertex(Point(std::sin(t) + side * ty / norm,
                                        std::sin(t) * std::cos(t) - side * tx / norm,
                                        radius * std::sin(a))));
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const auto at = [&](int r, int s) { return v[(r % rings) * sides + s % sides]; };
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return mesh;
}

// A thin closed tube that crosses itself (a swept part of a CAD model): the autorefinement keeps
// its surface outside the volume, so the result is one closed part without the pieces inside
// the crossing, where replacing the crossing by patches would cut the tube and cap the ends.
/// Repairs the closed tube `mesh`, which crosses itself, and checks that the result is its outer
/// surface: complete, one closed valid part free of self-intersections, a little less area, and
/// within `off_surface` of the input's surface. Returns the repair's self-intersection step.
MR::Repair_result expect_outer_surface(Mesh& mesh, double off_surface) {
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_GT(self_intersection_count(mesh), 0u);
  const Mesh input = mesh;
  const auto result = MR::automatic_repair(mesh);
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
  EXPECT_EQ(self_intersection_count(mesh), 0u);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(support::connected_components(mesh), 1u);
  const double area_before = support::area(input), area_after = support::area(mesh);
  EXPECT_LT(area_after, area_before);
  EXPECT_GT(area_after, 0.99 * area_before);
  EXPECT_LT(support::max_distance_to(mesh, input), off_surface);
  return result;
}

TEST(AutomaticRepair, AClosedPartCrossingItselfKeepsItsSurfaceOutsideTheVolume) {
  Mesh mesh = figure_eight_tube(0.004, 400, 8);
  const Mesh input = mesh;
  // The output lies on the input's surface, and the input's points are within one tube radius.
  const auto result = expect_outer_surface(mesh, 1e-9);
  std::vector<Point> points(input.points().begin(), input.points().end());
  EXPECT_LT(support::max_distance_to_triangle_mesh(points, mesh), 0.004 + 1e-9);
  const auto* step = find_step(result, "self-intersection removal");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("parts_autorefined"), 1.0);
}

/// The figure-eight tube with a square section whose top and bottom are flat (z = +-radius,
/// exactly): where the tube crosses itself, its top faces overlap in one plane and three faces
/// meet pairwise at the corners of the crossing, as in CAD parts made of overlapping boxes.
Mesh square_figure_eight_tube(double radius, int rings) {
  const double pi = std::acos(-1.0);
  const double sides[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};  // (across, up), in turn
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for (int i = 0; i < rings; ++i) {
    const double t = 2 * pi * (i + 0.5) / rings;
    const double tx = std::cos(t), ty = std::cos(2 * t), norm = std::hypot(tx, ty);
    for (const auto& side : sides)
      v.push_back(mesh.add_vertex(Point(std::sin(t) + radius * side[0] * ty / norm,
                                        std::sin(t) * std::cos(t) - radius * side[0] * tx / norm,
                                        radius * side[1])));
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < 4; ++j) {
      const auto at = [&](int r, int s) { return v[(r % rings) * 4 + s % 4]; };
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return mesh;
}

// Coplanar overlapping faces and triple intersections, which CGAL 5.5's autorefinement does not
// handle: the exact arrangement of the part gives its outer surface, one closed part on the
// input's surface with the pieces inside the crossing removed.
TEST(AutomaticRepair, APartWithCoplanarOverlapsGetsItsOuterSurfaceExactly) {
  Mesh mesh = square_figure_eight_tube(0.004, 400);
  // On the input's surface up to the grid of the arrangement (1e-9 of the diagonal).
  const auto result = expect_outer_surface(mesh, 1e-8);
  const auto* step = find_step(result, "self-intersection removal");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("parts_autorefined"), 1.0);
  EXPECT_EQ(step->count("parts_autorefined_exactly"), 1.0);
}

// A spindle torus (tube radius above the sweep radius) meshed symmetrically: near its axis every
// face is cut by dozens of others crossing one another, where the exact arrangement would take
// minutes (and CGAL 5.5's autorefinement throws or crashes). The part is left as it is within a
// second, the note says why, and the repair ends with a valid mesh.
TEST(AutomaticRepair, APartWhoseFacesAreCutByTooManyOthersIsNotAutorefined) {
  const double pi = std::acos(-1.0);
  Mesh mesh;
  const int around = 48, across = 24;
  std::vector<Mesh::Vertex_index> v;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const double u = 2 * pi * i / around, w = 2 * pi * j / across;
      v.push_back(mesh.add_vertex(Point((0.98 + std::cos(w)) * std::cos(u),
                                        (0.98 + std::cos(w)) * std::sin(u), std::sin(w))));
    }
  const auto at = [&](int i, int j) { return v[(i % around) * across + j % across]; };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  ASSERT_GT(self_intersection_count(mesh), 0u);
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  const auto* step = find_step(result, "self-intersection removal");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("parts_autorefined"), 0.0);
  const bool noted = std::any_of(step->notes.begin(), step->notes.end(), [](const std::string& n) {
    return n.find("cut by too many others") != std::string::npos;
  });
  EXPECT_TRUE(noted);
}

// A tube standing on a box, its open lower end lying on the box's top face (a part trimmed
// against another, as in furniture and railing models): every patch of that end touches the
// box, so no method can fill it with the box an obstacle. With other parts no obstacle
// (automatic_repair's last try, step "failed holes filled against other parts") the tube is
// closed, and the only new pairs are between the two parts.
TEST(AutomaticRepair, AnOpenEndLyingOnAnotherPartIsClosedAndTheContactKept) {
  const double pi = std::acos(-1.0);
  Mesh mesh;
  MR::make_subdivided_cube<Mesh, Point>(mesh, 2.0, 4);
  const std::size_t box_faces = mesh.number_of_faces();
  double top = -std::numeric_limits<double>::infinity();
  for (auto v : mesh.vertices()) top = std::max(top, mesh.point(v).z());
  // One ring of long faces: growing the hole would take the whole tube, so it is not grown.
  const int sides = 24, rings = 1;
  std::vector<Mesh::Vertex_index> v;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < sides; ++j)
      v.push_back(mesh.add_vertex(Point(1 + 0.3 * std::cos(2 * pi * j / sides),
                                        1 + 0.3 * std::sin(2 * pi * j / sides), top + i * 1.2)));
  const auto apex = mesh.add_vertex(Point(1, 1, top + rings * 1.2 + 0.1));
  const auto at = [&](int i, int j) { return v[i * sides + j % sides]; };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      mesh.add_face(at(i, j), at(i, j + 1), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i + 1, j));
    }
  for (int j = 0; j < sides; ++j) mesh.add_face(at(rings, j), at(rings, j + 1), apex);
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  ASSERT_GT(self_intersection_count(mesh), 0u);  // the tube's wall stands on the box's face
  const auto fill = [](Mesh& m, bool other_parts_are_obstacles) {
    MR::Fill_options options;
    options.other_parts_are_obstacles = other_parts_are_obstacles;
    MR::Default_visitor quiet;
    std::vector<MR::Fill_patch<Mesh>> patches;
    return MR::internal::fill_holes_with_options(m, get(CGAL::vertex_point, m), Kernel(), options,
                                                 MR::Any_visitor(quiet), patches);
  };
  Mesh with_obstacles = mesh;
  EXPECT_EQ(fill(with_obstacles, true).filled, 0u);
  EXPECT_EQ(count_border_cycles(with_obstacles), 1u);

  Mesh closed = mesh;
  const std::size_t pairs_before = self_intersection_count(mesh);
  EXPECT_EQ(fill(closed, false).filled, 1u);
  EXPECT_TRUE(CGAL::is_closed(closed));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(closed));
  EXPECT_EQ(support::connected_components(closed), 2u);
  EXPECT_GE(closed.number_of_faces(), box_faces + 2 * sides * rings + sides + 1);
  // Every new pair is between the tube's patch and the box: none inside a part.
  const auto pairs = support::self_intersections(closed);
  EXPECT_GT(pairs.size(), pairs_before);
  const auto repaired = MR::automatic_repair(closed);
  EXPECT_EQ(repaired.self_intersections_in_patches, 0u);
  EXPECT_EQ(repaired.self_intersections_between_components, pairs.size());

  // The pipeline closes the tube too, against the box, and adds no pair inside a part. The hole
  // is not grown: its one ring of faces is the whole tube wall, 5x longer than the border edges,
  // and growing would rebuild the wall as a faired membrane. Every wall vertex stays where it was.
  std::vector<Point> wall;
  for (auto vertex : v) wall.push_back(mesh.point(vertex));
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(result.holes.failed, 0u);
  EXPECT_EQ(result.self_intersections_in_patches, 0u);
  const auto* grown = find_step(result, "failed holes grown");
  ASSERT_NE(grown, nullptr);
  EXPECT_EQ(grown->count("not_grown_faces_too_long"), 1.0);
  EXPECT_EQ(grown->count("faces_removed"), 0.0);
  std::set<Point> output;
  for (auto vertex : mesh.vertices()) output.insert(mesh.point(vertex));
  for (const Point& p : wall) EXPECT_TRUE(output.count(p)) << p;
}

/// `automatic_repair` with `merge_intersecting_solids` made one solid: complete, one part, no
/// intersecting pair.
void expect_one_clean_solid(const Mesh& mesh, const MR::Repair_result& result) {
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
  EXPECT_EQ(support::connected_components(mesh), 1u);
  EXPECT_EQ(self_intersection_count(mesh), 0u);
}

/// Every hole filled, the mesh closed and valid, still two parts, and no patch meeting its own
/// part (the contacts between the parts are kept).
void expect_two_closed_parts_no_patch_meeting_its_own(const Mesh& mesh,
                                                      const MR::Repair_result& result) {
  EXPECT_EQ(result.holes.failed, 0u);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(support::connected_components(mesh), 2u);
  EXPECT_EQ(result.self_intersections_in_patches, 0u);
}

// A tube slid over a plank (a baluster reaching into a rail, as in Debian's railing models): its
// upper end, inside the plank's extent, flares into a skirt of `skirt_radius` x the tube's radius
// that folds down by `skirt_drop`, and the skirt's outer edge is the hole. Every patch of that
// edge cuts the tube's own wall, so no method fills it where it is; growing the hole by the skirt
// leaves the wall's top, whose cap crosses the plank. `wall` receives the wall's points.
Mesh tube_through_plank(double skirt_radius, double skirt_drop, std::vector<Point>& wall) {
  const double pi = std::acos(-1.0);
  Mesh mesh;
  MR::make_subdivided_cube<Mesh, Point>(mesh, 2.0, 4);
  for (auto vertex : mesh.vertices()) {  // the plank: x in [0.9, 1.1], y and z in [0, 2]
    const Point& p = mesh.point(vertex);
    mesh.point(vertex) = Point(0.9 + 0.1 * p.x(), p.y(), p.z());
  }
  const int sides = 24, rows = 31;
  const double radius = 0.3, bottom = -1.0, top = 1.5;
  const auto around = [&](double r, double angle, double z) {
    return mesh.add_vertex(Point(1 + r * std::cos(angle), 1 + r * std::sin(angle), z));
  };
  std::vector<std::vector<Mesh::Vertex_index>> rings(rows + 1);
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j < sides; ++j)
      rings[i].push_back(around(radius, 2 * pi * j / sides, bottom + (top - bottom) * i / rows));
  std::vector<Mesh::Vertex_index> skirt;
  for (int j = 0; j < sides; ++j)
    skirt.push_back(around(skirt_radius * radius, 2 * pi * (j + 0.5) / sides, top - skirt_drop));
  const auto next = [&](int j) { return (j + 1) % sides; };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < sides; ++j) {
      mesh.add_face(rings[i][j], rings[i][next(j)], rings[i + 1][next(j)]);
      mesh.add_face(rings[i][j], rings[i + 1][next(j)], rings[i + 1][j]);
    }
  for (int j = 0; j < sides; ++j) {
    mesh.add_face(rings[rows][j], rings[rows][next(j)], skirt[j]);
    mesh.add_face(rings[rows][next(j)], skirt[next(j)], skirt[j]);
  }
  const auto apex = mesh.add_vertex(Point(1, 1, bottom - 0.1));
  for (int j = 0; j < sides; ++j) mesh.add_face(rings[0][next(j)], rings[0][j], apex);
  wall.clear();
  for (const auto& ring : rings)
    for (auto vertex : ring) wall.push_back(mesh.point(vertex));
  return mesh;
}

// A narrow skirt (6% wider than the tube, 0.015 lower, within 1% of the diagonal of its patch) is
// removed and the end closed against the plank (step "failed holes grown against other parts").
// The plank and the tube stay two parts, and no patch meets its own part.
TEST(AutomaticRepair, AFoldedOutEndReachingIntoAnotherPartIsGrownAndClosedAgainstIt) {
  std::vector<Point> wall;
  Mesh mesh = tube_through_plank(1.06, 0.015, wall);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  ASSERT_GT(self_intersection_count(mesh), 0u);  // the wall crosses the plank

  const auto result = MR::automatic_repair(mesh);
  expect_two_closed_parts_no_patch_meeting_its_own(mesh, result);
  EXPECT_EQ(result.status(), MR::Repair_status::complete_except_kept);
  // Neither the growth with the plank an obstacle nor the fill against it without growth closed
  // it; growing by the skirt's ring against the plank did.
  const auto* grown = find_step(result, "failed holes grown");
  ASSERT_NE(grown, nullptr);
  EXPECT_EQ(grown->count("faces_removed"), 0.0);
  const auto* against = find_step(result, "failed holes filled against other parts");
  ASSERT_NE(against, nullptr);
  EXPECT_EQ(against->count("filled"), 0.0);
  const auto* grown_against = find_step(result, "failed holes grown against other parts");
  ASSERT_NE(grown_against, nullptr);
  EXPECT_EQ(grown_against->count("filled_with_rings_1"), 1.0);
  EXPECT_EQ(grown_against->count("faces_removed"), 48.0);  // the skirt's two faces per side
  // The wall is kept whole: every wall vertex is still there.
  std::set<Point> output;
  for (auto vertex : mesh.vertices()) output.insert(mesh.point(vertex));
  for (const Point& p : wall) EXPECT_TRUE(output.count(p)) << p;
}

// A wide skirt (1.3 x the tube's radius, 0.1 lower: 3.6% of the diagonal from the cap that
// would replace it) is not removed: the cap would not stand for the faces it replaced. The hole
// stays open and is listed, and the mesh is the input's.
TEST(AutomaticRepair, AGrownHoleWhosePatchWouldBeFarFromTheRemovedFacesIsLeftOpen) {
  std::vector<Point> wall;
  Mesh mesh = tube_through_plank(1.3, 0.1, wall);
  const std::size_t faces = mesh.number_of_faces();
  const auto result = MR::automatic_repair(mesh);
  EXPECT_EQ(result.holes.failed, 1u);
  EXPECT_EQ(result.status(), MR::Repair_status::incomplete);
  EXPECT_EQ(count_border_cycles(mesh), 1u);
  EXPECT_EQ(mesh.number_of_faces(), faces);
  const auto* grown_against = find_step(result, "failed holes grown against other parts");
  ASSERT_NE(grown_against, nullptr);
  EXPECT_GE(grown_against->count("patches_too_far"), 1.0);
  EXPECT_EQ(grown_against->count("faces_removed"), 0.0);
  // The hole says why its grown regions were put back, among them how far the faces removed
  // lay from the filled surface, over what bound.
  ASSERT_EQ(result.holes.holes.size(), 1u);
  const std::vector<std::string>& notes = result.holes.holes[0].notes;
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& note) {
    return note.find("were removed and put back: its faces reach ") != std::string::npos &&
           note.find(" from the filled surface, over the bound ") != std::string::npos;
  }));
}

// A table top open underneath, a leg reaching in through the opening without touching the top
// (a furniture model's slab whose bottom face is missing): the parts are apart, but every patch
// of the opening crosses the leg. The opening is closed with the leg no obstacle, and the new
// contact is kept like the input's contacts; with `merge_intersecting_solids` the two closed
// parts become one solid.
Mesh table_top_open_underneath_with_a_leg() {
  Mesh mesh, leg;
  MR::make_subdivided_cube<Mesh, Point>(mesh, 2.0, 4);  // the top: [0, 2]^2 x [0, 0.4]
  for (auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    mesh.point(v) = Point(p.x(), p.y(), 0.2 * p.z());
  }
  support::remove_faces_in_plane_z(mesh, 0);           // its underside
  MR::make_subdivided_cube<Mesh, Point>(leg, 2.0, 2);  // the leg: [0.8, 1.2]^2 x [-1, 0.2]
  for (auto v : leg.vertices()) {
    const Point& p = leg.point(v);
    leg.point(v) = Point(0.8 + 0.2 * p.x(), 0.8 + 0.2 * p.y(), -1 + 0.6 * p.z());
  }
  CGAL::copy_face_graph(leg, mesh);
  return mesh;
}

TEST(AutomaticRepair, AnOpeningThatAnotherPartReachesThroughIsClosedAndTheContactKept) {
  Mesh mesh = table_top_open_underneath_with_a_leg();
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  ASSERT_EQ(self_intersection_count(mesh), 0u);  // the leg touches nothing
  ASSERT_EQ(support::connected_components(mesh), 2u);
  const double top_area = CGAL::Polygon_mesh_processing::area(mesh);

  const auto result = MR::automatic_repair(mesh);
  expect_two_closed_parts_no_patch_meeting_its_own(mesh, result);
  EXPECT_GT(result.self_intersections_between_components, 0u);  // the leg crosses the new bottom
  EXPECT_EQ(result.status(), MR::Repair_status::complete_except_kept);
  const auto* against = find_step(result, "failed holes filled against other parts");
  ASSERT_NE(against, nullptr);
  EXPECT_EQ(against->count("filled"), 1.0);
  // The hole's record counts the patch that closed it, as the step does.
  ASSERT_EQ(result.holes.holes.size(), 1u);
  EXPECT_GT(result.holes.holes[0].faces_created, 0u);
  EXPECT_EQ(double(result.holes.holes[0].faces_created), against->count("faces_added"));
  // The bottom is flat (a missing planar face): it adds the 2 x 2 square to the area.
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::area(mesh), top_area + 4.0, 1e-9);

  Mesh merged = table_top_open_underneath_with_a_leg();
  const auto united = MR::automatic_repair(merged, MR::parameters::merge_intersecting_solids(true));
  expect_one_clean_solid(merged, united);
  EXPECT_TRUE(CGAL::is_closed(merged));
  // The union: the top (2 x 2 x 0.4) and the leg's part below it (0.4 x 0.4 x 1).
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(merged), 1.6 + 0.16, 1e-6);
}

/// A sheet extruded along x (0 to 2, two quads of two triangles per segment) from a profile in
/// the (y, z) plane, with vertices of its own.
void add_extruded_sheet(Mesh& mesh, const std::vector<std::array<double, 2>>& profile) {
  std::vector<std::array<Mesh::Vertex_index, 3>> rows;
  for (const auto& yz : profile) {
    std::array<Mesh::Vertex_index, 3> row;
    for (int i = 0; i < 3; ++i) row[i] = mesh.add_vertex(Point(i, yz[0], yz[1]));
    rows.push_back(row);
  }
  for (std::size_t k = 0; k + 1 < rows.size(); ++k)
    for (int i = 0; i < 2; ++i) {
      mesh.add_face(rows[k][i], rows[k][i + 1], rows[k + 1][i + 1]);
      mesh.add_face(rows[k][i], rows[k + 1][i + 1], rows[k + 1][i]);
    }
}

// Two sheets with a common seam whose vertices are distinct (stitching joins them), one folded
// back down through the other. Their intersections are between two parts in the input and
// inside one part once stitched: the input's own, not pairs the repair added.
TEST(AutomaticRepair, PairsBetweenPartsThatStitchingJoinsAreTheInputsOwn) {
  Mesh mesh;
  add_extruded_sheet(mesh, {{0, 0}, {1, 0}});
  add_extruded_sheet(mesh, {{1, 0}, {2, 0}, {2, 1}, {0.5, 1}, {0.5, -1}});
  ASSERT_GT(self_intersection_count(mesh), 0u);
  const auto result = MR::automatic_repair(mesh, MR::parameters::repair_self_intersections(false));
  EXPECT_EQ(result.self_intersections_input_between_components, result.self_intersections_input);
  EXPECT_GT(result.self_intersections_joined_by_stitching, 0u);
  EXPECT_EQ(result.self_intersections_in_patches, 0u);
  EXPECT_EQ(result.self_intersections_between_components, 0u);  // one part now
  // The pairs left are those of the fold (the seam's contacts are gone with the seam).
  EXPECT_GT(result.self_intersections_output, 0u);
  EXPECT_EQ(result.self_intersections_joined_by_stitching, result.self_intersections_output);
  bool listed = false;
  for (const std::string& line : result.remaining) {
    EXPECT_EQ(line.find("more than in the input"), std::string::npos) << line;
    listed = listed || line.find("between parts that stitching joined") != std::string::npos;
  }
  EXPECT_TRUE(listed);
}

/// The checks of a union of unit balls (`merge_intersecting_solids`): complete, `merged` parts
/// merged, closed, valid, free of self-intersections, `components` parts left, and the volume
/// within 1 % of `balls` balls minus `lenses` lenses of balls `distance` apart, scaled by the
/// volume of one polyhedral ball (`one`) and plus `extra` (in units of `one`).
void expect_union_of_balls(const Mesh& mesh, const MR::Repair_result& result, std::size_t merged,
                           std::size_t components, int balls, int lenses, double distance,
                           double one, double extra = 0) {
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
  EXPECT_EQ(result.solids_merged, merged);
  EXPECT_EQ(self_intersection_count(mesh), 0u);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  Mesh copy = mesh;
  EXPECT_EQ(CGAL::Polygon_mesh_processing::connected_components(
                copy, copy.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first),
            components);
  // Two unit balls d apart overlap in a lens of volume pi (4 + d) (2 - d)^2 / 12.
  const double d = distance;
  const double lens = std::acos(-1.0) * (4 + d) * (2 - d) * (2 - d) / 12;
  const double ball = 4 * std::acos(-1.0) / 3;
  const double expected = (balls * ball - lenses * lens) * one / ball + extra * one;
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(mesh), expected, 0.01 * expected);
}

// Two interpenetrating spheres and a third apart, with `merge_intersecting_solids`: the two
// become their union (one closed part, no self-intersection, the faces inside removed: its
// volume is that of the union of the two balls), the third is untouched.
TEST(AutomaticRepair, IntersectingSolidsBecomeTheirUnionWhenAsked) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 3);
  MR::make_sphere(mesh, Point(1.2, 0.1, 0), 1.0, 3);
  MR::make_sphere(mesh, Point(5, 0, 0), 0.5, 2);
  const double one = CGAL::Polygon_mesh_processing::volume(mesh) / (2 + 0.125);
  ASSERT_GT(self_intersection_count(mesh), 0u);
  const auto result = MR::automatic_repair(mesh, MR::parameters::merge_intersecting_solids(true));
  EXPECT_EQ(result.self_intersections_output, 0u);
  expect_union_of_balls(mesh, result, 2, 2, 2, 1, std::hypot(1.2, 0.1), one, 0.125);
  const auto* step = find_step(result, "intersecting solids merged");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("unions"), 1.0);
  EXPECT_GT(step->count("faces_removed"), step->count("faces_added") * 0.5);
}

// Five unit balls in a row, each overlapping the next (1.2 apart) and no other: the group is
// united in pairs and then pairs of unions, the fifth ball waiting a level, and the result is one
// closed solid of volume 5 balls minus 4 lenses.
TEST(AutomaticRepair, AnOddRowOfIntersectingSolidsBecomesOneSolid) {
  Mesh mesh;
  for (int k = 0; k < 5; ++k) MR::make_sphere(mesh, Point(1.2 * k, 0.05 * k, 0), 1.0, 3);
  const double one = CGAL::Polygon_mesh_processing::volume(mesh) / 5;
  const auto result = MR::automatic_repair(mesh, MR::parameters::merge_intersecting_solids(true));
  expect_union_of_balls(mesh, result, 5, 1, 5, 4, std::hypot(1.2, 0.05), one);
}

// Two cubes of the same height, one shifted sideways into the other: their top and bottom faces
// overlap in one plane, where CGAL 5.5's corefinement can crash (it did on a furniture model);
// the parts are kept apart and the note says why.
TEST(AutomaticRepair, SolidsWithCoplanarFacesThatMeetAreUnitedByTheExactArrangement) {
  Mesh mesh, shifted;
  MR::make_subdivided_cube<Mesh, Point>(mesh, 1.0, 2);
  MR::make_subdivided_cube<Mesh, Point>(shifted, 1.0, 2);
  for (auto v : shifted.vertices())
    shifted.point(v) = shifted.point(v) + Kernel::Vector_3(0.5, 0.3, 0);
  CGAL::copy_face_graph(shifted, mesh);
  const auto result = MR::automatic_repair(mesh, MR::parameters::merge_intersecting_solids(true));
  EXPECT_EQ(result.solids_merged, 2u);
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
  const auto* step = find_step(result, "intersecting solids merged");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("unions_by_exact_arrangement"), 1.0);
  // One closed solid, free of intersections, whose volume is that of the union of the cubes
  // (edge 1, shifted by (0.5, 0.3, 0): 2 - 0.5 x 0.7).
  EXPECT_EQ(support::connected_components(mesh), 1u);
  EXPECT_EQ(self_intersection_count(mesh), 0u);
  ASSERT_TRUE(CGAL::is_closed(mesh));
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(mesh), 2 - 0.5 * 0.7, 1e-9);
}

// A part that is open cannot be merged (corefinement needs volumes): the group is kept apart,
// the note says why, and the pairs stay listed as kept.
TEST(AutomaticRepair, AnOpenPartIsNotMergedAndTheNoteSaysWhy) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 3);
  Mesh open;
  MR::make_sphere(open, Point(1.2, 0.1, 0), 1.0, 3);
  punch_hole(open, Point(2.2, 0.1, 0), 0.3);
  open.collect_garbage();
  CGAL::copy_face_graph(open, mesh);
  const auto result =
      MR::automatic_repair(mesh, MR::parameters::merge_intersecting_solids(true).max_hole_edges(3));
  EXPECT_EQ(result.solids_merged, 0u);
  EXPECT_GT(result.self_intersections_between_components, 0u);
  const auto* step = find_step(result, "intersecting solids merged");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("groups_kept_apart"), 1.0);
  ASSERT_EQ(step->notes.size(), 1u);
  EXPECT_NE(step->notes[0].find("not closed"), std::string::npos) << step->notes[0];
}

/// A sphere with a hole whose border is folded as on scans: every third border vertex is pushed
/// away from the hole, past its outer neighbours, so that its faces fold over the surface
/// around it (overlapping triangles along a jagged border).
Mesh sphere_with_folded_hole_border() {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  punch_hole(mesh, Point(0, 0, 1), 0.35);
  mesh.collect_garbage();
  const auto cycles = CGAL::Mesh_repair::internal::border_cycles(mesh);
  std::vector<Mesh::Vertex_index> border;
  for (auto h : halfedges_around_face(cycles.front(), mesh)) border.push_back(mesh.target(h));
  for (std::size_t i = 0; i < border.size(); i += 3) {
    const Point p = mesh.point(border[i]);
    // Outwards from the hole's axis by 0.15 (about twice the edge length), back on the sphere.
    const double r = std::hypot(p.x(), p.y());
    const Point q(p.x() * (r + 0.15) / r, p.y() * (r + 0.15) / r, p.z());
    const double n = std::sqrt(CGAL::squared_distance(q, Point(0, 0, 0)));
    mesh.point(border[i]) = Point(q.x() / n, q.y() / n, q.z() / n);
  }
  return mesh;
}

// Two faces of a sphere that share only the vertex v are removed, and the faces on one side of
// them get their own copy of v: one border cycle that passes twice through v's point, at two
// distinct vertices (as soups of scans and CAD exports give). Hole filling welds the two into one
// before filling the two triangles; the step counts the weld apart from the patches' vertices,
// which are none (its net change of vertices is -1).
TEST(AutomaticRepair, ABorderTouchingItselfAtCoincidentVerticesIsWeldedAndCounted) {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 2);
  const Mesh::Vertex_index v = *sphere.vertices().begin();
  std::vector<Mesh::Face_index> fan;
  for (auto f : CGAL::faces_around_target(sphere.halfedge(v), sphere)) fan.push_back(f);
  ASSERT_GE(fan.size(), 5u);
  const std::size_t second = fan.size() / 2;  // f1 = fan[0], f2 = fan[second]
  std::vector<Point> points;
  for (auto w : sphere.vertices()) points.push_back(sphere.point(w));
  const std::size_t copy = points.size();
  points.push_back(sphere.point(v));
  std::set<Mesh::Face_index> one_side(fan.begin() + 1, fan.begin() + second);
  std::vector<std::vector<std::size_t>> polygons;
  for (auto f : sphere.faces()) {
    if (f == fan[0] || f == fan[second]) continue;
    std::vector<std::size_t> polygon;
    for (auto w : CGAL::vertices_around_face(sphere.halfedge(f), sphere))
      polygon.push_back(w == v && one_side.count(f) ? copy : std::size_t(w));
    polygons.push_back(polygon);
  }
  Mesh mesh;
  support::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  ASSERT_EQ(mesh.number_of_vertices(), sphere.number_of_vertices() + 1);

  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(mesh.number_of_vertices(), sphere.number_of_vertices());
  EXPECT_EQ(mesh.number_of_faces(), sphere.number_of_faces());
  const auto* filling = find_step(result, "hole filling");
  ASSERT_NE(filling, nullptr);
  EXPECT_EQ(filling->count("vertices_added"), 0.0);
  EXPECT_EQ(filling->count("coincident_border_vertices_welded"), 1.0);
  EXPECT_EQ(filling->count("faces_added"), 2.0);
}

// The contour's offending faces (exact predicates): none along a clean border, some along the
// folded one, all of them near it.
TEST(AutomaticRepair, OnlyAFoldedContourHasOffendingFaces) {
  auto offending = [](const Mesh& mesh, std::size_t& range_size) {
    std::vector<Mesh::Vertex_index> border;
    for (auto h :
         halfedges_around_face(CGAL::Mesh_repair::internal::border_cycles(mesh).front(), mesh))
      border.push_back(mesh.target(h));
    std::vector<int> ring_of;
    const auto range = CGAL::Mesh_repair::internal::faces_within_rings(mesh, border, 2, &ring_of);
    range_size = range.size();
    return CGAL::Mesh_repair::internal::offending_contour_faces(mesh, mesh.points(), Kernel(),
                                                                range, ring_of);
  };
  Mesh clean;
  MR::make_sphere(clean, Point(0, 0, 0), 1.0, 4);
  punch_hole(clean, Point(0, 0, 1), 0.35);
  clean.collect_garbage();
  std::size_t range = 0;
  EXPECT_TRUE(offending(clean, range).empty());
  EXPECT_GT(range, 0u);
  const Mesh folded = sphere_with_folded_hole_border();
  const auto found = offending(folded, range);
  EXPECT_GT(found.size(), 0u);
  EXPECT_LT(found.size(), range);
}

// Only the offending faces along the border go (the contour cleaning of step "failed holes
// grown"): fewer than the faces of one vertex ring around it.
TEST(AutomaticRepair, HolesWithFoldedBordersLoseTheirFoldedFacesAndAreFilled) {
  Mesh mesh = sphere_with_folded_hole_border();
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  const std::size_t faces_before = mesh.number_of_faces();
  std::vector<Mesh::Vertex_index> border;
  for (auto h :
       halfedges_around_face(CGAL::Mesh_repair::internal::border_cycles(mesh).front(), mesh))
    border.push_back(mesh.target(h));
  const std::size_t one_ring =
      CGAL::Mesh_repair::internal::faces_within_rings(mesh, border, 1).size();
  // Every method's patch meets the folded faces: plain hole filling leaves the hole open.
  Mesh filled = mesh;
  const auto plain = MR::fill_holes(filled);
  ASSERT_EQ(plain.failed, 1u) << "the folded border no longer defeats plain hole filling";
  EXPECT_EQ(filled.number_of_faces(), faces_before);

  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(result.holes.failed, 0u);
  EXPECT_EQ(self_intersection_count(mesh), 0u);
  const auto* grown = find_step(result, "failed holes grown");
  ASSERT_NE(grown, nullptr);
  EXPECT_EQ(grown->count("still_failed"), 0.0);
  EXPECT_EQ(grown->count("filled_with_contour_cleaned"), 1.0);
  EXPECT_GT(grown->count("faces_removed"), 0.0);
  EXPECT_LT(grown->count("faces_removed"), double(one_ring));
  ASSERT_EQ(result.holes.holes.size(), 1u);
  const auto& hole = result.holes.holes[0];
  EXPECT_TRUE(hole.filled);
  ASSERT_FALSE(hole.notes.empty());
  // The hole's record holds the patch that closed it, as the step counts it: the faces now are
  // the input's, less those the growth removed, plus the patch.
  EXPECT_EQ(double(hole.faces_created), grown->count("faces_added"));
  EXPECT_GT(hole.faces_created, 0u);
  EXPECT_EQ(mesh.number_of_faces(),
            faces_before - std::size_t(grown->count("faces_removed")) + hole.faces_created);
  const std::string said = "filled after removing the " +
                           std::to_string(std::size_t(grown->count("faces_removed"))) +
                           " folded, crossing, degenerate or ear face(s) along its border";
  EXPECT_TRUE(std::any_of(hole.notes.begin(), hole.notes.end(), [&](const std::string& note) {
    return note.find(said) != std::string::npos;
  })) << hole.notes.back();
  EXPECT_TRUE(hole.failure.empty());
  // The patch follows the sphere.
  for (auto v : mesh.vertices())
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(mesh.point(v), Point(0, 0, 0))), 1.0, 0.05);
}

// A hole that no growth can fill gets its removed faces back: nothing is lost. (The tube's end
// under the plank: its grown patches lie too far from the skirt they would replace, and it is
// then closed with the plank no obstacle, step "failed holes filled against other parts".)
TEST(AutomaticRepair, AGrownHoleThatStaysOpenGetsItsFacesBack) {
  std::vector<Point> wall;
  Mesh mesh = tube_through_plank(1.3, 0.1, wall);
  const std::size_t faces_before = mesh.number_of_faces();
  const auto result = MR::automatic_repair(mesh, MR::parameters::repair_self_intersections(false));
  const auto* grown = find_step(result, "failed holes grown");
  ASSERT_NE(grown, nullptr);
  EXPECT_EQ(grown->count("still_failed"), 1.0);
  EXPECT_EQ(grown->count("faces_removed"), 0.0);
  EXPECT_EQ(grown->count("faces_not_restored"), 0.0);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  // Faces of the input + the patches kept - the faces of replaced regions: those of the regions
  // put back are all there.
  const auto* filling = find_step(result, "hole filling");
  const auto* against = find_step(result, "failed holes filled against other parts");
  ASSERT_NE(filling, nullptr);
  ASSERT_NE(against, nullptr);
  EXPECT_EQ(double(mesh.number_of_faces()),
            double(faces_before) + filling->count("faces_added") + grown->count("faces_added") -
                grown->count("faces_removed") + against->count("faces_added"));
  EXPECT_EQ(count_border_cycles(mesh), result.holes.failed);
}

/// Unit cubes at the cells (i, j, k) of a grid, each with its own eight vertices: cubes in
/// neighbouring cells share a face written twice (a zero-volume wall).
Mesh cubes_at(const std::vector<std::array<int, 3>>& cells) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  const std::size_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& [x, y, z] : cells) {
    const std::size_t offset = points.size();
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) points.emplace_back(x + i, y + j, z + k);
    for (const auto& q : quads) {
      faces.push_back({offset + q[0], offset + q[1], offset + q[2]});
      faces.push_back({offset + q[0], offset + q[2], offset + q[3]});
    }
  }
  Mesh mesh;
  support::polygon_soup_to_polygon_mesh(points, faces, mesh);
  return mesh;
}

/// Two closed unit cubes, one on top of the other: the top of the first and the bottom of the
/// second are the same two triangles, reversed.
Mesh cubes_sharing_a_face() {
  return cubes_at({{0, 0, 0}, {0, 0, 1}});
}

// The wall between the cubes is a zero-volume pair: both faces go, the rims are stitched, and
// the result is one closed box without coincident vertices.
TEST(AutomaticRepair, AZeroVolumeWallBetweenTwoShellsIsRemovedAndTheShellsJoined) {
  Mesh mesh = cubes_sharing_a_face();
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(mesh.number_of_faces(), 20u);
  EXPECT_EQ(mesh.number_of_vertices(), 12u);
  EXPECT_TRUE(result.manifold);
  EXPECT_EQ(result.coincident_vertices_left, 0u);
  const auto step = std::find_if(result.steps.begin(), result.steps.end(),
                                 [](const auto& s) { return s.name == "coincident elements"; });
  ASSERT_NE(step, result.steps.end());
  EXPECT_EQ(step->count("duplicated_faces_removed"), 4.0);
  EXPECT_EQ(step->count("zero_volume_groups_removed"), 2.0);
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
}

/// The coincident-elements step's count named `name`, or -1.
double coincident_step_count(const MR::Repair_result& result, const std::string& name) {
  const auto* step = find_step(result, "coincident elements");
  return step == nullptr ? -1 : step->count(name);
}

/// The smallest distance between two distinct vertices of `mesh`.
double closest_vertices(const Mesh& mesh) {
  double closest = std::numeric_limits<double>::infinity();
  for (auto v : mesh.vertices())
    for (auto w : mesh.vertices())
      if (v < w)
        closest =
            std::min(closest, std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(w))));
  return closest;
}

// Two cubes touching at one corner: merging the corner would make a non-manifold vertex, and a
// file would show the two corners as one point. Each corner is moved about 1e-6 of the diagonal
// into its own cube: two solids apart, which a merging reader sees as they are.
TEST(AutomaticRepair, ShellsTouchingAtACornerAreMovedApart) {
  Mesh mesh = cubes_sharing_a_face();
  for (auto v : mesh.vertices())
    if (v.idx() >= 8) mesh.point(v) = mesh.point(v) + Kernel::Vector_3(1, 1, 0);
  ASSERT_EQ(MR::counts(MR::detect_defects(mesh)).non_manifold_vertices, 1u);
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(support::connected_components(mesh), 2u);
  EXPECT_TRUE(result.manifold);
  EXPECT_EQ(result.non_manifold_vertices_left, 0u);
  EXPECT_EQ(result.coincident_vertices_left, 0u);
  EXPECT_EQ(coincident_step_count(result, "contact_vertices_moved_apart"), 2.0);
  EXPECT_EQ(coincident_step_count(result, "contact_moves_undone"), 0.0);
  EXPECT_FALSE(support::does_self_intersect(mesh));
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
  // Apart by about twice the move (1e-6 of the diagonal, 3), and by no more.
  const double gap = closest_vertices(mesh);
  EXPECT_GT(gap, 1e-6);
  EXPECT_LT(gap, 1e-5);
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(mesh), 2.0, 1e-5);
  // One definition: detect_defects sees no non-manifold vertex either.
  EXPECT_EQ(MR::counts(MR::detect_defects(mesh)).non_manifold_vertices, 0u);
}

// A chain of seven cubes bent round so that its two ends touch along an edge: the walls between
// the cubes go, the chain is one solid, and the two copies of the edge where it touches itself
// are moved apart, each into its own end: one closed solid, manifold as a reader sees it.
TEST(AutomaticRepair, ASolidTouchingItselfAlongAnEdgeIsMovedApartThere) {
  Mesh mesh =
      cubes_at({{0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}});
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(support::connected_components(mesh), 1u);
  EXPECT_TRUE(result.manifold);
  EXPECT_EQ(result.non_manifold_edges_left, 0u);
  EXPECT_EQ(coincident_step_count(result, "contact_vertices_moved_apart"), 4.0);
  EXPECT_FALSE(support::does_self_intersect(mesh));
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(mesh), 7.0, 1e-5);
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
  EXPECT_EQ(MR::counts(MR::detect_defects(mesh)).non_manifold_edges, 0u);
}

TEST(FillHoles, APatchMeetingAnotherPartOfTheMeshIsRolledBack) {
  Mesh mesh = overlapping_spheres_with_facing_holes();
  ASSERT_EQ(count_border_cycles(mesh), 2u);
  ASSERT_FALSE(support::does_self_intersect(mesh));
  for (auto method : {MR::Fill_method::automatic, MR::Fill_method::liepa}) {
    Mesh filled = mesh;
    const auto result = MR::fill_holes(filled, MR::parameters::fill_method(method));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(filled));
    EXPECT_FALSE(support::does_self_intersect(filled)) << MR::to_string(method);
    // The first hole is filled; every attempt on the second crosses the first patch.
    EXPECT_EQ(result.filled, 1u) << MR::to_string(method);
    EXPECT_EQ(result.failed, 1u) << MR::to_string(method);
    EXPECT_EQ(count_border_cycles(filled), 1u);
    for (const auto& hole : result.holes) {
      if (!hole.filled) {
        EXPECT_NE(hole.failure.find("self-intersects"), std::string::npos);
      }
    }
  }
}

// Two spheres overlapping where their holes face each other: every patch of the second hole
// crosses the first one's patch. The second hole is grown and closed by a last resort that
// stays behind the first patch: two closed spheres that do not meet, nothing of the input
// farther than the growth's bound (1% of the diagonal) from the output.
TEST(AutomaticRepair, FacingHolesOfOverlappingSpheresAreClosedWithoutMeetingEachOther) {
  const Mesh input = overlapping_spheres_with_facing_holes();
  Mesh mesh = input;
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(result.holes.failed, 0u);
  EXPECT_EQ(result.self_intersections_output, 0u);
  EXPECT_EQ(self_intersection_count(mesh), 0u);
  EXPECT_EQ(support::connected_components(mesh), 2u);
  EXPECT_EQ(result.status(), MR::Repair_status::complete)
      << (result.remaining.empty() ? "" : result.remaining.front());
  const auto* grown = find_step(result, "failed holes grown");
  ASSERT_NE(grown, nullptr);
  EXPECT_GT(grown->count("faces_removed"), 0.0);
  EXPECT_EQ(grown->count("still_failed"), 0.0);
  // The balls' bounding box: [-1.95, 1.95] x [-1, 1]^2.
  const double diagonal = std::sqrt(3.9 * 3.9 + 2 * 2 + 2 * 2);
  std::vector<Point> points;
  for (auto v : input.vertices()) points.push_back(input.point(v));
  EXPECT_LE(support::max_distance_to_triangle_mesh(points, mesh), 0.01 * diagonal);
}

TEST(AutomaticRepair, RealScansWithHolesBecomeClosed) {
  for (const char* name : {"elephant-with-holes.off", "mech-holes-shark.off"}) {
    Mesh mesh;
    if (!read_demo_mesh(name, mesh)) GTEST_SKIP() << "libcgal-demo meshes absent";
    const auto result = MR::automatic_repair(mesh);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh)) << name;
    EXPECT_TRUE(CGAL::is_closed(mesh)) << name;
    EXPECT_EQ(result.holes.failed, 0u) << name;
  }
}

// A building reconstructed on its patch of terrain (libcgal-demo's polygon_mesh.off): the
// ground's 432-edge outline is jagged and the terrain dips below it, so every spanning patch
// crosses the ground; the outline is closed by a flat base below the lowest point.
TEST(AutomaticRepair, TheOutlineOfAReconstructedBuildingsGroundIsClosedByABase) {
  Mesh mesh;
  if (!read_demo_mesh("polygon_mesh.off", mesh)) GTEST_SKIP() << "libcgal-demo meshes absent";
  double lowest = std::numeric_limits<double>::infinity();
  for (auto v : mesh.vertices()) lowest = std::min(lowest, mesh.point(v).z());
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(result.complete()) << (result.remaining.empty() ? "" : result.remaining.front());
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(result.self_intersections_output, 0u);
  EXPECT_FALSE(support::does_self_intersect(mesh));
  std::size_t bases = 0;
  for (const auto& hole : result.holes.holes)
    for (const std::string& note : hole.notes) bases += note.rfind("filled by base", 0) == 0;
  EXPECT_EQ(bases, 1u);
  double base = std::numeric_limits<double>::infinity();
  for (auto v : mesh.vertices()) base = std::min(base, mesh.point(v).z());
  EXPECT_LT(base, lowest);
}

// A scanned figure whose surface passes through itself in many places (1,643 intersecting pairs
// in one component): the intersecting faces are removed with up to 6 rings and refilled until
// none is left; the repair keeps the surface (area not reduced).
TEST(AutomaticRepair, ManySelfIntersectionsOfAScanAreAllRemoved) {
  Mesh mesh;
  if (!read_demo_mesh("mannequin-devil.off", mesh)) GTEST_SKIP() << "libcgal-demo meshes absent";
  const double area_before = CGAL::Polygon_mesh_processing::area(mesh);
  const auto result = MR::automatic_repair(mesh);
  EXPECT_GT(result.self_intersections_input, 1000u);
  EXPECT_EQ(result.self_intersections_output, 0u);
  EXPECT_TRUE(support::self_intersections(mesh).empty());
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_GE(CGAL::Polygon_mesh_processing::area(mesh), area_before);  // the open base is closed
}

// A coarse CAD mesh whose derived stitching tolerance (6% of the diagonal) would push faces
// through their neighbours: the stitching trial must reduce or skip it.
// Two quads crossed like the flame of a game torch (minetest's torch, written anew: each a
// square of side 1 standing on a diagonal of the other's base) and a stick of six quads: a
// corner of one quad lies half an edge from the other's bottom edge, within the derived
// tolerance (half the shortest edge), and stitching it there folded the quad onto its neighbour
// by 0.5, a third of the diagonal. The derived tolerance may move no vertex farther than 1% of
// the diagonal, so nothing moves; a small gap elsewhere is still stitched.
TEST(AutomaticRepair, DerivedStitchingMovesNoVertexFartherThanOnePercentOfTheDiagonal) {
  const double r = std::sqrt(0.125), s = 0.0625;  // the torch's 0.353553 and its stick
  Mesh mesh;
  auto quad = [&](const Point& a, const Point& b, const Point& c, const Point& d) {
    ASSERT_NE(mesh.add_face(mesh.add_vertex(a), mesh.add_vertex(b), mesh.add_vertex(c),
                            mesh.add_vertex(d)),
              Mesh::null_face());
  };
  quad(Point(-r, 0, r), Point(-r, 1, r), Point(r, 1, -r), Point(r, 0, -r));
  quad(Point(-r, 0, -r), Point(r, 0, r), Point(r, 1, r), Point(-r, 1, -r));
  // The stick: a box of six separate quads through the flame's base.
  auto corner = [&](int x, int y, int z) { return Point(x ? s : -s, y ? 0.5625 : 0, z ? s : -s); };
  quad(corner(0, 0, 0), corner(0, 0, 1), corner(0, 1, 1), corner(0, 1, 0));
  quad(corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1));
  quad(corner(0, 0, 0), corner(1, 0, 0), corner(1, 0, 1), corner(0, 0, 1));
  quad(corner(0, 1, 0), corner(0, 1, 1), corner(1, 1, 1), corner(1, 1, 0));
  quad(corner(0, 0, 0), corner(0, 1, 0), corner(1, 1, 0), corner(1, 0, 0));
  quad(corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1));
  const std::vector<Point> input(mesh.points().begin(), mesh.points().end());
  const auto result = MR::automatic_repair(mesh);
  const auto* stitching = find_step(result, "tolerance stitching");
  ASSERT_NE(stitching, nullptr);
  EXPECT_GT(stitching->count("merges_undone_by_move_limit"), 0.0);
  EXPECT_EQ(stitching->count("max_displacement"), 0.0);
  // Every input corner is still a vertex where it was.
  std::set<std::array<double, 3>> output;
  for (auto v : mesh.vertices())
    output.insert({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
  for (const Point& p : input) EXPECT_TRUE(output.count({p.x(), p.y(), p.z()})) << p;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));

  // A cube of six separately meshed faces 0.08% of the diagonal apart is still stitched closed.
  Mesh cube = stitch_test::to_mesh(stitch_test::cube_of_separate_faces(0.001, {2, 3, 2, 3, 2, 3}));
  const auto stitched = MR::automatic_repair(cube);
  const auto* cube_stitching = find_step(stitched, "tolerance stitching");
  ASSERT_NE(cube_stitching, nullptr);
  EXPECT_GT(cube_stitching->count("node_merges"), 0.0);
  EXPECT_EQ(cube_stitching->count("merges_undone_by_move_limit"), 0.0);
  EXPECT_TRUE(CGAL::is_closed(cube));
  EXPECT_TRUE(stitched.complete());
}

TEST(AutomaticRepair, StitchingNeverAddsSelfIntersectionsOnCoarseCad) {
  Mesh mesh;
  if (!read_demo_mesh("ALSTOM_TEST4.off", mesh)) GTEST_SKIP() << "libcgal-demo meshes absent";
  const auto result = MR::automatic_repair(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(result.self_intersections_checked);
  EXPECT_LE(result.self_intersections_output, result.self_intersections_input);
  bool trial = false;
  for (const auto& step : result.steps) trial = trial || step.name == "stitching trial";
  EXPECT_TRUE(trial);
}

// Cracked copies of closed real meshes (cut across, the sides 0.1% and 0.3% of the diagonal
// apart, every third border edge split so the nodes do not match). On some, the derived
// stitching tolerance makes faces intersect next to the crack; the stitching trial freezes those
// vertices and stitches the rest, so every copy comes out closed and free of self-intersections.
TEST(AutomaticRepair, CracksWithTJunctionsInRealMeshesAreClosedCleanly) {
  double frozen = 0;
  for (const char* name : {"femur.off", "couplingdown.off"}) {
    Mesh closed;
    if (!read_demo_mesh(name, closed)) GTEST_SKIP() << "libcgal-demo meshes absent";
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(closed);
    const double diagonal =
        std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                  CGAL::square(box.zmax() - box.zmin()));
    const Kernel::Vector_3 normal = Kernel::Vector_3(0.3, -0.5, 0.8) / std::sqrt(0.98);
    for (double fraction : {0.001, 0.003}) {
      Mesh cracked =
          stitch_test::to_mesh(stitch_test::crack_across(closed, normal, fraction * diagonal));
      ASSERT_GT(stitch_test::split_border_edges(cracked, 3), 0u);
      ASSERT_GE(count_border_cycles(cracked), 2u) << name;
      const auto result = MR::automatic_repair(cracked);
      EXPECT_TRUE(CGAL::is_valid_polygon_mesh(cracked)) << name << ' ' << fraction;
      EXPECT_TRUE(CGAL::is_closed(cracked)) << name << ' ' << fraction;
      EXPECT_EQ(result.self_intersections_output, 0u) << name << ' ' << fraction;
      EXPECT_EQ(result.holes.failed, 0u) << name << ' ' << fraction;
      for (const auto& step : result.steps)
        if (step.name == "tolerance stitching") frozen += step.count("frozen_vertices");
    }
  }
  EXPECT_GT(frozen, 0.0);  // the trial had to freeze vertices on at least one copy
}

TEST(AutomaticRepair, TheOutlineOfALargeOpenSheetIsLeftOpenAndCounted) {
  // 250 x 250 cells, a 1000-edge outline: before the rule, the advancing front worked on it for
  // minutes.
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, -1, 1, -1, 1, 250, 250, [](double x, double y) {
    return 0.05 * std::sin(5 * x) * std::sin(4 * y);
  });
  const std::size_t faces_before = num_faces(mesh);
  const MR::Repair_result result = MR::automatic_repair(mesh);
  EXPECT_EQ(result.sheet_borders_left_open, 1u);
  EXPECT_EQ(result.holes_too_large, 0u);
  EXPECT_EQ(result.holes.filled, 0u);
  EXPECT_EQ(num_faces(mesh), faces_before);
  EXPECT_EQ(count_border_cycles(mesh), 1u);
  EXPECT_TRUE(result.valid);
  // Left open by the documented default rule: kept, not incomplete.
  bool listed = false;
  for (const std::string& line : result.kept)
    listed |= line.find("open sheet") != std::string::npos;
  EXPECT_TRUE(listed);
  EXPECT_TRUE(result.remaining.empty());
  EXPECT_EQ(result.status(), MR::Repair_status::complete_except_kept);
}

/// A 4 x 4 x 0.5 plate with a 1 x 1 through-hole, modelled as CAD models often are: both faces
/// have the opening cut out and its wall is missing (two border cycles of 8 edges, one above
/// the other). With `rod`, a square rod (its own closed part) passes through the opening and
/// touches its edges, as the rings of a calendar's binding do.
Mesh plate_with_a_bare_through_hole(bool rod = false) {
  Mesh mesh;
  std::map<std::array<int, 3>, Mesh::Vertex_index> at;
  auto v = [&](int i, int j, int k) {
    auto found = at.find({i, j, k});
    if (found != at.end()) return found->second;
    return at[{i, j, k}] = mesh.add_vertex(Point(-2 + 0.5 * i, -2 + 0.5 * j, 0.5 * k));
  };
  auto quad = [&](Mesh::Vertex_index a, Mesh::Vertex_index b, Mesh::Vertex_index c,
                  Mesh::Vertex_index d) {
    mesh.add_face(a, b, c);
    mesh.add_face(a, c, d);
  };
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      if ((i == 3 || i == 4) && (j == 3 || j == 4)) continue;  // the opening
      quad(v(i, j, 1), v(i + 1, j, 1), v(i + 1, j + 1, 1), v(i, j + 1, 1));
      quad(v(i, j + 1, 0), v(i + 1, j + 1, 0), v(i + 1, j, 0), v(i, j, 0));
    }
  for (int t = 0; t < 8; ++t) {  // the outer walls
    quad(v(t, 0, 0), v(t + 1, 0, 0), v(t + 1, 0, 1), v(t, 0, 1));
    quad(v(8, t, 0), v(8, t + 1, 0), v(8, t + 1, 1), v(8, t, 1));
    quad(v(t + 1, 8, 0), v(t, 8, 0), v(t, 8, 1), v(t + 1, 8, 1));
    quad(v(0, t + 1, 0), v(0, t, 0), v(0, t, 1), v(0, t + 1, 1));
  }
  // A box 0.4 wide in x, 0.8 in y (reaching y = +-0.4 inside the opening's +-0.5) and from
  // x = 0.3 to 0.7: it crosses the opening's wall at x = 0.5.
  if (!rod) return mesh;
  std::array<Mesh::Vertex_index, 8> c;  // corner x + 2y + 4z of the box
  for (int k = 0; k < 8; ++k)
    c[k] = mesh.add_vertex(Point(k & 1 ? 0.7 : 0.3, k & 2 ? 0.4 : -0.4, k & 4 ? 1.5 : -1.0));
  quad(c[0], c[2], c[3], c[1]);
  quad(c[4], c[5], c[7], c[6]);
  quad(c[0], c[4], c[6], c[2]);
  quad(c[1], c[3], c[7], c[5]);
  quad(c[0], c[1], c[5], c[4]);
  quad(c[2], c[6], c[7], c[3]);
  return mesh;
}

/// Euler characteristic V - E + F: 2 for a sphere, 0 for a torus (a plate with one opening).
long euler_characteristic(const Mesh& mesh) {
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

TEST(AutomaticRepair, AThroughHoleWithoutItsWallGetsTheWallNotTwoCaps) {
  Mesh mesh = plate_with_a_bare_through_hole();
  ASSERT_EQ(count_border_cycles(mesh), 2u);
  const std::size_t faces_before = num_faces(mesh);
  const MR::Repair_result result = MR::automatic_repair(mesh);
  const MR::Repair_step_report* step = find_step(result, "through holes bridged");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("tubes_added"), 1.0);
  EXPECT_EQ(step->count("faces_added"), 16.0);  // two triangles per edge of the opening
  EXPECT_EQ(result.holes.holes.size(), 0u);     // nothing was left for the hole filling
  EXPECT_EQ(num_faces(mesh), faces_before + 16);
  EXPECT_EQ(count_border_cycles(mesh), 0u);
  EXPECT_EQ(euler_characteristic(mesh), 0);  // the opening is still there: a torus
  EXPECT_FALSE(support::does_self_intersect(mesh));
  EXPECT_GT(CGAL::Polygon_mesh_processing::volume(mesh), 0.0);
  EXPECT_EQ(result.status(), MR::Repair_status::complete);
}

TEST(AutomaticRepair, AThroughHoleIsCappedWhenBridgingIsOff) {
  Mesh mesh = plate_with_a_bare_through_hole();
  const MR::Repair_result result =
      MR::automatic_repair(mesh, MR::parameters::bridge_through_holes(false));
  EXPECT_EQ(find_step(result, "through holes bridged"), nullptr);
  EXPECT_EQ(result.holes.filled, 2u);
  EXPECT_EQ(count_border_cycles(mesh), 0u);
  EXPECT_EQ(euler_characteristic(mesh), 2);
}

TEST(AutomaticRepair, AThroughHoleWithARodTouchingItsEdgesGetsItsWallAndKeepsTheContact) {
  Mesh mesh = plate_with_a_bare_through_hole(true);
  const std::size_t pairs_before = self_intersection_count(mesh);
  ASSERT_GT(pairs_before, 0u);  // the rod crosses the plate's faces at the opening's edge
  const MR::Repair_result result = MR::automatic_repair(mesh);
  const MR::Repair_step_report* step = find_step(result, "through holes bridged");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("tubes_added"), 1.0);
  EXPECT_EQ(count_border_cycles(mesh), 0u);
  EXPECT_EQ(support::connected_components(mesh), 2u);
  // Only contacts between the plate and the rod: the wall meets the rod, nothing else.
  EXPECT_GT(self_intersection_count(mesh), pairs_before);
  EXPECT_EQ(result.status(), MR::Repair_status::complete_except_kept);
}

TEST(AutomaticRepair, AnOpenSleeveIsCappedNotLinedFromInside) {
  // A barrel-shaped band, open at both ends: its two end circles are translated copies running in
  // opposite directions, as a through-hole's, but its faces run from one end to the other. A
  // straight tube between the ends would line the barrel without meeting it.
  Mesh mesh;
  const int sides = 24, rings = 8;
  std::vector<std::vector<Mesh::Vertex_index>> ring(rings + 1);
  for (int k = 0; k <= rings; ++k) {
    const double z = double(k) / rings, r = 1 + 0.3 * std::sin(CGAL_PI * z);
    for (int i = 0; i < sides; ++i) {
      const double a = 2 * CGAL_PI * i / sides;
      ring[k].push_back(mesh.add_vertex(Point(r * std::cos(a), r * std::sin(a), z)));
    }
  }
  for (int k = 0; k < rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const int j = (i + 1) % sides;
      mesh.add_face(ring[k][i], ring[k][j], ring[k + 1][j]);
      mesh.add_face(ring[k][i], ring[k + 1][j], ring[k + 1][i]);
    }
  ASSERT_EQ(count_border_cycles(mesh), 2u);
  const MR::Repair_result result = MR::automatic_repair(mesh);
  const MR::Repair_step_report* step = find_step(result, "through holes bridged");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("matching_pairs"), 0.0);
  EXPECT_EQ(result.holes.filled, 2u);
  EXPECT_EQ(euler_characteristic(mesh), 2);
  EXPECT_EQ(count_border_cycles(mesh), 0u);
}

}  // namespace

// A sphere with a hole holding a scan fragment (one triangle that shares the position of a border
// vertex but no vertex: what the soup repair leaves of a face attached at a single vertex), a
// small closed sphere and a small open disc far away.
Mesh sphere_with_a_fragment_in_its_hole() {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  punch_hole(mesh, Point(1, 0, 0), 0.3);
  mesh.collect_garbage();
  Point corner;
  double nearest = std::numeric_limits<double>::max();
  for (auto h : halfedges(mesh))
    if (is_border(h, mesh) &&
        CGAL::squared_distance(mesh.point(target(h, mesh)), Point(1, 0, 0)) < nearest) {
      corner = mesh.point(target(h, mesh));
      nearest = CGAL::squared_distance(corner, Point(1, 0, 0));
    }
  const auto a = mesh.add_vertex(corner);
  const auto b = mesh.add_vertex(Point(0.99, 0.1, 0.0));
  const auto c = mesh.add_vertex(Point(0.99, 0.0, 0.1));
  CGAL::Euler::add_face(std::vector<Mesh::Vertex_index>{a, b, c}, mesh);
  MR::make_sphere(mesh, Point(5, 0, 0), 0.5, 1);
  MR::make_height_field<Mesh, Point>(mesh, 4, 4.4, 2, 2.4, 3, 3,
                                     [](double, double) { return 0.0; });
  return mesh;
}

TEST(AutomaticRepair, AFragmentInAHoleIsRemovedAndCountedAndOtherPartsStay) {
  Mesh mesh = sphere_with_a_fragment_in_its_hole();
  ASSERT_EQ(support::connected_components(mesh), 4u);
  const std::size_t faces_before = num_faces(mesh);
  const MR::Repair_result result = MR::automatic_repair(mesh);
  const MR::Repair_step_report* step = find_step(result, "fragments in holes");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->count("fragments_removed"), 1.0);
  EXPECT_EQ(step->count("faces_removed"), 1.0);
  EXPECT_EQ(result.holes.filled, 1u);
  // The sphere closed; the far sphere and the disc (an open sheet, not in a hole) kept.
  EXPECT_EQ(support::connected_components(mesh), 3u);
  EXPECT_EQ(count_border_cycles(mesh), 1u);
  EXPECT_EQ(result.sheet_borders_left_open, 1u);
  EXPECT_GT(num_faces(mesh), faces_before - 1);
  EXPECT_TRUE(result.valid && result.manifold);
  EXPECT_EQ(result.status(), MR::Repair_status::complete_except_kept);
}

TEST(AutomaticRepair, AFragmentIsKeptWhenAskedAndTheReportMatchesTheMesh) {
  Mesh mesh = sphere_with_a_fragment_in_its_hole();
  const MR::Repair_result result =
      MR::automatic_repair(mesh, MR::parameters::remove_hole_fragments(false));
  EXPECT_EQ(find_step(result, "fragments in holes"), nullptr);
  // Whatever became of the fragment, what the report says is open is what the mesh shows.
  EXPECT_EQ(count_border_cycles(mesh), result.border_cycles_left);
  EXPECT_EQ(result.border_cycles_left,
            result.sheet_borders_left_open + result.holes_too_large + result.holes.failed);
  EXPECT_TRUE(result.valid);
}

namespace {

/// A sphere of radius 2 holding a sphere of radius 1, both facing outward, or the inner one
/// inward (`cavity`: a hollow ball).
Mesh sphere_in_sphere(bool cavity) {
  Mesh mesh, inner;
  MR::make_sphere(mesh, Point(0, 0, 0), 2.0, 3);
  MR::make_sphere(inner, Point(0.2, 0.1, 0), 1.0, 3);
  if (cavity) CGAL::Polygon_mesh_processing::reverse_face_orientations(inner);
  CGAL::copy_face_graph(inner, mesh);
  return mesh;
}

double step_count(const MR::Repair_result& result, const std::string& step,
                  const std::string& key) {
  const MR::Repair_step_report* found = find_step(result, step);
  if (found == nullptr) return -1;
  for (const auto& count : found->counts)
    if (count.first == key) return count.second;
  return 0;
}

}  // namespace

// A hollow ball written inside out: the outer surface is turned outward and the cavity's
// surface with it, so that the mesh bounds the shell's volume again; with the option off both
// stay as they were.
TEST(AutomaticRepair, AMeshWrittenInsideOutIsTurnedOutwardWithItsCavity) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Mesh mesh = sphere_in_sphere(true);
  const double shell_volume = PMP::volume(mesh);
  ASSERT_GT(shell_volume, 0.0);
  ASSERT_TRUE(PMP::does_bound_a_volume(mesh));
  PMP::reverse_face_orientations(mesh);
  Mesh kept = mesh;
  const MR::Repair_result result = MR::automatic_repair(mesh);
  EXPECT_EQ(result.closed_parts_reversed_outward, 1u);
  EXPECT_EQ(result.closed_parts_reversed_with_container, 1u);
  EXPECT_EQ(step_count(result, "orientation of closed parts", "nested_parts"), 1.0);
  EXPECT_NEAR(PMP::volume(mesh), shell_volume, 1e-9 * shell_volume);
  EXPECT_TRUE(PMP::does_bound_a_volume(mesh));
  EXPECT_EQ(result.status(), MR::Repair_status::complete);

  const MR::Repair_result off =
      MR::automatic_repair(kept, MR::parameters::orient_closed_parts(false));
  EXPECT_EQ(find_step(off, "orientation of closed parts"), nullptr);
  EXPECT_EQ(off.closed_parts_reversed_outward, 0u);
  EXPECT_NEAR(PMP::volume(kept), -shell_volume, 1e-9 * shell_volume);
}

// A solid inside a solid, both facing outward (the eyes inside a figure): nothing tells it
// from a cavity written the wrong way, so it keeps its orientation and is not made a cavity.
TEST(AutomaticRepair, ASolidInsideASolidKeepsFacingOutward) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Mesh mesh = sphere_in_sphere(false);
  const double volumes = PMP::volume(mesh);
  const MR::Repair_result result = MR::automatic_repair(mesh);
  EXPECT_EQ(step_count(result, "orientation of closed parts", "closed_parts"), 2.0);
  EXPECT_EQ(step_count(result, "orientation of closed parts", "nested_parts"), 1.0);
  EXPECT_EQ(result.closed_parts_reversed_outward, 0u);
  EXPECT_EQ(result.closed_parts_reversed_with_container, 0u);
  EXPECT_NEAR(PMP::volume(mesh), volumes, 1e-9 * volumes);
}

// 100 concentric spheres 1% apart: every face's box meets faces of its neighbours, and the
// count of intersecting pairs stops at its limit of candidate pairs with none found. That proves
// nothing about the faces it did not reach: the output is not called complete.
TEST(AutomaticRepair, AnOutputWhoseSelfIntersectionCountStoppedIsNotComplete) {
  Mesh mesh;
  for (int k = 0; k < 100; ++k) MR::make_sphere(mesh, Point(0, 0, 0), 1.0 + 0.01 * k, 2);
  ASSERT_EQ(num_faces(mesh), 100u * 320u);
  const MR::Repair_result result = MR::automatic_repair(mesh, MR::parameters::number_of_threads(1));
  EXPECT_TRUE(result.self_intersections_output_truncated);
  EXPECT_TRUE(result.closed);
  EXPECT_EQ(result.status(), MR::Repair_status::incomplete);
  ASSERT_EQ(result.remaining.size(), 1u);
  EXPECT_NE(result.remaining[0].find("stopped at its limit"), std::string::npos)
      << result.remaining[0];
  EXPECT_EQ(step_count(result, "orientation of closed parts", "closed_parts"), 100.0);
}
