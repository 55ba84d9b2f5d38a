// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_REPAIR_RESULT_H
#define CGAL_MESH_REPAIR_REPAIR_RESULT_H

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/json_writer.h>

#include <string>
#include <utility>
#include <vector>

/// \file repair_result.h
/// The result of `automatic_repair`: every step with its counts and time, every hole, and what
/// is left.

namespace CGAL {
namespace Mesh_repair {

/// One step of `automatic_repair`: what it changed (named counts), its time, and the operator's
/// own result as JSON.
struct Repair_step_report {
  std::string name;
  double seconds = 0;
  std::vector<std::pair<std::string, double>> counts;
  std::vector<std::string> notes;
  std::string details_json;  ///< the operator's result object, or empty

  double count(const std::string& key) const {
    for (const auto& c : counts)
      if (c.first == key) return c.second;
    return 0;
  }
};

/// How far a repair went, for scripts (the exit status of `mesh_repair repair`: 0, 3, 1).
enum class Repair_status {
  complete,              ///< valid, and nothing is left
  complete_except_kept,  ///< valid; only what was kept on purpose is left (`Repair_result::kept`)
  incomplete             ///< something asked for was not done (`Repair_result::remaining`)
};

inline const char* to_string(Repair_status s) {
  return s == Repair_status::complete               ? "complete"
         : s == Repair_status::complete_except_kept ? "complete_except_kept"
                                                    : "incomplete";
}

/// What `automatic_repair` did and what is left.
struct Repair_result {
  std::vector<Repair_step_report> steps;
  Fill_result holes;                        ///< every hole, filled or not, with its method
  std::size_t holes_too_large = 0;          ///< left open by `max_hole_size` / `max_hole_edges`
  std::size_t sheet_borders_left_open = 0;  ///< outlines of open sheets (`sheet_border_ratio`)
  std::size_t input_vertices = 0, input_faces = 0;
  std::size_t output_vertices = 0, output_faces = 0;
  std::size_t components_removed = 0;  ///< only with `keep_largest_component`
  std::size_t faces_removed_with_components = 0;
  /// Closed parts that faced inward, inside no other closed part, reversed to face outward.
  std::size_t closed_parts_reversed_outward = 0;
  /// Closed parts inside a part that was reversed, reversed with it (a cavity stays a cavity, a
  /// solid inside a solid stays one).
  std::size_t closed_parts_reversed_with_container = 0;
  std::size_t self_intersections_input = 0;  ///< pairs, when detection was asked
  /// Of the input's pairs, those between two connected components.
  std::size_t self_intersections_input_between_components = 0;
  std::size_t self_intersections_output = 0;  ///< pairs, when detection was asked
  /// Pairs inside the parts beyond the input's (pairs between parts that a patch closing one
  /// part against another adds are counted with the pairs between components).
  std::size_t self_intersections_in_patches = 0;
  /// Pairs between two parts that became pairs inside one part when stitching joined the parts
  /// (at the start, or when coincident halfedges are stitched at the end): still the input's
  /// own intersections (or kept ones between parts), not added, and not counted in
  /// `self_intersections_in_patches`. Of the pairs the last stitch moves inside a part, only
  /// those beyond the ones patches added between parts count here: a patch closing a hole
  /// against another part adds pairs, and they stay counted as added.
  std::size_t self_intersections_joined_by_stitching = 0;
  /// Of the pairs after the stitching steps (counted only when the input has pairs between
  /// components), those between two components: the input's, less the contacts along the seams
  /// that stitching closed. Patches that close holes against other parts add to them later.
  std::size_t self_intersections_between_components_after_stitching = 0;
  /// Set when a count stopped at its pair limit (internal/bounded_pairs.h: max(100000,
  /// 10 x faces)); the count is then a lower bound.
  bool self_intersections_input_truncated = false, self_intersections_output_truncated = false;
  /// Of the output's pairs, those between two connected components (an assembly of solids):
  /// kept on purpose (listed in `kept`), counted by the self-intersection removal step.
  std::size_t self_intersections_between_components = 0;
  /// Parts replaced by their union (`merge_intersecting_solids`).
  std::size_t solids_merged = 0;
  std::size_t border_cycles_left = 0;
  /// Non-manifold vertices and edges of the output by position: what a reader that merges
  /// coincident points (CGAL's `read_polygon_mesh`) sees, where separate sheets of the surface
  /// touch and are kept split (step "coincident elements", doc/automatic_repair.md).
  std::size_t non_manifold_vertices_left = 0, non_manifold_edges_left = 0;
  /// True when every vertex at a position of those non-manifold vertices and edges belongs to
  /// a connected component of its own: separate parts touching at a point or along a segment,
  /// kept like the intersections between components (listed in `kept`).
  bool non_manifold_only_between_components = false;
  /// Vertices at the position of another vertex (beyond the first at each position).
  std::size_t coincident_vertices_left = 0;
  /// `manifold`: no non-manifold vertex or edge, by position as well as in the halfedge structure.
  bool valid = false, closed = false, manifold = false;
  bool self_intersections_checked = false;
  bool cancelled = false;
  /// Requested steps that the mesh type does not support (e.g. "self-intersection removal" on
  /// OpenMesh, see `Supports_self_intersection_removal`); each is also a line of `remaining`.
  std::vector<std::string> unavailable_steps;
  /// What was asked and not done, one line each: empty unless the status is `incomplete`.
  std::vector<std::string> remaining;
  /// What is left on purpose, one line each: holes over `max_hole_size` / `max_hole_edges`,
  /// outlines of open sheets (`sheet_border_ratio`), the input's own self-intersections when
  /// their removal was not asked.
  std::vector<std::string> kept;

