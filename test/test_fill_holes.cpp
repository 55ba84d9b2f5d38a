// Hole filling: the dispatcher, advancing front, CGAL's Liepa, ring holes, pinched borders, the
// exact patch check and its rollback (fill_holes.h).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/hole_benchmark.h>
#include <CGAL/Mesh_repair/hole_filling/advancing_front.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include "scratch_folder.h"
#include "support/cgal_calls.h"
#include "support/hole_punching.h"

#include <cmath>
#include <limits>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <thread>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using face_descriptor = Mesh::Face_index;
namespace MR = CGAL::Mesh_repair;
namespace support = mesh_repair_test;
namespace fs = std::filesystem;
using mesh_repair_test::count_border_cycles;
using mesh_repair_test::punch_hole;

const double sphere_diagonal = 2.0 * std::sqrt(3.0);

Mesh sphere_with_hole(double hole_radius, int subdivisions = 4) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, subdivisions);
  punch_hole(mesh, Point(0, 0, 1), hole_radius);
  return mesh;
}

bool closed_valid_and_clean(const Mesh& mesh) {
  return CGAL::is_closed(mesh) && CGAL::is_valid_polygon_mesh(mesh) &&
         !support::does_self_intersect(mesh);
}

bool note_starts_with(const MR::Hole_fill_report& report, const std::string& start) {
  return !report.notes.empty() && report.notes.front().rfind(start, 0) == 0;
}

/// Largest distance of a vertex to the unit sphere, over the bounding-box diagonal.
double normalised_sphere_einf(const Mesh& mesh) {
  double worst = 0;
  for (auto v : vertices(mesh)) {
    const double r = std::sqrt(CGAL::squared_distance(mesh.point(v), Point(0, 0, 0)));
    worst = std::max(worst, std::abs(r - 1.0));
  }
  return worst / sphere_diagonal;
}

/// Intersecting face pairs in which a face created after the first `original_faces` takes part.
std::size_t new_intersections(const Mesh& mesh, std::size_t original_faces) {
  const std::vector<support::Face_pair> pairs = support::self_intersections(mesh);
  std::size_t count = 0;
  for (const auto& pair : pairs) {
    if (std::size_t(pair.first) >= original_faces || std::size_t(pair.second) >= original_faces)
      ++count;
  }
  return count;
}

TEST(FillHoles, AdvancingFrontClosesASphereHoleWithoutSelfIntersection) {
  Mesh mesh = sphere_with_hole(0.5);
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  const MR::Fill_result result =
      MR::fill_holes(mesh, MR::parameters::fill_method(MR::Fill_method::advancing_front));
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_TRUE(result.holes[0].filled) << result.holes[0].failure;
  EXPECT_EQ(result.holes[0].used, MR::Fill_method::advancing_front);
  EXPECT_GT(result.holes[0].border_edges, 20u);
  EXPECT_TRUE(result.holes[0].fallbacks.empty());
  EXPECT_TRUE(closed_valid_and_clean(mesh));
}

TEST(FillHoles, AdvancingFrontSphereCapEinfBelowOnePercentOfDiagonal) {
  Mesh mesh = sphere_with_hole(0.1 * sphere_diagonal);
  const MR::Fill_result result =
      MR::fill_holes(mesh, MR::parameters::fill_method(MR::Fill_method::advancing_front));
  ASSERT_TRUE(result.all_filled());
  ASSERT_TRUE(closed_valid_and_clean(mesh));
  EXPECT_LT(normalised_sphere_einf(mesh), 0.01);
}

TEST(FillHoles, AdvancingFrontWithoutQuadricStillClosesTheHoleWithMatchingDensity) {
  Mesh mesh = sphere_with_hole(0.5);
  const std::size_t removed_faces = 5120 - mesh.number_of_faces();
  MR::Fill_patch<Mesh> patch;
  const auto border = *std::find_if(halfedges(mesh).begin(), halfedges(mesh).end(),
                                    [&](auto h) { return is_border(h, mesh); });
  const MR::Hole_fill_report report = MR::fill_hole(
      mesh, border, patch,
      MR::parameters::fill_method(MR::Fill_method::advancing_front).fit_quadric(false));
  ASSERT_TRUE(report.filled) << report.failure;
  EXPECT_EQ(patch.faces.size(), report.faces_created);
  EXPECT_TRUE(closed_valid_and_clean(mesh));
  // Same density as the surroundings: within a factor 1.5 of the faces removed.
  EXPECT_GT(double(patch.faces.size()), removed_faces / 1.5);
  EXPECT_LT(double(patch.faces.size()), removed_faces * 1.5);
}

/// Smallest angle (degrees) over the faces of `faces`.
double smallest_angle(const Mesh& mesh, const std::vector<face_descriptor>& faces) {
  double smallest = 180;
  for (face_descriptor f : faces) {
    const auto h = mesh.halfedge(f);
    smallest = std::min(smallest, MR::internal::smallest_angle_deg(
                                      mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                      mesh.point(mesh.target(mesh.next(h)))));
  }
  return smallest;
}

/// Fills the holes `mesh_repair bench holes` punches into a demo mesh with the advancing front
/// alone (no other method behind it); expects every hole filled by the front, every patch free of
/// intersections with the whole mesh and of triangles sharper than `min_angle` degrees.
void expect_front_fills_punched_holes(const std::string& name, double radius,
                                      std::initializer_list<unsigned> seeds, double min_angle) {
  const fs::path path = fs::path(MESH_REPAIR_DEMO_DATA_DIR) / name;
  if (!fs::exists(path)) GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh base;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path.string(), base, soup), "");
  for (unsigned seed : seeds) {
    Mesh mesh = base;
    const auto punched = MR::punch_holes(
        mesh, MR::parameters::number_of_holes(3).hole_radius(radius).random_seed(seed));
    ASSERT_EQ(punched.holes.size(), 3u);
    std::vector<face_descriptor> patch_faces;
    for (const auto& hole : punched.holes) {
      const MR::Hole_fill_report report = MR::fill_hole(
          mesh, hole.border_halfedge,
          MR::parameters::fill_method(MR::Fill_method::advancing_front).random_seed(seed));
      ASSERT_TRUE(report.filled) << name << " seed " << seed << ": " << report.failure;
      EXPECT_EQ(report.used, MR::Fill_method::advancing_front);
      bool bounded = true;
      const auto faces = MR::hole_patch_faces(mesh, hole, bounded);
      EXPECT_TRUE(bounded);
      EXPECT_GE(smallest_angle(mesh, faces), min_angle) << name << " seed " << seed;
      patch_faces.insert(patch_faces.end(), faces.begin(), faces.end());
    }
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    const std::vector<support::Face_pair> pairs = support::self_intersections(mesh);
    const std::set<face_descriptor> in_patch(patch_faces.begin(), patch_faces.end());
    for (const auto& pair : pairs)
      EXPECT_FALSE(in_patch.count(pair.first) || in_patch.count(pair.second)) << name;
  }
}

// The benchmark keeps its holes only one ring apart, and their borders are jagged: enlarged
// ring by ring on its own, the hole met its neighbour or pinched on 4 of these 18 holes, which
// then kept the default order. Grown around pinches, stopped at other borders and enlarged by
// fewer rings where needed, every hole is validated.
TEST(FillHolesDemoData, SelfValidationEnlargesHolesBesideOtherHolesAndOnJaggedBorders) {
  const fs::path path = fs::path(MESH_REPAIR_DEMO_DATA_DIR) / "head.off";
  if (!fs::exists(path)) GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh base;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path.string(), base, soup), "");
  for (double radius : {0.05, 0.12})
    for (unsigned seed : {1u, 2u, 3u}) {
      Mesh mesh = base;
      const auto punched = MR::punch_holes(
          mesh, MR::parameters::number_of_holes(3).hole_radius(radius).random_seed(seed));
      ASSERT_EQ(punched.holes.size(), 3u);
      for (const auto& hole : punched.holes) {
        const MR::Hole_fill_report report =
            MR::fill_hole(mesh, hole.border_halfedge,
                          MR::parameters::fill_method(MR::Fill_method::self_validated));
        ASSERT_TRUE(report.filled) << "radius " << radius << " seed " << seed;
        EXPECT_TRUE(note_starts_with(report, "self-validation on the hole enlarged by "))
            << "radius " << radius << " seed " << seed << ": " << report.notes.front();
      }
      // head.off has borders of its own; only the punched holes are filled.
      EXPECT_EQ(count_border_cycles(mesh), count_border_cycles(base));
      EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
      EXPECT_FALSE(support::does_self_intersect(mesh)) << "radius " << radius << " seed " << seed;
    }
}

