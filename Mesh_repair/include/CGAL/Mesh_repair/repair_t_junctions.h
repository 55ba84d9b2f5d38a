// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_REPAIR_T_JUNCTIONS_H
#define CGAL_MESH_REPAIR_REPAIR_T_JUNCTIONS_H

/// \file repair_t_junctions.h
/// T-junction repair by node insertion and element splitting (thesis 4.3, Figures 4.4-4.6).
/// See doc/repair_t_junctions.md.

#include <CGAL/Mesh_repair/internal/stitching/stitching_trial.h>
#include <CGAL/Mesh_repair/parameters.h>

namespace CGAL {
namespace Mesh_repair {

/// \ingroup Mesh_repair
/// Repairs the T-junctions of `pm`: every border node within tolerance of the interior of another
/// border edge splits that edge at its projection (`CGAL::Euler::split_edge`, the incident
/// triangle split in two), the new node is merged with it, and the border edges whose ends were
/// merged are glued. Several nodes hitting one edge split it once each (Figure 4.6); passes repeat
/// until no node-edge pair is left. Node pairs are not merged here (see `stitch_gaps()`, which
/// does both); borders that coincide exactly are glued first with CGAL's `stitch_borders`.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph` with triangle faces
///         along its borders
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{merge_tolerance}
///     \cgalParamDescription{largest distance from a node to the edge it is inserted into}
///     \cgalParamType{double}
///     \cgalParamDefault{derived per node: half its shortest incident edge, and at most
///                       half the length of the edge hit}
///   \cgalParamNEnd
///   \cgalParamNBegin{relative_tolerance}
///     \cgalParamDescription{tolerance as a fraction of the bounding-box diagonal}
///     \cgalParamType{double}
///     \cgalParamDefault{unused}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_cubic_curves}
///     \cgalParamDescription{place the inserted node on the cubic boundary curve of the edge
///                           (thesis 4.3.1) instead of its chord}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return what was found and changed (`t_junctions_split`, `edges_stitched`, ...).
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Stitch_result repair_t_junctions(PolygonMesh& pm,
                                 const NamedParameters& np = parameters::default_values()) {
  internal::Stitch_settings settings;
  settings.merge_tolerance = internal::absolute_tolerance(pm, np);
  settings.merge_nodes = false;
  settings.use_cubic_curves = parameters::choose_parameter(
      parameters::get_parameter(np, internal_np::use_cubic_curves_t{}), true);
  return internal::run_gap_stitcher(pm, settings, np, false);
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_REPAIR_T_JUNCTIONS_H
