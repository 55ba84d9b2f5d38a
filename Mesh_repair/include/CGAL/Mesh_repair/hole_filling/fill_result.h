// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_FILL_RESULT_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_FILL_RESULT_H

/// \file fill_result.h
/// What every hole-filling method reports, so that all methods are called and measured the same
/// way by `fill_hole`/`fill_holes` (fill_holes.h), `automatic_repair` and `mesh_repair bench
/// holes`.

#include <CGAL/Mesh_repair/json_writer.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// The hole-filling methods. `automatic` and `self_validated` choose per hole (fill_holes.h):
/// `self_validated` lets the hole's known surroundings choose among the faired methods.
enum class Fill_method {
  advancing_front,
  liepa,
  shape_prediction,
  curvature_variation,
  automatic,
  self_validated
};

inline const char* to_string(Fill_method method) {
  switch (method) {
    case Fill_method::advancing_front:
      return "advancing_front";
    case Fill_method::liepa:
      return "liepa";
    case Fill_method::shape_prediction:
      return "shape_prediction";
    case Fill_method::curvature_variation:
      return "curvature_variation";
    case Fill_method::automatic:
      return "auto";
    case Fill_method::self_validated:
      return "self_validated";
  }
  return "unknown";
}

/// Parses a method name as written by `to_string` ("auto" or "automatic" for automatic).
inline bool fill_method_from_string(const std::string& name, Fill_method& method) {
  for (Fill_method m :
       {Fill_method::advancing_front, Fill_method::liepa, Fill_method::shape_prediction,
        Fill_method::curvature_variation, Fill_method::automatic, Fill_method::self_validated}) {
    if (name == to_string(m)) {
      method = m;
      return true;
    }
  }
  if (name == "automatic") {
    method = Fill_method::automatic;
    return true;
  }
  return false;
}

/// The elements a method added to the mesh for one hole.
template <class PolygonMesh>
struct Fill_patch {
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> faces;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vertices;
};

/// What happened to one hole.
struct Hole_fill_report {
  std::size_t border_edges = 0;   ///< edges of the outer border cycle
  std::size_t island_cycles = 0;  ///< island border cycles bridged into this hole (ring holes)
  double perimeter = 0;           ///< of the outer border cycle, model units
  Fill_method requested = Fill_method::advancing_front;
  Fill_method used = Fill_method::advancing_front;  ///< the method whose patch was kept
  bool filled = false;
  bool skipped = false;                ///< not selected (size limit or filter); left open
  bool sheet_border = false;           ///< skipped as the outline of an open sheet
  std::string failure;                 ///< why it was not filled (empty when filled)
  std::vector<std::string> fallbacks;  ///< methods tried and rejected before `used`, with reasons
  std::size_t faces_created = 0;
  std::size_t vertices_created = 0;
  double seconds = 0;
  std::vector<std::string> notes;  ///< non-fatal remarks on a kept patch (e.g. fairing failed)
  /// The method tested its patch itself, with exact predicates, in its final position, against
  /// itself and every face of the mesh its bounding box could meet (as the check of
  /// `fill_holes` does): the dispatcher does not test it a second time.
  bool exactly_checked = false;
};

/// What a `hole_filter` predicate of `fill_holes` sees of a hole before it is filled.
struct Hole_description {
  std::size_t border_edges = 0;   ///< edges of the outer border cycle
  std::size_t island_cycles = 0;  ///< island cycles inside it (ring hole), 0 for a simple hole
  std::size_t island_edges = 0;   ///< edges of those island cycles
  double perimeter = 0;           ///< of the outer border cycle, model units
  double diameter = 0;            ///< bounding-box diagonal of the outer cycle, model units
  double relative_size = 0;       ///< diameter / bounding-box diagonal of the mesh
  /// Vector area of the outer cycle over the area of the component it borders: near 1 for the
  /// outline of an open sheet, small for a hole in a closed surface (internal/open_sheets.h).
  double sheet_ratio = 0;
};

/// What `fill_holes` did to every hole of a mesh.
struct Fill_result {
  std::vector<Hole_fill_report> holes;
  std::size_t filled = 0, failed = 0, skipped = 0;
  std::size_t sheet_borders =
      0;  ///< of the skipped: outlines of open sheets (`sheet_border_ratio`)
  bool cancelled = false;
  bool all_filled() const { return failed == 0 && !cancelled; }
};

/// Writes one hole's report as a JSON object.
inline void write_json(Json_writer& json, const Hole_fill_report& report) {
  json.begin_object();
  json.key("border_edges").value(report.border_edges);
  json.key("island_cycles").value(report.island_cycles);
  json.key("perimeter").value(report.perimeter);
  json.key("requested").value(to_string(report.requested));
  json.key("used").value(to_string(report.used));
  json.key("filled").value(report.filled);
  json.key("skipped").value(report.skipped);
  json.key("sheet_border").value(report.sheet_border);
  json.key("failure").value(report.failure);
  json.key("fallbacks").begin_array();
  for (const std::string& fallback : report.fallbacks) json.value(fallback);
  json.end_array();
  json.key("notes").begin_array();
  for (const std::string& note : report.notes) json.value(note);
  json.end_array();
  json.key("faces_created").value(report.faces_created);
  json.key("vertices_created").value(report.vertices_created);
  json.key("seconds").value(report.seconds);
  json.end_object();
}

/// Writes the result of `fill_holes` as a JSON object with one entry per hole.
inline void write_json(Json_writer& json, const Fill_result& result) {
  json.begin_object();
  json.key("filled").value(result.filled);
  json.key("failed").value(result.failed);
  json.key("skipped").value(result.skipped);
  json.key("sheet_borders").value(result.sheet_borders);
  json.key("cancelled").value(result.cancelled);
  json.key("holes").begin_array();
  for (const Hole_fill_report& report : result.holes) write_json(json, report);
  json.end_array();
  json.end_object();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_FILL_RESULT_H
