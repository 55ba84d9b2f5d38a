// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair smooth: micro-GA smoothing on the rebuilt G1 surface (Chen et al.), the paper's
// conjugate-gradient baseline, or CGAL's angle_and_area_smoothing + tangential_relaxation, with
// the same quality and distance measures for all three.
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/mga_smooth.h>
#include <CGAL/Mesh_repair/triangles_to_quads.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <ctime>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const smooth_help =
    "usage: mesh_repair smooth IN -o OUT [--method mga|cg|cgal] [--quads] [--iterations N]\n"
    "                         [--seed S] [--threads N] [--generations G] [--feature-angle DEG]\n"
    "                         [--tangent-scale S] [--slide-feature-nodes] [--report R.json]\n"
    "                         [--quiet]\n"
    "  mga   micro-genetic node smoothing on a G1 surface rebuilt from IN (Chen et al.)\n"
    "  cg    the same with a conjugate-gradient search per node (the paper's baseline)\n"
    "  cgal  CGAL's angle_and_area_smoothing then tangential_relaxation (triangles only)\n"
    "  --quads converts IN to quads first (best-beta pairs, node elimination, edge swaps).\n"
    "  Quality is alpha (triangles) / beta (quads); --iterations is the number of sweeps\n"
    "  (default 3 for mga/cg, 1 for cgal); the report's `seconds` times the smoothing only.\n"
    "  --tangent-scale S (mga/cg): the surface's boundary curves keep S times their end\n"
    "  tangents: 0 = the input triangles, 1 = the full G1 surface, which bulges about 1/S\n"
    "  times as far off the input; default 0.45 (doc/mga_smooth.md). --cubic-weight is its\n"
    "  deprecated name. --slide-feature-nodes (mga/cg): nodes inside a feature line slide\n"
    "  along it instead of staying fixed (joints, corners and line ends stay fixed).\n";

namespace {

namespace MR = CGAL::Mesh_repair;

struct Quality {
  double worst = 1, mean = 0;
  std::size_t triangles = 0, quads = 0, others = 0;
};

Quality measure_quality(const Mesh& mesh) {
  Quality q;
  double sum = 0;
  for (auto f : faces(mesh)) {
    std::vector<Point> corners;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) corners.push_back(mesh.point(v));
    double value;
    if (corners.size() == 3) {
      value = MR::alpha(corners[0], corners[1], corners[2]);
      ++q.triangles;
    } else if (corners.size() == 4) {
      value = MR::quad_beta(corners[0], corners[1], corners[2], corners[3]);
      ++q.quads;
    } else {
      ++q.others;
      continue;
    }
    q.worst = std::min(q.worst, value);
    sum += value;
  }
  const std::size_t counted = q.triangles + q.quads;
  q.mean = counted ? sum / double(counted) : 0;
  if (!counted) q.worst = 0;
  return q;
}

// Largest distance from a vertex of `mesh` to the surface of `reference` (triangulated).
double max_distance_to(const Mesh& mesh, const Mesh& reference) {
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  Tree tree(faces(reference).first, faces(reference).second, reference);
  tree.accelerate_distance_queries();
  double largest = 0;
  for (auto v : vertices(mesh))
    largest = std::max(largest, std::sqrt(CGAL::to_double(tree.squared_distance(mesh.point(v)))));
  return largest;
}

void write_quality(MR::Json_writer& json, const std::string& name, const Quality& q) {
  json.key(name).begin_object();
  json.field("worst", q.worst).field("mean", q.mean);
  json.field("triangles", q.triangles).field("quads", q.quads);
  json.end_object();
}

}  // namespace

