// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair mesh-points: surface meshing of unorganised points (Chen et al. 2.1): CGAL's
// advancing-front surface reconstruction builds the primary triangulation, quality edge flips
// clean it, optional conversion to quads, then micro-GA smoothing on the rebuilt G1 surface.
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/mesh_points.h>

#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const mesh_points_help =
    "usage: mesh_repair mesh-points IN -o OUT [--quads] [--no-smooth] [--iterations N]\n"
    "                              [--seed S] [--threads N] [--feature-angle DEG]\n"
    "                              [--report R.json] [--quiet]\n"
    "  IN: .xyz or .pwn (x y z [more numbers] per line), or the vertices of .off, .obj, .stl, "
    ".ply.\n"
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
  const std::string error = MR::read_point_file(input, points);
  if (!error.empty()) throw Input_error(error);

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
  const MR::Mga_smooth_result& smoothing = meshed.smoothing;
  save_mesh(output, mesh);

  std::cout << input << ": " << points.size() << " points -> " << mesh.number_of_vertices()
            << " vertices, " << mesh.number_of_faces() << " faces (" << meshed.quads.quads
            << " quads); " << meshed.flips.flips << " flips; quality mean "
            << smoothing.mean_quality_before << " -> " << smoothing.mean_quality_after << ", worst "
            << smoothing.worst_quality_before << " -> " << smoothing.worst_quality_after << "; "
            << meshed.seconds << " s\n";
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    MR::write_report(json, input, output, meshed);
    save_text(arguments.get("--report"), text.str());
  }
  return smoothing.cancelled ? exit_incomplete : exit_success;
}

}  // namespace mesh_repair_cli
