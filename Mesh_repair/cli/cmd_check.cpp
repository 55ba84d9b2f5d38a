// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair check: reads a mesh (soup stage counted), runs detect_defects, prints a summary and
// optionally writes the JSON report (schema: doc/report_schema.md).
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/io.h>

#include <functional>
#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const check_help =
    "usage: mesh_repair check IN [--json OUT.json] [--tolerance X | --tolerance-rel F]\n"
    "                        [--no-self-intersections] [--quiet]\n"
    "\n"
    "Reports every defect of IN (OFF, OBJ, STL, PLY): border cycles and ring-hole islands,\n"
    "non-manifold edges and vertices, duplicated faces, inconsistent orientation, degenerate\n"
    "faces and slivers, small gaps and T-junctions, overlapping coplanar faces,\n"
    "self-intersections, connected components, closedness. Counts include what the reader's\n"
    "polygon-soup stage repaired.\n"
    "\n"
    "  --json OUT.json         also write the full report (doc/report_schema.md)\n"
    "  --tolerance X           gap / T-junction distance in model units\n"
    "                          (default: 0.25 x mean border edge length)\n"
    "  --tolerance-rel F       the same as a fraction of the bounding-box diagonal\n"
    "  --no-self-intersections skip CGAL's self-intersection test\n"
    "  --quiet                 no progress bar\n"
    "\n"
    "Exit status: 0 no defect, 1 defects found, 2 bad usage or unreadable input.\n";

int run_check(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  Arguments arguments(args, {"--no-self-intersections", "--quiet"},
                      {"--json", "--tolerance", "--tolerance-rel"});
  const std::string input = arguments.single_input(check_help);
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  const double tolerance = tolerance_option(arguments, mesh);

  Progress_bar progress(progress_wanted(arguments));
  MR::Defect_report report = MR::detect_defects(
      mesh, MR::parameters::merge_tolerance(tolerance)
                .detect_self_intersections(!arguments.has("--no-self-intersections"))
                .visitor(std::ref(progress)));
  if (report.cancelled) throw Input_error("interrupted");
  MR::add_soup_repair_report(report, soup, mesh);

  std::cout << input << ":\n" << MR::summary(report);
  const std::string soup_lines = describe_soup_repair(soup);
  if (!soup_lines.empty())
    std::cout << "repaired while reading (polygon-soup stage):\n" << soup_lines;

  if (arguments.has("--json")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    MR::write_json(json, report);
    save_text(arguments.get("--json"), text.str());
  }
  return MR::counts(report).any() ? exit_incomplete : exit_success;
}

}  // namespace mesh_repair_cli
