// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The ground-truth hole benchmark: punching, metrics, and the `mesh_repair bench holes` command.
#include <CGAL/Mesh_repair/hole_benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "scratch_folder.h"
#include "support/cgal_calls.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace MR = CGAL::Mesh_repair;
namespace support = mesh_repair_test;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

std::size_t border_cycles(const Mesh& mesh) {
  return support::boundary_cycles(mesh).size();
}

Mesh analytic(MR::Analytic_surface surface) {
  Mesh mesh;
  MR::make_analytic_mesh(mesh, surface);
  return mesh;
}

double max_edge_length(const Mesh& mesh) {
  double longest = 0;
  for (auto e : edges(mesh))
    longest = std::max(longest, std::sqrt(CGAL::to_double(CGAL::squared_distance(
                                    mesh.point(source(e, mesh)), mesh.point(target(e, mesh))))));
  return longest;
}

TEST(HoleBenchmark, PunchingKDiscHolesOpensExactlyKBorderCyclesOfTheRequestedRadius) {
  Mesh mesh = analytic(MR::Analytic_surface::sphere);
  const double h = max_edge_length(mesh);
  const auto punched =
      MR::punch_holes(mesh, MR::parameters::number_of_holes(4).hole_radius(0.08).random_seed(3));
  ASSERT_EQ(punched.holes.size(), 4u) << punched.shortfall;
  EXPECT_EQ(border_cycles(mesh), 4u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  const double radius = 0.08 * punched.bbox_diagonal;
  for (const auto& hole : punched.holes) {
    EXPECT_NEAR(hole.requested_radius, radius, 1e-12);
    // The border lies within one edge length of the requested edge-path radius.
    EXPECT_NEAR(hole.achieved_radius, radius, h);
    // Border vertices lie near the sphere of that (Euclidean, so slightly smaller) radius.
    for (auto v : CGAL::vertices_around_face(hole.border_halfedge, mesh)) {
      const double d =
          std::sqrt(CGAL::to_double(CGAL::squared_distance(mesh.point(v), hole.centre)));
      EXPECT_LT(d, radius + h);
      EXPECT_GT(d, 0.7 * radius - h);
    }
    EXPECT_EQ(hole.removed_patch.number_of_faces(), hole.removed_faces);
    EXPECT_EQ(hole.border.size(), hole.outer_border_edges);
  }
}

TEST(HoleBenchmark, PunchingIsDeterministicForASeed) {
  Mesh a = analytic(MR::Analytic_surface::torus), b = a;
  const auto np = MR::parameters::number_of_holes(3).hole_radius(0.05).random_seed(11);
  const auto pa = MR::punch_holes(a, np), pb = MR::punch_holes(b, np);
  ASSERT_EQ(pa.holes.size(), pb.holes.size());
  for (std::size_t i = 0; i < pa.holes.size(); ++i) {
    EXPECT_EQ(pa.holes[i].centre, pb.holes[i].centre);
    EXPECT_EQ(pa.holes[i].removed_faces, pb.holes[i].removed_faces);
  }
}

TEST(HoleBenchmark, HolesOnAnOpenSaddleNeverTouchItsBorder) {
  Mesh mesh = analytic(MR::Analytic_surface::saddle);
  const std::size_t before = border_cycles(mesh);
  const auto punched =
      MR::punch_holes(mesh, MR::parameters::number_of_holes(3).hole_radius(0.06).random_seed(1));
  EXPECT_EQ(border_cycles(mesh), before + punched.holes.size());
  EXPECT_EQ(punched.holes.size(), 3u) << punched.shortfall;
}

TEST(HoleBenchmark, RingHoleLeavesAnIslandAndTwoBorderCycles) {
  Mesh mesh = analytic(MR::Analytic_surface::sphere);
  const auto punched = MR::punch_holes(mesh, MR::parameters::number_of_holes(1)
                                                 .hole_radius(0.12)
                                                 .hole_shape(MR::Hole_shape::ring)
                                                 .random_seed(5));
  ASSERT_EQ(punched.holes.size(), 1u) << punched.shortfall;
  EXPECT_EQ(punched.holes[0].island_border_halfedges.size(), 1u);
  EXPECT_EQ(border_cycles(mesh), 2u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

TEST(HoleBenchmark, JaggedAndElongatedHolesOpenOneBorderCycleEach) {
  for (MR::Hole_shape shape : {MR::Hole_shape::jagged, MR::Hole_shape::elongated}) {
    Mesh mesh = analytic(MR::Analytic_surface::sphere);
    const auto punched = MR::punch_holes(
        mesh, MR::parameters::number_of_holes(2).hole_radius(0.1).hole_shape(shape).random_seed(2));
    ASSERT_EQ(punched.holes.size(), 2u) << MR::to_string(shape) << ": " << punched.shortfall;
    EXPECT_EQ(border_cycles(mesh), 2u) << MR::to_string(shape);
  }
}

// Surface_mesh keeps descriptors through Euler::remove_face, so the unpunched copy is the mesh
// with every hole "filled" by its own removed patch.
TEST(HoleBenchmark, MetricsAreZeroWhenTheRemovedPatchIsPutBack) {
  Mesh original = analytic(MR::Analytic_surface::torus);
  Mesh mesh = original;
  const auto punched =
      MR::punch_holes(mesh, MR::parameters::number_of_holes(3).hole_radius(0.06).random_seed(4));
  ASSERT_EQ(punched.holes.size(), 3u);
  for (const auto& hole : punched.holes) {
    const auto m = MR::measure_filled_hole(original, hole, punched.bbox_diagonal);
    EXPECT_TRUE(m.filled);
    EXPECT_TRUE(m.closed);
    EXPECT_TRUE(m.bounded);
    EXPECT_EQ(m.patch_faces, hole.removed_faces);
    EXPECT_LT(m.einf, 1e-12);
    EXPECT_LT(m.hausdorff, 1e-12);
    EXPECT_LT(m.normal_deviation_max_deg, 1e-9);
  }
}

// The curvature jump across the contour (Pernot 7): about 0 for the sphere's own faces put back,
// about the sphere's mean curvature x diagonal (1 x 2 sqrt(3)) for a flat refined patch.
TEST(HoleBenchmark, CurvatureJumpIsSmallForTheTruthAndTheSphereCurvatureForAFlatPatch) {
  Mesh original = analytic(MR::Analytic_surface::sphere);
  Mesh mesh = original;
  const auto punched =
      MR::punch_holes(mesh, MR::parameters::number_of_holes(2).hole_radius(0.1).random_seed(8));
  ASSERT_EQ(punched.holes.size(), 2u);
  for (const auto& hole : punched.holes) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    support::triangulate_and_refine_hole(mesh, hole.border_halfedge, faces, vertices);
    ASSERT_GT(vertices.size(), 3u);
  }
  for (const auto& hole : punched.holes) {
    const double truth =
        MR::measure_filled_hole(original, hole, punched.bbox_diagonal).curvature_jump;
    const double flat = MR::measure_filled_hole(mesh, hole, punched.bbox_diagonal).curvature_jump;
    EXPECT_GT(flat, 2.0);
    EXPECT_LT(flat, 5.0);
    EXPECT_LT(truth, 0.1 * flat);
  }
}

TEST(HoleBenchmark, ErrorNormsAreOrderedE1AtMostE2AtMostEinfAfterLiepaFill) {
  Mesh mesh = analytic(MR::Analytic_surface::sphere);
  const auto punched =
      MR::punch_holes(mesh, MR::parameters::number_of_holes(2).hole_radius(0.1).random_seed(8));
  ASSERT_EQ(punched.holes.size(), 2u);
  const auto exact = MR::analytic_distance<Point>(MR::Analytic_surface::sphere);
  std::vector<std::vector<Mesh::Face_index>> patches;
  for (const auto& hole : punched.holes) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    support::triangulate_refine_and_fair_hole(mesh, hole.border_halfedge, faces, vertices);
    patches.push_back(faces);
  }
  EXPECT_TRUE(CGAL::is_closed(mesh));
  const auto intersections = MR::count_patch_self_intersections(mesh, patches);
  for (std::size_t i = 0; i < punched.holes.size(); ++i) {
    const auto m = MR::measure_filled_hole(mesh, punched.holes[i], punched.bbox_diagonal, exact);
    EXPECT_TRUE(m.closed);
    EXPECT_EQ(m.patch_faces, patches[i].size());
    EXPECT_LE(m.e1, m.e2);
    EXPECT_LE(m.e2, m.einf);
    EXPECT_LE(m.e1_nodes, m.e2_nodes);
    EXPECT_LE(m.e2_nodes, m.einf_nodes);
    EXPECT_GT(m.einf, 0);
    // A faired patch on a unit sphere stays within a few percent of the radius.
    EXPECT_LT(m.einf_rel, 0.05);
    EXPECT_GT(m.min_alpha, 0);
    EXPECT_EQ(intersections[i], 0u);
  }
}

#ifdef MESH_REPAIR_CLI
TEST(HoleBenchmarkCli, SphereWithLiepaWritesOneResultLinePerHoleMethodAndSeed) {
  // In the process's scratch folder, removed when the suite exits.
  const std::string out =
      (mesh_repair_test::scratch_folder("mesh_repair_test_hole_benchmark_") / "bench_holes_cli")
          .string();
  const std::string command = std::string(MESH_REPAIR_CLI) +
                              " bench holes --analytic sphere --holes 2 --radius 0.05 --seeds "
                              "1,2 --methods liepa --no-plots --no-pictures --quiet --out " +
                              out;
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream results(out + "/results.jsonl");
  ASSERT_TRUE(results.good());
  std::size_t lines = 0;
  for (std::string line; std::getline(results, line);) {
    if (line.empty()) continue;
    ++lines;
    EXPECT_NE(line.find("\"method\":\"liepa\""), std::string::npos);
    EXPECT_NE(line.find("\"closed\":true"), std::string::npos);
  }
  EXPECT_EQ(lines, 2u * 2u);  // 2 holes x 1 method x 2 seeds
  std::ifstream table_file(out + "/table.md");
  ASSERT_TRUE(table_file.good());
  std::stringstream table;
  table << table_file.rdbuf();
  // Every hole is closed by the only method, so the same-hole medians cover all 4.
  EXPECT_NE(table.str().find("Medians over the 4 holes closed by every method"), std::string::npos)
      << table.str();
}
#endif

}  // namespace
