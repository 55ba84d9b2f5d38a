// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_BENCH_HOLES_H
#define CGAL_MESH_REPAIR_BENCH_HOLES_H

/// \file bench_holes.h
/// One run of the hole-filling benchmark (doc/bench_holes.md) on one surface: for each radius
/// and seed, holes punched with `punch_holes`, each method filling a copy of the punched mesh
/// hole by hole through `fill_hole`, and every fill measured with `measure_filled_hole`; one
/// `Hole_bench_row` per hole x method x radius x seed, written by `write_json` as a line of
/// `results.jsonl`. `mesh_repair bench holes` and the Python `bench_holes` both run it; the tool
/// draws its tables and pictures from the observer's calls.
/// \code
/// auto surface = CGAL::Mesh_repair::bench_surface(mesh, "bunny");
/// CGAL::Mesh_repair::Hole_bench_options options;
/// CGAL::Mesh_repair::bench_methods_from_names({"liepa_c1", "shape_prediction"}, options.methods);
/// Collect_rows observer;  // filled(run) appends run.rows
/// CGAL::Mesh_repair::run_hole_benchmark(mesh, surface, options, observer);
/// \endcode

#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/hole_benchmark.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/json_writer.h>

#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// A method of the benchmark: its name (`--methods`), the dispatcher's method, and the fairing
/// continuity of the `liepa_cK` variants (-1: the method's default).
struct Bench_method {
  std::string name;
  Fill_method method = Fill_method::liepa;
  int continuity = -1;
};

/// Every method the benchmark knows, in the order `all` lists them (`all` leaves out `liepa`,
/// the alias of `liepa_c1`).
inline const std::vector<Bench_method>& bench_methods() {
  static const std::vector<Bench_method> methods = {
      {"advancing_front", Fill_method::advancing_front, -1},
      {"liepa", Fill_method::liepa, -1},
      {"liepa_c0", Fill_method::liepa, 0},
      {"liepa_c1", Fill_method::liepa, 1},
      {"liepa_c2", Fill_method::liepa, 2},
      {"shape_prediction", Fill_method::shape_prediction, -1},
      {"curvature_variation", Fill_method::curvature_variation, -1},
      {"self_validated", Fill_method::self_validated, -1},
      {"auto", Fill_method::automatic, -1}};
  return methods;
}

/// The methods named by `names` (`all` for every one but `liepa`) into `methods`; the one-line
/// reason when a name is unknown or none is given, else an empty string.
inline std::string bench_methods_from_names(const std::vector<std::string>& names,
                                            std::vector<Bench_method>& methods) {
  methods.clear();
  for (const std::string& name : names) {
    bool known = false;
    for (const Bench_method& m : bench_methods()) {
      if (name == "all" ? m.name != "liepa" : m.name == name) methods.push_back(m);
      known = known || name == "all" || m.name == name;
    }
    if (!known) return "unknown method '" + name + "'";
  }
  return methods.empty() ? "the benchmark needs at least one method" : std::string();
}

/// What the benchmark knows of the surface the holes are punched in.
template <class Point>
struct Bench_surface {
  std::string name;
  bool analytic = false;  ///< `exact` gives the distance to the true surface
  double diagonal = 0;    ///< of the bounding box, before punching
  std::size_t input_border_cycles = 0;
  std::function<double(const Point&)> exact;
};

/// The `Bench_surface` of `pm`, named `name`; `exact`, when given, is the unsigned distance to
/// the true surface (`analytic_distance`), used for the E norms instead of the removed faces.
template <class PolygonMesh,
          class Point = typename boost::property_traits<typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::const_type>::value_type>
Bench_surface<Point> bench_surface(const PolygonMesh& pm, const std::string& name,
                                   std::function<double(const Point&)> exact = {}) {
  Bench_surface<Point> surface;
  surface.name = name;
  surface.analytic = bool(exact);
  surface.exact = std::move(exact);
  surface.diagonal = internal::mesh_bbox_diagonal(pm, get(CGAL::vertex_point, pm));
  surface.input_border_cycles = internal::border_cycles(pm).size();
  return surface;
}

/// What the benchmark punches: `holes` holes of each radius (fraction of the bounding-box
/// diagonal) for each seed, of one shape, each filled by every method.
struct Hole_bench_options {
  std::size_t holes = 1;
  std::vector<double> radii{0.05};
  std::vector<unsigned int> seeds{1};
  std::vector<Bench_method> methods;
  Hole_shape shape = Hole_shape::disc;
};