// Before the 3D checks and the closing of stuck fronts, 7 of these 9 elephant holes (radius
// 0.12 x diagonal) were left open by the front or rolled back as self-intersecting.
TEST(FillHolesDemoData, AdvancingFrontAloneFillsTheLargePunchedElephantHoles) {
  expect_front_fills_punched_holes("elephant.off", 0.12, {1, 2, 3}, 2.0);
}

// Holes where the front used to be stuck, to leave a self-intersecting patch or (seed 2) a
// triangle of zero area (a node projected onto a border edge): min angle was 6e-14 degrees.
TEST(FillHolesDemoData, AdvancingFrontAloneFillsSmallElephantHolesWithoutSlivers) {
  expect_front_fills_punched_holes("elephant.off", 0.05, {1, 2, 3}, 2.0);
}

TEST(FillHolesDemoData, AdvancingFrontAloneFillsTheFemurAndBunnyHoles) {
  expect_front_fills_punched_holes("femur.off", 0.12, {1, 2, 3}, 2.0);
  expect_front_fills_punched_holes("bunny00.off", 0.05, {1, 2, 3}, 2.0);
}

/// A front that cannot advance (no fan passes a 89-degree minimum angle) is closed by the
/// checked triangulation of its loop, which avoids an edge the mesh already has (1-3) and keeps
/// the loop's orientation; with a wall through the square no triangulation passes the exact 3D
/// test and the front reports failure with its open loop.
TEST(AdvancingFrontCore, StuckFrontIsClosedByTheCheckedTriangulationOfItsLoop) {
  namespace MI = MR::internal;
  MI::Front_input input;
  input.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  input.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  input.cycle = {0, 1, 2, 3};
  input.existing_edges = {{1, 3}};
  MI::Front_options options;
  options.min_angle_deg = 89;
  const auto identity = [](const MI::Vec3& p, const MI::Vec3&) { return p; };
  const auto size = [](const MI::Vec3&, double) { return 1.0; };

  const MI::Front_triangulation stuck = MI::advance_front(input, identity, size, options);
  EXPECT_FALSE(stuck.closed);
  ASSERT_EQ(stuck.remnant.size(), 1u);
  EXPECT_EQ(stuck.remnant[0].size(), 4u);

  options.close_remnant = true;
  const MI::Front_triangulation t = MI::advance_front(input, identity, size, options);
  ASSERT_TRUE(t.closed) << t.failure;
  EXPECT_EQ(t.remnant_edges, 4u);
  ASSERT_EQ(t.triangles.size(), 2u);
  for (const auto& tri : t.triangles) {
    const auto has = [&](std::size_t p) { return tri[0] == p || tri[1] == p || tri[2] == p; };
    EXPECT_TRUE(has(0) && has(2));  // the diagonal 0-2, not the existing edge 1-3
    // Counterclockwise seen from +z, like the loop.
    const MI::Vec3 n = MI::cross(MI::sub(t.points[tri[1]], t.points[tri[0]]),
                                 MI::sub(t.points[tri[2]], t.points[tri[0]]));
    EXPECT_GT(n[2], 0);
  }

  // A vertical wall standing in the square: every triangle of the square meets it.
  input.existing_edges.clear();
  input.context_points = {{0.4, 0.6, -1}, {0.6, 0.4, -1}, {0.5, 0.5, 1}};
  input.context_triangles = {{4, 5, 6}};
  const MI::Front_triangulation walled = MI::advance_front(input, identity, size, options);
  EXPECT_FALSE(walled.closed);
  EXPECT_FALSE(walled.failure.empty());

  // The attempts on one hole share one budget (fill_hole_advancing_front): the walled loop,
  // which has no valid triangulation, spends some of it; with the budget spent, a loop whose
  // first triangulation passes is still closed (one round of the program always runs).
  std::size_t left = 1000;
  options.remnant_visits_left = &left;
  EXPECT_FALSE(MI::advance_front(input, identity, size, options).closed);
  EXPECT_LT(left, 1000u);
  left = 0;
  input.context_points.clear();
  input.context_triangles.clear();
  EXPECT_TRUE(MI::advance_front(input, identity, size, options).closed);
}

/// The front checks its own patch, in its final (relaxed) positions, against itself and every
/// mesh face near the hole, so `fill_hole_advancing_front` skips the whole-mesh check
/// (`exactly_checked`); the flag drops when the context is incomplete or the patch leaves the
/// box in which the context holds every face, and CGAL's check agrees with a checked patch.
TEST(AdvancingFrontCore, ClosedFrontIsExactlyCheckedInItsFinalPositions) {
  namespace MI = MR::internal;
  Mesh mesh = sphere_with_hole(0.5);
  const std::size_t original_faces = mesh.number_of_faces();
  const auto border = *std::find_if(halfedges(mesh).begin(), halfedges(mesh).end(),
                                    [&](auto h) { return is_border(h, mesh); });
  std::vector<Mesh::Vertex_index> point_vertices;
  MI::Front_input input = MI::front_input_from_border(mesh, mesh.points(), border, point_vertices);
  EXPECT_TRUE(input.context_complete);
  const MI::Front_size size = MI::border_density(input, MI::front_spacing_factor);
  const auto onto_sphere = [](const MI::Vec3& p, const MI::Vec3&) { return MI::normalized(p); };
  MI::Front_options options;
  options.smoothing_iterations = 3;
  const MI::Front_triangulation t = MI::advance_front(input, onto_sphere, size, options);
  ASSERT_TRUE(t.closed) << t.failure;
  EXPECT_TRUE(t.exactly_checked);

  MR::Fill_patch<Mesh> patch;
  ASSERT_TRUE(MI::insert_front_triangulation(mesh, mesh.points(), t, point_vertices, patch));
  EXPECT_TRUE(closed_valid_and_clean(mesh));
  EXPECT_EQ(new_intersections(mesh, original_faces), 0u);

  MI::Front_input outside = input;  // a box that the new nodes leave
  outside.context_hi = outside.context_lo;
  const MI::Front_triangulation unboxed = MI::advance_front(outside, onto_sphere, size, options);
  ASSERT_TRUE(unboxed.closed);
  EXPECT_FALSE(unboxed.exactly_checked);
  MI::Front_input incomplete = input;  // e.g. a quad near the hole, which the front cannot test
  incomplete.context_complete = false;
  EXPECT_FALSE(MI::advance_front(incomplete, onto_sphere, size, options).exactly_checked);
}

/// Deferring the fans' 3D test to one test of the closed patch gives the same patch when no fan
/// would have failed it, and a patch that is not `exactly_checked` when one would have.
TEST(AdvancingFrontCore, DeferredThreeDimensionalTestGivesTheSamePatchOrFlagsIt) {
  namespace MI = MR::internal;
  Mesh mesh = sphere_with_hole(0.5);
  const auto border = *std::find_if(halfedges(mesh).begin(), halfedges(mesh).end(),
                                    [&](auto h) { return is_border(h, mesh); });
  std::vector<Mesh::Vertex_index> point_vertices;
  const MI::Front_input input =
      MI::front_input_from_border(mesh, mesh.points(), border, point_vertices);
  const MI::Front_size size = MI::border_density(input, MI::front_spacing_factor);
  const auto onto_sphere = [](const MI::Vec3& p, const MI::Vec3&) { return MI::normalized(p); };
  MI::Front_options options;
  const MI::Front_triangulation checked = MI::advance_front(input, onto_sphere, size, options);
  options.defer_3d_test = true;
  const MI::Front_triangulation deferred = MI::advance_front(input, onto_sphere, size, options);
  ASSERT_TRUE(checked.closed && deferred.closed);
  EXPECT_TRUE(checked.exactly_checked && deferred.exactly_checked);
  EXPECT_EQ(deferred.triangles, checked.triangles);
  EXPECT_EQ(deferred.points, checked.points);

  // A vertical wall standing in a square hole: the tangent-plane test does not see it, the
  // final 3D test does.
  MI::Front_input square;
  square.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  square.cycle = {0, 1, 2, 3};
  square.context_points = {{0.4, 0.6, -1}, {0.6, 0.4, -1}, {0.5, 0.5, 1}};
  square.context_triangles = {{4, 5, 6}};
  square.context_complete = true;
  square.context_lo = {-1, -1, -1};
  square.context_hi = {2, 2, 2};
  const auto identity = [](const MI::Vec3& p, const MI::Vec3&) { return p; };
  const auto unit = [](const MI::Vec3&, double) { return 1.0; };
  const MI::Front_triangulation walled = MI::advance_front(square, identity, unit, options);
  ASSERT_TRUE(walled.closed);
  EXPECT_FALSE(walled.exactly_checked);
  options.defer_3d_test = false;
  EXPECT_FALSE(MI::advance_front(square, identity, unit, options).closed);
}

