// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_AUTOMATIC_REPAIR_H
#define CGAL_MESH_REPAIR_AUTOMATIC_REPAIR_H

/// \file automatic_repair.h
/// The whole repair pipeline of thesis chapter 3 (Figures 3.2-3.3) in one call: gaps and
/// overlaps before holes, then degeneracies, then holes, then verification. See
/// doc/automatic_repair.md.

#include <CGAL/Mesh_repair/repair_result.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/coincident_elements.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/repair_steps.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

/// Every parameter of `automatic_repair`, read once.
template <class PolygonMesh, class NamedParameters>
Repair_options repair_options_from(const PolygonMesh& pm, const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Repair_options o;
  o.merge_tolerance = absolute_tolerance(pm, np);
  o.use_cubic_curves =
      choose_parameter(get_parameter(np, internal_np::use_cubic_curves_t{}), o.use_cubic_curves);
  o.keep_largest_component = choose_parameter(
      get_parameter(np, internal_np::keep_largest_component_t{}), o.keep_largest_component);
  o.detect_self_intersections = choose_parameter(
      get_parameter(np, internal_np::detect_self_intersections_t{}), o.detect_self_intersections);
  o.repair_self_intersections = choose_parameter(
      get_parameter(np, internal_np::repair_self_intersections_t{}), o.repair_self_intersections);
  o.merge_intersecting_solids = choose_parameter(
      get_parameter(np, internal_np::merge_intersecting_solids_t{}), o.merge_intersecting_solids);
  o.remove_hole_fragments = choose_parameter(
      get_parameter(np, internal_np::remove_hole_fragments_t{}), o.remove_hole_fragments);
  o.bridge_through_holes = choose_parameter(
      get_parameter(np, internal_np::bridge_through_holes_t{}), o.bridge_through_holes);
  o.orient_closed_parts = choose_parameter(get_parameter(np, internal_np::orient_closed_parts_t{}),
                                           o.orient_closed_parts);
  o.fill = fill_options_from(np);
  return o;
}

}  // namespace internal

