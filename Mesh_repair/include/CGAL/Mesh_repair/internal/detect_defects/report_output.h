// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_REPORT_OUTPUT_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_REPORT_OUTPUT_H

// The two faces of a Defect_report: JSON (schema in doc/report_schema.md) and a readable text
// summary.

#include <CGAL/Mesh_repair/defect_report.h>
#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/io.h>

#include <cmath>
#include <sstream>
#include <string>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

inline void write_coordinates(Json_writer& json, const Coordinates& c) {
  json.begin_array().value(c[0]).value(c[1]).value(c[2]).end_array();
}

inline void write_json(Json_writer& json, const Bounding_box& box) {
  json.begin_object();
  json.key("min");
  write_coordinates(json, box.min);
  json.key("max");
  write_coordinates(json, box.max);
  json.end_object();
}

inline void write_json(Json_writer& json, const Face_pair& pair) {
  json.begin_object().field("first", pair.first).field("second", pair.second);
  json.key("first_centroid");
  write_coordinates(json, pair.first_centroid);
  json.key("second_centroid");
  write_coordinates(json, pair.second_centroid);
  json.end_object();
}

inline void write_face_pairs(Json_writer& json, const std::string& name,
                             const std::vector<Face_pair>& pairs) {
  json.key(name).begin_array();
  for (const auto& p : pairs) write_json(json, p);
  json.end_array();
}

inline void write_histograms(Json_writer& json, const Quality_statistics& q) {
  json.key("quality").begin_object();
  json.field("triangles", q.triangles)
      .field("min_alpha", q.min_alpha)
      .field("mean_alpha", q.mean_alpha)
      .field("min_aspect_ratio", q.min_aspect_ratio)
      .field("mean_aspect_ratio", q.mean_aspect_ratio)
      .field("min_shape_factor", q.min_shape_factor)
      .field("mean_shape_factor", q.mean_shape_factor)
      .field("min_angle_deg", q.min_angle_deg)
      .field("max_angle_deg", q.max_angle_deg);
  json.key("histograms").begin_object();
  json.array("alpha", q.alpha_histogram);
  json.array("aspect_ratio", q.aspect_ratio_histogram);
  json.array("shape_factor", q.shape_factor_histogram);
  json.array("min_angle_deg", q.min_angle_histogram);
  json.end_object();
  json.end_object();
}

inline void write_border_cycles(Json_writer& json, const std::vector<Border_cycle>& cycles) {
  json.key("border_cycle_details").begin_array();
  for (const auto& c : cycles) {
    json.begin_object()
        .field("edges", c.edges)
        .field("perimeter", c.perimeter)
        .field("area", c.area)
        .field("island_of", c.island_of);
    json.key("bbox");
    write_json(json, c.bbox);
    json.key("first_point");
    write_coordinates(json, c.first_point);
    json.array("vertices", c.vertices);
    json.end_object();
  }
  json.end_array();
}

inline void write_non_manifold(Json_writer& json, const Defect_report& r) {
  json.key("non_manifold_edge_details").begin_array();
  for (const auto& e : r.non_manifold_edges) {
    json.begin_object()
        .field("source", e.source)
        .field("target", e.target)
        .field("face_sides", e.face_sides)
        .field("from_soup_stage", e.from_soup_stage);
    json.key("source_point");
    write_coordinates(json, e.source_point);
    json.key("target_point");
    write_coordinates(json, e.target_point);
    json.end_object();
  }
  json.end_array();
  json.key("non_manifold_vertex_details").begin_array();
  for (const auto& v : r.non_manifold_vertices) {
    json.begin_object().field("vertex", v.vertex).field("from_soup_stage", v.from_soup_stage);
    json.key("point");
    write_coordinates(json, v.point);
    json.end_object();
  }
  json.end_array();
}

inline void write_face_shapes(Json_writer& json, const Defect_report& r) {
  json.key("badly_shaped_face_details").begin_array();
  for (const auto& d : r.badly_shaped_faces) {
    json.begin_object()
        .field("face", d.face)
        .field("kind", name(d.kind))
        .field("longest_to_shortest", d.longest_to_shortest)
        .field("max_angle_deg", d.max_angle_deg);
    json.key("centroid");
    write_coordinates(json, d.centroid);
    json.end_object();
  }
  json.end_array();
  json.key("sliver_details").begin_array();
  for (const auto& s : r.slivers) {
    json.begin_object()
        .field("face", s.face)
        .field("shape_factor", s.shape_factor)
        .field("aspect_ratio", s.aspect_ratio);
    json.key("centroid");
    write_coordinates(json, s.centroid);
    json.end_object();
  }
  json.end_array();
}

