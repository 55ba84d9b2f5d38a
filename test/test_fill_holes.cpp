// Hole filling: the dispatcher, advancing front, CGAL's Liepa, ring holes, pinched borders, the
// exact patch check and its rollback (fill_holes.h).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include "hole_punching.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using face_descriptor = Mesh::Face_index;
namespace MR = CGAL::Mesh_repair;
namespace PMP = CGAL::Polygon_mesh_processing;
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
         !PMP::does_self_intersect(mesh);
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
  std::vector<std::pair<face_descriptor, face_descriptor>> pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
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
  for (MR::Fill_method method :
       {MR::Fill_method::advancing_front, MR::Fill_method::liepa, MR::Fill_method::automatic}) {
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
    std::vector<std::size_t> component(num_faces(filled) + filled.number_of_removed_faces());
    EXPECT_EQ(PMP::connected_components(filled, CGAL::make_property_map(component)), 1u);
  }
}

TEST(FillHoles, RingHoleDetectionCanBeTurnedOff) {
  Mesh mesh = sphere_with_ring_hole();
  const MR::Fill_result result = MR::fill_holes(
      mesh, MR::parameters::fill_method(MR::Fill_method::liepa).detect_ring_holes(false));
  EXPECT_EQ(result.holes.size(), 2u);
  for (const auto& hole : result.holes) EXPECT_EQ(hole.island_cycles, 0u);
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
  const MR::Fill_result result =
      MR::fill_holes(sheet, MR::parameters::fill_method(MR::Fill_method::liepa));
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_FALSE(result.holes[0].filled);
  EXPECT_NE(result.holes[0].failure.find("self-intersect"), std::string::npos)
      << result.holes[0].failure;
  EXPECT_EQ(result.holes[0].faces_created, 0u);
  EXPECT_EQ(sheet.number_of_faces(), faces_before);
  EXPECT_EQ(sheet.number_of_vertices(), vertices_before);
  EXPECT_EQ(count_border_cycles(sheet), 1u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(sheet));
  EXPECT_FALSE(PMP::does_self_intersect(sheet));
}

TEST(FillHoles, AutomaticRecordsTheFallbackWhenTheFrontFails) {
  Mesh sheet;
  MR::make_height_field<Mesh, Point>(sheet, 0, 1, 0, 1, 6, 6, [](double, double) { return 0.0; });
  const MR::Fill_result result = MR::fill_holes(sheet);
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_EQ(result.holes[0].requested, MR::Fill_method::automatic);
  EXPECT_EQ(result.holes[0].fallbacks.size(), 2u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(sheet));
}

void expect_demo_mesh_filled(const std::string& name) {
  const fs::path path = fs::path(MESH_REPAIR_DEMO_DATA_DIR) / name;
  if (!fs::exists(path)) GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  Mesh mesh;
  MR::Soup_repair_report soup;
  ASSERT_EQ(MR::read_mesh(path.string(), mesh, soup), "");
  const std::size_t original_faces = num_faces(mesh);
  ASSERT_GT(count_border_cycles(mesh), 0u);
  const MR::Fill_result result = MR::fill_holes(mesh);
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

#ifdef MESH_REPAIR_CLI
TEST(FillCli, FillsASphereHoleExitsZeroAndWritesOneReportEntryPerHole) {
  const fs::path dir =
      fs::temp_directory_path() / ("mesh_repair_fill_" + std::to_string(::getpid()));
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
#endif

}  // namespace
