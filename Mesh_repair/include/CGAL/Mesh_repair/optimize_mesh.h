// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_OPTIMIZE_MESH_H
#define CGAL_MESH_REPAIR_OPTIMIZE_MESH_H

/// \file optimize_mesh.h
/// Mesh optimisation by genetic-algorithm re-triangulation (thesis chapter 7): reduction of the
/// number of triangles, or improvement of their shape, keeping corners and feature lines.

#include <CGAL/Mesh_repair/internal/optimize_mesh/optimizer.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>

namespace CGAL {
namespace Mesh_repair {

namespace internal {
namespace optimize {

/// The options of `optimize_mesh()` from its named parameters (also used by the tests to switch
/// internal choices off).
template <class PolygonMesh, class NamedParameters>
Optimizer_options options_from_parameters(const PolygonMesh& pm, const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Optimizer_options options;
  options.mode = choose_parameter(get_parameter(np, internal_np::optimization_mode_t()),
                                  Optimization_mode::reduction);
  const bool reduction = options.mode == Optimization_mode::reduction;
  options.weighing_threshold =
      choose_parameter(get_parameter(np, internal_np::weighing_factor_threshold_t()),
                       std::numeric_limits<double>::infinity());
  const double default_ratio = std::isfinite(options.weighing_threshold) ? 0.0 : 0.5;
  const double ratio =
      choose_parameter(get_parameter(np, internal_np::target_face_ratio_t()), default_ratio);
  const std::size_t input_faces = std::size_t(num_faces(pm));
  options.target_faces = choose_parameter(get_parameter(np, internal_np::target_face_count_t()),
                                          std::size_t(std::llround(ratio * double(input_faces))));
  options.feature_angle_deg = choose_parameter(
      get_parameter(np, internal_np::feature_angle_deg_t()), default_feature_angle_deg);
  options.max_passes = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                        reduction ? 100 : 50);
  options.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);

  auto& settings = options.retriangulation;
  settings.quality_mode = !reduction;
  settings.fitness.w_shape =
      choose_parameter(get_parameter(np, internal_np::shape_weight_t()), reduction ? 0.2 : 0.6);
  settings.fitness.w_internal = choose_parameter(
      get_parameter(np, internal_np::smoothness_weight_t()), reduction ? 0.4 : 0.2);
  settings.fitness.w_boundary = choose_parameter(
      get_parameter(np, internal_np::surrounding_weight_t()), reduction ? 0.4 : 0.2);
  settings.min_angle_floor_deg =
      choose_parameter(get_parameter(np, internal_np::min_angle_floor_deg_t()), 15.0);
  settings.feature_cosine = std::cos(options.feature_angle_deg * CGAL_PI / 180.0);
  settings.ga.population_size =
      choose_parameter(get_parameter(np, internal_np::population_size_t()), 6);
  settings.ga.max_generations =
      choose_parameter(get_parameter(np, internal_np::max_generations_t()), 3);
  // Polygons of up to 6 nodes (the star of a degree-6 node): all their 14 or fewer
  // triangulations are evaluated instead of running the GA (its optimum, found exactly).
  settings.exhaustive_max_nodes = 6;
  // The GA's own stop on a target fitness is off: every region gets its generations.
  settings.ga.target_fitness = std::numeric_limits<double>::infinity();

  return options;
}

}  // namespace optimize
}  // namespace internal

namespace internal {
namespace optimize {

/// `optimize_mesh` on plain options (compiled once per mesh type).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Optimization_result optimize_with_options(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& gt,
                                          const Optimizer_options& options, Any_visitor visitor) {
  return Optimizer<PolygonMesh, VertexPointMap, GeomTraits, Any_visitor>(pm, vpm, gt, options,
                                                                         visitor)
      .run();
}

}  // namespace optimize
}  // namespace internal

