// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesh_repair repair: the automatic repair pipeline on one mesh, or on every mesh of a folder
// (--batch), each file in its own process so that one failure never stops the others.

#include "batch.h"
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Mesh_repair/check_written_mesh.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/io.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <sstream>

namespace mesh_repair_cli {

const char* const repair_help =
    "usage: mesh_repair repair IN -o OUT [options]\n"
    "       mesh_repair repair --batch IN_DIR --out-dir OUT_DIR [--jobs N] [--timeout S] "
    "[options]\n"
    "\n"
    "Repairs a mesh into a valid, watertight one: soup repair and orientation (duplicated faces\n"
    "that form a zero-volume wall between two shells removed whole), exact and tolerance\n"
    "stitching of gaps and overlaps, T-junctions, non-manifold vertices, degenerate faces, hole\n"
    "filling (thesis ch. 3). Every change is counted in the report.\n"
    "\n"
    "options:\n"
    "  -o OUT                   output mesh (.off .obj .stl .ply), written atomically\n"
    "  --report R.json          full JSON report (defects before/after, every step, every hole)\n"
    "  --tolerance auto|X       stitching tolerance, absolute model units (default auto)\n"
    "  --tolerance-rel F        stitching tolerance as a fraction of the bounding-box diagonal\n"
    "  --fill M                 auto|advancing_front|shape_prediction|curvature_variation|liepa|\n"
    "                           self_validated (default; see mesh_repair fill --help)\n"
    "  --continuity C           Liepa fairing continuity 0|1|2 (default 1)\n"
    "  --max-hole-size F        leave open holes larger than F x bounding-box diagonal\n"
    "  --max-hole-edges N       leave open holes with more than N border edges\n"
    "  --sheet-border-ratio F   a border whose flat filling has more than F x the area of its\n"
    "                           component is an open sheet's outline, left open (default 0.9)\n"
    "  --fill-sheet-borders     fill the outlines of open sheets too\n"
    "  --keep-components        keep every connected component (default; fragments in holes\n"
    "                           aside, see --keep-fragments)\n"
    "  --largest-component      keep only the largest component (removed ones are counted)\n"
    "  --keep-fragments         keep the small open fragments found in holes (by default they\n"
    "                           are removed before filling, and counted)\n"
    "  --no-through-holes       cap both ends of a through-hole whose wall is missing (by\n"
    "                           default a tube joins the two ends, and is counted)\n"
    "  --keep-orientation       keep the orientation of closed parts (by default each is\n"
    "                           turned to face outward when it faces inward, with the parts\n"
    "                           inside it; counted)\n"
    "  --no-ring-holes          fill islands and their hole separately\n"
    "  --no-self-intersections  neither count nor remove self-intersections (faster)\n"
    "  --keep-self-intersections  keep the input's self-intersections (default: closed parts\n"
    "                           autorefined, spike vertices moved back to the centre of their\n"
    "                           neighbours, the faces still intersecting others of their\n"
    "                           component replaced by checked patches; intersections between\n"
    "                           components are kept unless --merge-intersecting-solids)\n"
    "  --merge-intersecting-solids  replace closed parts that intersect one another by their\n"
    "                           union (CGAL corefinement; the faces inside are removed)\n"
    "  --threads N              threads of the whole command: independent holes, "
    "self-intersection\n"
    "                           counts, defect reports (default: all cores)\n"
    "  --seed S                 seed of the randomised methods (default 0)\n"
    "  --binary                 binary STL/PLY output\n"
    "  --quiet                  no progress bar\n"
    "batch options:\n"
    "  --batch IN_DIR           repair every .off/.obj/.stl/.ply file of IN_DIR\n"
    "  --out-dir OUT_DIR        where outputs, reports, summary.csv and summary.jsonl go\n"
    "  --jobs N                 files repaired at once (default 1)\n"
    "  --timeout S              seconds allowed per file (default 600)\n"
    "The written file is read back as CGAL's read_polygon_mesh reads it (coincident points\n"
    "merged); the report's valid, closed, manifold, defects after and, where the reading\n"
    "splits or drops anything, self-intersecting pairs are that reading's.\n"
    "exit status: 0 complete: valid, every requested repair done, nothing left;\n"
    "             3 complete except what was kept on purpose (listed): holes over\n"
    "               --max-hole-size/--max-hole-edges, outlines of open sheets,\n"
    "               self-intersections between separate components, the input's own\n"
    "               self-intersections with --keep-self-intersections;\n"
    "             1 incomplete: something asked was not done (listed);\n"
    "             2 bad usage or unreadable input\n";

namespace {

const std::set<std::string> repair_flags = {"--keep-components",
                                            "--keep-fragments",
                                            "--no-through-holes",
                                            "--keep-orientation",
                                            "--largest-component",
                                            "--no-ring-holes",
                                            "--no-self-intersections",
                                            "--remove-self-intersections",
                                            "--keep-self-intersections",
                                            "--merge-intersecting-solids",
                                            "--fill-sheet-borders",
                                            "--binary",
                                            "--quiet"};
const std::set<std::string> repair_valued = {
    "-o",        "--report",     "--tolerance",     "--tolerance-rel",
    "--fill",    "--continuity", "--max-hole-size", "--max-hole-edges",
    "--threads", "--seed",       "--batch",         "--out-dir",
    "--jobs",    "--timeout",    "--summary",       "--sheet-border-ratio"};

double sheet_border_ratio(const Arguments& args) {
  if (args.has("--fill-sheet-borders")) {
    if (args.has("--sheet-border-ratio"))
      throw Input_error("give either --sheet-border-ratio or --fill-sheet-borders");
    return std::numeric_limits<double>::infinity();
  }
  const double ratio = args.get_double("--sheet-border-ratio", 0.9);
  if (!(ratio > 0)) throw Input_error("--sheet-border-ratio must be positive");
  return ratio;
}

CGAL::Mesh_repair::Fill_method fill_option(const Arguments& args) {
  CGAL::Mesh_repair::Fill_method method = CGAL::Mesh_repair::Fill_method::self_validated;
  const std::string name = args.get("--fill", "self_validated");
  if (!CGAL::Mesh_repair::fill_method_from_string(name, method))
    throw Input_error(
        "--fill expects auto, advancing_front, shape_prediction, "
        "curvature_variation, liepa or self_validated, got '" +
        name + "'");
  return method;
}

void print_summary(const std::string& input, const CGAL::Mesh_repair::Soup_repair_report& soup,
                   const CGAL::Mesh_repair::Repair_result& r,
                   const CGAL::Mesh_repair::Written_mesh_check& written) {
  std::cout << input << ": " << r.input_vertices << " vertices, " << r.input_faces << " faces\n";
  const std::string soup_text = describe_soup_repair(soup);
  if (!soup_text.empty()) std::cout << "soup repair:\n" << soup_text;
  std::cout << "steps:\n";
  for (const auto& step : r.steps) {
    std::cout << "  " << step.name << " (" << step.seconds << " s)";
    bool first = true;
    for (const auto& c : step.counts) {
      if (c.second == 0) continue;
      std::cout << (first ? ": " : ", ") << c.first << ' ' << c.second;
      first = false;
    }
    std::cout << '\n';
    for (const auto& note : step.notes) std::cout << "    note: " << note << '\n';
  }
  std::cout << "holes: " << r.holes.holes.size() << " (" << r.holes.filled << " filled, "
            << r.holes.failed << " failed, " << r.holes_too_large << " left open as too large, "
            << r.sheet_borders_left_open << " left open as outlines of open sheets)\n";
  for (std::size_t i = 0; i < r.holes.holes.size(); ++i) {
    const auto& h = r.holes.holes[i];
    if (h.filled) continue;
    std::cout << "  hole " << i << " (" << h.border_edges << " edges): " << h.failure << '\n';
  }
  std::cout << "result: " << r.output_vertices << " vertices, " << r.output_faces << " faces";
  if (written.readable)
    std::cout << "; the written file read back: " << written.vertices << " vertices, "
              << written.faces << " faces";
  std::cout << ", " << (r.valid ? "valid" : "INVALID") << ", " << (r.closed ? "closed" : "open")
            << ", " << (r.manifold ? "manifold" : "non-manifold");
  if (r.self_intersections_checked)
    std::cout << ", " << (r.self_intersections_output_truncated ? "at least " : "")
              << r.self_intersections_output << " self-intersecting pairs";
  std::cout << '\n';
  switch (r.status()) {
    case CGAL::Mesh_repair::Repair_status::complete:
      std::cout << "status: complete: every requested repair was done\n";
      break;
    case CGAL::Mesh_repair::Repair_status::complete_except_kept:
      std::cout << "status: complete except what was kept on purpose\n";
      break;
    case CGAL::Mesh_repair::Repair_status::incomplete:
      std::cout << "status: incomplete\n";
      break;
  }
  if (!r.remaining.empty()) {
    std::cout << "left:\n";
    for (const auto& line : r.remaining) std::cout << "  " << line << '\n';
  }
  if (!r.kept.empty()) {
    std::cout << "kept:\n";
    for (const auto& line : r.kept) std::cout << "  " << line << '\n';
  }
}

std::string report_json(const std::string& input, const std::string& output,
                        const CGAL::Mesh_repair::Soup_repair_report& soup,
                        const CGAL::Mesh_repair::Defect_report& before,
                        const CGAL::Mesh_repair::Defect_report& after,
                        const CGAL::Mesh_repair::Repair_result& result,
                        const CGAL::Mesh_repair::Written_mesh_check& written, double seconds) {
  std::ostringstream text;
  CGAL::Mesh_repair::Json_writer json(text);
  json.begin_object().field("input", input).field("output", output).field("seconds", seconds);
  json.key("soup_repair");
  CGAL::Mesh_repair::write_json(json, soup);
  json.key("defects_before");
  CGAL::Mesh_repair::write_json(json, before);
  json.key("written_file");
  CGAL::Mesh_repair::write_json(json, written);
  json.key("defects_after");
  CGAL::Mesh_repair::write_json(json, after);
  json.key("repair");
  CGAL::Mesh_repair::write_json(json, result);
  json.end_object();
  return text.str();
}

// The few figures a batch run collects from each file, one `key=value` per line.
void write_summary(const std::string& path, int status, const CGAL::Mesh_repair::Repair_result& r,
                   const CGAL::Mesh_repair::Defect_counts& before, double seconds) {
  // Inputs whose only defects are holes: the regression suite expects them closed.
  const bool only_holes = before.border_cycles > 0 && before.non_manifold_edges == 0 &&
                          before.non_manifold_vertices == 0 && before.duplicated_faces == 0 &&
                          before.inconsistent_orientation == 0 && before.degenerate_faces == 0 &&
                          before.needles == 0 && before.caps == 0 && before.small_gaps == 0 &&
                          before.t_junctions == 0 && before.overlaps == 0 &&
                          r.self_intersections_checked && r.self_intersections_input == 0;
  std::ostringstream out;
  out << "status=" << status << "\nrepair_status=" << CGAL::Mesh_repair::to_string(r.status())
      << "\nfaces_before=" << r.input_faces << "\nfaces_after=" << r.output_faces
      << "\nholes=" << r.holes.holes.size() << "\nholes_filled=" << r.holes.filled
      << "\nholes_failed=" << r.holes.failed << "\nholes_too_large=" << r.holes_too_large
      << "\nsheet_borders_left_open=" << r.sheet_borders_left_open
      << "\nborder_cycles_after=" << r.border_cycles_left << "\nclosed=" << r.closed
      << "\nvalid=" << r.valid << "\nmanifold=" << r.manifold
      << "\nself_intersections_before=" << r.self_intersections_input
      << "\nself_intersections_after=" << r.self_intersections_output
      << "\nonly_holes_before=" << only_holes << "\nseconds=" << seconds << '\n';
  save_text(path, out.str());
}

/// Where the reading splits non-manifold vertices and edges (or drops a duplicated face), faces
/// that met there become separate faces that touch, and CGAL counts them as intersecting: the
/// pairs of the report are those of the reading, what a user of the file sees. A rise inside
/// the parts is listed as left.
void take_pairs_of_the_reading(Mesh& written, const CGAL::Mesh_repair::Defect_report& after,
                               CGAL::Mesh_repair::Repair_result& result) {
  auto component = written.add_property_map<Mesh::Face_index, std::size_t>("f:reading_part").first;
  CGAL::Polygon_mesh_processing::connected_components(written, component);
  std::size_t between = 0;
  for (const auto& pair : after.self_intersections)
    between += component[Mesh::Face_index(Mesh::size_type(pair.first))] !=
               component[Mesh::Face_index(Mesh::size_type(pair.second))];
  written.remove_property_map(component);
  const std::size_t all = after.self_intersections.size();
  const std::size_t within_repaired =
      result.self_intersections_output -
      std::min(result.self_intersections_output, result.self_intersections_between_components);
  if (all - between > within_repaired)
    result.remaining.push_back(
        "the written file, read back with coincident points merged, has " +
        std::to_string(all - between) +
        " self-intersecting face pair(s) inside its parts (the "
        "repaired mesh " +
        std::to_string(within_repaired) +
        "): faces that touch where the reading splits non-manifold vertices and edges");
  result.self_intersections_output = all;
  result.self_intersections_between_components = between;
  result.self_intersections_output_truncated = after.self_intersections_truncated;
}

/// The line for an input whose every face the repair removed (all of them degenerate, say):
/// bad input, like one with no face at all, rather than an empty output; names the steps.
std::string nothing_left(const std::string& input, const CGAL::Mesh_repair::Repair_result& result) {
  std::string removed;
  for (const auto& step : result.steps) {
    const double faces = step.count("faces_removed");
    if (faces > 0)
      removed += (removed.empty() ? "" : ", ") + step.name + " " + std::to_string(long(faces));
  }
  return input + ": no face left after repair (faces removed: " +
         (removed.empty() ? std::string("none counted") : removed) + "); nothing written";
}

int repair_one(const Arguments& args) {
  const std::string input = args.single_input("mesh_repair repair IN -o OUT");
  const std::string output = args.get("-o");
  if (output.empty()) throw Input_error("missing -o OUT");
  if (output == input) throw Input_error("the output must not overwrite the input");
  if (CGAL::Mesh_repair::mesh_format(output).empty())
    throw Input_error(output + ": unknown output format (use .off, .obj, .stl or .ply)");
  const auto start = std::chrono::steady_clock::now();

  Mesh mesh;
  CGAL::Mesh_repair::Soup_repair_report soup;
  load_mesh(input, mesh, soup, true);
  const double tolerance = tolerance_option(args, mesh);
  const long long threads = args.get_int("--threads", 0);
  if (threads < 0) throw Input_error("--threads must be positive");
#ifdef CGAL_LINKED_WITH_TBB
  // The whole command, the defect reports before and after included, not only the repair.
  std::unique_ptr<tbb::global_control> thread_limit;
  if (threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
  const long long continuity = args.get_int("--continuity", 1);
  if (continuity < 0 || continuity > 2) throw Input_error("--continuity must be 0, 1 or 2");
  if (args.has("--keep-components") && args.has("--largest-component"))
    throw Input_error("give either --keep-components or --largest-component");

  Progress_bar progress(progress_wanted(args));
  namespace MR = CGAL::Mesh_repair;
  // Defects before: the soup stage's findings merged with what the mesh still has. The
  // self-intersection count is the pipeline's own, so detection skips it here.
  MR::Defect_report before = MR::detect_defects(
      mesh, MR::parameters::merge_tolerance(tolerance).detect_self_intersections(false));
  MR::add_soup_repair_report(before, soup, mesh);
  auto result = MR::automatic_repair(
      mesh, MR::parameters::merge_tolerance(tolerance)
                .fill_method(fill_option(args))
                .fairing_continuity(unsigned(continuity))
                .max_hole_size(
                    args.get_double("--max-hole-size", std::numeric_limits<double>::infinity()))
                .max_hole_edges(std::size_t(
                    args.get_int("--max-hole-edges", std::numeric_limits<long long>::max())))
                .sheet_border_ratio(sheet_border_ratio(args))
                .keep_largest_component(args.has("--largest-component"))
                .remove_hole_fragments(!args.has("--keep-fragments"))
                .bridge_through_holes(!args.has("--no-through-holes"))
                .orient_closed_parts(!args.has("--keep-orientation"))
                .detect_ring_holes(!args.has("--no-ring-holes"))
                .detect_self_intersections(!args.has("--no-self-intersections"))
                .repair_self_intersections(!args.has("--keep-self-intersections") &&
                                           !args.has("--no-self-intersections"))
                .merge_intersecting_solids(args.has("--merge-intersecting-solids"))
                .number_of_threads(int(threads))
                .random_seed(unsigned(args.get_int("--seed", 0)))
                .visitor(std::ref(progress)));
  if (num_faces(mesh) == 0) throw Input_error(nothing_left(input, result));
  save_mesh(output, mesh, args.has("--binary"));
  // What the file holds: read back as CGAL reads it; the defects after are those of that
  // reading (what `mesh_repair check OUT` reports).
  Mesh written;
  const MR::Written_mesh_check written_check = MR::check_written_mesh(output, written);
  MR::apply_written_check(result, written_check);
  const Mesh& shown = written_check.readable ? written : mesh;
  const bool recount = written_check.readable && !written_check.read_as_written() &&
                       result.self_intersections_checked;
  MR::Defect_report after = MR::detect_defects(
      shown, MR::parameters::merge_tolerance(tolerance).detect_self_intersections(recount));
  if (recount) take_pairs_of_the_reading(written, after, result);
  if (written_check.readable) MR::add_soup_repair_report(after, written_check.reading, written);
  const double seconds = seconds_since(start);
  const int status = exit_status(result.status());
  if (args.has("--report"))
    save_text(args.get("--report"),
              report_json(input, output, soup, before, after, result, written_check, seconds));
  if (args.has("--summary"))
    write_summary(args.get("--summary"), status, result, MR::counts(before), seconds);
  print_summary(input, soup, result, written_check);
  const auto c0 = MR::counts(before), c1 = MR::counts(after);
  // A count that stopped at its pair limit is a lower bound ("at least", the report's flags).
  auto bound = [](bool truncated, std::size_t count) {
    return (truncated ? std::string("at least ") : std::string()) + std::to_string(count);
  };
  std::cout << "defects before -> after: border cycles " << c0.border_cycles << " -> "
            << c1.border_cycles << ", non-manifold edges " << c0.non_manifold_edges << " -> "
            << c1.non_manifold_edges << ", non-manifold vertices " << c0.non_manifold_vertices
            << " -> " << c1.non_manifold_vertices << ", duplicated faces " << c0.duplicated_faces
            << " -> " << c1.duplicated_faces << ", degenerate faces " << c0.degenerate_faces
            << " -> " << c1.degenerate_faces << ", needles " << c0.needles << " -> " << c1.needles
            << ", caps " << c0.caps << " -> " << c1.caps << ", small gaps "
            << bound(before.small_gaps_truncated, c0.small_gaps) << " -> "
            << bound(after.small_gaps_truncated, c1.small_gaps) << ", T-junctions "
            << bound(before.t_junctions_truncated, c0.t_junctions) << " -> "
            << bound(after.t_junctions_truncated, c1.t_junctions) << ", self-intersections "
            << bound(result.self_intersections_input_truncated, result.self_intersections_input)
            << " -> "
            << bound(result.self_intersections_output_truncated, result.self_intersections_output)
            << '\n';
  std::cout << "wrote " << output << " in " << seconds << " s\n";
  return status;
}

}  // namespace

int run_repair(const std::vector<std::string>& args) {
  Arguments arguments(args, repair_flags, repair_valued);
  if (arguments.has("--batch")) return run_batch_repair(arguments, args);
  return repair_one(arguments);
}

}  // namespace mesh_repair_cli