  Repair_status status() const {
    if (!valid || cancelled || !remaining.empty()) return Repair_status::incomplete;
    return kept.empty() ? Repair_status::complete : Repair_status::complete_except_kept;
  }
  /// True when the mesh is valid, every requested repair was done and nothing is left.
  bool complete() const { return status() == Repair_status::complete; }
};

inline void write_json(Json_writer& json, const Repair_result& r) {
  json.begin_object();
  json.field("status", to_string(r.status()))
      .field("complete", r.complete())
      .field("valid", r.valid)
      .field("closed", r.closed)
      .field("manifold", r.manifold)
      .field("non_manifold_vertices_left", r.non_manifold_vertices_left)
      .field("non_manifold_edges_left", r.non_manifold_edges_left)
      .field("non_manifold_only_between_components", r.non_manifold_only_between_components)
      .field("coincident_vertices_left", r.coincident_vertices_left)
      .field("cancelled", r.cancelled)
      .field("input_vertices", r.input_vertices)
      .field("input_faces", r.input_faces)
      .field("output_vertices", r.output_vertices)
      .field("output_faces", r.output_faces)
      .field("components_removed", r.components_removed)
      .field("faces_removed_with_components", r.faces_removed_with_components)
      .field("border_cycles_left", r.border_cycles_left)
      .field("holes_filled", r.holes.filled)
      .field("holes_failed", r.holes.failed)
      .field("holes_too_large", r.holes_too_large)
      .field("sheet_borders_left_open", r.sheet_borders_left_open)
      .field("self_intersections_checked", r.self_intersections_checked)
      .field("self_intersections_input", r.self_intersections_input)
      .field("self_intersections_input_between_components",
             r.self_intersections_input_between_components)
      .field("closed_parts_reversed_outward", r.closed_parts_reversed_outward)
      .field("closed_parts_reversed_with_container", r.closed_parts_reversed_with_container)
      .field("self_intersections_output", r.self_intersections_output)
      .field("self_intersections_in_patches", r.self_intersections_in_patches)
      .field("self_intersections_joined_by_stitching", r.self_intersections_joined_by_stitching)
      .field("self_intersections_between_components_after_stitching",
             r.self_intersections_between_components_after_stitching)
      .field("self_intersections_input_truncated", r.self_intersections_input_truncated)
      .field("self_intersections_output_truncated", r.self_intersections_output_truncated)
      .field("self_intersections_between_components", r.self_intersections_between_components)
      .field("solids_merged", r.solids_merged)
      .array("unavailable_steps", r.unavailable_steps)
      .array("remaining", r.remaining)
      .array("kept", r.kept);
  json.key("steps").begin_array();
  for (const auto& s : r.steps) {
    json.begin_object().field("name", s.name).field("seconds", s.seconds);
    json.key("counts").begin_object();
    for (const auto& c : s.counts) json.field(c.first, c.second);
    json.end_object();
    json.array("notes", s.notes);
    if (!s.details_json.empty()) json.key("details").raw(s.details_json);
    json.end_object();
  }
  json.end_array();
  json.key("holes").begin_array();
  for (const auto& h : r.holes.holes) write_json(json, h);
  json.end_array();
  json.end_object();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_REPAIR_RESULT_H