/// One hole filled by one method, measured: a line of `results.jsonl`.
struct Hole_bench_row {
  std::string mesh, method;
  bool analytic = false;
  Hole_shape shape = Hole_shape::disc;
  double radius = 0;
  unsigned int seed = 0;
  std::size_t hole = 0;  ///< index among the holes of this radius and seed
  std::size_t border_edges = 0, island_cycles = 0, removed_faces = 0;
  double perimeter = 0, requested_radius = 0, achieved_radius = 0, diagonal = 0;
  Hole_fill_report report;    ///< what the method said (`seconds`: its time on this hole)
  Hole_fill_metrics metrics;  ///< what the benchmark measured
  bool mesh_closed = false;   ///< as many border cycles as before the punching
  bool mesh_valid = false;    ///< `CGAL::is_valid_polygon_mesh` after every hole was filled
};

/// Writes `row` as one JSON object: the keys of a line of `results.jsonl` (doc/bench_holes.md).
inline void write_json(Json_writer& json, const Hole_bench_row& row) {
  const Hole_fill_report& report = row.report;
  const Hole_fill_metrics& m = row.metrics;
  json.begin_object();
  json.field("mesh", row.mesh).field("analytic", row.analytic);
  json.field("shape", to_string(row.shape)).field("radius", row.radius).field("seed", row.seed);
  json.field("hole", row.hole).field("method", row.method);
  json.field("border_edges", row.border_edges).field("island_cycles", row.island_cycles);
  json.field("perimeter", row.perimeter).field("removed_faces", row.removed_faces);
  json.field("requested_radius", row.requested_radius);
  json.field("achieved_radius", row.achieved_radius).field("diagonal", row.diagonal);
  json.field("reported_filled", report.filled).field("failure", report.failure);
  json.field("used_method", to_string(report.used));
  json.field("detected_island_cycles", report.island_cycles);
  std::string notes;
  for (const std::string& note : report.notes) notes += (notes.empty() ? "" : "; ") + note;
  for (const std::string& fallback : report.fallbacks)
    notes += (notes.empty() ? "fallback " : "; fallback ") + fallback;
  json.field("notes", notes);
  json.field("filled", m.filled).field("closed", m.closed).field("bounded", m.bounded);
  json.field("patch_faces", m.patch_faces).field("patch_vertices", m.patch_vertices);
  json.field("samples", m.samples);
  // The measures in alphabetical order, the order results.jsonl has always had.
  json.field("curvature_jump", m.curvature_jump);
  json.field("e1", m.e1).field("e1_nodes", m.e1_nodes).field("e1_rel", m.e1_rel);
  json.field("e2", m.e2).field("e2_nodes", m.e2_nodes).field("e2_rel", m.e2_rel);
  json.field("einf", m.einf).field("einf_nodes", m.einf_nodes).field("einf_rel", m.einf_rel);
  json.field("hausdorff", m.hausdorff).field("hausdorff_rel", m.hausdorff_rel);
  json.field("mean_alpha", m.mean_alpha).field("min_alpha", m.min_alpha);
  json.field("min_angle_deg", m.min_angle_deg);
  json.field("normal_deviation_max_deg", m.normal_deviation_max_deg);
  json.field("normal_deviation_mean_deg", m.normal_deviation_mean_deg);
  json.field("seconds", report.seconds);
  json.field("self_intersections", m.self_intersections);
  json.field("mesh_closed", row.mesh_closed).field("mesh_valid", row.mesh_valid);
  json.end_object();
}

/// One method on one punched mesh: the filled copy (its descriptors are those of the punched
/// mesh), the faces now covering each hole, and one row per hole.
template <class PolygonMesh>
struct Hole_bench_fill {
  PolygonMesh mesh;
  std::vector<std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>> patches;
  std::vector<Hole_bench_row> rows;
};

