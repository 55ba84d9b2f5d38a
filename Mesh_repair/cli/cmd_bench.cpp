// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair bench holes: the ground-truth hole-filling benchmark (doc/bench_holes.md). Punches
// holes with hole_benchmark.h, fills them with every requested method through the same
// dispatcher, measures each fill against the removed patch (or the exact surface) and writes
// results.jsonl, table.md, plots, and a picture of every hole with a page showing them.
#include "commands.h"
#include "common.h"
#include "picture.h"

#include <CGAL/Mesh_repair/bench_holes.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/json_writer.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

namespace mesh_repair_cli {

const char* const bench_help =
    "usage: mesh_repair bench holes [--mesh M]... [--meshes DIR]\n"
    "          [--analytic sphere|torus|saddle]...\n"
    "          --holes K --radius F[,F2,...] --seeds S1[,S2,...] --methods a[,b,...]|all\n"
    "          [--shape disc|jagged|elongated|ring] --out DIR [--no-plots]\n"
    "          [--no-pictures] [--plot-script plot_bench.py] [--quiet]\n"
    "Punches K holes of radius F x bounding-box diagonal into each mesh (deterministic per\n"
    "seed), fills them with every method in this process and measures each fill against the\n"
    "removed patch (exact distance on analytic surfaces): E1, E2, Einf (also / diagonal),\n"
    "Hausdorff distance, normal deviation across the border, patch quality, closedness,\n"
    "self-intersections, time. Writes DIR/results.jsonl (one line per hole x method x seed),\n"
    "DIR/table.md (median and worst per method), DIR/*.png (scripts/plot_bench.py) and, per\n"
    "hole, DIR/pictures/*.png: the truth and each method's patch with its surroundings,\n"
    "coloured by distance to the truth on one scale per hole (scripts/render_patches.py),\n"
    "shown beside each hole's figures in DIR/index.html (--no-pictures: none). Plots and\n"
    "pictures need python3-matplotlib; without it one line says so and the rest is written.\n"
    "Methods: advancing_front, liepa (CGAL's default continuity 1), liepa_c0, liepa_c1,\n"
    "liepa_c2, shape_prediction, curvature_variation (its defaults: phi_DeltaF over the free and\n"
    "contour nodes), self_validated (the hole's surroundings choose among the faired methods;\n"
    "the default of fill and repair), auto (front, then Liepa); all = every one of these but\n"
    "liepa.\n"
    "--meshes DIR adds every .off/.obj/.stl/.ply file of DIR (sorted by name): measure on your\n"
    "own closed meshes. With liepa_c1 among the methods, the table also gives each method's\n"
    "per-case ratio to it and how many cases it wins.\n"
    "Exit 0 when every case ran (failed fills are results, not errors).\n";

namespace {

namespace MR = CGAL::Mesh_repair;
using Hole = MR::Punched_hole<Mesh, Point>;

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

struct Bench_case {
  std::string name;
  std::string path;  // empty for analytic surfaces
  bool analytic = false;
  MR::Analytic_surface surface = MR::Analytic_surface::sphere;
};

struct Options {
  std::vector<Bench_case> cases;
  MR::Hole_bench_options bench;  // holes, radii, seeds, methods, shape
  std::string out;
  bool plots = true;
  bool pictures = true;
  bool progress = false;
  std::string plot_script;
};

// The mesh files of `folder` (by extension), sorted by name; one clear line when it is no folder
// or holds none.
std::vector<std::string> mesh_files_in(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::is_directory(folder, error)) throw Input_error(folder + ": --meshes expects a folder");
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (entry.is_regular_file(error) &&
        (ext == ".off" || ext == ".obj" || ext == ".stl" || ext == ".ply"))
      files.push_back(entry.path().string());
  }
  if (error) throw Input_error(folder + ": cannot be listed (" + error.message() + ")");
  if (files.empty()) throw Input_error(folder + ": holds no .off, .obj, .stl or .ply file");
  std::sort(files.begin(), files.end());
  return files;
}

