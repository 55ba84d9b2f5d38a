// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair optimize: GA mesh reduction or triangle-quality improvement with feature retention
// (optimize_mesh, thesis chapter 7).
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/optimize_mesh.h>
#include <CGAL/Mesh_repair/quality.h>

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const optimize_help =
    "usage: mesh_repair optimize IN -o OUT [--mode reduction|quality]\n"
    "                           [--target-ratio R | --target-faces N | --max-deviation D]\n"
    "                           [--feature-angle 135] [--min-angle 15] [--seed S]\n"
    "                           [--report R.json] [--quiet]\n"
    "  reduction (default): removes the triangles around the nodes of flat elements and\n"
    "  re-triangulates each emptied region with a genetic algorithm, until --target-faces,\n"
    "  --target-ratio (default 0.5) or, with --max-deviation D, while the normal-deviation\n"
    "  weighing factor (thesis eq. 7.4, in [0,4]) stays below D. quality: re-triangulates\n"
    "  each element with its edge neighbours when that raises the triangles' shape, face count\n"
    "  unchanged. Corners and feature lines (dihedral angle below --feature-angle) are kept.\n"
    "  Exit status 1 when the reduction target is not reached.\n";

int run_optimize(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  Arguments arguments(args, {"--quiet"},
                      {"-o", "--mode", "--target-ratio", "--target-faces", "--max-deviation",
                       "--feature-angle", "--min-angle", "--seed", "--report"});
  const std::string input = arguments.single_input(optimize_help);
  const std::string output = arguments.get("-o");
  if (output.empty()) throw Input_error("optimize: -o OUT is required");
  const std::string mode_name = arguments.get("--mode", "reduction");
  if (mode_name != "reduction" && mode_name != "quality")
    throw Input_error("optimize: --mode must be reduction or quality");
  const bool reduction = mode_name == "reduction";
  if (arguments.has("--target-ratio") + arguments.has("--target-faces") > 1)
    throw Input_error("optimize: give --target-ratio or --target-faces, not both");
  const double feature_angle = arguments.get_double("--feature-angle", 135.0);
  if (feature_angle < 0 || feature_angle > 180)
    throw Input_error("optimize: --feature-angle must be in [0,180]");
  const double min_angle = arguments.get_double("--min-angle", 15.0);
  if (min_angle < 0 || min_angle > 60) throw Input_error("optimize: --min-angle must be in [0,60]");
  const double max_deviation =
      arguments.get_double("--max-deviation", std::numeric_limits<double>::infinity());
  if (max_deviation < 0) throw Input_error("optimize: --max-deviation must be >= 0");
  const long long seed = arguments.get_int("--seed", 0);
  if (seed < 0) throw Input_error("optimize: --seed must be >= 0");

  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  if (!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  const std::size_t input_faces = mesh.number_of_faces();
  double ratio = std::isfinite(max_deviation) ? 0.0 : 0.5;
  std::size_t target_faces = 0;
  if (arguments.has("--target-faces")) {
    const long long n = arguments.get_int("--target-faces", 0);
    if (n < 0) throw Input_error("optimize: --target-faces must be >= 0");
    target_faces = std::size_t(n);
  } else {
    ratio = arguments.get_double("--target-ratio", ratio);
    if (ratio < 0 || ratio > 1) throw Input_error("optimize: --target-ratio must be in [0,1]");
    target_faces = std::size_t(std::llround(ratio * double(input_faces)));
  }
  const auto quality_before = MR::quality_statistics(mesh);

  Progress_bar bar(progress_wanted(arguments));
  const auto start = std::chrono::steady_clock::now();
  const MR::Optimization_result result = MR::optimize_mesh(
      mesh, MR::parameters::optimization_mode(reduction ? MR::Optimization_mode::reduction
                                                        : MR::Optimization_mode::quality)
                .target_face_count(target_faces)
                .weighing_factor_threshold(max_deviation)
                .feature_angle_deg(feature_angle)
                .min_angle_floor_deg(min_angle)
                .random_seed(static_cast<unsigned int>(seed))
                .visitor(std::ref(bar)));
  const double seconds = seconds_since(start);
  mesh.collect_garbage();
  save_mesh(output, mesh);
  const auto quality_after = MR::quality_statistics(mesh);

  if (!arguments.has("--quiet")) {
    std::cout << input << ": " << mode_name << ", faces " << result.input_faces << " -> "
              << result.output_faces << " in " << result.passes << " passes ("
              << result.regions_replaced << " regions re-triangulated), smallest angle "
              << quality_before.min_angle_deg << " -> " << quality_after.min_angle_deg
              << " deg, mean alpha " << quality_before.mean_alpha << " -> "
              << quality_after.mean_alpha << ", " << result.corner_nodes << " corners kept, "
              << seconds << " s; " << result.stop_reason << "\n";
  }
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    json.begin_object();
    json.field("input", input).field("output", output).field("mode", mode_name);
    json.key("soup");
    MR::write_json(json, soup);
    json.field("target_faces", target_faces).field("seconds", seconds);
    json.key("optimization");
    MR::write_json(json, result);
    json.key("quality_before");
    MR::write_json(json, quality_before);
    json.key("quality_after");
    MR::write_json(json, quality_after);
    json.end_object();
    save_text(arguments.get("--report"), text.str());
  }
  if (result.cancelled) return exit_incomplete;
  return (!reduction || result.target_reached) ? exit_success : exit_incomplete;
}

}  // namespace mesh_repair_cli