/// A face of another component pierces the hole's region from the sphere's centre to far
/// outside: a surface closing the sphere puts one end inside and the other outside, so it must
/// cross the face (a sliver from z = 0.6 only was avoided by a patch dipping below it). Since
/// the front collects every face near the hole (not only the ring) and tests each new triangle
/// against it, no patch is kept; the mesh is unchanged.
TEST(FillHoles, AdvancingFrontKeepsNoPatchThroughAFaceOfAnotherComponent) {
  Mesh mesh = sphere_with_hole(0.5);
  const auto a = mesh.add_vertex(Point(0.02, 0.0, 0.0));
  const auto b = mesh.add_vertex(Point(-0.02, 0.01, 0.0));
  const auto c = mesh.add_vertex(Point(0.0, -0.01, 3.0));
  mesh.add_face(a, b, c);
  const std::size_t faces_before = mesh.number_of_faces();
  const auto border = *std::find_if(halfedges(mesh).begin(), halfedges(mesh).end(), [&](auto h) {
    return is_border(h, mesh) && mesh.target(h) != a && mesh.target(h) != b && mesh.target(h) != c;
  });
  MR::Fill_patch<Mesh> patch;
  const MR::Hole_fill_report report = MR::fill_hole_advancing_front(mesh, border, patch);
  EXPECT_FALSE(report.filled);
  EXPECT_EQ(mesh.number_of_faces(), faces_before);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_FALSE(support::does_self_intersect(mesh));
}

TEST(FillHoles, LiepaClosesASphereHoleWithEveryContinuity) {
  for (unsigned continuity : {0u, 1u, 2u}) {
    Mesh mesh = sphere_with_hole(0.5);
    const MR::Fill_result result = MR::fill_holes(
        mesh, MR::parameters::fill_method(MR::Fill_method::liepa).fairing_continuity(continuity));
    ASSERT_EQ(result.holes.size(), 1u);
    EXPECT_TRUE(result.holes[0].filled) << result.holes[0].failure;
    EXPECT_EQ(result.holes[0].used, MR::Fill_method::liepa);
    EXPECT_TRUE(closed_valid_and_clean(mesh)) << "continuity " << continuity;
  }
}

TEST(FillHoles, EveryMethodClosesThreeTorusHoles) {
  for (MR::Fill_method method : {MR::Fill_method::advancing_front, MR::Fill_method::liepa,
                                 MR::Fill_method::automatic, MR::Fill_method::self_validated}) {
    Mesh mesh;
    MR::make_torus<Mesh, Point>(mesh, 2.0, 0.7, 64, 24);
    punch_hole(mesh, Point(2.7, 0, 0), 0.45);    // outer equator
    punch_hole(mesh, Point(0, 1.3, 0), 0.35);    // inner (saddle) side
    punch_hole(mesh, Point(-2.0, 0, 0.7), 0.4);  // top
    ASSERT_EQ(count_border_cycles(mesh), 3u);
    const MR::Fill_result result = MR::fill_holes(mesh, MR::parameters::fill_method(method));
    EXPECT_EQ(result.filled, 3u) << MR::to_string(method);
    EXPECT_TRUE(closed_valid_and_clean(mesh)) << MR::to_string(method);
  }
}

/// A sphere whose band between two heights is removed: the cap above floats as an island inside
/// the hole of the rest, a ring hole.
Mesh sphere_with_ring_hole() {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  std::vector<face_descriptor> band;
  for (auto f : faces(mesh)) {
    double z = 0;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) z += mesh.point(v).z() / 3;
    if (z > 0.55 && z < 0.8) band.push_back(f);
  }
  for (auto f : band) CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
  return mesh;
}

/// The note of a self-validated fill starts with what the ranking was measured on.
// On a sphere the ring around a hole has the hole's own curvature, so the method it ranks first
// must be as faithful on the hole as the best of the candidates.
TEST(FillHoles, SelfValidatedChoiceIsAsFaithfulAsTheBestCandidateOnASphere) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& candidate : MR::internal::self_validation_candidates()) {
    Mesh mesh = sphere_with_hole(0.35, 5);
    auto np = MR::parameters::fill_method(candidate.method);
    const MR::Fill_result result =
        candidate.continuity < 0
            ? MR::fill_holes(mesh, np)
            : MR::fill_holes(mesh, np.fairing_continuity(candidate.continuity));
    if (result.all_filled() && closed_valid_and_clean(mesh))
      best = std::min(best, normalised_sphere_einf(mesh));
  }
  ASSERT_TRUE(std::isfinite(best));
  Mesh mesh = sphere_with_hole(0.35, 5);
  const MR::Fill_result result =
      MR::fill_holes(mesh, MR::parameters::fill_method(MR::Fill_method::self_validated));
  ASSERT_EQ(result.holes.size(), 1u);
  const MR::Hole_fill_report& hole = result.holes[0];
  ASSERT_TRUE(hole.filled) << hole.failure;
  EXPECT_EQ(hole.requested, MR::Fill_method::self_validated);
  EXPECT_TRUE(note_starts_with(hole, "self-validation on the hole enlarged by 2 ring(s)"))
      << hole.notes.front();
  EXPECT_TRUE(closed_valid_and_clean(mesh));
  EXPECT_LE(normalised_sphere_einf(mesh), 1.1 * best) << hole.notes.front();
}

// A ring hole (whose enlargement would swallow the island) keeps the default order.
TEST(FillHoles, SelfValidationOfARingHoleKeepsTheDefaultOrder) {
  Mesh ring = sphere_with_ring_hole();
  const MR::Fill_result ringed =
      MR::fill_holes(ring, MR::parameters::fill_method(MR::Fill_method::self_validated));
  ASSERT_EQ(ringed.holes.size(), 1u);
  EXPECT_TRUE(ringed.holes[0].filled) << ringed.holes[0].failure;
  EXPECT_TRUE(note_starts_with(ringed.holes[0], "self-validation: not done on a ring hole"));
  EXPECT_TRUE(closed_valid_and_clean(ring));
}

TEST(FillHoles, RingHoleIsClosedWithOnePatchJoiningTheIsland) {
  Mesh mesh = sphere_with_ring_hole();
  ASSERT_EQ(count_border_cycles(mesh), 2u);
  for (MR::Fill_method method : {MR::Fill_method::advancing_front, MR::Fill_method::liepa}) {
    Mesh filled = mesh;
    const MR::Fill_result result = MR::fill_holes(filled, MR::parameters::fill_method(method));
    ASSERT_EQ(result.holes.size(), 1u) << MR::to_string(method);
    EXPECT_EQ(result.holes[0].island_cycles, 1u);
    EXPECT_TRUE(result.holes[0].filled) << result.holes[0].failure;
    EXPECT_TRUE(closed_valid_and_clean(filled)) << MR::to_string(method);
    EXPECT_EQ(support::connected_components(filled), 1u);
  }
}

