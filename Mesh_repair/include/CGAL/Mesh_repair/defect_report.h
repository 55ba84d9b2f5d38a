// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_DEFECT_REPORT_H
#define CGAL_MESH_REPAIR_DEFECT_REPORT_H

// The result of `detect_defects`: every defect with its location. Indices are those of the
// mesh's vertex and face index maps (for a Surface_mesh, the descriptors' integer values);
// coordinates are doubles. Plain data, no template, so that reports of any mesh type share one
// JSON writer and one text summary.

#include <CGAL/Mesh_repair/soup_repair_report.h>
#include <CGAL/Mesh_repair/quality.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

using Coordinates = std::array<double, 3>;

/// Axis-aligned box of a set of points.
struct Bounding_box {
  Coordinates min{0, 0, 0}, max{0, 0, 0};
};

/// One closed loop of border halfedges (a hole, or the outer border of an open patch).
struct Border_cycle {
  std::size_t edges = 0;
  double perimeter = 0;
  double area = 0;  ///< norm of the loop's vector area: the area of a flat fan closing it
  Bounding_box bbox;
  std::vector<std::size_t> vertices;  ///< in the order of the border halfedges
  Coordinates first_point{0, 0, 0};
  /// Index (in `Defect_report::border_cycles`) of the hole this cycle looks like an island of
  /// (thesis 4.4, ring holes), or -1.
  long island_of = -1;
};

/// A vertex and where it is.
struct Vertex_location {
  std::size_t vertex = 0;
  Coordinates point{0, 0, 0};
  bool from_soup_stage = false;  ///< found (and split) by the polygon-soup stage of `read_mesh`
};

/// A geometric edge carried by more than two face sides.
struct Non_manifold_edge {
  std::size_t source = 0, target = 0;  ///< one mesh vertex at each end
  Coordinates source_point{0, 0, 0}, target_point{0, 0, 0};
  std::size_t face_sides = 0;  ///< faces along the edge (0 when found by the soup stage)
  bool from_soup_stage = false;
};

/// Two faces and their centroids (duplicates, overlaps, self-intersections).
struct Face_pair {
  std::size_t first = 0, second = 0;
  Coordinates first_centroid{0, 0, 0}, second_centroid{0, 0, 0};
};

/// How a badly shaped face is bad: zero area (degenerate: its corners are collinear, exact
/// predicate), a needle (one edge much shorter than the longest) or a cap (one angle close to
/// 180 degrees). Needles and caps have an area: they are not degenerate.
enum class Degeneracy { zero_area, needle, cap };

inline const char* name(Degeneracy d) {
  return d == Degeneracy::zero_area ? "zero_area" : d == Degeneracy::needle ? "needle" : "cap";
}

/// A badly shaped face and why (`kind`).
struct Badly_shaped_face {
  std::size_t face = 0;
  Degeneracy kind = Degeneracy::zero_area;
  Coordinates centroid{0, 0, 0};
  double longest_to_shortest = 0;  ///< edge-length ratio (infinite for a zero-length edge)
  double max_angle_deg = 0;
};

/// A badly shaped but not degenerate triangle.
struct Sliver {
  std::size_t face = 0;
  Coordinates centroid{0, 0, 0};
  double shape_factor = 0;  ///< thesis eq. 4.14, normalised
  double aspect_ratio = 0;  ///< Pernot eq. 1
};

/// Two border vertices closer than the tolerance (a small gap, or a seam of coincident points).
struct Small_gap {
  std::size_t first = 0, second = 0;
  Coordinates first_point{0, 0, 0}, second_point{0, 0, 0};
  double distance = 0;
  bool same_cycle = false;
};

/// A border vertex lying within the tolerance of the interior of another border edge.
struct T_junction {
  std::size_t vertex = 0, edge_source = 0, edge_target = 0;
  Coordinates vertex_point{0, 0, 0}, foot{0, 0, 0};  ///< foot: closest point on the edge
  double distance = 0;
};

/// Orientation of the volume bounded by a closed component.
enum class Volume_orientation { not_closed, outward, inward };

struct Connected_component {
  std::size_t faces = 0, vertices = 0, border_edges = 0;
  Volume_orientation orientation = Volume_orientation::not_closed;
};