/// \ingroup Mesh_repair
/// Repairs `pm` in the order of thesis Figure 3.2: exact stitching of coincident borders
/// (CGAL), tolerance stitching of gaps and small overlaps with T-junction repair (thesis 4.2-4.3),
/// removal of duplicated and overlapping coplanar faces, non-manifold vertices (CGAL), degenerate
/// faces (CGAL) and slivers (thesis 4.5), optionally all but the largest component, hole-contour
/// cleaning (Pernot 4), hole filling (one method per hole, with fallbacks; holes over the size
/// limits are left open and reported; holes whose every patch was rejected are grown by rings
/// of faces and filled again), replacement of the faces that intersect others of their
/// component, and a verification (valid, manifold, closed, self-intersections in and around the
/// patches); last, the output is made to be what a file shows (step "coincident elements": faces
/// duplicating another by position removed, coincident borders stitched, vertices where sheets
/// touch kept split and counted; `manifold` is by position as in `detect_defects`).
///
/// Every step is timed and counted in the result; nothing is removed without being counted.
/// `pm` is valid after the call even when a step fails or the visitor cancels.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph` with triangle faces
/// \param pm the mesh to repair
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{merge_tolerance}
///     \cgalParamDescription{largest gap closed by stitching, model units}
///     \cgalParamType{double}
///     \cgalParamDefault{derived from the local edge lengths, moves bounded (see `stitch_gaps`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{relative_tolerance}
///     \cgalParamDescription{the stitching tolerance as a fraction of the bounding-box diagonal
///       (when `merge_tolerance` is not given)}
///     \cgalParamType{double} \cgalParamDefault{derived (see `stitch_gaps`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_cubic_curves}
///     \cgalParamDescription{stitching merges nodes on cubic boundary curves (thesis 4.3.1)}
///     \cgalParamType{bool} \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{(hole-filling parameters)}
///     \cgalParamDescription{every parameter of `fill_holes` and of its methods
///       (`hole_filter`, `check_self_intersections`, `fit_quadric`, `population_size`,
///       `topological_grid`, ...) is forwarded to the hole-filling step}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits} \cgalParamDefault{deduced from the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{fill_method}
///     \cgalParamDescription{the hole-filling method (see `fill_holes`)}
///     \cgalParamType{`Fill_method`}
///     \cgalParamDefault{`Fill_method::self_validated`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fairing_continuity}
///     \cgalParamDescription{continuity of Liepa fairing when that method is used}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_hole_size}
///     \cgalParamDescription{holes whose border is larger than this fraction of the bounding-box
///                           diagonal are left open and reported}
///     \cgalParamType{double}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{sheet_border_ratio}
///     \cgalParamDescription{border cycles whose vector area exceeds this fraction of the area
///                           of the component they border are the outlines of open sheets and
///                           are left open and counted (`sheet_borders_left_open`); see
///                           `fill_holes`. Infinity fills them}
///     \cgalParamType{double}
///     \cgalParamDefault{0.9}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_hole_edges}
///     \cgalParamDescription{holes with more border edges are left open and reported}
///     \cgalParamType{std::size_t}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{detect_ring_holes}
///     \cgalParamDescription{fill a hole and the islands inside it as one region}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{keep_largest_component}
///     \cgalParamDescription{remove every connected component but the largest (counted)}
///     \cgalParamType{bool}
///     \cgalParamDefault{`false`: every component is kept (but see `remove_hole_fragments`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{remove_hole_fragments}
///     \cgalParamDescription{before the holes are filled, remove the fragments of scans found in
///       them: open components of at most 10 faces and at most 1/100 of the faces of a part,
///       attached at a vertex to the border of one of that part's holes (every patch of the hole
///       would meet them, and they would stay open). Counted in the step "fragments in holes";
///       closed components are never removed. Doc: automatic_repair.md, "Fragments in holes"}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{bridge_through_holes}
///     \cgalParamDescription{before the holes are filled, give the through-holes of a part whose
///       wall is missing their wall: two border cycles of one part that are translated copies of
///       each other (at most 2 radii apart, along their axis, running in opposite directions, the
///       faces along them not leaning toward each other) are joined by a tube of 2 triangles per
///       edge, kept only if no face of it meets another face (exact predicates; faces of other
///       parts may be met when the part already met another part). Counted in the step "through
///       holes bridged". Doc: automatic_repair.md, "Through-holes"}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{orient_closed_parts}
///     \cgalParamDescription{after the holes are filled and the intersections removed, turn
///       every closed triangulated part that faces inward and lies inside no other closed part
///       outward, and reverse the closed parts inside it with it (every vertex strictly inside,
///       CGAL's `Side_of_triangle_mesh`): a cavity stays a cavity, a solid inside a solid stays
///       one. A part that crosses another is a solid of its own; open parts are left as they
///       are. Counted in `Repair_result::closed_parts_reversed_outward` and
///       `closed_parts_reversed_with_container` and in the step "orientation of closed parts".
///       Doc: automatic_repair.md, "Orientation of closed parts"}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{detect_self_intersections}
///     \cgalParamDescription{count self-intersections of the input and the output}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{repair_self_intersections}
///     \cgalParamDescription{remove the intersections of faces of one connected component:
///       spike vertices beside holes are moved back to the centre of their neighbours before the
///       filling (step "spikes"); then closed parts are autorefined within bounds, spikes moved
///       back, and the faces still intersecting, with the faces within 1 to 6 vertex rings,
///       replaced by checked Liepa patches (all or nothing per region); intersections between
///       components are kept (doc: automatic_repair.md, "Self-intersections")}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_intersecting_solids}
///     \cgalParamDescription{replace closed parts that intersect one another (an assembly of
///       interpenetrating solids) by their union, computed by CGAL's corefinement; the faces
///       inside the union are removed, so the area drops. A group of intersecting parts of which
///       one is open, intersects itself or bounds no volume, or in which two parts have
///       coplanar faces that meet, is kept apart (a note says why).
///       Points pass through doubles (exact kernels are rounded there). Doc:
///       automatic_repair.md, "Self-intersections"}
///     \cgalParamType{bool}
///     \cgalParamDefault{`false`: each part stays a solid of its own, nothing is lost}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads of TBB's pool during the call: the self-intersection
///                           counts and the hole filling (independent holes filled on copies
///                           of their surroundings at the same time, spliced in hole order)
///                           run on it; the output is the same for any number of threads, see
///                           doc/automatic_repair.md}
///     \cgalParamType{int}
///     \cgalParamDefault{0: all cores}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the randomised methods}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress and cancellation (`Default_visitor`), as `std::ref(v)`}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return every step with its counts and time, every hole, what is left (`remaining`: asked and
/// not done; `kept`: left on purpose) and `status()`.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Repair_result automatic_repair(PolygonMesh& pm,
                               const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GeomTraits = typename CGAL::GetGeomTraits<PolygonMesh, NamedParameters>::type;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  const GeomTraits traits =
      choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
  internal::Visitor_parameter<NamedParameters> visitor(np);
  return internal::run_automatic_repair(pm, vpm, traits, internal::repair_options_from(pm, np),
                                        visitor.get());
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_AUTOMATIC_REPAIR
extern
#endif
    template Repair_result
    run_automatic_repair<Core_mesh, Core_vpm, Core_traits>(Core_mesh&, Core_vpm, const Core_traits&,
                                                           const Repair_options&, Any_visitor);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_AUTOMATIC_REPAIR_H