Options parse_options(const std::vector<std::string>& args) {
  if (args.empty() || args[0] != "holes")
    throw Input_error("expected 'bench holes' (the only benchmark); see --help");
  const Arguments arguments(std::vector<std::string>(args.begin() + 1, args.end()),
                            {"--no-plots", "--no-pictures", "--quiet"},
                            {"--mesh", "--meshes", "--analytic", "--holes", "--radius", "--seeds",
                             "--methods", "--shape", "--out", "--plot-script"});
  if (!arguments.positional().empty())
    throw Input_error("unexpected argument '" + arguments.positional()[0] + "'");
  Options o;
  for (const std::string& name : arguments.get_all("--analytic")) {
    Bench_case c;
    if (!MR::analytic_surface_from_string(name, c.surface))
      throw Input_error("--analytic expects sphere, torus or saddle, got '" + name + "'");
    c.name = name;
    c.analytic = true;
    o.cases.push_back(c);
  }
  for (const std::string& path : arguments.get_all("--mesh"))
    o.cases.push_back({std::filesystem::path(path).stem().string(), path, false, {}});
  for (const std::string& folder : arguments.get_all("--meshes"))
    for (const std::string& path : mesh_files_in(folder))
      o.cases.push_back({std::filesystem::path(path).stem().string(), path, false, {}});
  if (o.cases.empty()) throw Input_error("give at least one --mesh, --meshes or --analytic");
  const long long holes = arguments.get_int("--holes", 1);
  if (holes < 1) throw Input_error("--holes must be at least 1");
  o.bench.holes = std::size_t(holes);
  o.bench.radii.clear();
  for (const std::string& r : split_list(arguments.get("--radius", "0.05"))) {
    const double radius = parse_double(r, "--radius");
    if (radius <= 0 || radius >= 0.5) throw Input_error("--radius must be in (0, 0.5)");
    o.bench.radii.push_back(radius);
  }
  o.bench.seeds.clear();
  for (const std::string& s : split_list(arguments.get("--seeds", "1"))) {
    const long long seed = parse_int(s, "--seeds");
    if (seed < 0) throw Input_error("--seeds must be non-negative");
    o.bench.seeds.push_back(static_cast<unsigned int>(seed));
  }
  const std::string error = MR::bench_methods_from_names(
      split_list(arguments.get("--methods", "liepa")), o.bench.methods);
  if (!error.empty()) throw Input_error("--methods: " + error);
  if (!MR::hole_shape_from_string(arguments.get("--shape", "disc"), o.bench.shape))
    throw Input_error("--shape expects disc, jagged, elongated or ring");
  o.out = arguments.get("--out");
  if (o.out.empty()) throw Input_error("--out DIR is required");
  o.plots = !arguments.has("--no-plots");
  o.pictures = !arguments.has("--no-pictures");
  o.progress = progress_wanted(arguments);
  o.plot_script = arguments.get("--plot-script");
  return o;
}

// What the tables and pictures need of a line of results.jsonl.
struct Row {
  std::string mesh, method, failure, used;
  double radius = 0;
  unsigned int seed = 0;
  std::size_t hole = 0;
  bool filled = false, closed = false, self_intersecting = false;
  bool analytic = false;
  std::map<std::string, double> values;
};

// The measures of the table: (key, label, larger is worse).
const std::vector<std::tuple<std::string, std::string, bool>>& table_measures() {
  static const std::vector<std::tuple<std::string, std::string, bool>> measures = {
      {"e1_rel", "E1/diag", true},
      {"e2_rel", "E2/diag", true},
      {"einf_rel", "Einf/diag", true},
      {"hausdorff_rel", "Hausdorff/diag", true},
      {"normal_deviation_max_deg", "normal dev. max (deg)", true},
      {"normal_deviation_mean_deg", "normal dev. mean (deg)", true},
      {"curvature_jump", "curvature jump x diag", true},
      {"min_alpha", "min alpha", false},
      {"min_angle_deg", "min angle (deg)", false},
      {"seconds", "time (s)", true}};
  return measures;
}

using Case_context = MR::Bench_surface<Point>;

Row table_row(const MR::Hole_bench_row& r) {
  const MR::Hole_fill_metrics& m = r.metrics;
  Row row;
  row.mesh = r.mesh;
  row.method = r.method;
  row.failure = r.report.failure;
  row.used = MR::to_string(r.report.used);
  row.radius = r.radius;
  row.seed = r.seed;
  row.hole = r.hole;
  row.analytic = r.analytic;
  row.filled = m.filled;
  row.closed = m.closed;
  row.self_intersecting = m.self_intersections > 0;
  row.values = {{"e2_rel", m.e2_rel},
                {"einf_rel", m.einf_rel},
                {"e1_rel", m.e1_rel},
                {"hausdorff_rel", m.hausdorff_rel},
                {"normal_deviation_max_deg", m.normal_deviation_max_deg},
                {"normal_deviation_mean_deg", m.normal_deviation_mean_deg},
                {"curvature_jump", m.curvature_jump},
                {"min_alpha", m.min_alpha},
                {"min_angle_deg", m.min_angle_deg},
                {"seconds", r.report.seconds}};
  return row;
}