inline void write_proximity(Json_writer& json, const Defect_report& r) {
  json.key("small_gap_details").begin_array();
  for (const auto& g : r.small_gaps) {
    json.begin_object()
        .field("first", g.first)
        .field("second", g.second)
        .field("distance", g.distance)
        .field("same_cycle", g.same_cycle);
    json.key("first_point");
    write_coordinates(json, g.first_point);
    json.key("second_point");
    write_coordinates(json, g.second_point);
    json.end_object();
  }
  json.end_array();
  json.key("t_junction_details").begin_array();
  for (const auto& t : r.t_junctions) {
    json.begin_object()
        .field("vertex", t.vertex)
        .field("edge_source", t.edge_source)
        .field("edge_target", t.edge_target)
        .field("distance", t.distance);
    json.key("vertex_point");
    write_coordinates(json, t.vertex_point);
    json.key("foot");
    write_coordinates(json, t.foot);
    json.end_object();
  }
  json.end_array();
}

inline const char* name(Volume_orientation o) {
  return o == Volume_orientation::outward  ? "outward"
         : o == Volume_orientation::inward ? "inward"
                                           : "not_closed";
}

inline void write_components(Json_writer& json, const std::vector<Connected_component>& cs) {
  json.key("component_details").begin_array();
  for (const auto& c : cs)
    json.begin_object()
        .field("faces", c.faces)
        .field("vertices", c.vertices)
        .field("border_edges", c.border_edges)
        .field("closed", c.border_edges == 0)
        .field("orientation", name(c.orientation))
        .end_object();
  json.end_array();
}

}  // namespace internal

/// Writes `report` as one JSON object: the integer counts at top level (combined with the soup
/// stage when attached), then the details. Schema: doc/report_schema.md.
inline void write_json(Json_writer& json, const Defect_report& r) {
  const Defect_counts c = counts(r);
  json.begin_object()
      .field("vertices", r.vertices)
      .field("faces", r.faces)
      .field("edges", r.edges)
      .field("border_cycles", c.border_cycles)
      .field("ring_hole_islands", c.ring_hole_islands)
      .field("non_manifold_edges", c.non_manifold_edges)
      .field("non_manifold_vertices", c.non_manifold_vertices)
      .field("duplicated_faces", c.duplicated_faces)
      .field("inconsistent_orientation", c.inconsistent_orientation)
      .field("degenerate_faces", c.degenerate_faces)
      .field("needles", c.needles)
      .field("caps", c.caps)
      .field("slivers", c.slivers)
      .field("small_gaps", c.small_gaps)
      .field("t_junctions", c.t_junctions)
      .field("overlaps", c.overlaps)
      .field("self_intersections", c.self_intersections)
      .field("connected_components", c.connected_components)
      .field("closed", r.closed)
      .field("orientable", r.orientable && (!r.has_soup_stage || r.soup_stage.orientable))
      .field("triangle_mesh", r.triangle_mesh)
      .field("self_intersections_checked", r.self_intersections_checked)
      .field("tolerance", r.tolerance)
      .field("tolerance_derived", r.tolerance_derived)
      .field("cancelled", r.cancelled)
      .field("small_gaps_truncated", r.small_gaps_truncated)
      .field("t_junctions_truncated", r.t_junctions_truncated)
      .field("overlaps_truncated", r.overlaps_truncated)
      .field("self_intersections_truncated", r.self_intersections_truncated)
      .field("defects_found", c.any());
  internal::write_border_cycles(json, r.border_cycles);
  internal::write_non_manifold(json, r);
  internal::write_face_pairs(json, "duplicated_face_details", r.duplicated_faces);
  json.array("inconsistently_oriented_faces", r.inconsistently_oriented_faces);
  internal::write_face_shapes(json, r);
  internal::write_proximity(json, r);
  internal::write_face_pairs(json, "overlap_details", r.overlaps);
  internal::write_face_pairs(json, "self_intersection_details", r.self_intersections);
  internal::write_components(json, r.components);
  internal::write_histograms(json, r.quality);
  if (r.has_soup_stage) {
    json.key("soup_repair");
    write_json(json, r.soup_stage);
  }
  json.end_object();
}