/// A sphere with a ring hole and `holes` simple holes spread over it (Fibonacci points).
Mesh sphere_with_many_holes(int holes) {
  Mesh mesh = sphere_with_ring_hole();
  const double golden = CGAL_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < holes; ++i) {
    const double z = -0.9 + 1.3 * (i + 0.5) / holes;  // below the ring hole's band
    const double r = std::sqrt(1.0 - z * z);
    punch_hole(mesh, Point(r * std::cos(golden * i), r * std::sin(golden * i), z), 0.13);
  }
  return mesh;
}

/// Every vertex position and every face's corners, in index order: equal only when the two
/// meshes are the same element for element.
std::pair<std::vector<Point>, std::vector<std::size_t>> elements(const Mesh& mesh) {
  std::pair<std::vector<Point>, std::vector<std::size_t>> all;
  for (auto v : vertices(mesh)) all.first.push_back(mesh.point(v));
  for (auto f : faces(mesh)) {
    all.second.push_back(std::size_t(f));
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) all.second.push_back(v);
  }
  return all;
}

TEST(FillHoles, ParallelFillingGivesTheSameMeshAsOneThread) {
  for (MR::Fill_method method : {MR::Fill_method::automatic, MR::Fill_method::self_validated,
                                 MR::Fill_method::shape_prediction, MR::Fill_method::liepa}) {
    const Mesh input = sphere_with_many_holes(method == MR::Fill_method::automatic ? 40 : 12);
    const std::size_t holes = count_border_cycles(input) - 1;  // the island joins its hole
    ASSERT_GE(holes, method == MR::Fill_method::automatic ? 30u : 10u);
    Mesh serial = input, parallel = input;
    const auto np = MR::parameters::fill_method(method).random_seed(7);
    const MR::Fill_result one = MR::fill_holes(serial, np.number_of_threads(1));
    const MR::Fill_result two = MR::fill_holes(parallel, np.number_of_threads(2));
    EXPECT_EQ(one.filled, holes) << MR::to_string(method);
    EXPECT_EQ(two.filled, holes) << MR::to_string(method);
    EXPECT_TRUE(CGAL::is_closed(parallel) && CGAL::is_valid_polygon_mesh(parallel));
    EXPECT_EQ(serial.number_of_vertices(), parallel.number_of_vertices());
    EXPECT_TRUE(elements(serial) == elements(parallel)) << MR::to_string(method);
    for (std::size_t k = 0; k < one.holes.size(); ++k)
      EXPECT_EQ(one.holes[k].used, two.holes[k].used) << MR::to_string(method) << " hole " << k;
  }
}

TEST(FillHoles, RingHoleDetectionCanBeTurnedOff) {
  Mesh mesh = sphere_with_ring_hole();
  const MR::Fill_result result = MR::fill_holes(
      mesh, MR::parameters::fill_method(MR::Fill_method::liepa).detect_ring_holes(false));
  EXPECT_EQ(result.holes.size(), 2u);
  for (const auto& hole : result.holes) EXPECT_EQ(hole.island_cycles, 0u);
}

/// A flat 6 x 6 grid (z = 0, facing +z) without its middle 2 x 2 squares, and a unit square
/// patch floating in that hole, facing +z (`island_faces_up`) or turned over (-z).
Mesh flat_hole_with_island(bool island_faces_up) {
  Mesh mesh;
  std::vector<std::vector<Mesh::Vertex_index>> grid(7, std::vector<Mesh::Vertex_index>(7));
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j) grid[i][j] = mesh.add_vertex(Point(i, j, 0));
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      if (i >= 2 && i < 4 && j >= 2 && j < 4) continue;
      mesh.add_face(grid[i][j], grid[i + 1][j], grid[i + 1][j + 1]);
      mesh.add_face(grid[i][j], grid[i + 1][j + 1], grid[i][j + 1]);
    }
  }
  const auto a = mesh.add_vertex(Point(2.5, 2.5, 0)), b = mesh.add_vertex(Point(3.5, 2.5, 0)),
             c = mesh.add_vertex(Point(3.5, 3.5, 0)), d = mesh.add_vertex(Point(2.5, 3.5, 0));
  if (island_faces_up) {
    mesh.add_face(a, b, c);
    mesh.add_face(a, c, d);
  } else {
    mesh.add_face(a, c, b);
    mesh.add_face(a, d, c);
  }
  return mesh;
}

// Detection reports the islands that filling bridges: one test (thesis 4.4) decides both. An
// island facing the surface's way is one; a turned-over island is an orientation defect that no
// strip joins without a fold, so it is neither reported nor bridged.
TEST(FillHoles, DetectionReportsTheIslandsThatFillingBridges) {
  for (const bool faces_up : {true, false}) {
    Mesh mesh = flat_hole_with_island(faces_up);
    ASSERT_EQ(count_border_cycles(mesh), 3u);  // the grid's outer border, the hole, the island
    const std::size_t reported = MR::counts(MR::detect_defects(mesh)).ring_hole_islands;
    const MR::Fill_result result =
        MR::fill_holes(mesh, MR::parameters::fill_method(MR::Fill_method::liepa));
    std::size_t bridged = 0;
    for (const auto& hole : result.holes) bridged += hole.island_cycles;
    EXPECT_EQ(reported, bridged) << (faces_up ? "island facing up" : "island turned over");
    EXPECT_EQ(reported, faces_up ? 1u : 0u);
  }
}

TEST(FillHoles, SelectionBySizeLeavesTheLargeHoleOpen) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  punch_hole(mesh, Point(0, 0, 1), 0.6);
  punch_hole(mesh, Point(0, 0, -1), 0.2);
  ASSERT_EQ(count_border_cycles(mesh), 2u);
  Mesh by_edges = mesh, by_size = mesh, by_filter = mesh;
  const MR::Fill_result edges = MR::fill_holes(by_edges, MR::parameters::max_hole_edges(20));
  EXPECT_EQ(edges.filled, 1u);
  EXPECT_EQ(edges.skipped, 1u);
  EXPECT_EQ(count_border_cycles(by_edges), 1u);
  const MR::Fill_result size = MR::fill_holes(by_size, MR::parameters::max_hole_size(0.2));
  EXPECT_EQ(size.filled, 1u);
  EXPECT_EQ(size.skipped, 1u);
  const MR::Fill_result filter = MR::fill_holes(
      by_filter,
      MR::parameters::hole_filter([](const MR::Hole_description& d) { return d.perimeter > 2; }));
  EXPECT_EQ(filter.filled, 1u);
  EXPECT_EQ(filter.skipped, 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(by_filter));
}

TEST(FillHoles, SelfIntersectingPatchIsRolledBackAndTheMeshUnchanged) {
  // The border of a flat open sheet bounds no hole: any triangulation of it lies on the sheet,
  // so every patch overlaps its ring and must be rejected.
  Mesh sheet;
  MR::make_height_field<Mesh, Point>(sheet, 0, 1, 0, 1, 6, 6, [](double, double) { return 0.0; });
  const std::size_t faces_before = sheet.number_of_faces();
  const std::size_t vertices_before = sheet.number_of_vertices();
  // (sheet_border_ratio would leave it open before any method is tried.)
  const MR::Fill_result result =
      MR::fill_holes(sheet, MR::parameters::fill_method(MR::Fill_method::liepa)
                                .sheet_border_ratio(std::numeric_limits<double>::infinity()));
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_FALSE(result.holes[0].filled);
  EXPECT_NE(result.holes[0].failure.find("self-intersect"), std::string::npos)
      << result.holes[0].failure;
  EXPECT_EQ(result.holes[0].faces_created, 0u);
  EXPECT_EQ(sheet.number_of_faces(), faces_before);
  EXPECT_EQ(sheet.number_of_vertices(), vertices_before);
  EXPECT_EQ(count_border_cycles(sheet), 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(sheet));
  EXPECT_FALSE(support::does_self_intersect(sheet));
}

