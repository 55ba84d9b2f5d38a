// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_STITCH_GAPS_H
#define CGAL_MESH_REPAIR_STITCH_GAPS_H

/// \file stitch_gaps.h
/// Closing of small gaps and overlaps between border strips by merging free nodes (thesis 4.2),
/// with T-junction repair (4.3) and cubic boundary curves (4.3.1). See doc/stitch_gaps.md.

#include <CGAL/Mesh_repair/internal/stitching/stitching_trial.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>

namespace CGAL {
namespace Mesh_repair {

/// \ingroup Mesh_repair
/// Stitches the gaps and small overlaps of `pm`: border nodes closer than the merge tolerance
/// are paired greedily by distance (kd-tree), never two nodes of one face; each group moves to
/// the projection of its midpoint onto the intersection line of the nodes' tangent planes (the
/// midpoint when the planes are near-parallel or the line is farther than the tolerance); border
/// nodes within tolerance of the interior of another border edge split that edge (T-junctions);
/// then border edges whose ends were merged are glued. Borders that coincide exactly are glued
/// first with CGAL's `stitch_borders`.
///
/// The mesh stays valid: only vertex moves, `CGAL::Euler::split_edge`/`split_face`, CGAL's
/// `stitch_borders` and a linear-time equivalent of CGAL's `stitch_borders(pm, pairs)` (same
/// checks, same result) change it. Nothing is merged farther apart than the tolerance.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph` (triangle faces along
///         the borders for T-junction splits)
/// \param pm the mesh to stitch
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{merge_tolerance}
///     \cgalParamDescription{largest distance between merged nodes, in model units}
///     \cgalParamType{double}
///     \cgalParamDefault{derived per node: half its shortest incident edge; the pair
///                       tolerance is the smaller of the two nodes', and no input vertex moves
///                       farther than half its shortest incident edge (reported in the result)}
///   \cgalParamNEnd
///   \cgalParamNBegin{relative_tolerance}
///     \cgalParamDescription{the tolerance as a fraction of the bounding-box diagonal; used when
///                           `merge_tolerance` is not given}
///     \cgalParamType{double}
///     \cgalParamDefault{unused}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_cubic_curves}
///     \cgalParamDescription{place T-junction nodes on the cubic point-normal boundary curve of
///                           the split edge (thesis eq. 4.2-4.7) instead of on its chord}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{check_self_intersections}
///     \cgalParamDescription{stitch a copy first and, while it has more self-intersecting face
///                           pairs than `pm`, freeze the vertices of the faces that intersect
///                           (they neither move nor take T-junction nodes) and try again, up to
///                           8 rounds; then stitch `pm` leaving the frozen vertices alone. When
///                           no round adds nothing, `pm` is left unchanged
///                           (`Stitch_result::check_failed`). Costs a self-intersection pass
///                           per round}
///     \cgalParamType{bool}
///     \cgalParamDefault{`false` (the command line's `stitch` sets it)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress and cancellation, see `Default_visitor`}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return what was found and changed, see `Stitch_result`.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Stitch_result stitch_gaps(PolygonMesh& pm,
                          const NamedParameters& np = parameters::default_values()) {
  internal::Stitch_settings settings;
  settings.merge_tolerance = internal::absolute_tolerance(pm, np);
  settings.use_cubic_curves = parameters::choose_parameter(
      parameters::get_parameter(np, internal_np::use_cubic_curves_t{}), true);
  return internal::run_gap_stitcher(
      pm, settings, np,
      parameters::choose_parameter(
          parameters::get_parameter(np, internal_np::check_self_intersections_t{}), false));
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_STITCH_GAPS_H