namespace internal {

template <class PolygonMesh>
Hole_fill_report bench_fill_one(PolygonMesh& pm,
                                typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                                const Bench_method& method, unsigned int seed) {
  const auto start = std::chrono::steady_clock::now();
  Hole_fill_report report;
  try {
    const auto np = parameters::fill_method(method.method).random_seed(seed);
    report = method.continuity >= 0
                 ? fill_hole(pm, h, np.fairing_continuity(unsigned(method.continuity)))
                 : fill_hole(pm, h, np);
  } catch (const std::exception& e) {
    report.failure = std::string("exception: ") + e.what();
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

template <class Point, class PolygonMesh>
Hole_bench_row bench_row(const Bench_surface<Point>& surface, const Hole_bench_options& options,
                         double radius, unsigned int seed, std::size_t index,
                         const Punched_hole<PolygonMesh, Point>& hole, const Bench_method& method) {
  Hole_bench_row row;
  row.mesh = surface.name;
  row.analytic = surface.analytic;
  row.shape = options.shape;
  row.radius = radius;
  row.seed = seed;
  row.hole = index;
  row.method = method.name;
  row.border_edges = hole.outer_border_edges;
  row.island_cycles = hole.island_border_halfedges.size();
  row.perimeter = hole.outer_perimeter;
  row.removed_faces = hole.removed_faces;
  row.requested_radius = hole.requested_radius;
  row.achieved_radius = hole.achieved_radius;
  row.diagonal = surface.diagonal;
  return row;
}

}  // namespace internal

/// Fills every hole of `holed` (a copy of it) with `method`, seeded with `seed`, and measures
/// each fill against its truth: one row per hole. An exception of a method is its hole's
/// failure ("exception: ...").
template <class PolygonMesh, class Point>
Hole_bench_fill<PolygonMesh> bench_fill_holes(
    const PolygonMesh& holed, const std::vector<Punched_hole<PolygonMesh, Point>>& holes,
    const Bench_surface<Point>& surface, const Hole_bench_options& options, double radius,
    unsigned int seed, const Bench_method& method) {
  Hole_bench_fill<PolygonMesh> run{holed, {}, {}};  // copies keep descriptors: `holes` stay valid
  std::vector<Hole_fill_report> reports;
  for (const auto& hole : holes)
    reports.push_back(internal::bench_fill_one(run.mesh, hole.border_halfedge, method, seed));
  for (const auto& hole : holes) {
    bool bounded = true;
    run.patches.push_back(hole_patch_faces(run.mesh, hole, bounded));
  }
  const std::vector<std::size_t> intersections =
      CGAL::is_triangle_mesh(run.mesh) ? count_patch_self_intersections(run.mesh, run.patches)
                                       : std::vector<std::size_t>(holes.size(), 0);
  const bool valid = CGAL::is_valid_polygon_mesh(run.mesh);
  const bool closed = internal::border_cycles(run.mesh).size() == surface.input_border_cycles;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    Hole_bench_row row = internal::bench_row(surface, options, radius, seed, i, holes[i], method);
    row.report = reports[i];
    row.metrics = measure_filled_hole(run.mesh, holes[i], surface.diagonal, surface.exact);
    row.metrics.self_intersections = intersections[i];
    row.mesh_closed = closed;
    row.mesh_valid = valid;
    run.rows.push_back(std::move(row));
  }
  return run;
}

/// An observer of `run_hole_benchmark` that ignores every event; derive from it and hide what
/// you need.
struct Hole_bench_default_observer {
  /// Holes were punched (`punched.shortfall` says when fewer than asked fit).
  template <class PolygonMesh, class Punch_result>
  void punched(const PolygonMesh& /*holed*/, const Punch_result& /*punched*/, double /*radius*/,
               unsigned int /*seed*/) {}
  /// A method filled every hole of the punched mesh; returning false stops the benchmark.
  template <class Fill>
  bool filled(const Fill& /*run*/, const Bench_method& /*method*/) {
    return true;
  }
  /// Every method has filled the holes of the last punched mesh.
  void punched_done() {}
};

/// Runs the benchmark on `pm` (not modified): for each radius and seed of `options`, punches
/// `options.holes` holes into a copy, and for each method fills and measures them
/// (`bench_fill_holes`), telling `observer` at each stage. Returns false when the observer
/// stopped it.
template <class PolygonMesh, class Point, class Observer>
bool run_hole_benchmark(const PolygonMesh& pm, const Bench_surface<Point>& surface,
                        const Hole_bench_options& options, Observer& observer) {
  for (double radius : options.radii) {
    for (unsigned int seed : options.seeds) {
      PolygonMesh holed = pm;
      const auto punched = punch_holes(holed, parameters::number_of_holes(options.holes)
                                                  .hole_radius(radius)
                                                  .hole_shape(options.shape)
                                                  .random_seed(seed));
      observer.punched(holed, punched, radius, seed);
      for (const Bench_method& method : options.methods)
        if (!observer.filled(
                bench_fill_holes(holed, punched.holes, surface, options, radius, seed, method),
                method))
          return false;
      observer.punched_done();
    }
  }
  return true;
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h): the tool's bench command and the
// Python module fill and measure the punched holes of Surface_mesh<Epick>.
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_HOLE_BENCHMARK
extern
#endif
    template Hole_bench_fill<internal::Core_mesh>
    bench_fill_holes<internal::Core_mesh, internal::Core_traits::Point_3>(
        const internal::Core_mesh&,
        const std::vector<Punched_hole<internal::Core_mesh, internal::Core_traits::Point_3>>&,
        const Bench_surface<internal::Core_traits::Point_3>&, const Hole_bench_options&, double,
        unsigned int, const Bench_method&);
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_BENCH_HOLES_H