TEST(FillHoles, AutomaticRecordsTheFallbackWhenTheFrontFails) {
  Mesh sheet;
  MR::make_height_field<Mesh, Point>(sheet, 0, 1, 0, 1, 6, 6, [](double, double) { return 0.0; });
  const MR::Fill_result result =
      MR::fill_holes(sheet, MR::parameters::fill_method(MR::Fill_method::automatic)
                                .sheet_border_ratio(std::numeric_limits<double>::infinity()));
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_EQ(result.holes[0].requested, MR::Fill_method::automatic);
  // No patch spans the sheet's outline without covering the sheet: the front, Liepa and the
  // last resorts (Liepa C0, refined, triangulated only, the same three on the projected
  // triangulation) are all rejected and listed; the base closes the sheet into a slab.
  EXPECT_EQ(result.holes[0].fallbacks.size(), 8u);
  EXPECT_TRUE(result.holes[0].filled);
  EXPECT_TRUE(closed_valid_and_clean(sheet));
}

TEST(FillHoles, DefaultIsSelfValidatedAndListsEveryRejectedCandidate) {
  Mesh sheet;
  MR::make_height_field<Mesh, Point>(sheet, 0, 1, 0, 1, 6, 6, [](double, double) { return 0.0; });
  const MR::Fill_result result = MR::fill_holes(
      sheet, MR::parameters::sheet_border_ratio(std::numeric_limits<double>::infinity()));
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_EQ(result.holes[0].requested, MR::Fill_method::self_validated);
  // The four faired candidates in their validated order, the front (handing on, then closing
  // its remnant), then the last resorts: the membrane, refined only, triangulated only, the same
  // on the projected triangulation, then the base, which closes the sheet into a slab.
  const auto& fallbacks = result.holes[0].fallbacks;
  ASSERT_EQ(fallbacks.size(), 12u);
  EXPECT_EQ(fallbacks[4].rfind("advancing_front (", 0), 0u) << fallbacks[4];
  EXPECT_EQ(fallbacks[4].find("remnant"), std::string::npos) << fallbacks[4];
  EXPECT_EQ(fallbacks[5].rfind("advancing_front (remnant closed) (", 0), 0u) << fallbacks[5];
  EXPECT_EQ(fallbacks[6].rfind("liepa (C0) (", 0), 0u) << fallbacks[6];
  EXPECT_EQ(fallbacks[7].rfind("liepa (refined, not faired) (", 0), 0u) << fallbacks[7];
  EXPECT_EQ(fallbacks[8].rfind("liepa (triangulated only) (", 0), 0u) << fallbacks[8];
  EXPECT_EQ(fallbacks[11].rfind("projected triangulation (", 0), 0u) << fallbacks[11];
  EXPECT_TRUE(result.holes[0].filled);
  EXPECT_TRUE(closed_valid_and_clean(sheet));
}

TEST(FillHoles, ShapePredictionFallsBackToLiepaThenTheFrontAndTimesEachAttempt) {
  Mesh sheet;
  MR::make_height_field<Mesh, Point>(sheet, 0, 1, 0, 1, 6, 6, [](double, double) { return 0.0; });
  const MR::Fill_result result =
      MR::fill_holes(sheet, MR::parameters::fill_method(MR::Fill_method::shape_prediction)
                                .sheet_border_ratio(std::numeric_limits<double>::infinity()));
  ASSERT_EQ(result.holes.size(), 1u);
  const auto& fallbacks = result.holes[0].fallbacks;
  // Every patch spanning the outline lies on the sheet (see above): each method is rejected, in
  // the order of `shape_prediction_sequence`, then the last resorts, each listed with the time
  // it took. The base closes the outline last: the sheet becomes a slab one border edge thick.
  const char* order[] = {"shape_prediction (",
                         "liepa (",
                         "advancing_front (",
                         "liepa (C0) (",
                         "liepa (refined, not faired) (",
                         "liepa (triangulated only) (",
                         "projected triangulation, refined and faired (C0) (",
                         "projected triangulation, refined (",
                         "projected triangulation ("};
  ASSERT_EQ(fallbacks.size(), std::size(order));
  for (std::size_t k = 0; k < std::size(order); ++k) {
    EXPECT_EQ(fallbacks[k].rfind(order[k], 0), 0u) << fallbacks[k];
    EXPECT_NE(fallbacks[k].find(" s): "), std::string::npos) << fallbacks[k];
  }
  EXPECT_TRUE(result.holes[0].filled);
  EXPECT_TRUE(closed_valid_and_clean(sheet));
  EXPECT_NEAR(std::abs(CGAL::Polygon_mesh_processing::volume(sheet)), 1.0 / 6, 1e-9);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(sheet));
}

void expect_demo_mesh_filled(const std::string& name,
                             MR::Fill_method method = MR::Fill_method::self_validated) {
  const fs::path path = fs::path(MESH_REPAIR_DEMO_DATA_DIR) / name;
  if (!fs::exists(path)) GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh mesh;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path.string(), mesh, soup), "");
  const std::size_t original_faces = num_faces(mesh);
  ASSERT_GT(count_border_cycles(mesh), 0u);
  const MR::Fill_result result = MR::fill_holes(mesh, MR::parameters::fill_method(method));
  for (const auto& hole : result.holes) EXPECT_TRUE(hole.filled) << name << ": " << hole.failure;
  EXPECT_TRUE(result.all_filled());
  EXPECT_TRUE(CGAL::is_closed(mesh)) << name;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh)) << name;
  EXPECT_EQ(new_intersections(mesh, original_faces), 0u) << name;
}

TEST(FillHolesDemoData, ElephantWithHolesIsClosedValidAndPatchesDoNotIntersect) {
  expect_demo_mesh_filled("elephant-with-holes.off");
}
TEST(FillHolesDemoData, MechHolesSharkIsClosedValidAndPatchesDoNotIntersect) {
  expect_demo_mesh_filled("mech-holes-shark.off");
}
TEST(FillHolesDemoData, HolesOffIsClosedValidAndPatchesDoNotIntersect) {
  expect_demo_mesh_filled("holes.off");
}
/// The cylinder's one hole is a 126-edge saddle loop spanning the whole mesh, on which the front
/// stalls after a few triangles. Its remnant is closed by the least-area checked triangulation,
/// found lazily (the exact test on the optimum's triangles only): testing every candidate
/// triangle against the 16,442 faces took over 5 minutes with the front and 95 s with shape
/// prediction.
TEST(FillHolesDemoData, SaddleLoopAcrossTheCylinderIsClosedByEachFrontMethod) {
  expect_demo_mesh_filled("cylinder_locally_refined.off", MR::Fill_method::advancing_front);
  expect_demo_mesh_filled("cylinder_locally_refined.off", MR::Fill_method::shape_prediction);
}

/// blobby_3cc is a blob cut into three pieces a thin crack apart. The cut of one piece faces its
/// neighbours' caps, every faired patch crosses them, and the front goes around the neighbour:
/// its remnant (130 edges for a 71-edge hole) was closed by 2,831 faces, a bag wrapping the whole
/// model. A remnant longer than the border is no longer closed: every patch kept stays inside
/// the model's box, and the hole no method fills without crossing a neighbour is left open.
TEST(FillHolesDemoData, APieceFacingItsNeighboursAcrossACrackIsNotWrappedInABag) {
  const fs::path path = fs::path(MESH_REPAIR_DEMO_DATA_DIR) / "blobby_3cc.off";
  if (!fs::exists(path)) GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh mesh;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path.string(), mesh, soup), "");
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const std::size_t original_faces = num_faces(mesh);
  const MR::Fill_result result = MR::fill_holes(mesh);
  ASSERT_EQ(result.holes.size(), 4u);
  EXPECT_GE(result.filled, 3u);
  EXPECT_LT(num_faces(mesh), original_faces + 1500);  // the caps: about 800 faces
  const CGAL::Bbox_3 filled = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double margin =
      0.01 * std::sqrt(CGAL::squared_distance(Point(box.xmin(), box.ymin(), box.zmin()),
                                              Point(box.xmax(), box.ymax(), box.zmax())));
  for (int d = 0; d < 3; ++d) {
    EXPECT_GE(filled.min(d), box.min(d) - margin) << d;
    EXPECT_LE(filled.max(d), box.max(d) + margin) << d;
  }
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(new_intersections(mesh, original_faces), 0u);
}

