// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_SOUP_REPAIR_REPORT_H
#define CGAL_MESH_REPAIR_SOUP_REPAIR_REPORT_H

/// \file soup_repair_report.h
/// The result type of the polygon-soup stage of `read_mesh` (io.h), on its own so that the
/// reports that hold it (defect_report.h) do not include the readers.

#include <CGAL/Mesh_repair/json_writer.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What the polygon-soup stage found and changed. Point indices refer to the soup as read.
struct Soup_repair_report {
  std::size_t input_points = 0;
  std::size_t input_polygons = 0;
  std::size_t points_merged = 0;                ///< geometrically identical points merged into one
  std::size_t polygons_simplified = 0;          ///< polygons with repeated consecutive points
  std::size_t polygons_split = 0;               ///< pinched polygons split into several
  std::size_t degenerate_polygons_removed = 0;  ///< fewer than three distinct points
  std::size_t duplicated_polygons_removed = 0;  ///< same points as another polygon (any order)
  /// Groups of duplicated polygons removed whole as zero-volume walls (`Read_options`); their
  /// polygons are counted in `duplicated_polygons_removed` too.
  std::size_t zero_volume_walls_removed = 0;
  /// Internal walls removed (with `remove_zero_volume_walls`): sheets written once whose whole
  /// outline is non-manifold, inside the closed surface the rest of their part forms.
  std::size_t internal_walls_removed = 0;
  std::size_t internal_wall_polygons_removed = 0;  ///< their polygons
  std::size_t isolated_points_removed = 0;         ///< points used by no polygon
  std::size_t non_manifold_edges = 0;              ///< edges used by more than two polygons
  std::size_t non_manifold_vertices = 0;           ///< vertices whose polygons form several fans
  std::size_t vertices_duplicated = 0;             ///< points added to make the soup manifold
  std::size_t polygons_reversed = 0;               ///< polygons flipped to agree with neighbours
  std::size_t polygons_triangulated = 0;           ///< faces with more than three sides split
  std::size_t triangles_from_polygons = 0;         ///< triangles that replaced them
  /// Header lines of no known keyword the reader skipped as free text (not geometry).
  std::size_t header_lines_skipped = 0;
  bool orientable = true;  ///< orientation needed no vertex duplication
  /// Locations: soup point pairs of non-manifold edges, soup points of non-manifold vertices.
  std::vector<std::pair<std::size_t, std::size_t>> non_manifold_edge_points;
  std::vector<std::size_t> non_manifold_vertex_points;

  /// True when the soup stage changed nothing.
  bool clean() const {
    return points_merged + polygons_simplified + polygons_split + degenerate_polygons_removed +
               duplicated_polygons_removed + internal_wall_polygons_removed +
               isolated_points_removed + vertices_duplicated + polygons_reversed +
               polygons_triangulated ==
           0;
  }
};

/// Writes the soup report as a JSON object (the `soup_repair` member of every report).
inline void write_json(Json_writer& json, const Soup_repair_report& r) {
  json.begin_object()
      .field("input_points", r.input_points)
      .field("input_polygons", r.input_polygons)
      .field("points_merged", r.points_merged)
      .field("polygons_simplified", r.polygons_simplified)
      .field("polygons_split", r.polygons_split)
      .field("degenerate_polygons_removed", r.degenerate_polygons_removed)
      .field("duplicated_polygons_removed", r.duplicated_polygons_removed)
      .field("zero_volume_walls_removed", r.zero_volume_walls_removed)
      .field("internal_walls_removed", r.internal_walls_removed)
      .field("internal_wall_polygons_removed", r.internal_wall_polygons_removed)
      .field("isolated_points_removed", r.isolated_points_removed)
      .field("non_manifold_edges", r.non_manifold_edges)
      .field("non_manifold_vertices", r.non_manifold_vertices)
      .field("vertices_duplicated", r.vertices_duplicated)
      .field("polygons_reversed", r.polygons_reversed)
      .field("polygons_triangulated", r.polygons_triangulated)
      .field("triangles_from_polygons", r.triangles_from_polygons)
      .field("header_lines_skipped", r.header_lines_skipped)
      .field("orientable", r.orientable);
  json.key("non_manifold_edge_points").begin_array();
  for (const auto& e : r.non_manifold_edge_points)
    json.begin_array().value(e.first).value(e.second).end_array();
  json.end_array();
  json.array("non_manifold_vertex_points", r.non_manifold_vertex_points);
  json.end_object();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_SOUP_REPAIR_REPORT_H