// --- pictures --------------------------------------------------------------------------------

std::string format(double value);
double median(std::vector<double> values);

// A name safe in a file name and in HTML.
std::string file_name_part(const std::string& text) {
  std::string name = text;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
  return name;
}

// The picture of one hole, named after it, and the rows it shows.
struct Picture_entry {
  std::string title, picture;  // picture: relative to DIR
  std::string mesh;
  double radius = 0;
  unsigned int seed = 0;
  std::size_t hole = 0;
};

// The pictures of one punched mesh (one case, radius and seed): one scene per hole, the truth's
// panel first, then one panel per method, all from the same faces around the hole (Surface_mesh
// copies keep descriptors, so the faces around a hole of `holed` are the same in every filled
// copy, where a method may have moved the border's neighbours).
class Hole_pictures {
 public:
  Hole_pictures(const Mesh& holed, const std::vector<Hole>& holes, const Case_context& context,
                double radius, unsigned int seed)
      : holes_(holes), context_(context), radius_(radius), seed_(seed) {
    for (std::size_t i = 0; i < holes.size(); ++i) views_.push_back(truth_view(holed, i));
  }

  // The panel of `method` for each hole: its patch in `filled`, coloured by distance to the truth.
  void add_method(const Mesh& filled, const std::vector<std::vector<Mesh::Face_index>>& patches,
                  const MR::Bench_method& method, const Row* rows) {
    for (std::size_t i = 0; i < views_.size(); ++i) {
      const Row& row = rows[i];
      Picture_panel panel = method_panel(filled, i, patches[i], row);
      View& view = views_[i];
      double farthest = 0;
      for (double v : panel.values)
        if (std::isfinite(v)) farthest = std::max(farthest, v);
      (row.closed && !row.self_intersecting ? view.clean : view.other).push_back(farthest);
      // The method kept when it is not the one asked for (self_validated's choice, fallbacks).
      const bool other = row.filled && row.used != MR::to_string(method.method);
      panel.title = method.name + (other ? " (" + row.used + ")" : "");
      view.scene.panels.push_back(std::move(panel));
    }
  }

  // Writes each hole's scene as DIR/pictures/NAME.json; the pictures are NAME.png.
  void write(const std::string& out, std::vector<std::pair<std::string, std::string>>& jobs,
             std::vector<Picture_entry>& entries) {
    for (std::size_t i = 0; i < views_.size(); ++i) {
      View& view = views_[i];
      set_scale(view);
      const std::string name = file_name_part(context_.name) + "-r" + format(radius_) + "-s" +
                               std::to_string(seed_) + "-h" + std::to_string(i);
      const std::string base = out + "/pictures/" + name;
      save_text(base + ".json", scene_json(view.scene));
      jobs.emplace_back(base + ".json", base + ".png");
      entries.push_back(
          {view.scene.title, "pictures/" + name + ".png", context_.name, radius_, seed_, i});
    }
  }

 private:
  struct View {
    std::vector<Mesh::Face_index> around;
    std::vector<std::vector<Mesh::Vertex_index>> borders;
    Picture_scene scene;
    double truth_max = 0;
    std::vector<double> clean, other;  // each method's farthest face: clean patches, the rest
  };

  View truth_view(const Mesh& holed, std::size_t i) {
    const Hole& hole = holes_[i];
    View view;
    view.borders.push_back(border_loop(holed, hole.border_halfedge));
    for (Mesh::Halfedge_index h : hole.island_border_halfedges)
      view.borders.push_back(border_loop(holed, h));
    std::vector<Mesh::Vertex_index> seeds;
    for (const auto& loop : view.borders) seeds.insert(seeds.end(), loop.begin(), loop.end());
    view.around = surrounding_faces(holed, seeds, surrounding_rings(hole.outer_border_edges), {});
    const Mesh& truth = hole.removed_patch;
    view.scene.title = context_.name + ", radius " + format(radius_) + ", seed " +
                       std::to_string(seed_) + ", hole " + std::to_string(i) + ": " +
                       std::to_string(hole.outer_border_edges) + " border edges";
    view.scene.normal = mean_normal(truth, truth.faces());
    view.scene.scale_label = context_.analytic
                                 ? "distance to the exact surface / bounding-box diagonal"
                                 : "distance to the removed faces / bounding-box diagonal";
    Picture_panel panel;
    Panel_builder builder(panel);
    const std::vector<Mesh::Face_index> truth_faces(truth.faces().begin(), truth.faces().end());
    const std::vector<double> values = face_distances(truth, truth_faces, hole);
    for (std::size_t k = 0; k < truth_faces.size(); ++k) {
      builder.add_face(truth, truth_faces[k], values[k]);
      view.truth_max = std::max(view.truth_max, values[k]);  // analytic: the faceting error
    }
    add_surroundings(builder, holed, view);
    panel.title = "truth";
    panel.subtitle = "the removed faces";
    view.scene.panels.push_back(std::move(panel));
    return view;
  }