#ifdef MESH_REPAIR_CLI
TEST(FillCli, FillsASphereHoleExitsZeroAndWritesOneReportEntryPerHole) {
  // Removed when the process ends, also when an assertion stops the test.
  const fs::path dir = mesh_repair_test::scratch_folder("mesh_repair_test_fill_cli_") / "sphere";
  fs::create_directories(dir);
  Mesh mesh = sphere_with_hole(0.5, 3);
  ASSERT_EQ(MR::write_mesh((dir / "in.off").string(), mesh), "");
  const std::string command = std::string(MESH_REPAIR_CLI) + " fill " + (dir / "in.off").string() +
                              " -o " + (dir / "out.off").string() + " --method advancing_front" +
                              " --report " + (dir / "report.json").string() + " --quiet";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  Mesh out;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh((dir / "out.off").string(), out, soup), "");
  EXPECT_TRUE(CGAL::is_closed(out));
  std::ifstream report(dir / "report.json");
  std::stringstream text;
  text << report.rdbuf();
  EXPECT_NE(text.str().find("\"filled\": true"), std::string::npos) << text.str();
  const std::string bad = std::string(MESH_REPAIR_CLI) + " fill " + (dir / "in.off").string() +
                          " -o " + (dir / "x.off").string() + " --method nonsense 2>/dev/null";
  EXPECT_EQ(WEXITSTATUS(std::system(bad.c_str())), 2);
  fs::remove_all(dir);
}

/// `--threads N` gives the same mesh as one thread, byte for byte; 0 is refused.
TEST(FillCli, ThreadsOptionGivesTheSameOutputAndRefusesZero) {
  // Removed when the process ends, also when an assertion stops the test.
  const fs::path dir = mesh_repair_test::scratch_folder("mesh_repair_test_fill_cli_") / "threads";
  fs::create_directories(dir);
  Mesh mesh = sphere_with_hole(0.3, 3);
  punch_hole(mesh, Point(0, 0, -1), 0.3);
  punch_hole(mesh, Point(1, 0, 0), 0.3);
  ASSERT_EQ(MR::write_mesh((dir / "in.off").string(), mesh), "");
  std::string outputs[2];
  for (int threads : {1, 2}) {
    const fs::path out = dir / ("out" + std::to_string(threads) + ".off");
    const std::string command =
        std::string(MESH_REPAIR_CLI) + " fill " + (dir / "in.off").string() + " -o " +
        out.string() + " --method advancing_front --quiet --threads " + std::to_string(threads);
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    outputs[threads - 1] = text.str();
  }
  EXPECT_FALSE(outputs[0].empty());
  EXPECT_EQ(outputs[0], outputs[1]);
  const std::string bad = std::string(MESH_REPAIR_CLI) + " fill " + (dir / "in.off").string() +
                          " -o " + (dir / "x.off").string() + " --threads 0 2>/dev/null";
  EXPECT_EQ(WEXITSTATUS(std::system(bad.c_str())), 2);
  EXPECT_FALSE(fs::exists(dir / "x.off"));
  fs::remove_all(dir);
}
#endif

/// A bumpy open sheet over [-1,1]^2, n x n cells: its outline is the only border cycle.
Mesh bumpy_sheet(int n) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, -1, 1, -1, 1, n, n, [](double x, double y) {
    return 0.1 * std::sin(3 * x) * std::cos(2 * y);
  });
  return mesh;
}

TEST(FillHoles, SheetBorderRatioIsOneForAFlatSheetAndSmallForAHoleInASphere) {
  Mesh flat;
  MR::make_height_field<Mesh, Point>(flat, 0, 2, 0, 1, 8, 4, [](double, double) { return 0.0; });
  const auto flat_groups = MR::internal::hole_groups(flat, flat.points(), true);
  ASSERT_EQ(flat_groups.size(), 1u);
  EXPECT_NEAR(MR::internal::sheet_border_ratios(flat, flat.points(), flat_groups)[0], 1.0, 1e-12);
  // A cap of height 0.155 of the unit sphere cut off by z = 1 - 1.3^2 / 2: the remaining surface
  // has area 2 pi (1 + 0.155), the cut circle pi (1 - 0.155^2).
  Mesh bowl = sphere_with_hole(1.3, 5);
  const auto bowl_groups = MR::internal::hole_groups(bowl, bowl.points(), true);
  ASSERT_EQ(bowl_groups.size(), 1u);
  const double z = 1 - 1.3 * 1.3 / 2;
  EXPECT_NEAR(MR::internal::sheet_border_ratios(bowl, bowl.points(), bowl_groups)[0],
              (1 - z * z) / (2 * (1 + z)), 0.02);
}

/// A 5 x 5 grid of cells (two triangles each) on a gentle saddle, without the cell `hole` (when
/// in range); the cells of `cut` take a copy of the corner (2,2) instead of it, so that the edges
/// between them and the other cells around the corner are cut.
Mesh grid_cut_at_a_corner(const std::set<std::pair<int, int>>& cut, std::pair<int, int> hole,
                          Point& corner, Point& below) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> grid;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) grid.push_back(mesh.add_vertex(Point(i, j, 0.05 * i * j)));
  corner = mesh.point(grid[6 * 2 + 2]);
  below = mesh.point(grid[6 * 1 + 2]);
  const auto corner_copy = mesh.add_vertex(corner);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      if (std::make_pair(i, j) == hole) continue;
      auto at = [&](int a, int b) {
        return cut.count({i, j}) && a == 2 && b == 2 ? corner_copy : grid[6 * b + a];
      };
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return mesh;
}

/// The edges of `mesh` from `a` to `b` (either way); none of them on a border.
std::size_t interior_edges_between(const Mesh& mesh, const Point& a, const Point& b) {
  std::size_t found = 0;
  for (auto e : edges(mesh)) {
    const Point s = mesh.point(source(e, mesh)), t = mesh.point(target(e, mesh));
    if ((s == a && t == b) || (s == b && t == a)) {
      ++found;
      EXPECT_FALSE(CGAL::is_border(e, mesh));
    }
  }
  return found;
}

