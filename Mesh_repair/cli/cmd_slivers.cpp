// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair slivers: removes skewed triangles by node merging and edge swapping, keeping
// feature edges (remove_slivers, thesis 4.5).
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/remove_slivers.h>

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const slivers_help =
    "usage: mesh_repair slivers IN -o OUT [--shape-factor 0.7] [--feature-angle 135]\n"
    "                          [--edge-length L] [--report R.json] [--quiet]\n"
    "  Triangles with a shape factor (thesis eq. 4.14, in [0,1]) below --shape-factor are\n"
    "  slivers: those with an edge shorter than L (default a quarter of the mean edge length)\n"
    "  lose it by node merging, the others swap their longest edge. Edges whose faces meet at\n"
    "  less than --feature-angle degrees (180 = flat) are kept. Exit status 1 when slivers "
    "remain.\n";

int run_slivers(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  Arguments arguments(args, {"--quiet"},
                      {"-o", "--shape-factor", "--feature-angle", "--edge-length", "--report"});
  const std::string input = arguments.single_input(slivers_help);
  const std::string output = arguments.get("-o");
  if (output.empty()) throw Input_error("slivers: -o OUT is required");
  const double threshold = arguments.get_double("--shape-factor", 0.7);
  const double feature_angle = arguments.get_double("--feature-angle", 135.0);
  const double edge_length = arguments.get_double("--edge-length", -1.0);
  if (threshold < 0 || threshold > 1) throw Input_error("slivers: --shape-factor must be in [0,1]");
  if (feature_angle < 0 || feature_angle > 180)
    throw Input_error("slivers: --feature-angle must be in [0,180]");
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  if (!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  const std::size_t faces_before = mesh.number_of_faces();

  Progress_bar bar(progress_wanted(arguments));
  const auto start = std::chrono::steady_clock::now();
  const MR::Sliver_result result =
      MR::remove_slivers(mesh, MR::parameters::shape_factor_threshold(threshold)
                                   .feature_angle_deg(feature_angle)
                                   .tolerance_edge_length(edge_length)
                                   .visitor(std::ref(bar)));
  const double seconds = seconds_since(start);
  save_mesh(output, mesh);

  if (!arguments.has("--quiet")) {
    std::cout << input << ": slivers " << result.slivers_before << " -> " << result.slivers_after
              << " (" << result.collapsed << " collapsed, " << result.flipped << " swapped, "
              << result.kept_for_features << " kept for features, "
              << result.refused_fold + result.refused_self_intersection + result.refused_topology
              << " refused), worst shape factor " << result.min_shape_factor_before << " -> "
              << result.min_shape_factor_after << ", " << seconds << " s\n";
  }
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    json.begin_object();
    json.field("input", input).field("output", output);
    json.key("soup");
    MR::write_json(json, soup);
    json.field("faces_before", faces_before).field("faces_after", mesh.number_of_faces());
    json.field("seconds", seconds);
    json.key("slivers");
    MR::write_json(json, result);
    json.end_object();
    save_text(arguments.get("--report"), text.str());
  }
  if (result.cancelled) return exit_incomplete;
  return result.slivers_after == 0 ? exit_success : exit_incomplete;
}

}  // namespace mesh_repair_cli