int run_smooth(const std::vector<std::string>& args) {
  Arguments arguments(args, {"--quads", "--quiet", "--slide-feature-nodes"},
                      {"-o", "--method", "--iterations", "--seed", "--threads", "--generations",
                       "--feature-angle", "--tangent-scale", "--cubic-weight", "--report"});
  const std::string input = arguments.single_input(smooth_help);
  const std::string output = arguments.get("-o");
  if (output.empty()) throw Input_error("smooth: -o OUT is required");
  const std::string method = arguments.get("--method", "mga");
  if (method != "mga" && method != "cg" && method != "cgal")
    throw Input_error("smooth: --method must be mga, cg or cgal");
  const bool quads = arguments.has("--quads");
  if (quads && method == "cgal")
    throw Input_error("smooth: CGAL's smoothing works on triangles only; drop --quads");
  const int iterations = int(arguments.get_int("--iterations", method == "cgal" ? 1 : 3));
  const unsigned seed = unsigned(arguments.get_int("--seed", 0));
  const int threads = int(arguments.get_int("--threads", 1));
  const int generations = int(arguments.get_int("--generations", 3));
  const double feature_angle = arguments.get_double("--feature-angle", 120.0);
  const double tangent_scale = arguments.get_double(
      "--tangent-scale", arguments.get_double("--cubic-weight", 0.45));  // the deprecated name
  if (iterations < 0 || threads < 1 || generations < 1)
    throw Input_error("smooth: --iterations >= 0, --threads >= 1, --generations >= 1");
  if (!(tangent_scale >= 0 && tangent_scale <= 1))
    throw Input_error("smooth: --tangent-scale must be in [0, 1]");

  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  Mesh reference = mesh;
  CGAL::Polygon_mesh_processing::triangulate_faces(reference);

  double conversion_seconds = 0;
  MR::Quad_conversion_result conversion;
  if (quads) {
    const auto start = std::chrono::steady_clock::now();
    conversion = MR::triangles_to_quads(mesh, MR::parameters::feature_angle_deg(feature_angle));
    conversion_seconds = seconds_since(start);
  }
  const Quality before = measure_quality(mesh);

  Progress_bar bar(progress_wanted(arguments));
  MR::Mga_smooth_result result;
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();  // all threads of the process
  if (method == "cgal") {
    namespace PMP = CGAL::Polygon_mesh_processing;
    PMP::angle_and_area_smoothing(mesh, CGAL::parameters::number_of_iterations(iterations));
    PMP::tangential_relaxation(mesh, CGAL::parameters::number_of_iterations(iterations));
  } else {
    auto np = MR::parameters::feature_angle_deg(feature_angle)
                  .number_of_threads(threads)
                  .max_generations(generations)
                  .random_seed(seed)
                  .number_of_iterations(iterations)
                  .surface_tangent_scale(tangent_scale)
                  .slide_feature_nodes(arguments.has("--slide-feature-nodes"))
                  .visitor(std::ref(bar));
    result = method == "mga" ? MR::mga_smooth(mesh, np) : MR::conjugate_gradient_smooth(mesh, np);
  }
  const double seconds = seconds_since(start);
  const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const Quality after = measure_quality(mesh);
  const double distance = max_distance_to(mesh, reference);
  const double diagonal = bbox_diagonal(reference);
  save_mesh(output, mesh);

  std::cout << std::setprecision(4) << input << ": " << method << (quads ? " (quads)" : "")
            << ", quality worst " << before.worst << " -> " << after.worst << ", mean "
            << before.mean << " -> " << after.mean << ", max distance to input " << distance << " ("
            << distance / diagonal << " of the diagonal), " << seconds << " s\n";
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    json.begin_object();
    json.field("input", input).field("output", output).field("method", method);
    json.field("quads", quads).field("iterations", iterations).field("seed", seed);
    json.field("threads", threads).field("vertices", mesh.number_of_vertices());
    json.field("faces", mesh.number_of_faces());
    json.field("quality_measure", quads ? "beta (quads), alpha (triangles)" : "alpha");
    write_quality(json, "quality_before", before);
    write_quality(json, "quality_after", after);
    json.field("worst_quality_before", before.worst).field("mean_quality_before", before.mean);
    json.field("worst_quality_after", after.worst).field("mean_quality_after", after.mean);
    json.field("max_distance_to_input", distance);
    json.field("max_distance_to_input_relative", distance / diagonal);
    json.field("seconds", seconds).field("cpu_seconds", cpu_seconds);
    if (quads) {
      json.key("conversion").begin_object();
      json.field("seconds", conversion_seconds).field("merged_pairs", conversion.merged_pairs);
      json.field("eliminated_nodes", conversion.eliminated_nodes);
      json.field("swapped_edges", conversion.swapped_edges);
      json.field("collapsed_elements", conversion.collapsed_elements);
      json.field("remaining_triangles", conversion.remaining_triangles);
      json.end_object();
    }
    if (method != "cgal") {
      json.key("smoothing").begin_object();
      json.field("sweeps", result.sweeps).field("moves", result.moves);
      json.field("rejected_folds", result.rejected_folds).field("converged", result.converged);
      json.field("free_nodes", result.free_nodes).field("border_nodes", result.border_nodes);
      json.field("feature_nodes", result.feature_nodes);
      json.field("sliding_nodes", result.sliding_nodes);
      json.field("constrained_nodes", result.constrained_nodes);
      json.end_object();
    }
    json.end_object();
    save_text(arguments.get("--report"), text.str());
  }
  return result.cancelled ? exit_incomplete : exit_success;
}

}  // namespace mesh_repair_cli