  Picture_panel method_panel(const Mesh& filled, std::size_t i,
                             const std::vector<Mesh::Face_index>& patch, const Row& row) {
    Picture_panel panel;
    Panel_builder builder(panel);
    const std::vector<double> values = face_distances(filled, patch, holes_[i]);
    for (std::size_t k = 0; k < patch.size(); ++k) builder.add_face(filled, patch[k], values[k]);
    add_surroundings(builder, filled, views_[i]);
    if (patch.empty()) {
      panel.subtitle = "not filled";
    } else {
      panel.subtitle = "Einf/diag " + format(row.values.at("einf_rel"));
      if (!row.closed) panel.subtitle += ", not closed";
      if (row.self_intersecting) panel.subtitle += ", self-intersecting";
    }
    return panel;
  }

  void add_surroundings(Panel_builder& builder, const Mesh& mesh, const View& view) const {
    for (Mesh::Face_index f : view.around) builder.add_face(mesh, f, std::nan(""));
    for (const auto& loop : view.borders) builder.add_border(mesh, loop);
  }

  // Distance of each face's centroid to the truth, over the diagonal.
  std::vector<double> face_distances(const Mesh& mesh, const std::vector<Mesh::Face_index>& faces,
                                     const Hole& hole) const {
    std::vector<Point> centroids;
    for (Mesh::Face_index f : faces) {
      const auto h = mesh.halfedge(f);
      centroids.push_back(CGAL::centroid(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                         mesh.point(mesh.target(mesh.next(h)))));
    }
    std::vector<double> d = MR::distances_to_truth(hole, centroids, context_.exact);
    for (double& v : d) v /= context_.diagonal > 0 ? context_.diagonal : 1.0;
    return d;
  }

  // One scale for every method of the hole, up to the farthest face of the patches that closed it
  // cleanly, leaving out those more than four times the median of them: one bad patch would
  // otherwise wash out every other panel (on the sphere, CGAL's C0 membrane is 20 times farther
  // than the faired fills). Farther faces take the top colour; the colour bar ends in an arrow.
  static void set_scale(View& view) {
    const std::vector<double>& maxima = view.clean.empty() ? view.other : view.clean;
    const double typical = median(maxima);
    double top = view.truth_max;
    for (double m : maxima)
      if (m <= 4 * typical) top = std::max(top, m);
    view.scene.scale_max = top > 0 ? top : 1e-6;
    for (const auto* list : {&view.clean, &view.other})
      for (double m : *list) view.scene.scale_clipped |= m > view.scene.scale_max;
  }

  const std::vector<Hole>& holes_;
  const Case_context& context_;
  double radius_;
  unsigned int seed_;
  std::vector<View> views_;
};

Mesh load_case(const Bench_case& c, Case_context& context) {
  Mesh mesh;
  if (c.analytic) {
    MR::make_analytic_mesh(mesh, c.surface);
    context = MR::bench_surface(mesh, c.name, MR::analytic_distance<Point>(c.surface));
  } else {
    MR::Soup_repair_report soup;
    load_mesh(c.path, mesh, soup);
    context = MR::bench_surface(mesh, c.name);
  }
  return mesh;
}

// The tool's side of `run_hole_benchmark`: the lines of results.jsonl, the rows of the tables,
// the warnings of holes that did not fit, the pictures of each punched mesh, the progress bar.
class Bench_collector : public MR::Hole_bench_default_observer {
 public:
  Bench_collector(const Options& options, Progress_bar& bar)
      : options_(options),
        bar_(bar),
        total_(options.cases.size() * options.bench.radii.size() * options.bench.seeds.size() *
               options.bench.methods.size()) {}

