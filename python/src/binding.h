// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_PYTHON_BINDING_H
#define MESH_REPAIR_PYTHON_BINDING_H

// What the two translation units of the Python module share. operators.cpp calls the library on
// the compiled core's mesh type and knows nothing of Python; module.cpp converts arrays, releases
// the GIL and turns the exceptions below into Python ones. Every operator works on a mesh built
// from its input (a file or a copy of the caller's arrays) and returns new arrays and the JSON
// text of its report, written by the library's own `write_json` overloads.

#include <CGAL/Mesh_repair/internal/compiled_core.h>
#include <CGAL/Mesh_repair/io.h>

#include <atomic>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace mesh_repair_python {

using Mesh = CGAL::Mesh_repair::internal::Core_mesh;
using Point = CGAL::Mesh_repair::internal::Core_traits::Point_3;
using Soup = CGAL::Mesh_repair::Polygon_soup<Point>;

/// Bad input (the CLI's exit status 2): ValueError in Python, with this one line.
struct Input_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The visitor asked to stop (Ctrl-C or an exception in the progress callback); module.cpp
/// raises the Python exception the visitor kept. Nothing is returned, the input is untouched.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

/// The library's visitor (visitor.h) seen from Python: polls for Ctrl-C and calls the progress
/// callback. Defined in module.cpp (it needs the GIL); operators.cpp only passes it on.
class Python_visitor {
 public:
  Python_visitor();
  ~Python_visitor();
  Python_visitor(const Python_visitor&) = delete;
  Python_visitor& operator=(const Python_visitor&) = delete;
  void start_step(const char* name);
  bool progress(double fraction);
  void end_step(const char* name);
  bool cancelled() const { return cancelled_.load(); }
  /// The Python callable `callback(step, fraction)`, or null (a PyObject*, borrowed).
  void* callback = nullptr;
  /// The Python error that cancelled the work (a py::error_already_set*), owned.
  void* error = nullptr;

 private:
  bool poll(const char* step, double fraction, bool force);
  std::thread::id caller_;
  std::atomic<bool> cancelled_{false};  // written by the caller's thread, read by workers
  double last_poll_ = -1;
  std::string step_;
};

/// A mesh to work on: `path` when it is a file, else the soup copied from the caller's arrays
/// (`name` for the messages).
struct Mesh_input {
  std::string path;
  std::string name = "input arrays";
  Soup soup;
};

/// New arrays: coordinates row by row, and faces as `corners` rows of `face_degree` vertex
/// indices, or as `polygons` when the faces do not all have the same degree (quads and
/// triangles after smoothing).
struct Mesh_output {
  std::vector<double> points;
  std::vector<std::int64_t> corners;
  std::size_t face_degree = 3;
  std::vector<std::vector<std::int64_t>> polygons;
};

/// What an operator returns: the mesh it made (absent for `check`) and its report as JSON text.
struct Operator_output {
  Mesh_output mesh;
  std::string report;
};

// Options of each operator, with the CLI's meaning; the Python wrapper holds the defaults.
struct Check_options {
  double tolerance = -1, tolerance_rel = -1;  ///< negative: not given
  bool self_intersections = true;
};
struct Repair_options {
  double tolerance = -1, tolerance_rel = -1;
  std::string fill = "self_validated";
  int continuity = 1;
  double max_hole_size = std::numeric_limits<double>::infinity();
  long long max_hole_edges = -1;  ///< negative: no limit
  double sheet_border_ratio = 0.9;
  bool largest_component = false, ring_holes = true, self_intersections = true;
  bool remove_self_intersections = true;
  bool merge_intersecting_solids = false;
  bool remove_hole_fragments = true;
  bool bridge_through_holes = true;
  bool orient_closed_parts = true;
  int threads = 0;
  unsigned seed = 0;
};
struct Fill_options {
  std::string method = "self_validated";
  int continuity = 1;
  long long max_hole_edges = -1;
  double max_hole_size = -1;  ///< negative: no limit
  double sheet_border_ratio = 0.9;
  bool ring_holes = true;
  int threads = 0;
  unsigned seed = 0;
};
struct Stitch_options {
  double tolerance = -1, tolerance_rel = -1;
  bool curves = true;
  bool check_self_intersections = true;
};
struct Sliver_options {
  double shape_factor = 0.7, feature_angle = 135, edge_length = -1;
};
struct Suppress_options {
  std::vector<std::int64_t> faces;  ///< indices into the faces of the loaded mesh
  std::string method = "shape_prediction";
  unsigned seed = 0;
};
struct Optimize_options {
  std::string mode = "reduction";
  double target_ratio = -1;     ///< negative: not given
  long long target_faces = -1;  ///< negative: not given
  double max_deviation = std::numeric_limits<double>::infinity();
  double feature_angle = 135, min_angle = 15;
  unsigned seed = 0;
};

struct Smooth_options {
  std::string method = "mga";
  bool quads = false;
  int iterations = -1;  ///< negative: the method's default
  unsigned seed = 0;
  int threads = 1, generations = 3;
  double feature_angle = 120, tangent_scale = 0.45;
  bool slide_feature_nodes = false;
};
struct Mesh_points_options {
  bool quads = false, smooth = true;
  int iterations = 3, threads = 0;
  unsigned seed = 0;
  double feature_angle = 120;
};
struct Bench_options {
  long long holes = 1;
  std::vector<double> radius{0.05};
  std::vector<unsigned> seeds{1};
  std::vector<std::string> methods{"liepa"};
  std::string shape = "disc";
};

/// Reads, validates, repairs and orients the input (a file through `read_mesh`, arrays through
/// the same soup stage, consuming `input.soup`), as every CLI command does. Throws Input_error.
void load_mesh(Mesh_input& input, Mesh& mesh, CGAL::Mesh_repair::Soup_repair_report& soup);

/// The arrays of `mesh` (garbage skipped, vertices renumbered in order).
Mesh_output mesh_arrays(const Mesh& mesh);

Operator_output read(const Mesh_input& input, bool repair_soup);
std::string write(const std::string& path, const Mesh_input& input, bool binary);
Operator_output check(Mesh_input& input, const Check_options& options, Python_visitor& visitor);
Operator_output repair(Mesh_input& input, const Repair_options& options, Python_visitor& visitor);
Operator_output fill_holes(Mesh_input& input, const Fill_options& options, Python_visitor& visitor);
Operator_output stitch(Mesh_input& input, const Stitch_options& options, Python_visitor& visitor);
Operator_output remove_slivers(Mesh_input& input, const Sliver_options& options,
                               Python_visitor& visitor);
Operator_output optimize(Mesh_input& input, const Optimize_options& options,
                         Python_visitor& visitor);
Operator_output suppress_feature(Mesh_input& input, const Suppress_options& options,
                                 Python_visitor& visitor);
Operator_output smooth(Mesh_input& input, const Smooth_options& options, Python_visitor& visitor);
/// `input`: a point file, or the points in `input.soup.points` (no faces).
Operator_output mesh_points(Mesh_input& input, const Mesh_points_options& options,
                            Python_visitor& visitor);
/// No mesh out: the report holds one result per hole x method x radius x seed.
Operator_output bench_holes(Mesh_input& input, const Bench_options& options,
                            Python_visitor& visitor);

}  // namespace mesh_repair_python

#endif  // MESH_REPAIR_PYTHON_BINDING_H
