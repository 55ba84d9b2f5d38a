// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Timing and comparison tables of stitch_gaps, repair_t_junctions and remove_slivers
// (doc/benchmarks.md "## stitch_gaps", doc/stitch_gaps.md, doc/remove_slivers.md).
//   bench_stitch speed [BORDER_VERTICES...]   stitching time on strips separated by gaps
//   bench_stitch tables                        the thesis-figure cases, ours against CGAL's
#include "support/stitch_test_meshes.h"

#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/remove_slivers.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/merge_border_vertices.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

namespace {
using namespace stitch_test;
namespace MR = CGAL::Mesh_repair;
namespace PMP = CGAL::Polygon_mesh_processing;

double seconds_of(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Horizontal strips one cell high, `columns` cells long, separated by gaps of 0.05 (cell = 1);
/// every other strip is shifted by 0.1 along x so nodes do not match. All nodes are border nodes.
Mesh strips(std::size_t border_vertices, int columns) {
  Mesh mesh;
  const std::size_t strip_count = std::max<std::size_t>(2, border_vertices / (2 * (columns + 1)));
  mesh.reserve(strip_count * 2 * (columns + 1), strip_count * 5 * columns,
               strip_count * 2 * columns);
  CGAL::Random random(1);
  for (std::size_t s = 0; s < strip_count; ++s) {
    const double shift = (s % 2) ? 0.1 : 0.0;
    std::vector<vertex_descriptor> bottom, top;
    for (int i = 0; i <= columns; ++i) {
      const double x = i + shift;
      bottom.push_back(mesh.add_vertex(Point(x, s + 0.025, random.get_double(-0.01, 0.01))));
      top.push_back(mesh.add_vertex(Point(x, s + 0.975, random.get_double(-0.01, 0.01))));
    }
    for (int i = 0; i < columns; ++i) {
      mesh.add_face(bottom[i], bottom[i + 1], top[i + 1]);
      mesh.add_face(bottom[i], top[i + 1], top[i]);
    }
  }
  return mesh;
}

/// Prints the time of every step of the operator (start_step/end_step of the visitor).
struct Step_timer {
  std::chrono::steady_clock::time_point start;
  std::string summary;
  void start_step(const char*) { start = std::chrono::steady_clock::now(); }
  bool progress(double) { return true; }
  void end_step(const char* name) {
    char text[128];
    std::snprintf(text, sizeof text, "%s %.3f s; ", name,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    summary += text;
  }
};

void speed(const std::vector<std::size_t>& sizes) {
  std::printf(
      "| border vertices | faces | stitch_gaps (s) | node merges | T-junctions | edges glued | "
      "border cycles after |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (std::size_t n : sizes) {
    double best = 1e30;
    MR::Stitch_result result;
    Mesh last;
    for (int run = 0; run < 3; ++run) {
      Mesh mesh = strips(n, 1000);
      Step_timer timer;
      const double t = seconds_of([&] {
        result =
            MR::stitch_gaps(mesh, MR::parameters::merge_tolerance(0.25).visitor(std::ref(timer)));
      });
      std::fprintf(stderr, "%zu: %s\n", n, timer.summary.c_str());
      best = std::min(best, t);
      if (run == 2) last = std::move(mesh);
    }
    std::printf("| %zu | %zu | %.3f | %zu | %zu | %zu | %zu |\n", result.border_nodes,
                std::size_t(last.number_of_faces()), best, result.node_merges,
                result.t_junctions_split, result.edges_stitched, border_cycle_count(last));
  }
}

struct Case {
  std::string name;
  Mesh mesh;
  double tolerance;  // negative: derived
};

std::vector<Case> stitch_cases() {
  std::vector<Case> cases;
  cases.push_back({"cube, 6 separate faces, non-matching nodes, gap 0.014 (Fig 4.16)",
                   to_mesh(cube_of_separate_faces(0.01, {3, 4, 5, 4, 3, 6})), -1});
  cases.push_back({"cube, 6 separate faces, matching nodes, gap 0.014",
                   to_mesh(cube_of_separate_faces(0.01, {4, 4, 4, 4, 4, 4})), -1});
  cases.push_back({"cube, 6 faces with exactly coincident borders",
                   to_mesh(cube_of_separate_faces(0.0, {3, 4, 5, 4, 3, 6})), -1});
  cases.push_back({"curved patches, 7 vs 11 nodes, gap 0.01 (Fig 4.8)",
                   to_mesh(curved_patches(7, 11, 0.01)), -1});
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  cases.push_back({"sphere cut in 6 patches, jitter <= 0.02",
                   to_mesh(cut_and_jitter(sphere, 6, 0.02, 1)), 0.02});
  Mesh with_t = to_mesh(cut_and_jitter(sphere, 5, 0.01, 7));
  split_border_edges(with_t, 3);
  cases.push_back({"sphere cut in 5 patches, jitter <= 0.01, T-joints", std::move(with_t), 0.01});
  Mesh with_holes = to_mesh(cut_and_jitter(sphere, 8, 0.015, 11));
  split_border_edges(with_holes, 4);
  CGAL::Euler::remove_face(halfedge(*faces(with_holes).begin(), with_holes), with_holes);
  cases.push_back(
      {"sphere soup: gaps, overlaps, T-joints, 1 hole (Fig 4.17)", std::move(with_holes), 0.015});
  const std::string data = MESH_REPAIR_DEMO_DATA_DIR;
  Mesh quads;
  if (std::filesystem::exists(data + "/quads_to_stitch.off") &&
      CGAL::IO::read_polygon_mesh(data + "/quads_to_stitch.off", quads)) {
    PMP::triangulate_faces(quads);
    cases.push_back({"quads_to_stitch.off (libcgal-demo, triangulated)", std::move(quads), -1});
  }
  Mesh elephant;
  if (std::filesystem::exists(data + "/elephant.off") &&
      CGAL::IO::read_polygon_mesh(data + "/elephant.off", elephant)) {
    double shortest = 1e30;
    for (auto e : edges(elephant))
      shortest = std::min(shortest, std::sqrt(PMP::squared_edge_length(e, elephant)));
    cases.push_back({"elephant.off cut in 6 patches, jitter <= 0.3 shortest edge",
                     to_mesh(cut_and_jitter(elephant, 6, 0.3 * shortest, 5)), 0.3 * shortest});
  }
  return cases;
}

void stitch_table() {
  std::printf(
      "| case | method | closed | manifold | border cycles before -> after | faces before -> after "
      "| max displacement | time (ms) |\n");
  std::printf("|---|---|---|---|---|---|---:|---:|\n");
  for (const Case& c : stitch_cases()) {
    const std::size_t cycles = border_cycle_count(c.mesh), faces_before = c.mesh.number_of_faces();
    auto row = [&](const char* method, const Mesh& m, double displacement, double t) {
      std::printf("| %s | %s | %s | %s | %zu -> %zu | %zu -> %zu | %.3g | %.1f |\n", c.name.c_str(),
                  method, CGAL::is_closed(m) ? "yes" : "no",
                  non_manifold_vertex_count(m) == 0 ? "yes" : "no", cycles, border_cycle_count(m),
                  faces_before, std::size_t(m.number_of_faces()), displacement, 1000 * t);
    };
    Mesh ours = c.mesh;
    MR::Stitch_result result;
    const double t_ours = seconds_of([&] {
      result = c.tolerance > 0 ? MR::stitch_gaps(ours, MR::parameters::merge_tolerance(c.tolerance))
                               : MR::stitch_gaps(ours);
    });
    row("stitch_gaps", ours, result.max_displacement, t_ours);
    Mesh cgal = c.mesh;
    const double t_cgal = seconds_of([&] {
      PMP::stitch_borders(cgal);
      PMP::merge_duplicated_vertices_in_boundary_cycles(cgal);
    });
    row("CGAL stitch_borders + merge_duplicated_vertices_in_boundary_cycles", cgal, 0.0, t_cgal);
  }
}

struct Sliver_stats {
  std::size_t slivers = 0;
  double min_f = 1;
};

Sliver_stats sliver_stats(const Mesh& mesh) {
  Sliver_stats s;
  for (auto f : faces(mesh)) {
    auto h = halfedge(f, mesh);
    const double value = MR::shape_factor(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                          mesh.point(target(next(h, mesh), mesh)));
    s.min_f = std::min(s.min_f, value);
    if (value < 0.7) ++s.slivers;
  }
  return s;
}

std::vector<Case> sliver_cases() {
  std::vector<Case> cases;
  Soup grid;
  add_grid_patch(grid, Point(0, 0, 0), Vector(6, 0, 0), Vector(0, 6, 0), 6, 6);
  Mesh needle = to_mesh(grid);
  for (auto v : vertices(needle))
    if (needle.point(v) == Point(3, 3, 0)) needle.point(v) = Point(3.97, 3, 0);
  cases.push_back({"flat grid, node 0.03 from its neighbour (Fig 4.13)", std::move(needle), -1});
  Mesh cap = to_mesh(grid);
  for (auto v : vertices(cap))
    if (cap.point(v) == Point(2, 2, 0)) cap.point(v) = Point(2.45, 1.55, 0);
  cases.push_back({"flat grid, node near a diagonal: cap (Fig 4.14)", std::move(cap), -1});
  Mesh cube = to_mesh(cube_of_separate_faces(0.01, {3, 4, 5, 4, 3, 6}));
  MR::stitch_gaps(cube);
  cases.push_back({"cube of Fig 4.16 after stitch_gaps (T-junction slivers)", std::move(cube), -1});
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  CGAL::Random random(3);
  for (auto v : vertices(sphere)) {
    if (random.get_double() > 0.3) continue;
    const Point q =
        sphere.point(v) +
        0.06 * Vector(random.get_double(-1, 1), random.get_double(-1, 1), random.get_double(-1, 1));
    sphere.point(v) =
        CGAL::ORIGIN + (q - CGAL::ORIGIN) / std::sqrt((q - CGAL::ORIGIN).squared_length());
  }
  cases.push_back({"sphere, 30% of nodes jittered on the surface", std::move(sphere), -1});
  const std::string data = MESH_REPAIR_DEMO_DATA_DIR;
  Mesh fandisk;
  if (std::filesystem::exists(data + "/fandisk.off") &&
      CGAL::IO::read_polygon_mesh(data + "/fandisk.off", fandisk))
    cases.push_back({"fandisk.off (libcgal-demo)", std::move(fandisk), -1});
  return cases;
}

double max_distance(const Mesh& mesh, const Mesh& reference) {
  std::vector<Point> points;
  for (auto v : vertices(mesh)) points.push_back(mesh.point(v));
  return PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(points, reference);
}

void sliver_table() {
  std::printf(
      "| case | method | slivers (f < 0.7) before -> after | min f before -> after | faces before "
      "-> after | valid | self-intersects | max distance to input | time (ms) |\n");
  std::printf("|---|---|---|---|---|---|---|---:|---:|\n");
  for (const Case& c : sliver_cases()) {
    const Sliver_stats before = sliver_stats(c.mesh);
    const bool intersected = self_intersects(c.mesh);
    auto row = [&](const char* method, const Mesh& m, double t) {
      const Sliver_stats after = sliver_stats(m);
      std::printf(
          "| %s | %s | %zu -> %zu | %.3f -> %.3f | %zu -> %zu | %s | %s -> %s | %.3g | %.1f |\n",
          c.name.c_str(), method, before.slivers, after.slivers, before.min_f, after.min_f,
          std::size_t(c.mesh.number_of_faces()), std::size_t(m.number_of_faces()),
          CGAL::is_valid_polygon_mesh(m) ? "yes" : "no", intersected ? "yes" : "no",
          self_intersects(m) ? "yes" : "no", max_distance(m, c.mesh), 1000 * t);
    };
    Mesh ours = c.mesh;
    const double t_ours = seconds_of([&] { MR::remove_slivers(ours); });
    row("remove_slivers", ours, t_ours);
    Mesh degenerate = c.mesh;
    const double t_degenerate = seconds_of([&] { PMP::remove_degenerate_faces(degenerate); });
    degenerate.collect_garbage();
    row("CGAL remove_degenerate_faces", degenerate, t_degenerate);
    Mesh almost = c.mesh;
    // CGAL's defaults in its own tests: caps above 160 degrees, needles longer than 4x, no
    // collapse length bound; the same 135-degree feature notion is not available there.
    const double t_almost = seconds_of([&] {
      PMP::experimental::remove_almost_degenerate_faces(almost, std::cos(160.0 / 180.0 * CGAL_PI),
                                                        4, 0);
    });
    almost.collect_garbage();
    row("CGAL experimental::remove_almost_degenerate_faces(cos 160deg, 4, 0)", almost, t_almost);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "speed";
  if (mode == "tables") {
    std::printf("### stitching\n\n");
    stitch_table();
    std::printf("\n### slivers\n\n");
    sliver_table();
    return 0;
  }
  std::vector<std::size_t> sizes;
  for (int i = 2; i < argc; ++i) sizes.push_back(std::stoul(argv[i]));
  if (sizes.empty()) sizes = {10000, 100000, 1000000};
  speed(sizes);
  return 0;
}
