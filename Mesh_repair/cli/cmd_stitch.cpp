// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair stitch: closes gaps, small overlaps and T-junctions within a tolerance
// (stitch_gaps, thesis 4.2-4.3).
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>

#include <CGAL/Polygon_mesh_processing/border.h>

#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const stitch_help =
    "usage: mesh_repair stitch IN -o OUT [--tolerance X | --tolerance-rel F] [--no-curves]\n"
    "                         [--allow-self-intersections] [--report R.json] [--quiet]\n"
    "  Merges border nodes closer than the tolerance (X in model units, F a fraction of the\n"
    "  bounding-box diagonal; default: half the shortest border edge at each node), splits\n"
    "  border edges at nodes within tolerance of them (T-junctions) and glues the seams.\n"
    "  Stitching that would make faces intersect is first tried on a copy: the vertices of\n"
    "  those faces are left unstitched (counted as frozen); --allow-self-intersections skips\n"
    "  that check.\n"
    "  --no-curves places T-junction nodes on the chord instead of the cubic boundary curve.\n"
    "  Exit status 1 when border edges remain.\n";

namespace {

std::size_t border_cycles(const Mesh& mesh) {
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  return cycles.size();
}

}  // namespace

int run_stitch(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  Arguments arguments(args, {"--no-curves", "--allow-self-intersections", "--quiet"},
                      {"-o", "--tolerance", "--tolerance-rel", "--report"});
  const std::string input = arguments.single_input(stitch_help);
  const std::string output = arguments.get("-o");
  if (output.empty()) throw Input_error("stitch: -o OUT is required");
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  const double tolerance = tolerance_option(arguments, mesh);
  const std::size_t faces_before = mesh.number_of_faces();
  const std::size_t cycles_before = border_cycles(mesh);

  Progress_bar bar(progress_wanted(arguments));
  const auto start = std::chrono::steady_clock::now();
  const MR::Stitch_result result = MR::stitch_gaps(
      mesh, MR::parameters::merge_tolerance(tolerance)
                .use_cubic_curves(!arguments.has("--no-curves"))
                .check_self_intersections(!arguments.has("--allow-self-intersections"))
                .visitor(std::ref(bar)));
  const double seconds = seconds_since(start);
  const std::size_t cycles_after = border_cycles(mesh);
  save_mesh(output, mesh);

  if (!arguments.has("--quiet")) {
    std::cout << input << ": " << result.node_merges << " node merges, " << result.t_junctions_split
              << " T-junction splits, " << result.edges_stitched + result.coincident_edges_stitched
              << " edges glued (tolerance " << result.merge_tolerance
              << (result.tolerance_derived ? ", derived" : "") << "); border cycles "
              << cycles_before << " -> " << cycles_after << ", max move " << result.max_displacement
              << " (" << result.max_move_to_shortest_edge << " of the shortest incident edge), "
              << seconds << " s\n";
    if (result.frozen_vertices > 0)
      std::cout << "  " << result.frozen_vertices
                << " vertices left unstitched: stitching them made faces intersect ("
                << result.self_intersections_avoided << " pairs on the first try)\n";
    if (result.check_failed)
      std::cout << "  nothing stitched: every try made faces intersect; the mesh is unchanged\n";
  }
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    json.begin_object();
    json.field("input", input).field("output", output);
    json.key("soup");
    MR::write_json(json, soup);
    json.field("faces_before", faces_before).field("faces_after", mesh.number_of_faces());
    json.field("border_cycles_before", cycles_before).field("border_cycles_after", cycles_after);
    json.field("closed", cycles_after == 0).field("seconds", seconds);
    json.key("stitch");
    MR::write_json(json, result);
    json.end_object();
    save_text(arguments.get("--report"), text.str());
  }
  if (result.cancelled) return exit_incomplete;
  return cycles_after == 0 ? exit_success : exit_incomplete;
}

}  // namespace mesh_repair_cli
