// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_OPTIMIZATION_RESULT_H
#define CGAL_MESH_REPAIR_OPTIMIZATION_RESULT_H

/// \file optimization_result.h
/// The mode and the result of `optimize_mesh` (thesis chapter 7).

#include <CGAL/Mesh_repair/json_writer.h>

#include <cstddef>

namespace CGAL {
namespace Mesh_repair {

/// What `optimize_mesh()` does to the regions it removes.
enum class Optimization_mode {
  reduction,  ///< thesis 7.2.3(a): remove the triangles around the nodes of an element
  quality     ///< thesis 7.2.3(b): re-triangulate the element and its edge neighbours
};

/// What `optimize_mesh()` did.
struct Optimization_result {
  std::size_t input_faces = 0, output_faces = 0;
  std::size_t passes = 0;
  std::size_t regions_replaced = 0;
  // Regions left as they were, by reason:
  std::size_t regions_duplicate_edge = 0;     ///< a new edge would duplicate an existing one
  std::size_t regions_fold_or_crease = 0;     ///< a new normal would turn away, or a crease appear
  std::size_t regions_self_intersection = 0;  ///< a new triangle would cross the surroundings
  std::size_t regions_not_better = 0;         ///< the GA did not beat the old triangles
  std::size_t regions_too_far = 0;  ///< reduction: the patch would leave removed points too far
  std::size_t regions_without_triangulation = 0;
  std::size_t regions_refused_by_mesh = 0;  ///< rolled back
  std::size_t corner_nodes = 0;             ///< "vertex" nodes at the first classification
  std::size_t feature_edges = 0;            ///< at the first classification
  bool target_reached = false;
  bool cancelled = false;
  const char* stop_reason = "";
};

/// Writes the result as a JSON object (the `optimization` member of `mesh_repair optimize`'s
/// report).
inline void write_json(Json_writer& json, const Optimization_result& r) {
  json.begin_object();
  json.field("input_faces", r.input_faces).field("output_faces", r.output_faces);
  json.field("passes", r.passes).field("regions_replaced", r.regions_replaced);
  json.field("regions_duplicate_edge", r.regions_duplicate_edge);
  json.field("regions_fold_or_crease", r.regions_fold_or_crease);
  json.field("regions_self_intersection", r.regions_self_intersection);
  json.field("regions_not_better", r.regions_not_better);
  json.field("regions_too_far", r.regions_too_far);
  json.field("regions_without_triangulation", r.regions_without_triangulation);
  json.field("regions_refused_by_mesh", r.regions_refused_by_mesh);
  json.field("corner_nodes", r.corner_nodes).field("feature_edges", r.feature_edges);
  json.field("target_reached", r.target_reached).field("cancelled", r.cancelled);
  json.field("stop_reason", r.stop_reason);
  json.end_object();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_OPTIMIZATION_RESULT_H
