// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_REMOVE_SLIVERS_H
#define CGAL_MESH_REPAIR_REMOVE_SLIVERS_H

/// \file remove_slivers.h
/// Removal of skewed elements by element reconstruction (thesis 4.5, eq. 4.13-4.14, Figures
/// 4.13-4.14). See doc/remove_slivers.md.

#include <CGAL/Mesh_repair/internal/sliver_removal/sliver_remover.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

/// `remove_slivers` on plain settings (compiled once per mesh type).
template <class TriangleMesh, class VertexPointMap, class GeomTraits>
Sliver_result remove_slivers_with_settings(TriangleMesh& tm, VertexPointMap vpm,
                                           const GeomTraits& gt, const Sliver_settings& settings,
                                           Any_visitor visitor) {
  Sliver_remover<TriangleMesh, VertexPointMap, GeomTraits, Any_visitor> remover(tm, vpm, gt,
                                                                                settings, visitor);
  Sliver_result result = remover.run();
  result.valid = CGAL::is_valid_polygon_mesh(tm);
  return result;
}

}  // namespace internal

/// \ingroup Mesh_repair
/// Removes the slivers of `tm`: triangles whose shape factor f (thesis eq. 4.14, normalised to
/// [0,1], see `shape_factor()`) is below the threshold. A sliver with an edge shorter than the
/// tolerance edge length loses that edge by merging its nodes (Figure 4.13): a node on a feature
/// line or the border keeps its position, otherwise both meet at the midpoint; two feature nodes
/// merge only along a feature edge. Other slivers swap their longest edge when that raises the
/// worse shape factor of the two faces (Figure 4.14(b)); when that edge is a feature, the apex
/// merges onto one of its ends instead (Figure 4.14(c)). Feature edges (dihedral angle below
/// `feature_angle_deg`) are never removed or created.
///
/// Every change is checked exactly before it is made: the link condition (manifoldness), no new
/// triangle degenerate (`Collinear_3`) or reversed (`Orientation_3` against the old normal), and
/// no new triangle intersecting another within two rings (`Do_intersect_3`, `Coplanar_3`); a
/// refused change is counted in the result and the mesh is left as it was.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` with triangle faces
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{shape_factor_threshold}
///     \cgalParamDescription{triangles with a smaller (normalised) shape factor are slivers}
///     \cgalParamType{double}
///     \cgalParamDefault{0.7 (the thesis' value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{tolerance_edge_length}
///     \cgalParamDescription{sliver edges shorter than this are collapsed, longer ones flipped}
///     \cgalParamType{double}
///     \cgalParamDefault{a quarter of the mean edge length of `tm`}
///   \cgalParamNEnd
///   \cgalParamNBegin{feature_angle_deg}
///     \cgalParamDescription{edges whose faces meet at a smaller angle (180 = flat) are features}
///     \cgalParamType{double}
///     \cgalParamDefault{135}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{largest number of passes over the slivers}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{5}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return what was found, changed and refused, see `Sliver_result`.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Sliver_result remove_slivers(TriangleMesh& tm,
                             const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Geom_traits = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  internal::Sliver_settings settings;
  settings.shape_factor_threshold =
      choose_parameter(get_parameter(np, internal_np::shape_factor_threshold_t{}), 0.7);
  settings.tolerance_edge_length =
      choose_parameter(get_parameter(np, internal_np::tolerance_edge_length_t{}), -1.0);
  settings.feature_angle_deg = choose_parameter(
      get_parameter(np, internal_np::feature_angle_deg_t{}), default_feature_angle_deg);
  settings.max_passes =
      int(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 5u));
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  const Geom_traits gt =
      choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  internal::Visitor_parameter<NamedParameters> visitor(np);
  return internal::remove_slivers_with_settings(tm, vpm, gt, settings, visitor.get());
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_REMOVE_SLIVERS
extern
#endif
    template Sliver_result
    remove_slivers_with_settings<Core_mesh, Core_vpm, Core_traits>(Core_mesh&, Core_vpm,
                                                                   const Core_traits&,
                                                                   const Sliver_settings&,
                                                                   Any_visitor);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_REMOVE_SLIVERS_H