  void start_case(const Case_context& context) { context_ = &context; }

  void punched(const Mesh& holed, const MR::Punch_result<Mesh, Point>& punched, double radius,
               unsigned int seed) {
    if (!punched.shortfall.empty()) {
      warnings.push_back(context_->name + ", radius " + format(radius) + ", seed " +
                         std::to_string(seed) + ": " + punched.shortfall);
      std::cerr << "\nmesh_repair bench: " << warnings.back() << '\n';
    }
    if (options_.pictures)
      pictures_ = std::make_unique<Hole_pictures>(holed, punched.holes, *context_, radius, seed);
  }

  bool filled(const MR::Hole_bench_fill<Mesh>& run, const MR::Bench_method& method) {
    for (const MR::Hole_bench_row& row : run.rows) {
      MR::Json_writer json(jsonl, false);
      MR::write_json(json, row);  // one line
      rows.push_back(table_row(row));
    }
    if (pictures_)
      pictures_->add_method(run.mesh, run.patches, method, &rows[rows.size() - run.rows.size()]);
    return bar_.progress(double(++done_) / double(total_));
  }

  void punched_done() {
    if (pictures_) pictures_->write(options_.out, jobs, entries);
    pictures_.reset();
  }

  std::ostringstream jsonl;
  std::vector<Row> rows;
  std::vector<std::string> warnings;
  std::vector<std::pair<std::string, std::string>> jobs;  // scene file, picture
  std::vector<Picture_entry> entries;

