// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair smooth: micro-GA smoothing on the rebuilt G1 surface (Chen et al.), the paper's
// conjugate-gradient baseline, or CGAL's angle_and_area_smoothing + tangential_relaxation, with
// the same quality and distance measures for all three.
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/smooth_mesh.h>

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

namespace MR = CGAL::Mesh_repair;

int run_smooth(const std::vector<std::string>& args) {
  Arguments arguments(args, {"--quads", "--quiet", "--slide-feature-nodes"},
                      {"-o", "--method", "--iterations", "--seed", "--threads", "--generations",
                       "--feature-angle", "--tangent-scale", "--cubic-weight", "--report"});
  const std::string input = arguments.single_input(smooth_help);
  const std::string output = arguments.get("-o");
  if (output.empty()) throw Input_error("smooth: -o OUT is required");
  MR::Smooth_mesh_options options;
  const std::string method = arguments.get("--method", "mga");
  if (!MR::smoothing_method_from_string(method, options.method))
    throw Input_error("smooth: --method must be mga, cg or cgal");
  options.quads = arguments.has("--quads");
  if (options.quads && options.method == MR::Smoothing_method::cgal)
    throw Input_error("smooth: CGAL's smoothing works on triangles only; drop --quads");
  options.iterations = int(arguments.get_int("--iterations", method == "cgal" ? 1 : 3));
  options.seed = unsigned(arguments.get_int("--seed", 0));
  options.threads = int(arguments.get_int("--threads", 1));
  options.generations = int(arguments.get_int("--generations", 3));
  options.feature_angle_deg = arguments.get_double("--feature-angle", 120.0);
  options.tangent_scale = arguments.get_double(
      "--tangent-scale", arguments.get_double("--cubic-weight", 0.45));  // the deprecated name
  options.slide_feature_nodes = arguments.has("--slide-feature-nodes");
  if (options.iterations < 0 || options.threads < 1 || options.generations < 1)
    throw Input_error("smooth: --iterations >= 0, --threads >= 1, --generations >= 1");
  if (!(options.tangent_scale >= 0 && options.tangent_scale <= 1))
    throw Input_error("smooth: --tangent-scale must be in [0, 1]");

  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  Progress_bar bar(progress_wanted(arguments));
  const MR::Smooth_mesh_result result = MR::smooth_mesh(mesh, options, MR::Any_visitor(bar));
  save_mesh(output, mesh);

  const double distance = result.max_distance_to_input;
  std::cout << std::setprecision(4) << input << ": " << method << (options.quads ? " (quads)" : "")
            << ", quality worst " << result.before.worst << " -> " << result.after.worst
            << ", mean " << result.before.mean << " -> " << result.after.mean
            << ", max distance to input " << distance << " (" << distance / result.diagonal
            << " of the diagonal), " << result.seconds << " s\n";
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    MR::write_report(json, input, output, result);
    save_text(arguments.get("--report"), text.str());
  }
  return result.cancelled ? exit_incomplete : exit_success;
}

}  // namespace mesh_repair_cli
