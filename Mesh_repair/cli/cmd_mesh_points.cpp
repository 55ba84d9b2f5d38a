// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair mesh-points: surface meshing of unorganised points (Chen et al. 2.1): CGAL's
// advancing-front surface reconstruction builds the primary triangulation, quality edge flips
// clean it, optional conversion to quads, then micro-GA smoothing on the rebuilt G1 surface.
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/mesh_points.h>

#include <CGAL/IO/read_points.h>

#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const mesh_points_help =
    "usage: mesh_repair mesh-points IN.xyz|IN.ply -o OUT [--quads] [--no-smooth] [--iterations N]\n"
    "                              [--seed S] [--threads N] [--feature-angle DEG]\n"
    "                              [--report R.json] [--quiet]\n"
    "  Triangulates unorganised points with CGAL's advancing-front reconstruction, flips edges\n"
    "  to raise quality, optionally converts to quads, and smooths with the micro-GA, nodes on\n"
    "  the G1 surface through the points (the paper's mapping).\n";

int run_mesh_points(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  Arguments arguments(args, {"--quads", "--no-smooth", "--quiet"},
                      {"-o", "--iterations", "--seed", "--threads", "--feature-angle", "--report"});
  const std::string input = arguments.single_input(mesh_points_help);
  const std::string output = arguments.get("-o");
  if (output.empty()) throw Input_error("mesh-points: -o OUT is required");
  const int iterations = int(arguments.get_int("--iterations", 3));
  const int threads = int(arguments.get_int("--threads", 0));
  const unsigned seed = unsigned(arguments.get_int("--seed", 0));
  const double feature_angle = arguments.get_double("--feature-angle", 120.0);
  if (iterations < 0 || threads < 0) throw Input_error("mesh-points: bad --iterations/--threads");

  std::vector<Point> points;
  if (!CGAL::IO::read_points(input, std::back_inserter(points)) || points.size() < 3)
    throw Input_error("mesh-points: cannot read at least three points from " + input);

  const auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  Progress_bar bar(progress_wanted(arguments));
  const MR::Mesh_points_result meshed = MR::mesh_points(
      points, mesh,
      MR::parameters::feature_angle_deg(feature_angle)
          .convert_to_quads(arguments.has("--quads"))
          .number_of_iterations(arguments.has("--no-smooth") ? 0u : unsigned(iterations))
          .number_of_threads(threads)
          .random_seed(seed)
          .visitor(std::ref(bar)));
  if (meshed.reconstructed_faces == 0)
    throw Input_error("mesh-points: the reconstruction produced no triangle");
  const double reconstruction_seconds = meshed.reconstruction_seconds;
  const MR::Edge_flip_result& flips = meshed.flips;
  const MR::Quad_conversion_result& conversion = meshed.quads;
  const MR::Mga_smooth_result& smoothing = meshed.smoothing;
  const double seconds = seconds_since(start);
  save_mesh(output, mesh);

  std::cout << input << ": " << points.size() << " points -> " << mesh.number_of_vertices()
            << " vertices, " << mesh.number_of_faces() << " faces (" << conversion.quads
            << " quads); " << flips.flips << " flips; quality mean "
            << smoothing.mean_quality_before << " -> " << smoothing.mean_quality_after << ", worst "
            << smoothing.worst_quality_before << " -> " << smoothing.worst_quality_after << "; "
            << seconds << " s\n";
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    json.begin_object();
    json.field("input", input).field("output", output).field("points", points.size());
    json.field("vertices", mesh.number_of_vertices()).field("faces", mesh.number_of_faces());
    json.field("reconstruction_seconds", reconstruction_seconds).field("seconds", seconds);
    json.field("edge_flips", flips.flips).field("quads", conversion.quads);
    json.field("remaining_triangles", conversion.remaining_triangles);
    json.field("worst_quality_before", smoothing.worst_quality_before);
    json.field("mean_quality_before", smoothing.mean_quality_before);
    json.field("worst_quality_after", smoothing.worst_quality_after);
    json.field("mean_quality_after", smoothing.mean_quality_after);
    json.field("sweeps", smoothing.sweeps).field("moves", smoothing.moves);
    json.end_object();
    save_text(arguments.get("--report"), text.str());
  }
  return smoothing.cancelled ? exit_incomplete : exit_success;
}

}  // namespace mesh_repair_cli
