// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_SHAPE_PREDICTION_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_SHAPE_PREDICTION_H

/// \file shape_prediction.h
/// High-fidelity hole filling with shape prediction (thesis chapter 5): boundary smoothing
/// (eq. 5.1), rough-set simplification (5.3.2), genetic-algorithm initial triangulation (5.4),
/// quartic triangular Bezier patches (5.5), advancing front with every new node mapped onto the
/// patches and smoothing guided by them (5.6). See doc/shape_prediction.md.

#include <CGAL/Mesh_repair/hole_filling/fill_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/advancing_front_core.h>
#include <CGAL/Mesh_repair/internal/hole_filling/patch_check.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/front_on_patches.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/hole_polygon.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/shape_estimate.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <array>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

/// `fill_hole_shape_prediction` on plain options; `face_boxes`: the dispatcher's boxes of the
/// faces near the hole, or null.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Hole_fill_report fill_hole_shape_prediction(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits&,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const Shape_prediction_options& sp,
    Face_box_cache<PolygonMesh, VertexPointMap>* face_boxes) {
  shape_prediction::Shape_estimate_options options;
  options.ga.random_seed = sp.random_seed;
  options.ga.population_size = sp.population_size;
  options.ga.max_generations = sp.max_generations;
  options.ga.target_fitness = sp.target_fitness;
  // The GA stops after 15 generations without a better triangulation (optimize_mesh keeps 60):
  // on the 126 bench holes 15 gave the same or better fidelity than 30 and 60 (median Einf/diag
  // 0.00624 against 0.00633, 124 holes closed against 123) in 0.87 of the time
  // (doc/shape_prediction.md, "GA stall").
  options.ga.stall_generations = 15;
  // ... counting only improvements of at least 0.002 (of the fitness range [0, 1]): on the
  // bench table and held-out holes the same fidelity in 0.91-0.92 of the time
  // (doc/shape_prediction.md).
  options.ga.stall_improvement = 0.002;
  options.fitness.w_internal = sp.fitness_weights[0];
  options.fitness.w_boundary = sp.fitness_weights[1];
  options.fitness.w_deviation = sp.fitness_weights[2];
  options.smoothing_iterations = sp.boundary_smoothing_iterations;
  options.simplify = sp.use_rough_set_simplification;
  return shape_prediction::fill_hole<GeomTraits>(pm, vpm, border_halfedge, patch, options,
                                                 sp.curvature_flow_iterations, face_boxes);
}

}  // namespace internal

/// Fills the hole bounded by the border halfedge `border_halfedge` by shape prediction. The
/// faces and vertices it creates are appended to `patch`; the border vertices do not move. Only
/// `CGAL::Mesh_repair::fill_hole()` and `fill_holes()` check and roll back patches (and fall back
/// to `liepa`, then `advancing_front`, when this method fails; see `shape_prediction_sequence`
/// in fill_holes.h): call those unless you check the patch yourself.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph`, triangulated
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the genetic algorithm; the fill is reproducible for it}
///     \cgalParamType{unsigned int} \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{population_size}
///     \cgalParamDescription{GA population} \cgalParamType{int} \cgalParamDefault{30}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_generations}
///     \cgalParamDescription{GA stops after this many generations (thesis: 500)}
///     \cgalParamType{int} \cgalParamDefault{500}
///   \cgalParamNEnd
///   \cgalParamNBegin{target_fitness}
///     \cgalParamDescription{GA stops once the best total fitness f_fit of eq. 5.13 reaches it}
///     \cgalParamType{double} \cgalParamDefault{0.7}
///   \cgalParamNEnd
///   \cgalParamNBegin{fitness_weights}
///     \cgalParamDescription{w_a, w_b, w_c of eq. 5.13 (internal smoothness, boundary
///       smoothness, deviation factors)}
///     \cgalParamType{std::array<double, 3>} \cgalParamDefault{{1/3, 1/3, 1/3}}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_smoothing_iterations}
///     \cgalParamDescription{passes of eq. 5.1 on a copy of the border; the smoothed positions
///       only guide the GA triangulation}
///     \cgalParamType{int} \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_rough_set_simplification}
///     \cgalParamDescription{only the essential nodes of 5.3.2 enter the GA; the others are
///       put back before the patches are built}
///     \cgalParamType{bool} \cgalParamDefault{true}
///   \cgalParamNEnd
///   \cgalParamNBegin{curvature_flow_iterations}
///     \cgalParamDescription{passes of umbrella (uniform mean-curvature) flow of the new
///       nodes, each move mapped back onto the patches}
///     \cgalParamType{int} \cgalParamDefault{5}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits} \cgalParamDefault{deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the report: `filled` when the front closed and every triangle was added; otherwise
/// `failure` says which stage failed.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Hole_fill_report fill_hole_shape_prediction(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GeomTraits = typename CGAL::GetGeomTraits<PolygonMesh, NamedParameters>::type;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  using VPM = std::remove_const_t<decltype(vpm)>;
  const GeomTraits traits =
      choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
  return internal::fill_hole_shape_prediction(
      pm, vpm, traits, border_halfedge, patch, internal::shape_prediction_options_from(np),
      static_cast<internal::Face_box_cache<PolygonMesh, VPM>*>(nullptr));
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_SHAPE_PREDICTION
extern
#endif
    template Hole_fill_report
    fill_hole_shape_prediction<Core_mesh, Core_vpm, Core_traits>(
        Core_mesh&, Core_vpm, const Core_traits&, Core_halfedge, Fill_patch<Core_mesh>&,
        const Shape_prediction_options&, Face_box_cache<Core_mesh, Core_vpm>*);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_SHAPE_PREDICTION_H