 private:
  const Options& options_;
  Progress_bar& bar_;
  std::size_t total_, done_ = 0;
  const Case_context* context_ = nullptr;
  std::unique_ptr<Hole_pictures> pictures_;
};

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string format(double value) {
  if (!std::isfinite(value)) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

std::vector<std::string> method_order(const std::vector<Row>& rows) {
  std::vector<std::string> order;
  for (const Row& row : rows)
    if (std::find(order.begin(), order.end(), row.method) == order.end())
      order.push_back(row.method);
  return order;
}

void summary_table(std::ostream& out, const std::vector<Row>& rows) {
  out << "| method | holes | filled | closed | self-intersecting |";
  for (const auto& measure : table_measures()) out << ' ' << std::get<1>(measure) << " |";
  out << "\n|---|---|---|---|---|";
  for (std::size_t i = 0; i < table_measures().size(); ++i) out << "---|";
  out << '\n';
  for (const std::string& method : method_order(rows)) {
    std::size_t holes = 0, filled = 0, closed = 0, intersecting = 0;
    for (const Row& row : rows) {
      if (row.method != method) continue;
      ++holes;
      filled += row.filled;
      closed += row.closed;
      intersecting += row.self_intersecting;
    }
    out << "| " << method << " | " << holes << " | " << filled << " | " << closed << " | "
        << intersecting << " |";
    for (const auto& [key, label, larger_is_worse] : table_measures()) {
      std::vector<double> values;
      for (const Row& row : rows) {
        if (row.method != method) continue;
        const double v = row.values.at(key);
        if (std::isfinite(v)) values.push_back(v);
      }
      double worst = std::numeric_limits<double>::quiet_NaN();
      if (!values.empty())
        worst = larger_is_worse ? *std::max_element(values.begin(), values.end())
                                : *std::min_element(values.begin(), values.end());
      out << ' ' << format(median(values)) << " / " << format(worst) << " |";
    }
    out << '\n';
  }
}

// Median Einf/diag per mesh and radius, with the count of closed holes.
void per_case_table(std::ostream& out, const std::vector<Row>& rows) {
  const std::vector<std::string> methods = method_order(rows);
  out << "| mesh | radius |";
  for (const std::string& m : methods) out << ' ' << m << " |";
  out << "\n|---|---|";
  for (std::size_t i = 0; i < methods.size(); ++i) out << "---|";
  out << '\n';
  std::vector<std::pair<std::string, double>> cases;
  for (const Row& row : rows)
    if (std::find(cases.begin(), cases.end(), std::make_pair(row.mesh, row.radius)) == cases.end())
      cases.emplace_back(row.mesh, row.radius);
  for (const auto& [mesh, radius] : cases) {
    out << "| " << mesh << " | " << format(radius) << " |";
    for (const std::string& method : methods) {
      std::vector<double> values;
      std::size_t holes = 0, closed = 0;
      for (const Row& row : rows) {
        if (row.mesh != mesh || row.radius != radius || row.method != method) continue;
        ++holes;
        closed += row.closed;
        if (std::isfinite(row.values.at("einf_rel"))) values.push_back(row.values.at("einf_rel"));
      }
      out << ' ' << format(median(values)) << " (" << closed << '/' << holes << ") |";
    }
    out << '\n';
  }
}

// Median Einf/diag and curvature jump per method on the analytic surfaces and on the meshes read
// from files (the two sets the curvature_variation goals are stated on).
void surface_kind_table(std::ostream& out, const std::vector<Row>& rows) {
  out << "| method | analytic holes | analytic Einf/diag | analytic curvature jump x diag | "
         "mesh holes | mesh Einf/diag | mesh curvature jump x diag "
         "|\n|---|---|---|---|---|---|---|\n";
  for (const std::string& method : method_order(rows)) {
    out << "| " << method << " |";
    for (bool analytic : {true, false}) {
      std::vector<double> einf, jump;
      std::size_t holes = 0;
      for (const Row& row : rows) {
        if (row.method != method || row.analytic != analytic) continue;
        ++holes;
        if (std::isfinite(row.values.at("einf_rel"))) einf.push_back(row.values.at("einf_rel"));
        if (std::isfinite(row.values.at("curvature_jump")))
          jump.push_back(row.values.at("curvature_jump"));
      }
      out << ' ' << holes << " | " << format(median(einf)) << " | " << format(median(jump)) << " |";
    }
    out << '\n';
  }
}

// Medians over the holes that every method closed: each method measured on the same holes, so a
// method that closes a hard hole the others leave open is not penalised for it.
void common_holes_table(std::ostream& out, const std::vector<Row>& rows) {
  const std::vector<std::string> methods = method_order(rows);
  using Hole_key = std::tuple<std::string, double, unsigned int, std::size_t>;
  std::map<Hole_key, std::size_t> closed_by;
  for (const Row& row : rows)
    if (row.closed) ++closed_by[Hole_key(row.mesh, row.radius, row.seed, row.hole)];
  const auto common = [&](const Row& row) {
    const auto it = closed_by.find(Hole_key(row.mesh, row.radius, row.seed, row.hole));
    return it != closed_by.end() && it->second == methods.size();
  };
  std::size_t holes = 0;
  for (const Row& row : rows) holes += row.method == methods.front() && common(row);
  out << "\nMedians over the " << holes << " holes closed by every method:\n\n";
  out << "| method | Einf/diag | E2/diag | curvature jump x diag | normal dev. max (deg) | "
         "min angle (deg) | time (s) |\n|---|---|---|---|---|---|---|\n";
  for (const std::string& method : methods) {
    out << "| " << method << " |";
    for (const char* key : {"einf_rel", "e2_rel", "curvature_jump", "normal_deviation_max_deg",
                            "min_angle_deg", "seconds"}) {
      std::vector<double> values;
      for (const Row& row : rows)
        if (row.method == method && common(row) && std::isfinite(row.values.at(key)))
          values.push_back(row.values.at(key));
      out << ' ' << format(median(values)) << " |";
    }
    out << '\n';
  }
}

// Each method against CGAL's C1 fairing (`liepa_c1`) case by case, on the holes both closed: the
// median and quartiles of the Einf ratio, and the cases it wins (strictly smaller error).
void ratio_to_c1_table(std::ostream& out, const std::vector<Row>& rows) {
  using Hole_key = std::tuple<std::string, double, unsigned int, std::size_t>;
  std::map<Hole_key, double> c1;
  for (const Row& row : rows)
    if (row.method == "liepa_c1" && row.closed && !row.self_intersecting)
      c1[Hole_key(row.mesh, row.radius, row.seed, row.hole)] = row.values.at("einf_rel");
  if (c1.empty()) return;
  out << "\nEinf against CGAL's C1 fairing (liepa_c1), per case, over the holes both closed "
         "without self-intersection:\n\n| method | cases | ratio, median | ratio, 25% | "
         "ratio, 75% | cases won |\n|---|---|---|---|---|---|\n";
  for (const std::string& method : method_order(rows)) {
    if (method == "liepa_c1") continue;
    std::vector<double> ratios;
    std::size_t won = 0;
    for (const Row& row : rows) {
      if (row.method != method || !row.closed || row.self_intersecting) continue;
      const auto ref = c1.find(Hole_key(row.mesh, row.radius, row.seed, row.hole));
      const double value = row.values.at("einf_rel");
      if (ref == c1.end() || !(ref->second > 0) || !std::isfinite(value)) continue;
      ratios.push_back(value / ref->second);
      won += value < ref->second;
    }
    if (ratios.empty()) continue;
    std::sort(ratios.begin(), ratios.end());
    out << "| " << method << " | " << ratios.size() << " | " << format(median(ratios)) << " | "
        << format(ratios[ratios.size() / 4]) << " | " << format(ratios[(3 * ratios.size()) / 4])
        << " | " << won << " |\n";
  }
}

// Why holes stayed open, per method: each distinct reason with its count.
void failure_list(std::ostream& out, const std::vector<Row>& rows) {
  std::map<std::pair<std::string, std::string>, std::size_t> reasons;
  for (const Row& row : rows)
    if (!row.closed)
      ++reasons[{row.method,
                 row.failure.empty() ? "not closed (no reason reported)" : row.failure}];
  if (reasons.empty()) return;
  out << "\nHoles not closed, by method and reason:\n\n";
  for (const auto& [key, count] : reasons)
    out << "- " << key.first << ": " << count << " x " << key.second << '\n';
}

std::string table_markdown(const std::vector<Row>& rows, const std::string& command,
                           const std::vector<std::string>& warnings) {
  std::ostringstream out;
  out << "Command: `" << command << "`\n\n";
  out << "Each cell: median / worst over every hole (worst = largest error, smallest quality). "
         "Distances divided by the bounding-box diagonal. `filled`: every border edge of the hole "
         "has a face; `closed`: filled and the patch has no border edge.\n\n";
  summary_table(out, rows);
  out << "\nMedian Einf/diag per mesh and hole radius (closed holes / holes):\n\n";
  per_case_table(out, rows);
  out << "\nMedians on the analytic surfaces and on the meshes read from files:\n\n";
  surface_kind_table(out, rows);
  common_holes_table(out, rows);
  ratio_to_c1_table(out, rows);
  failure_list(out, rows);
  for (const std::string& w : warnings) out << "\nNote: " << w << '\n';
  return out.str();
}

std::string plot_script_path(const Options& options) {
  if (!options.plot_script.empty()) return options.plot_script;
  if (const char* env = std::getenv("MESH_REPAIR_PLOT_SCRIPT")) return env;
  return script_path("plot_bench.py");
}

// Plots are a convenience: a missing script or a failing one is a warning, never a failure.
void make_plots(const Options& options) {
  const std::string script = plot_script_path(options);
  if (!std::filesystem::exists(script)) {
    std::cerr << "mesh_repair bench: plot script not found, no plots (--plot-script)\n";
    return;
  }
  if (run_python_script(script, {options.out + "/results.jsonl", options.out}) != 0)
    std::cerr << "mesh_repair bench: the plot script failed; results and table are written\n";
}

std::string html(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    if (c == '<')
      escaped += "&lt;";
    else if (c == '>')
      escaped += "&gt;";
    else if (c == '&')
      escaped += "&amp;";
    else if (c == '"')
      escaped += "&quot;";
    else
      escaped += c;
  }
  return escaped;
}

