// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair fill: fills the holes of a mesh with one method of fill_holes.h, writes the mesh and
// optionally a JSON report with one entry per hole.
#include "commands.h"
#include "common.h"
#include "picture.h"

#include <CGAL/Mesh_repair/check_written_mesh.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/io.h>

#include <CGAL/Polygon_mesh_processing/border.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

namespace mesh_repair_cli {

const char* const fill_help =
    "usage: mesh_repair fill IN -o OUT\n"
    "           [--method advancing_front|liepa|shape_prediction|curvature_variation|\n"
    "                     self_validated|auto]\n"
    "           [--continuity 0|1|2] [--max-hole-edges N] [--max-hole-size F] [--seed S]\n"
    "           [--sheet-border-ratio F | --fill-sheet-borders]\n"
    "           [--no-ring-holes] [--threads N] [--report R.json] [--picture P.png]\n"
    "           [--quiet]\n"
    "           [--objective forces|force_variation] [--nodes free|free_and_contour]\n"
    "           [--grid disc|refined_liepa] [--force-density uniform|inverse_length|cotangent]\n"
    "           [--constraints FILE]\n"
    "\n"
    "Fills the holes of IN and writes OUT. Every patch is checked with exact predicates (closed,\n"
    "no self-intersection with itself or its ring) and rolled back if it fails. A hole with\n"
    "islands inside (ring hole) is bridged to them and filled as one region.\n"
    "\n"
    "  -o OUT               output mesh (OFF, OBJ, STL, PLY)\n"
    "  --method M           advancing_front (thesis 4.4), liepa (CGAL), shape_prediction,\n"
    "                       curvature_variation, self_validated (default: the hole's\n"
    "                       surroundings choose; each faired method fills the hole enlarged\n"
    "                       by two rings, the one nearest the removed rings goes first;\n"
    "                       doc/fill_holes.md), or auto (advancing front, then Liepa: faster,\n"
    "                       less faithful)\n"
    "  --continuity C       fairing continuity of liepa: 0, 1 (default) or 2\n"
    "  --max-hole-edges N   leave holes with more border edges open\n"
    "  --max-hole-size F    leave holes wider than F x bounding-box diagonal open\n"
    "  --sheet-border-ratio F  a border whose flat filling has more than F x the area of its\n"
    "                       component is an open sheet's outline, left open (default 0.9)\n"
    "  --fill-sheet-borders fill the outlines of open sheets too\n"
    "  --seed S             random seed of the randomised methods (default 0)\n"
    "  --no-ring-holes      fill every border cycle on its own (no island detection)\n"
    "  --threads N          threads for independent holes (default: all cores); the output\n"
    "                       is the same for every N\n"
    "  --report R.json      write one JSON entry per hole\n"
    "  --picture P.png      draw the filled holes (the 12 largest) and the holes left open with\n"
    "                       their surroundings, each patch coloured by the method that filled\n"
    "                       it, borders in black; needs python3-matplotlib (without it one\n"
    "                       line says so and the rest of the command still succeeds)\n"
    "  --quiet              no progress bar, no summary\n"
    "curvature_variation (Pernot et al., doc/curvature_variation.md):\n"
    "  --objective O        forces (eq. 8) or force_variation (eq. 9, default)\n"
    "  --nodes N            nodes summed: free, or free_and_contour (default)\n"
    "  --grid G             topological grid: disc or refined_liepa (default)\n"
    "  --force-density D    uniform, inverse_length or cotangent (default)\n"
    "  --constraints FILE   lines 'point X Y Z', 'polyline X1 Y1 Z1 X2 Y2 Z2 ...',\n"
    "                       'spacing S', '# comment': points the patches must pass through\n"
    "\n"
    "OUT is read back as CGAL's read_polygon_mesh reads it (coincident points merged); the\n"
    "closedness reported is that reading's.\n"
    "Exit status: 0 every hole filled and OUT, read back, closed; 3 every selected hole filled,\n"
    "the others left open on purpose (--max-hole-edges, --max-hole-size, outlines of open\n"
    "sheets); 1 some hole left open, or OUT read back has more border cycles than the filled\n"
    "mesh; 2 bad usage or unreadable input.\n";

namespace {

CGAL::Mesh_repair::Fill_method parse_method(const std::string& name) {
  CGAL::Mesh_repair::Fill_method method;
  if (!CGAL::Mesh_repair::fill_method_from_string(name, method))
    throw Input_error("unknown --method " + name + " (see --help)");
  return method;
}

void print_summary(const CGAL::Mesh_repair::Fill_result& result,
                   const CGAL::Mesh_repair::Written_mesh_check& written) {
  namespace MR = CGAL::Mesh_repair;
  std::cout << result.holes.size() << " hole(s): " << result.filled << " filled, " << result.failed
            << " failed, " << result.skipped << " left open by selection (" << result.sheet_borders
            << " of them outlines of open sheets)\n";
  for (std::size_t k = 0; k < result.holes.size(); ++k) {
    const MR::Hole_fill_report& hole = result.holes[k];
    std::cout << "  hole " << k << ": " << hole.border_edges << " border edges";
    if (hole.island_cycles > 0) std::cout << ", " << hole.island_cycles << " island(s)";
    if (hole.skipped) {
      std::cout << (hole.sheet_border ? ", left open: " + hole.failure : ", not selected") << '\n';
      continue;
    }
    if (hole.filled) {
      std::cout << ", filled by " << MR::to_string(hole.used) << " (" << hole.faces_created
                << " faces)";
    } else {
      std::cout << ", FAILED: " << hole.failure;
    }
    for (const std::string& fallback : hole.fallbacks) std::cout << "; tried " << fallback;
    std::cout << "\n";
  }
  if (!written.readable) {
    std::cout << "the written file cannot be read back: " << written.error << '\n';
    return;
  }
  std::cout << "output read back: " << written.vertices << " vertices, " << written.faces
            << " faces, " << (written.closed ? "closed" : "open") << " (" << written.border_cycles
            << " border cycle(s)), " << (written.manifold() ? "manifold" : "non-manifold") << '\n';
}

// 0 complete, 3 complete but for the holes left open on purpose, 1 incomplete (see fill_help).
int fill_status(const CGAL::Mesh_repair::Fill_result& result, std::size_t border_cycles_in_memory,
                const CGAL::Mesh_repair::Written_mesh_check& written) {
  if (!result.all_filled() || !written.readable || !written.valid ||
      written.border_cycles > border_cycles_in_memory)
    return exit_incomplete;
  if (result.skipped > 0) return exit_complete_except_kept;
  return written.closed ? exit_success : exit_incomplete;
}

struct Curvature_options {
  CGAL::Mesh_repair::Curvature_objective objective =
      CGAL::Mesh_repair::Curvature_objective::force_variation;
  CGAL::Mesh_repair::Objective_nodes nodes =
      CGAL::Mesh_repair::Objective_nodes::free_and_contour_nodes;
  CGAL::Mesh_repair::Topological_grid grid = CGAL::Mesh_repair::Topological_grid::refined_liepa;
  CGAL::Mesh_repair::Force_density density = CGAL::Mesh_repair::Force_density::cotangent;
  CGAL::Mesh_repair::Fill_constraints<Point> constraints;
};

Curvature_options parse_curvature_options(const Arguments& arguments) {
  namespace MR = CGAL::Mesh_repair;
  Curvature_options options;
  auto parse = [&](const char* option, auto& value, auto parser) {
    if (arguments.has(option) && !parser(arguments.get(option), value))
      throw Input_error(std::string("unknown ") + option + " " + arguments.get(option));
  };
  parse("--objective", options.objective, MR::curvature_objective_from_string);
  parse("--nodes", options.nodes, MR::objective_nodes_from_string);
  parse("--grid", options.grid, MR::topological_grid_from_string);
  parse("--force-density", options.density, MR::force_density_from_string);
  if (arguments.has("--constraints")) {
    std::ostringstream text;
    for (const std::string& line : read_option_file(arguments.get("--constraints")))
      text << line << '\n';
    std::istringstream in(text.str());
    const std::string error = MR::read_fill_constraints(in, options.constraints);
    if (!error.empty()) throw Input_error(arguments.get("--constraints") + ": " + error);
  }
  return options;
}

// --- the picture of --picture -------------------------------------------------------------

// More panels than this would be too small to read; the largest holes are the ones to look at.
constexpr std::size_t max_picture_panels = 12;

// A hole to draw: its patch (empty when left open) and border loops.
struct Shown_hole {
  std::size_t report = 0;
  std::size_t border_edges = 0;
  std::set<Mesh::Face_index> patch;
  std::vector<std::vector<Mesh::Vertex_index>> borders;
};

std::vector<Shown_hole> filled_holes(
    const Mesh& mesh, const CGAL::Mesh_repair::Fill_result& result,
    const std::vector<CGAL::Mesh_repair::Fill_patch<Mesh>>& patches) {
  std::vector<Shown_hole> shown;
  for (std::size_t k = 0; k < result.holes.size() && k < patches.size(); ++k) {
    if (!result.holes[k].filled) continue;
    Shown_hole hole{k, result.holes[k].border_edges, {}, {}};
    for (Mesh::Face_index f : patches[k].faces)
      if (!mesh.is_removed(f)) hole.patch.insert(f);
    if (hole.patch.empty()) continue;
    hole.borders = region_borders(mesh, hole.patch);
    shown.push_back(hole);
  }
  return shown;
}

// The holes that failed are border cycles of the output; the report of each is the failed one
// of the same border size (the reports do not keep a border halfedge).
std::vector<Shown_hole> open_holes(const Mesh& mesh, const CGAL::Mesh_repair::Fill_result& result) {
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  std::vector<bool> matched(result.holes.size(), false);
  std::vector<Shown_hole> shown;
  for (Mesh::Halfedge_index h : cycles) {
    std::vector<Mesh::Vertex_index> loop = border_loop(mesh, h);
    for (std::size_t k = 0; k < result.holes.size(); ++k) {
      const auto& report = result.holes[k];
      if (matched[k] || report.filled || report.skipped || report.border_edges != loop.size())
        continue;
      matched[k] = true;
      shown.push_back({k, loop.size(), {}, {loop}});
      break;
    }
  }
  return shown;
}

std::string shorten(const std::string& text, std::size_t length) {
  return text.size() <= length ? text : text.substr(0, length - 3) + "...";
}

// What filled a hole, for the picture: the method, or the last resort that closed it when the
// methods' patches were rejected (its report's `used` is then Liepa, whose stages the last
// resorts are; the note names the stage: "filled by base: ...").
std::string patch_label(const CGAL::Mesh_repair::Hole_fill_report& report) {
  const std::string prefix = "filled by ";
  for (const std::string& note : report.notes) {
    if (note.rfind(prefix, 0) != 0) continue;
    const std::size_t end = note.find(": the patches of the methods before it were rejected");
    if (end != std::string::npos) return note.substr(prefix.size(), end - prefix.size());
  }
  return CGAL::Mesh_repair::to_string(report.used);
}

// Each patch face's legend index: the method that filled its hole.
std::map<Mesh::Face_index, double> faces_by_method(const CGAL::Mesh_repair::Fill_result& result,
                                                   const std::vector<Shown_hole>& filled,
                                                   std::vector<std::string>& legend) {
  std::map<Mesh::Face_index, double> category;
  for (const Shown_hole& hole : filled) {
    const std::string name = patch_label(result.holes[hole.report]);
    auto it = std::find(legend.begin(), legend.end(), name);
    if (it == legend.end()) it = legend.insert(legend.end(), name);
    for (Mesh::Face_index f : hole.patch) category[f] = double(it - legend.begin());
  }
  return category;
}

Picture_panel hole_panel(const Mesh& mesh, const Shown_hole& hole,
                         const CGAL::Mesh_repair::Hole_fill_report& report,
                         const std::map<Mesh::Face_index, double>& category) {
  Picture_panel panel;
  Panel_builder builder(panel);
  std::vector<Mesh::Vertex_index> seeds;
  for (const auto& loop : hole.borders) seeds.insert(seeds.end(), loop.begin(), loop.end());
  const auto around =
      surrounding_faces(mesh, seeds, surrounding_rings(hole.border_edges), hole.patch);
  for (Mesh::Face_index f : hole.patch) builder.add_face(mesh, f, category.at(f));
  for (Mesh::Face_index f : around) {
    const auto it = category.find(f);  // a neighbouring hole's patch keeps its colour
    builder.add_face(mesh, f, it == category.end() ? std::nan("") : it->second);
  }
  for (const auto& loop : hole.borders) builder.add_border(mesh, loop);
  panel.normal = hole.patch.empty() ? mean_normal(mesh, around) : mean_normal(mesh, hole.patch);
  panel.title = "hole " + std::to_string(hole.report) + ": " + std::to_string(hole.border_edges) +
                " border edges";
  panel.subtitle =
      report.filled ? patch_label(report) + ", " + std::to_string(report.faces_created) + " faces"
                    : "left open: " + shorten(report.failure, 80);
  return panel;
}

Picture_scene fill_scene(const std::string& input, const Mesh& mesh,
                         const CGAL::Mesh_repair::Fill_result& result,
                         const std::vector<CGAL::Mesh_repair::Fill_patch<Mesh>>& patches) {
  std::vector<Shown_hole> holes = filled_holes(mesh, result, patches);
  Picture_scene scene;
  scene.by_category = true;
  const auto category = faces_by_method(result, holes, scene.legend);
  const std::vector<Shown_hole> open = open_holes(mesh, result);
  holes.insert(holes.end(), open.begin(), open.end());
  std::stable_sort(holes.begin(), holes.end(), [](const Shown_hole& a, const Shown_hole& b) {
    return a.border_edges > b.border_edges;
  });
  const std::size_t total = holes.size();
  holes.resize(std::min(holes.size(), max_picture_panels));
  for (const Shown_hole& hole : holes)
    scene.panels.push_back(hole_panel(mesh, hole, result.holes[hole.report], category));
  scene.title =
      std::filesystem::path(input).filename().string() + ": " + std::to_string(result.filled) +
      " hole(s) filled, " + std::to_string(result.failed) + " left open" +
      (total > holes.size() ? "; the " + std::to_string(holes.size()) + " largest shown" : "");
  return scene;
}

// Writes the scene beside the picture, renders it, removes the scene. The mesh is written by
// then: a picture that cannot be made is one line, not a failure of the fill.
void write_fill_picture(const std::string& picture, const Picture_scene& scene) {
  if (scene.panels.empty()) {
    std::cerr << "mesh_repair fill: no picture: no hole was filled or left open\n";
    return;
  }
  const std::string scene_file = picture + ".scene-" + std::to_string(::getpid()) + ".json";
  try {
    save_text(scene_file, scene_json(scene));
  } catch (const Input_error& e) {
    std::cerr << "mesh_repair fill: no picture: " << e.what() << '\n';
    return;
  }
  render_pictures({{scene_file, picture}}, "mesh_repair fill");
  std::error_code ignored;
  std::filesystem::remove(scene_file, ignored);
}

}  // namespace

int run_fill(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  Arguments arguments(args, {"--quiet", "--no-ring-holes", "--fill-sheet-borders"},
                      {"-o", "--method", "--continuity", "--max-hole-edges", "--max-hole-size",
                       "--seed", "--threads", "--report", "--objective", "--nodes", "--grid",
                       "--force-density", "--constraints", "--sheet-border-ratio", "--picture"});
  const std::string input = arguments.single_input(fill_help);
  if (!arguments.has("-o")) throw Input_error("missing -o OUT; " + usage_line(fill_help));
  const MR::Fill_method method = parse_method(arguments.get("--method", "self_validated"));
  const long long continuity = arguments.get_int("--continuity", 1);
  if (continuity < 0 || continuity > 2) throw Input_error("--continuity must be 0, 1 or 2");
  const long long max_edges = arguments.get_int("--max-hole-edges", -1);
  if (arguments.has("--max-hole-edges") && max_edges < 3)
    throw Input_error("--max-hole-edges must be at least 3");
  const double max_size = arguments.get_double("--max-hole-size", -1);
  if (arguments.has("--max-hole-size") && !(max_size > 0))
    throw Input_error("--max-hole-size must be positive");
  const bool fill_sheets = arguments.has("--fill-sheet-borders");
  if (fill_sheets && arguments.has("--sheet-border-ratio"))
    throw Input_error("give either --sheet-border-ratio or --fill-sheet-borders");
  const double sheet_ratio = fill_sheets ? std::numeric_limits<double>::infinity()
                                         : arguments.get_double("--sheet-border-ratio", 0.9);
  if (!(sheet_ratio > 0)) throw Input_error("--sheet-border-ratio must be positive");
  const std::string picture = arguments.get("--picture");
  if (arguments.has("--picture") && std::filesystem::path(picture).extension() != ".png")
    throw Input_error("--picture expects a .png file, got '" + picture + "'");
  const long long seed = arguments.get_int("--seed", 0);
  if (seed < 0) throw Input_error("--seed must be non-negative");
  const long long threads = arguments.get_int("--threads", 0);
  if (arguments.has("--threads") && threads < 1) throw Input_error("--threads must be positive");

  const Curvature_options curvature = parse_curvature_options(arguments);

  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  if (!CGAL::is_triangle_mesh(mesh)) throw Input_error(input + ": not a triangle mesh");

  Progress_bar progress(progress_wanted(arguments));
  std::vector<MR::Fill_patch<Mesh>> patches;
  const MR::Fill_result result = MR::fill_holes(
      mesh, patches,
      MR::parameters::fill_method(method)
          .fairing_continuity(unsigned(continuity))
          .max_hole_edges(max_edges < 0 ? std::numeric_limits<std::size_t>::max()
                                        : std::size_t(max_edges))
          .max_hole_size(max_size < 0 ? std::numeric_limits<double>::infinity() : max_size)
          .sheet_border_ratio(sheet_ratio)
          .random_seed(unsigned(seed))
          .number_of_threads(int(std::min<long long>(threads, 1024)))
          .detect_ring_holes(!arguments.has("--no-ring-holes"))
          .visitor(std::ref(progress))
          .curvature_objective(curvature.objective)
          .objective_nodes(curvature.nodes)
          .topological_grid(curvature.grid)
          .force_density(curvature.density)
          .fill_constraints(curvature.constraints));
  if (result.cancelled) throw Input_error("interrupted");

  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  save_mesh(arguments.get("-o"), mesh);
  Mesh written;
  const MR::Written_mesh_check written_check = MR::check_written_mesh(arguments.get("-o"), written);
  const int status = fill_status(result, cycles.size(), written_check);
  if (!arguments.has("--quiet")) print_summary(result, written_check);
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    json.begin_object();
    json.key("input").value(input);
    json.key("output").value(arguments.get("-o"));
    json.key("method").value(MR::to_string(method));
    json.key("status").value(status == exit_success                ? "complete"
                             : status == exit_complete_except_kept ? "complete_except_kept"
                                                                   : "incomplete");
    json.key("output_closed").value(written_check.closed);
    json.key("written_file");
    MR::write_json(json, written_check);
    json.key("result");
    MR::write_json(json, result);
    json.end_object();
    text << "\n";
    save_text(arguments.get("--report"), text.str());
  }
  if (!picture.empty()) write_fill_picture(picture, fill_scene(input, mesh, result, patches));
  return status;
}

}  // namespace mesh_repair_cli