/// \ingroup PkgMeshRepairRef
/// Optimises the triangle mesh `pm` in place (thesis 7.1-7.3). Edges are classified feature /
/// non-feature (border, or dihedral angle below `feature_angle_deg`) and nodes into corner,
/// fixed and removable edge-feature, fixed and removable interior nodes, the fixed ones forming
/// a maximal independent set (7.2.1-7.2.2). Elements are then ranked by the weighing factor of
/// eq. 7.1-7.4 (normal deviation of the affected elements), and, in that order, non-touching
/// regions are removed and re-triangulated by the genetic algorithm of 7.3 with the fitness of
/// eq. 7.6-7.9:
/// - `Optimization_mode::reduction`: the star of a removable node (7.2.3a), a removable feature
///   node's star with its feature line kept as one edge; regions are ranked by the distance
///   their removal is expected to cause, every removed input node is tracked on its closest
///   face, and a patch is refused when a tracked node would end farther from it than the pass'
///   bound (see doc/optimize_mesh.md, "Distance control"); small polygons (up to 6 nodes) are
///   triangulated by evaluating all their triangulations, larger ones by the GA; passes repeat
///   until the target face count, the weighing-factor bound or no more progress;
/// - `Optimization_mode::quality`: the element and its three edge neighbours (7.2.3b), replaced
///   only when both the fitness and the smallest angle of the region improve; the face count
///   does not change.
/// A new patch is used only if it passes exact checks: no new edge duplicating an existing one,
/// every new normal on the side of the old region's (exact `Angle_3`), no new crease (exact
/// dihedral comparison with the feature angle), no fold, no intersection with the surrounding
/// faces (exact `Do_intersect_3`). Otherwise the old triangles stay. Corners and fixed feature
/// nodes are never removed, feature edges never disappear except when a removable feature node
/// is replaced by the chord joining its two feature neighbours.
///
/// `pm` stays valid (`CGAL::is_valid_polygon_mesh`) and keeps its border cycles' topology; a
/// closed mesh stays closed. With `Surface_mesh`, removed elements are only marked: call
/// `collect_garbage()` before relying on indices.
///
/// \tparam PolygonMesh a model of `FaceListGraph` and `MutableFaceGraph`, triangulated
/// \param pm the mesh
/// \param np an optional sequence of named parameters among those below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{optimization_mode}
///     \cgalParamDescription{`Optimization_mode::reduction` or `Optimization_mode::quality`}
///     \cgalParamDefault{`Optimization_mode::reduction`}
///   \cgalParamNEnd
///   \cgalParamNBegin{target_face_count}
///     \cgalParamDescription{reduction stops when the mesh has at most this many faces}
///     \cgalParamDefault{unset: `target_face_ratio` applies}
///   \cgalParamNEnd
///   \cgalParamNBegin{target_face_ratio}
///     \cgalParamDescription{or at most this fraction of the input faces}
///     \cgalParamDefault{`0.5` unless `weighing_factor_threshold` is given (then `0`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{weighing_factor_threshold}
///     \cgalParamDescription{error bound: elements whose weighing factor d (eq. 7.4, in
///       [0, 4]) exceeds it are never chosen}
///     \cgalParamDefault{infinity}
///   \cgalParamNEnd
///   \cgalParamNBegin{feature_angle_deg}
///     \cgalParamDescription{dihedral angle (180 = flat) below which an edge is a feature; a node
///       whose two feature edges make an angle below it is fixed}
///     \cgalParamDefault{`135`}
///   \cgalParamNEnd
///   \cgalParamNBegin{shape_weight, smoothness_weight, surrounding_weight}
///     \cgalParamDescription{w_a, w_b, w_c of eq. 7.9 (shape factor 7.6, smoothness inside the
///       patch 7.7, smoothness with the surrounding triangles 7.8), each factor in [0,1]}
///     \cgalParamDefault{reduction: `0.2, 0.4, 0.4`; quality: `0.6, 0.2, 0.2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{min_angle_floor_deg}
///     \cgalParamDescription{reduction: a region is replaced only when the new smallest angle is
///       at least min(old smallest angle, this)}
///     \cgalParamDefault{`15`}
///   \cgalParamNEnd
///   \cgalParamNBegin{population_size, max_generations}
///     \cgalParamDescription{GA size per region}
///     \cgalParamDefault{`6`, `3` (the population is seeded with the minimum-dihedral
///       triangulation, so a few generations suffice on regions of about ten nodes)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{maximal number of passes}
///     \cgalParamDefault{`100` (reduction), `50` (quality); passes stop earlier when none changes
///     the mesh}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the GA; the result is reproducible for a seed}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, geom_traits}
///     \cgalParamDefault{`get(CGAL::vertex_point, pm)`, the kernel of its points}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress and cancellation, see `Default_visitor`}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was done and why it stopped (`Optimization_result`).
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Optimization_result optimize_mesh(PolygonMesh& pm,
                                  const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Geom_traits = typename GetGeomTraits<PolygonMesh, NamedParameters>::type;

  const Geom_traits gt =
      choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  internal::Visitor_parameter<NamedParameters> visitor(np);
  return internal::optimize::optimize_with_options(
      pm, vpm, gt, internal::optimize::options_from_parameters(pm, np), visitor.get());
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace optimize {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_OPTIMIZE_MESH
extern
#endif
    template Optimization_result
    optimize_with_options<Core_mesh, Core_vpm, Core_traits>(Core_mesh&, Core_vpm,
                                                            const Core_traits&,
                                                            const Optimizer_options&, Any_visitor);
}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_OPTIMIZE_MESH_H