/// Everything `detect_defects` found. The vectors hold the locations; `counts()` below gives
/// the numbers of the summary and of the JSON's top-level keys.
struct Defect_report {
  std::size_t vertices = 0, faces = 0, edges = 0;
  bool triangle_mesh = true;
  double tolerance = 0;            ///< distance used for gaps and T-junctions
  bool tolerance_derived = false;  ///< true when derived from the mean border edge length

  std::vector<Border_cycle> border_cycles;
  std::vector<Non_manifold_edge> non_manifold_edges;
  std::vector<Vertex_location> non_manifold_vertices;
  std::vector<Face_pair> duplicated_faces;
  /// Faces to reverse so that faces glued along shared (possibly coincident) edges agree,
  /// counted per glued component as the smaller side.
  std::vector<std::size_t> inconsistently_oriented_faces;
  bool orientable = true;
  /// Zero-area faces, needles and caps, each with its kind (`counts` separates them).
  std::vector<Badly_shaped_face> badly_shaped_faces;
  std::vector<Sliver> slivers;
  std::vector<Small_gap> small_gaps;
  std::vector<T_junction> t_junctions;
  std::vector<Face_pair> overlaps;  ///< coplanar faces whose interiors overlap
  bool self_intersections_checked = false;
  std::vector<Face_pair> self_intersections;
  /// Set when an enumeration stopped at its pair limit (`Options::pair_limit` of detection,
  /// default max(100000, 10 x faces), or 10 x border vertices for gaps and T-junctions): the
  /// list holds the first pairs found and its count is a lower bound.
  bool small_gaps_truncated = false, t_junctions_truncated = false, overlaps_truncated = false,
       self_intersections_truncated = false;
  std::vector<Connected_component> components;
  bool closed = false;  ///< no border edge (and not empty)
  Quality_statistics quality;
  bool cancelled = false;  ///< the visitor stopped detection; later steps are missing

  /// Counts of the soup stage of `read_mesh`, set by `add_soup_repair_report`.
  bool has_soup_stage = false;
  Soup_repair_report soup_stage;
};

/// The numbers of a report. When the soup stage is attached, they combine what the soup stage
/// found and repaired with what remains in the mesh (see `add_soup_repair_report`).
struct Defect_counts {
  std::size_t border_cycles = 0, ring_hole_islands = 0, non_manifold_edges = 0,
              non_manifold_vertices = 0, duplicated_faces = 0, inconsistent_orientation = 0;
  std::size_t degenerate_faces = 0;   ///< zero-area faces (+ soup polygons removed as degenerate)
  std::size_t needles = 0, caps = 0;  ///< badly shaped faces with an area
  std::size_t slivers = 0, small_gaps = 0, t_junctions = 0, overlaps = 0, self_intersections = 0,
              connected_components = 0;

  /// True when any defect is counted. Border cycles count: an open mesh is a defect to repair.
  bool any() const {
    return border_cycles + non_manifold_edges + non_manifold_vertices + duplicated_faces +
               inconsistent_orientation + degenerate_faces + needles + caps + slivers + small_gaps +
               t_junctions + overlaps + self_intersections >
           0;
  }
};

inline Defect_counts counts(const Defect_report& r) {
  Defect_counts c;
  c.border_cycles = r.border_cycles.size();
  for (const auto& cycle : r.border_cycles) c.ring_hole_islands += cycle.island_of >= 0 ? 1 : 0;
  c.non_manifold_edges = r.non_manifold_edges.size();
  c.non_manifold_vertices = r.non_manifold_vertices.size();
  c.duplicated_faces = r.duplicated_faces.size();
  c.inconsistent_orientation = r.inconsistently_oriented_faces.size();
  for (const auto& f : r.badly_shaped_faces) {
    c.degenerate_faces += f.kind == Degeneracy::zero_area ? 1 : 0;
    c.needles += f.kind == Degeneracy::needle ? 1 : 0;
    c.caps += f.kind == Degeneracy::cap ? 1 : 0;
  }
  if (r.has_soup_stage) {
    c.duplicated_faces += r.soup_stage.duplicated_polygons_removed;
    c.inconsistent_orientation += r.soup_stage.polygons_reversed;
    c.degenerate_faces += r.soup_stage.degenerate_polygons_removed;
  }
  c.slivers = r.slivers.size();
  c.small_gaps = r.small_gaps.size();
  c.t_junctions = r.t_junctions.size();
  c.overlaps = r.overlaps.size();
  c.self_intersections = r.self_intersections.size();
  c.connected_components = r.components.size();
  return c;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_DEFECT_REPORT_H