// The figures of every method on one hole, as an HTML table.
void hole_table(std::ostream& out, const Picture_entry& entry, const std::vector<Row>& rows) {
  out << "<table><tr><th>method</th><th>kept patch</th><th>closed</th><th>Einf/diag</th>"
         "<th>E2/diag</th><th>Hausdorff/diag</th><th>normal dev. max (deg)</th><th>time (s)</th>"
         "</tr>\n";
  for (const Row& row : rows) {
    if (row.mesh != entry.mesh || row.radius != entry.radius || row.seed != entry.seed ||
        row.hole != entry.hole)
      continue;
    const std::string closed = row.closed ? (row.self_intersecting ? "self-intersecting" : "yes")
                                          : (row.failure.empty() ? "no" : "no: " + row.failure);
    out << "<tr><td>" << html(row.method) << "</td><td>" << html(row.filled ? row.used : "-")
        << "</td><td>" << html(closed) << "</td>";
    for (const char* key :
         {"einf_rel", "e2_rel", "hausdorff_rel", "normal_deviation_max_deg", "seconds"})
      out << "<td>" << format(row.values.at(key)) << "</td>";
    out << "</tr>\n";
  }
  out << "</table>\n";
}

// DIR/index.html: every hole's picture beside the figures of every method on it.
std::string pictures_page(const std::vector<Picture_entry>& entries, const std::vector<Row>& rows,
                          const std::string& command, const std::string& out_dir) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>bench holes</title>\n"
         "<style>body{font-family:sans-serif;font-size:14px} .hole{display:flex;flex-wrap:wrap;"
         "gap:1em;align-items:flex-start} .hole a{flex:1 1 480px} img{max-width:100%} "
         "table{border-collapse:collapse} "
         "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right} td:first-child,"
         "th:first-child{text-align:left}</style></head><body>\n";
  out << "<h1>Hole-filling benchmark</h1>\n<p><code>" << html(command) << "</code></p>\n"
      << "<p>Medians and worst cases: <a href=\"table.md\">table.md</a>; every measure: "
         "<a href=\"results.jsonl\">results.jsonl</a> (doc/bench_holes.md). In each picture the "
         "truth and every method's patch are coloured by the distance of each face's centre to "
         "the truth over the bounding-box diagonal, on one scale per hole (up to the farthest "
         "face of the patches that closed the hole cleanly, but for those more than four times "
         "the median of them, which saturate); grey: the surface kept around the hole; black: "
         "the hole's border.</p>\n";
  for (const Picture_entry& entry : entries) {
    out << "<h3>" << html(entry.title) << "</h3>\n<div class=\"hole\">\n";
    hole_table(out, entry, rows);
    if (std::filesystem::exists(out_dir + "/" + entry.picture))
      out << "<a href=\"" << html(entry.picture) << "\"><img src=\"" << html(entry.picture)
          << "\" alt=\"" << html(entry.title) << "\"></a>\n";
    else
      out << "<p>(no picture: see the command's messages)</p>\n";
    out << "</div>\n";
  }
  out << "</body></html>\n";
  return out.str();
}