/// A readable multi-line summary: one line per kind of defect, with its count and, for the
/// first few, where it is.
inline std::string summary(const Defect_report& r, std::size_t examples = 3) {
  const Defect_counts c = counts(r);
  std::ostringstream out;
  // A count that stopped at its pair limit is a lower bound.
  auto at_least = [](bool truncated) { return truncated ? "at least " : ""; };
  auto point = [](const Coordinates& p) {
    std::ostringstream s;
    s << '(' << p[0] << ", " << p[1] << ", " << p[2] << ')';
    return s.str();
  };
  out << r.vertices << " vertices, " << r.faces << " faces, " << c.connected_components
      << " connected component(s), " << (r.closed ? "closed" : "open") << '\n';
  out << "border cycles:          " << c.border_cycles;
  if (c.ring_hole_islands > 0) out << " (" << c.ring_hole_islands << " island(s) of ring holes)";
  out << '\n';
  for (std::size_t i = 0; i < r.border_cycles.size() && i < examples; ++i)
    out << "  cycle " << i << ": " << r.border_cycles[i].edges << " edges, perimeter "
        << r.border_cycles[i].perimeter << ", area ~" << r.border_cycles[i].area << ", at "
        << point(r.border_cycles[i].first_point) << '\n';
  out << "non-manifold edges:     " << c.non_manifold_edges << '\n';
  for (std::size_t i = 0; i < r.non_manifold_edges.size() && i < examples; ++i)
    out << "  " << point(r.non_manifold_edges[i].source_point) << " - "
        << point(r.non_manifold_edges[i].target_point) << '\n';
  out << "non-manifold vertices:  " << c.non_manifold_vertices << '\n';
  for (std::size_t i = 0; i < r.non_manifold_vertices.size() && i < examples; ++i)
    out << "  " << point(r.non_manifold_vertices[i].point) << '\n';
  out << "duplicated faces:       " << c.duplicated_faces << '\n';
  out << "inconsistent orientation (faces): " << c.inconsistent_orientation << '\n';
  auto shapes = [&](Degeneracy kind) {
    std::size_t shown = 0;
    for (const auto& f : r.badly_shaped_faces)
      if (f.kind == kind && shown++ < examples)
        out << "  face " << f.face << " at " << point(f.centroid) << '\n';
  };
  out << "degenerate faces (zero area): " << c.degenerate_faces << '\n';
  shapes(Degeneracy::zero_area);
  out << "needles:                " << c.needles << '\n';
  shapes(Degeneracy::needle);
  out << "caps:                   " << c.caps << '\n';
  shapes(Degeneracy::cap);
  out << "slivers:                " << c.slivers << '\n';
  out << "small gaps (tolerance " << r.tolerance << (r.tolerance_derived ? ", derived" : "")
      << "): " << at_least(r.small_gaps_truncated) << c.small_gaps << '\n';
  for (std::size_t i = 0; i < r.small_gaps.size() && i < examples; ++i)
    out << "  " << point(r.small_gaps[i].first_point) << " ~ "
        << point(r.small_gaps[i].second_point) << ", distance " << r.small_gaps[i].distance << '\n';
  out << "T-junctions:            " << at_least(r.t_junctions_truncated) << c.t_junctions << '\n';
  for (std::size_t i = 0; i < r.t_junctions.size() && i < examples; ++i)
    out << "  vertex at " << point(r.t_junctions[i].vertex_point) << ", distance "
        << r.t_junctions[i].distance << '\n';
  out << "overlapping faces:      " << at_least(r.overlaps_truncated) << c.overlaps << '\n';
  out << "self-intersections:     ";
  if (r.self_intersections_checked)
    out << at_least(r.self_intersections_truncated) << c.self_intersections << " face pair(s)\n";
  else
    out << "not checked\n";
  for (std::size_t i = 0; i < r.components.size() && i < examples; ++i)
    out << "  component " << i << ": " << r.components[i].faces << " faces, "
        << internal::name(r.components[i].orientation) << '\n';
  // A figure that overflowed (coordinates near 1e308) is printed as n/a, never as -nan.
  auto figure = [](double x) {
    std::ostringstream text;
    if (std::isfinite(x))
      text << x;
    else
      text << "n/a";
    return text.str();
  };
  out << "quality: min angle " << figure(r.quality.min_angle_deg) << " deg, mean shape factor "
      << figure(r.quality.mean_shape_factor) << ", mean Q " << figure(r.quality.mean_aspect_ratio)
      << '\n';
  if (r.small_gaps_truncated || r.t_junctions_truncated || r.overlaps_truncated ||
      r.self_intersections_truncated)
    out << "some enumerations stopped at their pair limit (proportional to the mesh size): "
           "the counts marked \"at least\" are lower bounds\n";
  if (r.cancelled) out << "detection was cancelled: the report is partial\n";
  return out.str();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_REPORT_OUTPUT_H