// A hole whose border runs out along a cut edge and back: the cut's two sides end at coincident
// copies of the hole's corner. Welding the copies leaves a loop of two edges joining the same
// two vertices, which no method can triangulate and `is_valid_polygon_mesh` rejects; it is
// zipped into one edge with the rest of the hole filled.
TEST(FillHoles, AHoleRunningAlongACutEdgeIsFilledAndTheCutZipped) {
  Point corner, below;
  Mesh mesh = grid_cut_at_a_corner({{2, 1}}, {2, 2}, corner, below);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  ASSERT_EQ(count_border_cycles(mesh), 2u);  // the outline and the hole with the cut
  const std::size_t vertices_before = mesh.number_of_vertices();
  const MR::Fill_result result = MR::fill_holes(mesh);
  EXPECT_EQ(result.filled, 1u);
  EXPECT_EQ(result.sheet_borders, 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(count_border_cycles(mesh), 1u);
  EXPECT_EQ(mesh.number_of_vertices(), vertices_before - 1);   // the copy welded away
  EXPECT_EQ(interior_edges_between(mesh, below, corner), 1u);  // where the cut was
  EXPECT_FALSE(support::does_self_intersect(mesh));
}

// Two cut edges meeting at an inner vertex, and no cell missing: the "hole" is two slits, and
// welding its coincident corners zips both; the grid is whole again, with no face added.
TEST(FillHoles, AHoleOfTwoCutEdgesIsZippedShut) {
  Point corner, below;
  Mesh mesh = grid_cut_at_a_corner({{2, 1}, {2, 2}}, {-1, -1}, corner, below);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  ASSERT_EQ(count_border_cycles(mesh), 2u);
  const std::size_t vertices_before = mesh.number_of_vertices();
  const std::size_t faces_before = mesh.number_of_faces();
  const MR::Fill_result result = MR::fill_holes(mesh);
  EXPECT_EQ(result.filled, 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(count_border_cycles(mesh), 1u);
  EXPECT_EQ(mesh.number_of_vertices(), vertices_before - 1);
  EXPECT_EQ(mesh.number_of_faces(), faces_before);
  EXPECT_EQ(interior_edges_between(mesh, below, corner), 1u);
  EXPECT_EQ(interior_edges_between(mesh, corner, Point(2, 3, 0.05 * 2 * 3)), 1u);
}

// A closed fan of six triangles around an apex whose outline passes twice through one point (two
// distinct vertices there, both joined to the apex by inner edges). Welding them would join the
// apex to the weld by two edges, an edge of four faces in a file: the weld is refused, and
// whatever the methods do, no two edges join the same two vertices.
TEST(FillHoles, APinchWhoseWeldWouldDoubleAnEdgeIsNotWelded) {
  Mesh mesh;
  const auto apex = mesh.add_vertex(Point(0, 0, 1));
  const std::vector<Point> ring{{1, 0, 0}, {0.5, 1, 0},   {-0.5, 1, 0},
                                {1, 0, 0}, {-0.5, -1, 0}, {0.5, -1, 0}};
  std::vector<Mesh::Vertex_index> around;
  for (const Point& p : ring) around.push_back(mesh.add_vertex(p));
  for (std::size_t i = 0; i < 6; ++i)
    ASSERT_NE(mesh.add_face(apex, around[i], around[(i + 1) % 6]), Mesh::null_face());
  MR::fill_holes(mesh, MR::parameters::sheet_border_ratio(std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  std::set<std::pair<Mesh::Vertex_index, Mesh::Vertex_index>> joined;
  for (auto e : edges(mesh)) {
    const Mesh::Vertex_index s = source(e, mesh), t = target(e, mesh);
    const std::pair<Mesh::Vertex_index, Mesh::Vertex_index> ends(std::min(s, t), std::max(s, t));
    EXPECT_TRUE(joined.insert(ends).second)
        << "two edges join " << ends.first << " and " << ends.second;
  }
}

TEST(FillHoles, TheOutlineOfAnOpenSheetIsLeftOpenAndItsHoleFilled) {
  Mesh mesh = bumpy_sheet(60);
  punch_hole(mesh, Point(0.2, -0.1, 0.1 * std::sin(0.6) * std::cos(-0.2)), 0.25);
  ASSERT_EQ(count_border_cycles(mesh), 2u);
  // Live faces: num_faces of a Surface_mesh also counts removed ones, whose slots a patch reuses.
  const std::size_t faces_before = mesh.number_of_faces();
  const MR::Fill_result result = MR::fill_holes(mesh);
  EXPECT_EQ(result.filled, 1u);
  EXPECT_EQ(result.skipped, 1u);
  EXPECT_EQ(result.sheet_borders, 1u);
  EXPECT_EQ(count_border_cycles(mesh), 1u);
  std::size_t sheet_reports = 0;
  for (const MR::Hole_fill_report& hole : result.holes) {
    if (!hole.sheet_border) continue;
    ++sheet_reports;
    EXPECT_EQ(hole.border_edges, 240u);
    EXPECT_NE(hole.failure.find("open sheet"), std::string::npos) << hole.failure;
  }
  EXPECT_EQ(sheet_reports, 1u);
  EXPECT_GT(mesh.number_of_faces(), faces_before);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_FALSE(support::does_self_intersect(mesh));
}

TEST(FillHoles, InfiniteSheetBorderRatioHandsTheOutlineToTheMethods) {
  // A shallow cap of the unit sphere (30 degrees): its outline bounds 0.93 of its area. With the
  // rule off it is a hole like any other and every method is tried on it.
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  punch_hole(mesh, Point(0, 0, -1), std::sqrt(2.0 * (1 + std::cos(CGAL_PI / 6))));
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  Mesh kept = mesh;
  const MR::Fill_result by_default = MR::fill_holes(kept);
  EXPECT_EQ(by_default.sheet_borders, 1u);
  EXPECT_EQ(count_border_cycles(kept), 1u);
  const MR::Fill_result result = MR::fill_holes(
      mesh, MR::parameters::sheet_border_ratio(std::numeric_limits<double>::infinity()));
  EXPECT_EQ(result.sheet_borders, 0u);
  EXPECT_EQ(result.skipped, 0u);
  EXPECT_EQ(result.filled + result.failed, 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST(FillHoles, AHemisphereSizedHoleIsStillFilled) {
  Mesh mesh = sphere_with_hole(1.3, 4);
  const MR::Fill_result result = MR::fill_holes(mesh);
  EXPECT_EQ(result.sheet_borders, 0u);
  EXPECT_EQ(result.filled, 1u);
  EXPECT_TRUE(closed_valid_and_clean(mesh));
}

/// The cube [0, 2]^3 of 4 x 4 grids without the faces of its bottom, lowered by `dip` at one
/// bottom corner (0: the border is planar).
Mesh box_open_underneath(double dip) {
  Mesh box;
  MR::make_subdivided_cube<Mesh, Point>(box, 2.0, 4);
  support::remove_faces_in_plane_z(box, 0);
  for (auto v : box.vertices())
    if (box.point(v) == Point(0, 0, 0)) box.point(v) = Point(0, 0, -dip);
  return box;
}

// A box without its bottom (a CAD part that lost a face): the border lies in one plane and the
// walls leave it at 90 degrees. Every faired candidate continues the walls into a bowl below the
// box; the flat membrane comes first and gives the box back: its area and volume exactly.
TEST(FillHoles, AMissingPlanarFaceOfABoxIsFilledFlat) {
  Mesh box = box_open_underneath(0);
  const MR::Fill_result result = MR::fill_holes(box);
  ASSERT_EQ(result.filled, 1u);
  EXPECT_TRUE(closed_valid_and_clean(box));
  EXPECT_EQ(result.holes[0].used, MR::Fill_method::liepa);
  EXPECT_TRUE(note_starts_with(result.holes[0], "a missing planar face"));
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::area(box), 24.0, 1e-9);
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(box), 8.0, 1e-9);

  // One corner lowered by a thousandth: not planar, so the validated order, whose faired patch
  // bulges below the box.
  Mesh bent = box_open_underneath(1e-3);
  const MR::Fill_result validated = MR::fill_holes(bent);
  ASSERT_EQ(validated.filled, 1u);
  EXPECT_TRUE(note_starts_with(validated.holes[0], "self-validation"));
  EXPECT_GT(CGAL::Polygon_mesh_processing::volume(bent), 8.1);
}

/// A courtyard building on flat ground, as a height field over [-1,1]^2 (n x n cells): ground at
/// 0 out to the outline, a roof ring at 0.6, a courtyard sunk to -0.3; the outline jagged by up
/// to 0.01. Like a reconstructed building on its patch of terrain, the surface lies on both sides
/// of the outline's plane and runs along it: any surface spanning the outline crosses it.
Mesh courtyard_on_ground(int n) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, -1, 1, -1, 1, n, n, [](double x, double y) {
    const double r = std::max(std::abs(x), std::abs(y));
    if (r > 0.999) return 0.01 * std::sin(23 * x + 17 * y);
    return r > 0.8 ? 0.0 : r > 0.5 ? 0.6 : -0.3;
  });
  return mesh;
}

// Every spanning patch, faired, Liepa's or projected, meets the ground or the courtyard; the
// outline is extruded straight down to a flat base below the courtyard and closed there.
TEST(FillHoles, AnOutlineTheSurfaceDipsBelowIsClosedByABase) {
  Mesh mesh = courtyard_on_ground(40);
  ASSERT_EQ(count_border_cycles(mesh), 1u);
  double lowest = 0;
  for (auto v : mesh.vertices()) lowest = std::min(lowest, mesh.point(v).z());
  const MR::Fill_result result = MR::fill_holes(mesh);
  ASSERT_EQ(result.holes.size(), 1u);
  const MR::Hole_fill_report& hole = result.holes[0];
  ASSERT_TRUE(hole.filled) << hole.failure;
  EXPECT_EQ(hole.notes.back(),
            "filled by base: the patches of the methods before it were rejected");
  EXPECT_TRUE(closed_valid_and_clean(mesh));
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::does_bound_a_volume(mesh));
  // The base lies one mean border edge (0.05) below the courtyard, walls straight down.
  double base = 0;
  for (auto v : mesh.vertices()) base = std::min(base, mesh.point(v).z());
  EXPECT_LT(base, lowest - 0.04);
  EXPECT_GT(base, lowest - 0.07);
}

// Liepa's method alone leaves the courtyard's outline open (its patches cross the ground);
// with `then_last_resorts`, as automatic_repair fills its grown holes, the base closes it and the
// report lists the rejected Liepa patch first.
TEST(FillHoles, LiepaThenLastResortsClosesWhatLiepaAloneLeavesOpen) {
  for (const bool last_resorts : {false, true}) {
    Mesh mesh = courtyard_on_ground(40);
    MR::Fill_options options;
    options.method = MR::Fill_method::liepa;
    options.liepa.then_last_resorts = last_resorts;
    std::vector<MR::Fill_patch<Mesh>> patches;
    MR::Default_visitor quiet;
    const MR::Fill_result result = MR::internal::fill_holes_with_options(
        mesh, mesh.points(), Kernel(), options, MR::Any_visitor(quiet), patches);
    ASSERT_EQ(result.holes.size(), 1u);
    const MR::Hole_fill_report& hole = result.holes[0];
    EXPECT_EQ(hole.filled, last_resorts) << hole.failure;
    EXPECT_EQ(closed_valid_and_clean(mesh), last_resorts);
    if (!last_resorts) continue;
    ASSERT_FALSE(hole.fallbacks.empty());
    EXPECT_EQ(hole.fallbacks.front().rfind("liepa_c1 (", 0), 0u) << hole.fallbacks.front();
    EXPECT_EQ(hole.notes.back(),
              "filled by base: the patches of the methods before it were rejected");
  }
}

// The projected triangulation of a flat outline: no new vertex, n - 2 triangles in the plane, and
// the mesh closed (the triangles lie on the sheet's own faces: that is for the caller's check).
TEST(FillHoles, ProjectedTriangulationOfAnOutlineAddsOnlyTheBorderTriangles) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, 0, 2, 0, 1, 8, 4, [](double, double) { return 0.0; });
  const std::vector<Mesh::Halfedge_index> borders = support::boundary_cycles(mesh);
  ASSERT_EQ(borders.size(), 1u);
  const std::size_t n = CGAL::halfedges_around_face(borders[0], mesh).size();
  std::vector<face_descriptor> faces;
  EXPECT_EQ(
      MR::internal::triangulate_projected_border(mesh, mesh.points(), Kernel(), borders[0], faces),
      "");
  EXPECT_EQ(faces.size(), n - 2);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  for (face_descriptor f : faces)
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      EXPECT_EQ(mesh.point(v).z(), 0.0);
}

