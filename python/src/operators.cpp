// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The operators of the Python module, on the compiled core's mesh type: each loads its input the
// way the CLI does (soup stage counted), calls one library operator with the caller's options and
// the Python visitor, and returns the new arrays and the report the matching CLI command writes
// with --report / --json, built from the library's write_json overloads. No Python in here.
#include "binding.h"

#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Mesh_repair/bench_holes.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/internal/soup_validation.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/mesh_points.h>
#include <CGAL/Mesh_repair/optimize_mesh.h>
#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/remove_slivers.h>
#include <CGAL/Mesh_repair/smooth_mesh.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>
#include <CGAL/Mesh_repair/suppress_feature.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>

namespace mesh_repair_python {
namespace {

namespace MR = CGAL::Mesh_repair;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string input_name(const Mesh_input& input) {
  return input.path.empty() ? input.name : input.path;
}

double bbox_diagonal(const Mesh& mesh) {
  if (mesh.number_of_vertices() == 0) return 0;
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

// The CLI's --tolerance / --tolerance-rel: absolute, or a fraction of the bounding-box diagonal;
// negative when neither is given (the operators then derive it).
double tolerance(double absolute, double relative, const Mesh& mesh) {
  if (absolute >= 0) return absolute;
  return relative >= 0 ? relative * bbox_diagonal(mesh) : -1;
}

std::size_t border_cycles(const Mesh& mesh) {
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  return cycles.size();
}

MR::Fill_method fill_method(const std::string& name, const char* option) {
  MR::Fill_method method;
  if (!MR::fill_method_from_string(name, method))
    throw Input_error(std::string(option) +
                      " expects auto, advancing_front, shape_prediction, curvature_variation, "
                      "liepa or self_validated, got '" +
                      name + "'");
  return method;
}

void throw_if_cancelled(const Python_visitor& visitor) {
  if (visitor.cancelled()) throw Cancelled();
}

// The opening members every report shares: where the mesh came from and where it went (null:
// the caller got arrays, no file was written).
void open_report(MR::Json_writer& json, const Mesh_input& input) {
  json.begin_object().field("input", input_name(input));
  json.key("output").raw("null");
}

Operator_output finish(Mesh& mesh, std::ostringstream& text) {
  Operator_output out;
  out.mesh = mesh_arrays(mesh);
  out.report = text.str();
  return out;
}

// The points of `mesh_points`: a point file read as the CLI reads it, or the caller's points,
// checked as a file's are.
std::vector<Point> load_points(Mesh_input& input) {
  std::vector<Point> points;
  std::string error;
  if (!input.path.empty()) {
    error = MR::read_point_file(input.path, points);
  } else {
    points = std::move(input.soup.points);
    error = points.size() < 3 ? input.name + ": fewer than three points"
                              : MR::internal::validate_points(input.name, points);
  }
  if (!error.empty()) throw Input_error(error);
  return points;
}

// The Python side of `run_hole_benchmark`: each row into the report's `results` array, the
// holes that did not fit into `shortfalls`, and the visitor's progress after each method (where
// a pending Ctrl-C stops the benchmark).
class Bench_collector : public MR::Hole_bench_default_observer {
 public:
  Bench_collector(MR::Json_writer& json, Python_visitor& visitor, std::size_t total)
      : json_(json), visitor_(visitor), total_(total) {}

  template <class Punch_result>
  void punched(const Mesh&, const Punch_result& punched, double radius, unsigned seed) {
    if (!punched.shortfall.empty()) shortfalls.push_back({radius, seed, punched.shortfall});
  }

  bool filled(const MR::Hole_bench_fill<Mesh>& run, const MR::Bench_method&) {
    for (const MR::Hole_bench_row& row : run.rows) MR::write_json(json_, row);
    return visitor_.progress(double(++done_) / double(total_));
  }

  struct Shortfall {
    double radius;
    unsigned seed;
    std::string reason;
  };
  std::vector<Shortfall> shortfalls;

 private:
  MR::Json_writer& json_;
  Python_visitor& visitor_;
  std::size_t total_, done_ = 0;
};

MR::Hole_bench_options bench_options(const Bench_options& options) {
  MR::Hole_bench_options bench;
  const std::string error = MR::bench_methods_from_names(options.methods, bench.methods);
  if (!error.empty()) throw Input_error("methods: " + error);
  if (!MR::hole_shape_from_string(options.shape, bench.shape))
    throw Input_error("shape expects disc, jagged, elongated or ring, got '" + options.shape + "'");
  bench.holes = std::size_t(options.holes);
  bench.radii = options.radius;
  bench.seeds = options.seeds;
  return bench;
}

}  // namespace

void load_mesh(Mesh_input& input, Mesh& mesh, MR::Soup_repair_report& soup) {
  if (!input.path.empty()) {
    const std::string error = MR::read_mesh(input.path, mesh, soup);
    if (!error.empty()) throw Input_error(error);
    return;
  }
  // The arrays get the checks and the soup stage a file gets after its reader.
  std::string error =
      MR::internal::validate_soup(input.name, input.soup.points, input.soup.polygons);
  // The soup is module.cpp's copy of the arrays: the soup stage may consume it.
  if (error.empty())
    error = MR::repaired_soup_to_mesh(input.soup, mesh, soup, MR::Read_options(), input.name);
  input.soup = Soup();  // freed here, as read_mesh frees its own: a million small vectors
  if (!error.empty()) throw Input_error(error);
}

Mesh_output mesh_arrays(const Mesh& mesh) {
  Mesh_output out;
  std::vector<std::int64_t> index(mesh.num_vertices(), -1);  // removed ones included
  out.points.reserve(3 * mesh.number_of_vertices());
  std::int64_t next = 0;
  for (auto v : mesh.vertices()) {
    index[v.idx()] = next++;
    const Point& p = mesh.point(v);
    out.points.insert(out.points.end(), {p.x(), p.y(), p.z()});
  }
  std::size_t degree = 0;
  bool uniform = true;
  for (auto f : mesh.faces()) {
    const std::size_t d = mesh.degree(f);
    uniform = uniform && (degree == 0 || d == degree);
    degree = d;
  }
  out.face_degree = degree == 0 ? 3 : degree;
  if (uniform) out.corners.reserve(out.face_degree * mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    std::vector<std::int64_t> polygon;
    for (auto v : vertices_around_face(mesh.halfedge(f), mesh))
      (uniform ? out.corners : polygon).push_back(index[v.idx()]);
    if (!uniform) out.polygons.push_back(std::move(polygon));
  }
  return out;
}

Operator_output read(const Mesh_input& input, bool repair_soup) {
  Mesh mesh;
  MR::Soup_repair_report soup;
  MR::Read_options options;
  options.repair_soup = repair_soup;
  const std::string error = MR::read_mesh(input.path, mesh, soup, options);
  if (!error.empty()) throw Input_error(error);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  json.begin_object().field("input", input.path);
  json.field("vertices", mesh.number_of_vertices()).field("faces", mesh.number_of_faces());
  json.key("soup_repair");
  MR::write_json(json, soup);
  json.end_object();
  return finish(mesh, text);
}

std::string write(const std::string& path, const Mesh_input& input, bool binary) {
  if (MR::mesh_format(path).empty())
    throw Input_error(path + ": unknown output format (use .off, .obj, .stl or .ply)");
  // Written as given: checked like a file's soup, but not repaired (that is `repair`'s job).
  std::string error =
      MR::internal::validate_soup(input.name, input.soup.points, input.soup.polygons);
  if (!error.empty()) throw Input_error(error);
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(input.soup.polygons))
    throw Input_error(input.name +
                      ": not a valid polygon mesh (non-manifold or inconsistently oriented "
                      "faces); repair it first");
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(input.soup.points,
                                                              input.soup.polygons, mesh);
  error = MR::write_mesh(path, mesh, binary);
  if (!error.empty()) throw Input_error(error);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  json.begin_object().field("output", path);
  json.field("vertices", mesh.number_of_vertices()).field("faces", mesh.number_of_faces());
  json.field("binary", binary).end_object();
  return text.str();
}

Operator_output check(Mesh_input& input, const Check_options& options, Python_visitor& visitor) {
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  MR::Defect_report report = MR::detect_defects(
      mesh,
      MR::parameters::merge_tolerance(tolerance(options.tolerance, options.tolerance_rel, mesh))
          .detect_self_intersections(options.self_intersections)
          .visitor(std::ref(visitor)));
  throw_if_cancelled(visitor);
  MR::add_soup_repair_report(report, soup, mesh);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  MR::write_json(json, report);
  Operator_output out;  // no arrays: the mesh is the caller's, unchanged
  out.report = text.str();
  return out;
}

Operator_output repair(Mesh_input& input, const Repair_options& options, Python_visitor& visitor) {
  const auto start = Clock::now();
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  const double merge_tolerance = tolerance(options.tolerance, options.tolerance_rel, mesh);
  // As `mesh_repair repair`: defects before (soup stage merged in) and after, self-intersections
  // counted by the pipeline itself. The visitor goes to them too: on a large mesh they are
  // seconds without another chance to see Ctrl-C.
  MR::Defect_report before =
      MR::detect_defects(mesh, MR::parameters::merge_tolerance(merge_tolerance)
                                   .detect_self_intersections(false)
                                   .visitor(std::ref(visitor)));
  throw_if_cancelled(visitor);
  MR::add_soup_repair_report(before, soup, mesh);
  const MR::Repair_result result = MR::automatic_repair(
      mesh, MR::parameters::merge_tolerance(merge_tolerance)
                .fill_method(fill_method(options.fill, "fill"))
                .fairing_continuity(unsigned(options.continuity))
                .max_hole_size(options.max_hole_size)
                .max_hole_edges(options.max_hole_edges < 0 ? std::numeric_limits<std::size_t>::max()
                                                           : std::size_t(options.max_hole_edges))
                .sheet_border_ratio(options.sheet_border_ratio)
                .keep_largest_component(options.largest_component)
                .detect_ring_holes(options.ring_holes)
                .detect_self_intersections(options.self_intersections)
                .repair_self_intersections(options.remove_self_intersections &&
                                           options.self_intersections)
                .merge_intersecting_solids(options.merge_intersecting_solids)
                .remove_hole_fragments(options.remove_hole_fragments)
                .bridge_through_holes(options.bridge_through_holes)
                .orient_closed_parts(options.orient_closed_parts)
                .number_of_threads(options.threads)
                .random_seed(options.seed)
                .visitor(std::ref(visitor)));
  throw_if_cancelled(visitor);
  const MR::Defect_report after =
      MR::detect_defects(mesh, MR::parameters::merge_tolerance(merge_tolerance)
                                   .detect_self_intersections(false)
                                   .visitor(std::ref(visitor)));
  throw_if_cancelled(visitor);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  open_report(json, input);
  json.field("seconds", seconds_since(start));
  json.key("soup_repair");
  MR::write_json(json, soup);
  json.key("defects_before");
  MR::write_json(json, before);
  json.key("defects_after");
  MR::write_json(json, after);
  json.key("repair");
  MR::write_json(json, result);
  json.end_object();
  return finish(mesh, text);
}

Operator_output fill_holes(Mesh_input& input, const Fill_options& options,
                           Python_visitor& visitor) {
  const MR::Fill_method method = fill_method(options.method, "method");
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  if (!CGAL::is_triangle_mesh(mesh)) throw Input_error(input_name(input) + ": not a triangle mesh");
  const MR::Fill_result result = MR::fill_holes(
      mesh, MR::parameters::fill_method(method)
                .fairing_continuity(unsigned(options.continuity))
                .max_hole_edges(options.max_hole_edges < 0 ? std::numeric_limits<std::size_t>::max()
                                                           : std::size_t(options.max_hole_edges))
                .max_hole_size(options.max_hole_size < 0 ? std::numeric_limits<double>::infinity()
                                                         : options.max_hole_size)
                .sheet_border_ratio(options.sheet_border_ratio)
                .random_seed(options.seed)
                .number_of_threads(options.threads)
                .detect_ring_holes(options.ring_holes)
                .visitor(std::ref(visitor)));
  throw_if_cancelled(visitor);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  open_report(json, input);
  json.field("method", MR::to_string(method)).field("output_closed", CGAL::is_closed(mesh));
  json.key("result");
  MR::write_json(json, result);
  json.end_object();
  return finish(mesh, text);
}

Operator_output stitch(Mesh_input& input, const Stitch_options& options, Python_visitor& visitor) {
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  const std::size_t faces_before = mesh.number_of_faces();
  const std::size_t cycles_before = border_cycles(mesh);
  const auto start = Clock::now();
  const MR::Stitch_result result = MR::stitch_gaps(
      mesh,
      MR::parameters::merge_tolerance(tolerance(options.tolerance, options.tolerance_rel, mesh))
          .use_cubic_curves(options.curves)
          .check_self_intersections(options.check_self_intersections)
          .visitor(std::ref(visitor)));
  const double seconds = seconds_since(start);
  throw_if_cancelled(visitor);
  const std::size_t cycles_after = border_cycles(mesh);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  open_report(json, input);
  json.key("soup");
  MR::write_json(json, soup);
  json.field("faces_before", faces_before).field("faces_after", mesh.number_of_faces());
  json.field("border_cycles_before", cycles_before).field("border_cycles_after", cycles_after);
  json.field("closed", cycles_after == 0).field("seconds", seconds);
  json.key("stitch");
  MR::write_json(json, result);
  json.end_object();
  return finish(mesh, text);
}

Operator_output remove_slivers(Mesh_input& input, const Sliver_options& options,
                               Python_visitor& visitor) {
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  if (!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  const std::size_t faces_before = mesh.number_of_faces();
  const auto start = Clock::now();
  const MR::Sliver_result result =
      MR::remove_slivers(mesh, MR::parameters::shape_factor_threshold(options.shape_factor)
                                   .feature_angle_deg(options.feature_angle)
                                   .tolerance_edge_length(options.edge_length)
                                   .visitor(std::ref(visitor)));
  const double seconds = seconds_since(start);
  throw_if_cancelled(visitor);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  open_report(json, input);
  json.key("soup");
  MR::write_json(json, soup);
  json.field("faces_before", faces_before).field("faces_after", mesh.number_of_faces());
  json.field("seconds", seconds);
  json.key("slivers");
  MR::write_json(json, result);
  json.end_object();
  return finish(mesh, text);
}

Operator_output optimize(Mesh_input& input, const Optimize_options& options,
                         Python_visitor& visitor) {
  if (options.mode != "reduction" && options.mode != "quality")
    throw Input_error("mode must be reduction or quality, got '" + options.mode + "'");
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  if (!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  // The CLI's targets: --target-faces, else --target-ratio (default 0.5, or 0 when only the
  // deviation bound stops the reduction).
  double ratio = options.target_ratio;
  if (ratio < 0) ratio = std::isfinite(options.max_deviation) ? 0.0 : 0.5;
  const std::size_t target_faces =
      options.target_faces >= 0 ? std::size_t(options.target_faces)
                                : std::size_t(std::llround(ratio * double(mesh.number_of_faces())));
  const auto quality_before = MR::quality_statistics(mesh);
  const auto start = Clock::now();
  const MR::Optimization_result result = MR::optimize_mesh(
      mesh, MR::parameters::optimization_mode(options.mode == "reduction"
                                                  ? MR::Optimization_mode::reduction
                                                  : MR::Optimization_mode::quality)
                .target_face_count(target_faces)
                .weighing_factor_threshold(options.max_deviation)
                .feature_angle_deg(options.feature_angle)
                .min_angle_floor_deg(options.min_angle)
                .random_seed(options.seed)
                .visitor(std::ref(visitor)));
  const double seconds = seconds_since(start);
  throw_if_cancelled(visitor);
  mesh.collect_garbage();
  const auto quality_after = MR::quality_statistics(mesh);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  open_report(json, input);
  json.field("mode", options.mode);
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
  return finish(mesh, text);
}

Operator_output suppress_feature(Mesh_input& input, const Suppress_options& options,
                                 Python_visitor& visitor) {
  const MR::Fill_method method = fill_method(options.method, "method");
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  std::vector<Mesh::Face_index> faces;
  for (const std::int64_t index : options.faces) {
    if (index < 0 || index >= std::int64_t(mesh.number_of_faces()))
      throw Input_error("faces_to_remove: index " + std::to_string(index) + " out of range (" +
                        std::to_string(mesh.number_of_faces()) + " faces)");
    faces.push_back(Mesh::Face_index(Mesh::size_type(index)));
  }
  if (faces.empty()) throw Input_error("the selection contains no face");
  const auto suppression = MR::suppress_feature(
      mesh, faces,
      MR::parameters::fill_method(method).random_seed(options.seed).visitor(std::ref(visitor)));
  throw_if_cancelled(visitor);
  mesh.collect_garbage();
  // The keys of `mesh_repair suppress --report` (the implants are not written here).
  std::ostringstream text;
  MR::Json_writer json(text, false);
  json.begin_object().field("input", input_name(input));
  json.field("removed_faces", faces.size()).field("method", MR::to_string(method));
  json.key("holes").begin_array();
  for (const auto& r : suppression.holes) {
    json.begin_object().field("filled", r.filled).field("used", MR::to_string(r.used));
    json.field("border_edges", r.border_edges).field("faces_created", r.faces_created);
    json.field("vertices_created", r.vertices_created).field("failure", r.failure);
    json.field("seconds", r.seconds).end_object();
  }
  json.end_array().field("implant_patches_written", 0).end_object();
  return finish(mesh, text);
}

Operator_output smooth(Mesh_input& input, const Smooth_options& options, Python_visitor& visitor) {
  MR::Smooth_mesh_options o;
  if (!MR::smoothing_method_from_string(options.method, o.method))
    throw Input_error("method must be mga, cg or cgal, got '" + options.method + "'");
  o.quads = options.quads;
  o.iterations = options.iterations;
  o.seed = options.seed;
  o.threads = options.threads;
  o.generations = options.generations;
  o.feature_angle_deg = options.feature_angle;
  o.tangent_scale = options.tangent_scale;
  o.slide_feature_nodes = options.slide_feature_nodes;
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  const MR::Smooth_mesh_result result = MR::smooth_mesh(mesh, o, MR::Any_visitor(visitor));
  throw_if_cancelled(visitor);
  std::ostringstream text;
  MR::Json_writer json(text, false);
  MR::write_report(json, input_name(input), "", result);
  return finish(mesh, text);
}

Operator_output mesh_points(Mesh_input& input, const Mesh_points_options& options,
                            Python_visitor& visitor) {
  const std::vector<Point> points = load_points(input);
  Mesh mesh;
  const MR::Mesh_points_result result =
      MR::mesh_points(points, mesh,
                      MR::parameters::feature_angle_deg(options.feature_angle)
                          .convert_to_quads(options.quads)
                          .number_of_iterations(options.smooth ? unsigned(options.iterations) : 0u)
                          .number_of_threads(options.threads)
                          .random_seed(options.seed)
                          .visitor(std::ref(visitor)));
  throw_if_cancelled(visitor);
  if (result.reconstructed_faces == 0)
    throw Input_error(input_name(input) + ": the reconstruction produced no triangle");
  std::ostringstream text;
  MR::Json_writer json(text, false);
  MR::write_report(json, input_name(input), "", result);
  return finish(mesh, text);
}

Operator_output bench_holes(Mesh_input& input, const Bench_options& options,
                            Python_visitor& visitor) {
  const MR::Hole_bench_options bench = bench_options(options);
  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  // The truth is the removed surface: an open mesh's own holes would be measured as part of it.
  const std::size_t cycles = border_cycles(mesh);
  if (cycles > 0)
    throw Input_error(input_name(input) + ": the mesh is not closed (" + std::to_string(cycles) +
                      " border cycles); bench_holes punches holes into a closed mesh");
  const std::string name =
      input.path.empty() ? input.name : std::filesystem::path(input.path).stem().string();
  std::ostringstream text;
  MR::Json_writer json(text, false);
  json.begin_object().field("input", input_name(input));
  json.key("methods").begin_array();
  for (const MR::Bench_method& m : bench.methods) json.value(m.name);
  json.end_array().key("results").begin_array();
  Bench_collector collector(json, visitor,
                            bench.radii.size() * bench.seeds.size() * bench.methods.size());
  visitor.start_step("bench holes");
  MR::run_hole_benchmark(mesh, MR::bench_surface(mesh, name), bench, collector);
  visitor.end_step("bench holes");
  throw_if_cancelled(visitor);
  json.end_array().key("shortfalls").begin_array();
  for (const auto& s : collector.shortfalls) {
    json.begin_object().field("radius", s.radius).field("seed", s.seed);
    json.field("reason", s.reason).end_object();
  }
  json.end_array().end_object();
  Operator_output out;  // no arrays: the benchmark leaves the caller's mesh as it was
  out.report = text.str();
  return out;
}

}  // namespace mesh_repair_python
