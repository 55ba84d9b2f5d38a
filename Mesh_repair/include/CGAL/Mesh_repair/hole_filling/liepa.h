// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_LIEPA_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_LIEPA_H

/// \file liepa.h
/// CGAL's `triangulate_refine_and_fair_hole` (Liepa 2003: minimum-weight triangulation of the
/// border polygon, refinement to the border's density, fairing of the new vertices) behind the
/// interface shared by every hole-filling method, so it is called and measured like the others.
/// See doc/liepa.md.

#include <CGAL/Mesh_repair/hole_filling/fill_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/cubic_search_limit.h>
#include <CGAL/Mesh_repair/internal/hole_filling/projected_triangulation.h>
#include <CGAL/Mesh_repair/internal/hole_filling/remembered_triangulation.h>
#include <CGAL/Mesh_repair/parameters.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <cstddef>
#include <iterator>
#include <string>
#include <tuple>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

/// CGAL's stages of Liepa's method up to `last_stage` (`triangulate_refine_and_fair_hole` and
/// its shorter forms), the triangulation remembered per thread
/// (remembered_triangulation.h); `faired` false when the fairing failed.
template <class PolygonMesh, class VertexPointMap, class NamedParameters>
void triangulate_liepa(PolygonMesh& pm,
                       typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border,
                       VertexPointMap vpm, bool exhaustive_search_allowed,
                       Fill_patch<PolygonMesh>& patch, Liepa_stage last_stage,
                       const NamedParameters& np, bool& faired) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> triangles;
  triangulate_hole_remembered(pm, border, vpm, exhaustive_search_allowed, triangles, np);
  patch.faces.insert(patch.faces.end(), triangles.begin(), triangles.end());
  if (last_stage == Liepa_stage::triangulate || triangles.empty()) return;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> refined;
  PMP::refine(pm, triangles, std::back_inserter(patch.faces), std::back_inserter(refined), np);
  if (last_stage == Liepa_stage::fair) faired = PMP::fair(pm, refined, np);
  patch.vertices.insert(patch.vertices.end(), refined.begin(), refined.end());
}

/// `fill_hole_liepa` on plain options; `vpm` and `traits` as read by the public function.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Hole_fill_report fill_hole_liepa(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const Liepa_options& options) {
  Hole_fill_report report;
  report.requested = report.used = Fill_method::liepa;
  if (options.fairing_continuity > 2) {
    report.failure = "fairing_continuity must be 0, 1 or 2";
    return report;
  }
  namespace PMP = CGAL::Polygon_mesh_processing;
  // CGAL falls back to the O(n^3) search over every triangulation when its Delaunay search
  // space holds none; past `max_cubic_search_edges` that search takes minutes and O(n^2)
  // memory, so the fill fails instead and the next method takes the hole.
  // The Delaunay pass runs the same search on the ranges it cannot close; `Cubic_search_limit`
  // stops those past the limit too (the mesh is not modified before the triangulation exists).
  std::vector<typename GeomTraits::Point_3> corners;
  for (auto h : halfedges_around_face(border_halfedge, pm))
    corners.push_back(get(vpm, target(h, pm)));
  report.failure = cgal_triangulation_refusal(corners);
  if (!report.failure.empty()) return report;
  const bool bounded = corners.size() > max_cubic_search_edges;
  Cubic_search_limit limit;
  const auto np = CGAL::parameters::vertex_point_map(vpm)
                      .geom_traits(traits)
                      .fairing_continuity(options.fairing_continuity)
                      .do_not_use_cubic_algorithm(bounded)
                      .visitor(limit);
  bool faired = true;
  if (options.triangulation != Hole_triangulation::minimum_weight) {
    report.failure =
        options.triangulation == Hole_triangulation::projected
            ? triangulate_projected_border(pm, vpm, traits, border_halfedge, patch.faces)
            : extrude_border_to_base(pm, vpm, traits, border_halfedge, patch.faces, patch.vertices);
    if (!report.failure.empty()) return report;
    // Only the refinement's vertices are faired: the base's ring stays in its plane.
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> refined;
    if (options.last_stage != Liepa_stage::triangulate) {
      const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> triangles =
          patch.faces;
      PMP::refine(pm, triangles, std::back_inserter(patch.faces), std::back_inserter(refined), np);
    }
    if (options.last_stage == Liepa_stage::fair) faired = PMP::fair(pm, refined, np);
    patch.vertices.insert(patch.vertices.end(), refined.begin(), refined.end());
  } else {
    try {
      triangulate_liepa(pm, border_halfedge, vpm, !bounded, patch, options.last_stage, np, faired);
    } catch (const Cubic_search_too_large&) {
      report.failure = "CGAL's triangulation needs an exhaustive search over more than " +
                       std::to_string(max_cubic_search_edges) +
                       " border vertices (O(n^3)); not run";
      return report;
    }
  }
  report.faces_created = patch.faces.size();
  report.vertices_created = patch.vertices.size();
  report.filled = !patch.faces.empty();
  if (!report.filled)
    report.failure = bounded ? "CGAL found no triangulation in its Delaunay search space (the "
                               "exhaustive search is not run on borders of more than " +
                                   std::to_string(max_cubic_search_edges) + " edges)"
                             : "CGAL found no triangulation of the border polygon";
  if (report.filled && !faired && !patch.vertices.empty())
    report.notes.push_back("fairing failed (singular system); the refined patch is not faired");
  return report;
}

}  // namespace internal

/// Fills the hole bounded by the border halfedge `border_halfedge` with CGAL's
/// `triangulate_refine_and_fair_hole`. The faces and vertices it creates are appended to
/// `patch`. Only `CGAL::Mesh_repair::fill_hole()` and `fill_holes()` check and roll back
/// patches: call those unless you check the patch yourself.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{fairing_continuity}
///     \cgalParamDescription{tangential continuity of the faired patch with the surrounding
///       mesh: 0 (C0, membrane), 1 (C1, thin plate) or 2 (C2)}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits} \cgalParamDefault{deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// The report says `filled` when CGAL produced a triangulation; a failed fairing (singular
/// system) keeps the unfaired refined patch and is recorded in `notes`.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Hole_fill_report fill_hole_liepa(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GeomTraits = typename CGAL::GetGeomTraits<PolygonMesh, NamedParameters>::type;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  const GeomTraits traits =
      choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
  return internal::fill_hole_liepa(pm, vpm, traits, border_halfedge, patch,
                                   internal::liepa_options_from(np));
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_LIEPA
extern
#endif
    template Hole_fill_report
    fill_hole_liepa<Core_mesh, Core_vpm, Core_traits>(Core_mesh&, Core_vpm, const Core_traits&,
                                                      Core_halfedge, Fill_patch<Core_mesh>&,
                                                      const Liepa_options&);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_LIEPA_H