// Plots and pictures need matplotlib: without it one line says so, and the scene files stay so
// the pictures can be drawn later (scripts/render_patches.py SCENE PNG ...).
void draw(const Options& options, const std::vector<std::pair<std::string, std::string>>& jobs) {
  const std::string unavailable = plotting_unavailable();
  if (!unavailable.empty()) {
    const char* what = !options.pictures ? "no plots"
                       : options.plots   ? "no plots and no pictures"
                                         : "no pictures";
    std::cerr << "mesh_repair bench: " << what << ": " << unavailable
              << (jobs.empty() ? ""
                               : "; the pictures' scenes are kept in " + options.out +
                                     "/pictures (scripts/render_patches.py draws them)")
              << '\n';
    return;
  }
  if (options.plots) make_plots(options);
  if (jobs.empty() || !render_pictures(jobs, "mesh_repair bench")) return;
  std::error_code ignored;
  for (const auto& job : jobs) std::filesystem::remove(job.first, ignored);
}

std::string quoted_command(const std::vector<std::string>& args) {
  std::string command = "mesh_repair bench";
  for (const std::string& a : args) command += ' ' + a;
  return command;
}

}  // namespace

int run_bench(const std::vector<std::string>& args) {
  const Options options = parse_options(args);
  std::error_code error;
  std::filesystem::create_directories(options.out, error);
  if (error) throw Input_error(options.out + ": cannot be created: " + error.message());
  Progress_bar bar(options.progress);
  if (options.pictures) std::filesystem::create_directories(options.out + "/pictures", error);
  if (error) throw Input_error(options.out + "/pictures: cannot be created: " + error.message());
  Bench_collector collector(options, bar);
  bar.start_step("bench holes");
  for (const Bench_case& c : options.cases) {
    Case_context context;
    const Mesh base = load_case(c, context);
    collector.start_case(context);
    if (!MR::run_hole_benchmark(base, context, options.bench, collector)) return exit_incomplete;
  }
  bar.end_step("bench holes");
  const std::vector<Row>& rows = collector.rows;
  save_text(options.out + "/results.jsonl", collector.jsonl.str());
  save_text(options.out + "/table.md",
            table_markdown(rows, quoted_command(args), collector.warnings));
  if (options.plots || options.pictures) draw(options, collector.jobs);
  if (options.pictures)
    save_text(options.out + "/index.html",
              pictures_page(collector.entries, rows, quoted_command(args), options.out));
  std::cout << rows.size() << " results in " << options.out << "/results.jsonl, table in "
            << options.out << "/table.md"
            << (options.pictures ? ", pictures in " + options.out + "/index.html" : "") << '\n';
  return exit_success;
}

}  // namespace mesh_repair_cli