// The reach of a patch: a pyramid over the square border (+-1, +-1, 0), its apex the one new
// vertex, reaches height / sqrt(2) border radii; a bag (height 5) is past the limit, a cap not.
TEST(FillHoles, APatchReachIsMeasuredInBorderRadii) {
  for (const double height : {1.0, 5.0}) {
    Mesh mesh;
    const auto a = mesh.add_vertex(Point(-1, -1, 0)), b = mesh.add_vertex(Point(1, -1, 0)),
               c = mesh.add_vertex(Point(1, 1, 0)), d = mesh.add_vertex(Point(-1, 1, 0)),
               apex = mesh.add_vertex(Point(0, 0, height));
    MR::Fill_patch<Mesh> patch;
    patch.faces = {mesh.add_face(a, b, apex), mesh.add_face(b, c, apex), mesh.add_face(c, d, apex),
                   mesh.add_face(d, a, apex)};
    patch.vertices = {apex};
    const double reach =
        MR::internal::patch_reach_in_border_radii(mesh, patch, get(CGAL::vertex_point, mesh));
    EXPECT_NEAR(reach, height / std::sqrt(2.0), 1e-12);
    EXPECT_EQ(reach > MR::internal::max_patch_reach_in_border_radii, height > 3.0 * std::sqrt(2.0));
  }
}

}  // namespace

namespace {

// CGAL's triangulation alone, the coarsest last resort, adds no vertex: n - 2 triangles.
TEST(FillHoles, LiepaTriangulationStageAddsOnlyTheBorderTriangles) {
  Mesh mesh = sphere_with_hole(0.5);
  const std::vector<Mesh::Halfedge_index> borders = support::boundary_cycles(mesh);
  ASSERT_EQ(borders.size(), 1u);
  const std::size_t n = CGAL::halfedges_around_face(borders[0], mesh).size();
  MR::Fill_patch<Mesh> patch;
  MR::Liepa_options options;
  options.last_stage = MR::Liepa_stage::triangulate;
  const MR::Hole_fill_report report = MR::internal::fill_hole_liepa(
      mesh, get(CGAL::vertex_point, mesh), Kernel(), borders[0], patch, options);
  EXPECT_TRUE(report.filled) << report.failure;
  EXPECT_EQ(patch.vertices.size(), 0u);
  EXPECT_EQ(patch.faces.size(), n - 2);
  EXPECT_TRUE(closed_valid_and_clean(mesh));
}

// CGAL's triangulation of a hole is remembered per thread (remembered_triangulation.h): the
// next fill of the same hole, entered at the same halfedge, takes it from memory, and must build
// the very faces and halfedges that a search of its own builds (here: in a thread whose memory
// is empty).
TEST(FillHoles, ARememberedLiepaTriangulationBuildsTheSameMeshAsAFreshSearch) {
  const Mesh input = sphere_with_hole(0.5);
  const auto fill = [](Mesh& mesh) {
    const std::vector<Mesh::Halfedge_index> borders = support::boundary_cycles(mesh);
    MR::Fill_patch<Mesh> patch;
    return MR::internal::fill_hole_liepa(mesh, get(CGAL::vertex_point, mesh), Kernel(),
                                         borders.at(0), patch, MR::Liepa_options());
  };
  MR::internal::Hole_triangulation_key<Point> key;
  std::vector<Mesh::Halfedge_index> sides;
  ASSERT_TRUE(MR::internal::hole_triangulation_key(input, support::boundary_cycles(input).at(0),
                                                   get(CGAL::vertex_point, input), key, sides));
  ASSERT_GE(sides.size(), MR::internal::min_remembered_border_edges);

  Mesh fresh = input;
  bool fresh_filled = false, remembered_in_thread = false;
  std::thread([&] {
    fresh_filled = fill(fresh).filled;
    remembered_in_thread =
        MR::internal::remembered_triangulations_of_this_thread<Point>().find(key) != nullptr;
  }).join();
  EXPECT_TRUE(fresh_filled);
  EXPECT_TRUE(remembered_in_thread);

  const auto& memory = MR::internal::remembered_triangulations_of_this_thread<Point>();
  Mesh first = input, second = input;
  EXPECT_TRUE(fill(first).filled);
  ASSERT_NE(memory.find(key), nullptr);
  const std::size_t entries = memory.entries.size();
  EXPECT_TRUE(fill(second).filled);
  EXPECT_EQ(memory.entries.size(), entries);  // taken from memory, not searched again
  EXPECT_TRUE(elements(first) == elements(fresh));
  EXPECT_TRUE(elements(second) == elements(fresh));
  EXPECT_TRUE(closed_valid_and_clean(second));
}

// The mouth of a paraboloid bowl over a square: a saddle-shaped border of 1,004 edges, above
// the large-hole limit. Every faired patch folds there; the coarser last resorts close it.
TEST(FillHoles, ALargeSaddleHoleGoesToTheLastResortsAndIsClosed) {
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, -1, 1, -1, 1, 251, 251,
                                     [](double x, double y) { return 1.5 * (x * x + y * y); });
  const std::size_t faces_before = mesh.number_of_faces();
  const MR::Fill_result result = MR::fill_holes(mesh);
  ASSERT_EQ(result.holes.size(), 1u);
  const MR::Hole_fill_report& hole = result.holes[0];
  EXPECT_TRUE(hole.filled) << hole.failure;
  EXPECT_EQ(hole.used, MR::Fill_method::liepa);
  ASSERT_FALSE(hole.notes.empty());
  EXPECT_NE(hole.notes.front().find("a large hole (1004 border edges"), std::string::npos)
      << hole.notes.front();
  EXPECT_LE(hole.fallbacks.size(), 2u);  // C0, then refined: no other method was tried
  EXPECT_GT(mesh.number_of_faces(), faces_before);
  EXPECT_TRUE(closed_valid_and_clean(mesh));
}

}  // namespace
