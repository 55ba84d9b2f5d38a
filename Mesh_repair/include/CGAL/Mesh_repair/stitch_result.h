// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_STITCH_RESULT_H
#define CGAL_MESH_REPAIR_STITCH_RESULT_H

#include <CGAL/Mesh_repair/json_writer.h>

#include <cstddef>

namespace CGAL {
namespace Mesh_repair {

/// What `stitch_gaps()` and `repair_t_junctions()` found and changed.
struct Stitch_result {
  /// Merge tolerance used: the value given, or, when derived from the local edge lengths,
  /// the largest local tolerance (see `min_local_tolerance`).
  double merge_tolerance = 0;
  bool tolerance_derived = false;  ///< true when no tolerance was given
  double min_local_tolerance = 0;  ///< smallest local tolerance (equal to the given one if any)
  std::size_t border_nodes = 0;    ///< border vertices examined (after exact stitching)
  std::size_t border_edges_before = 0;
  std::size_t border_edges_after = 0;
  std::size_t coincident_edges_stitched = 0;  ///< by CGAL's `stitch_borders`, before anything else
  std::size_t node_merges = 0;                ///< node pairs (or clusters) merged within tolerance
  std::size_t rejected_same_face = 0;         ///< pairs refused: two nodes of one face
  std::size_t rejected_too_far = 0;           ///< pairs refused: cluster would exceed tolerance
  std::size_t rejected_same_side = 0;         ///< clusters refused: two nodes along one border side
  /// pairs refused: the far corners of the two faces of one edge (a folded flap; merged, the
  /// two faces would be one duplicated face)
  std::size_t rejected_folded_flap = 0;
  std::size_t t_junctions_split = 0;  ///< nodes inserted into border edges and kept (thesis 4.3)
  std::size_t t_junction_splits_undone = 0;     ///< inserted nodes removed again: glued to nothing
  std::size_t tangent_plane_merges = 0;         ///< merge points on the tangent-plane line
  std::size_t midpoint_merges = 0;              ///< merge points at the midpoint (fallback)
  std::size_t edges_stitched = 0;               ///< border edge pairs glued after merging
  std::size_t unstitched_clusters = 0;          ///< merged nodes whose borders could not be glued
  std::size_t unglued_nodes_restored = 0;       ///< of those, nodes put back where they were
  std::size_t merges_undone_by_move_limit = 0;  ///< clusters whose merge point was too far
  /// With `check_self_intersections`: the stitchings tried on copies, the vertices left alone
  /// because stitching them made faces intersect, the pairs the first try would have added, and
  /// whether every try added some (the mesh is then unchanged).
  std::size_t self_intersection_rounds = 0;
  std::size_t frozen_vertices = 0;
  std::size_t self_intersections_avoided = 0;
  bool check_failed = false;
  double max_displacement = 0;  ///< largest vertex move
  /// Largest move of an input vertex divided by its shortest incident edge (at most
  /// `default_tolerance_fraction`, 0.5, with a derived tolerance).
  double max_move_to_shortest_edge = 0;
  /// Set when the node pairs within tolerance exceed the pair limit (max(100000, 10 x border
  /// nodes), internal/bounded_pairs.h): then no node is merged and no T-junction is split, and
  /// `node_pairs_within_tolerance` (a lower bound) says how many were found before stopping.
  bool node_pairs_truncated = false;
  std::size_t node_pairs_within_tolerance = 0;
  /// Set when the T-junction search met more candidate box pairs than its budget (10 x the pair
  /// limit of the border nodes and edges): the pass stopped and split nothing.
  bool t_junction_search_truncated = false;
  bool cancelled = false;  ///< the visitor asked to stop
  bool valid = true;       ///< `is_valid_polygon_mesh` after the call
};

inline void write_json(Json_writer& json, const Stitch_result& r) {
  json.begin_object()
      .field("merge_tolerance", r.merge_tolerance)
      .field("tolerance_derived", r.tolerance_derived)
      .field("min_local_tolerance", r.min_local_tolerance)
      .field("border_nodes", r.border_nodes)
      .field("border_edges_before", r.border_edges_before)
      .field("border_edges_after", r.border_edges_after)
      .field("coincident_edges_stitched", r.coincident_edges_stitched)
      .field("node_merges", r.node_merges)
      .field("rejected_same_face", r.rejected_same_face)
      .field("rejected_too_far", r.rejected_too_far)
      .field("rejected_same_side", r.rejected_same_side)
      .field("rejected_folded_flap", r.rejected_folded_flap)
      .field("t_junctions_split", r.t_junctions_split)
      .field("t_junction_splits_undone", r.t_junction_splits_undone)
      .field("tangent_plane_merges", r.tangent_plane_merges)
      .field("midpoint_merges", r.midpoint_merges)
      .field("node_pairs_truncated", r.node_pairs_truncated)
      .field("node_pairs_within_tolerance", r.node_pairs_within_tolerance)
      .field("t_junction_search_truncated", r.t_junction_search_truncated)
      .field("edges_stitched", r.edges_stitched)
      .field("unstitched_clusters", r.unstitched_clusters)
      .field("unglued_nodes_restored", r.unglued_nodes_restored)
      .field("merges_undone_by_move_limit", r.merges_undone_by_move_limit)
      .field("self_intersection_rounds", r.self_intersection_rounds)
      .field("frozen_vertices", r.frozen_vertices)
      .field("self_intersections_avoided", r.self_intersections_avoided)
      .field("check_failed", r.check_failed)
      .field("max_displacement", r.max_displacement)
      .field("max_move_to_shortest_edge", r.max_move_to_shortest_edge)
      .field("cancelled", r.cancelled)
      .field("valid", r.valid)
      .end_object();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_STITCH_RESULT_H
