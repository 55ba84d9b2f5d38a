// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_FILL_OPTIONS_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_FILL_OPTIONS_H

/// \file fill_options.h
/// The options of every hole-filling method and of the dispatcher, as plain structs. The public
/// functions read their named parameters into these once, at the boundary; everything below is
/// templated on the mesh only, so each method is compiled once per mesh type whatever parameters
/// a caller passes. The defaults here are the defaults of the named parameters (documented in
/// each method's header).

#include <CGAL/Mesh_repair/hole_filling/curvature_variation_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/parameters.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// Options of `fill_hole_advancing_front` (thesis 4.4).
struct Advancing_front_options {
  bool fit_quadric = true;  ///< project new nodes on a quadric fitted to the ring
  /// Close a stuck front's remnant with a checked triangulation; the `automatic` and
  /// `shape_prediction` sequences turn it off and hand the hole to the next method instead.
  bool close_stuck_front = true;
  /// The work allowed to those closings on one hole, in stored triangles visited (60 million:
  /// about 5 s; 8 steps of their dynamic programs count as one visit), shared by all its attempts;
  /// past it, a closing stops after its first 8 rounds and the loop is left open
  /// (doc/advancing_front.md, "Closing a stuck front"). The filling lowers it to 20,000 per face of
  /// the mesh on meshes of fewer than 3,000 faces.
  std::size_t remnant_visits_per_hole = 60'000'000;
  bool check_self_intersections = true;   ///< exact check of each attempt
  unsigned int smoothing_iterations = 3;  ///< tangential relaxation passes of the new nodes
};

/// How far `fill_hole_liepa` goes: CGAL's triangulation of the border polygon alone
/// (`triangulate_hole`), refined to the border's density (`triangulate_and_refine_hole`), or
/// refined and faired (`triangulate_refine_and_fair_hole`). The coarser stages are the last
/// resorts of the sequences: on large or saddle-shaped borders the fairing, and sometimes the
/// refinement, folds the patch onto itself where the triangulation alone does not.
enum class Liepa_stage { triangulate, refine, fair };

/// The first triangulation of `fill_hole_liepa`: Liepa's minimum-weight triangulation of the
/// border polygon (CGAL), the constrained Delaunay triangulation of the border projected along
/// its normal where that projection is a simple polygon, or the same after the border is
/// extruded along its normal to a flat base beyond its part of the mesh. The projected ones are
/// last resorts for the jagged, nearly flat outlines of scans (projected_triangulation.h).
enum class Hole_triangulation { minimum_weight, projected, projected_base };

/// Options of `fill_hole_liepa` (CGAL's `triangulate_refine_and_fair_hole`).
struct Liepa_options {
  unsigned int fairing_continuity = 1;  ///< 0 (membrane), 1 (thin plate) or 2
  Liepa_stage last_stage = Liepa_stage::fair;
  /// The first triangulation, before the refinement and the fairing.
  Hole_triangulation triangulation = Hole_triangulation::minimum_weight;
  /// When the patch is rejected, the last resorts of the automatic sequences follow (C0,
  /// refined only, triangulated only, the projected triangulation, a base): automatic_repair's
  /// grown holes, whose patches must also stay near the faces they replace.
  bool then_last_resorts = false;
};

/// Options of `fill_hole_shape_prediction` (thesis chapter 5).
struct Shape_prediction_options {
  unsigned int random_seed = 0;
  int population_size = 30;
  int max_generations = 500;
  double target_fitness = 0.7;
  std::array<double, 3> fitness_weights{1.0 / 3, 1.0 / 3, 1.0 / 3};  ///< w_a, w_b, w_c (eq. 5.13)
  int boundary_smoothing_iterations = 1;                             ///< eq. 5.1 passes
  bool use_rough_set_simplification = true;                          ///< 5.3.2
  int curvature_flow_iterations = 5;  ///< smoothing of the new nodes on the patches
};

/// Options of `fill_holes_curvature_variation` (Pernot et al. 5-6).
struct Curvature_variation_fill_options {
  Topological_grid grid = Topological_grid::refined_liepa;
  double density_control_factor = std::sqrt(2.0);  ///< refinement of the Liepa grid
  Curvature_objective objective = Curvature_objective::force_variation;
  Objective_nodes nodes = Objective_nodes::free_and_contour_nodes;
  Force_density density = Force_density::cotangent;
  bool area_normalized_forces = true;
  /// Point and polyline constraints (Pernot 6.4), coordinates in model units.
  Fill_constraints<std::array<double, 3>> constraints;
  /// Receives the deformation's report when not null.
  Curvature_deformation_report* deformation_report = nullptr;
};

/// Options of `fill_holes` and `fill_hole`: the selection of holes, the method and the options
/// of every method.
struct Fill_options {
  Fill_method method = Fill_method::self_validated;
  std::size_t max_hole_edges = std::numeric_limits<std::size_t>::max();
  double max_hole_size = std::numeric_limits<double>::infinity();  ///< of the bbox diagonal
  /// A border cycle whose vector area exceeds this fraction of the area of the component it
  /// borders is the outline of an open sheet and is left open (infinity: filled like any hole).
  double sheet_border_ratio = 0.9;
  std::function<bool(const Hole_description&)> hole_filter;  ///< empty: every hole
  bool detect_ring_holes = true;
  bool check_self_intersections = true;
  /// False: a patch may meet other connected components (a tube trimmed against a post, its
  /// open end lying on the post's face); its own component, itself and earlier patches of its
  /// component stay obstacles. automatic_repair retries the holes no method could fill so.
  bool other_parts_are_obstacles = true;
  int number_of_threads = 0;  ///< 0: TBB's default
  Advancing_front_options advancing_front;
  Liepa_options liepa;
  Shape_prediction_options shape_prediction;
  Curvature_variation_fill_options curvature_variation;
};

namespace internal {

template <class NamedParameters>
Advancing_front_options advancing_front_options_from(const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Advancing_front_options o;
  o.fit_quadric = choose_parameter(get_parameter(np, internal_np::fit_quadric_t()), o.fit_quadric);
  o.check_self_intersections = choose_parameter(
      get_parameter(np, internal_np::check_self_intersections_t()), o.check_self_intersections);
  o.smoothing_iterations = choose_parameter(
      get_parameter(np, CGAL::internal_np::number_of_iterations), o.smoothing_iterations);
  return o;
}

template <class NamedParameters>
Liepa_options liepa_options_from(const NamedParameters& np) {
  Liepa_options o;
  o.fairing_continuity = parameters::choose_parameter(
      parameters::get_parameter(np, CGAL::internal_np::fairing_continuity), o.fairing_continuity);
  return o;
}

template <class NamedParameters>
Shape_prediction_options shape_prediction_options_from(const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Shape_prediction_options o;
  o.random_seed =
      choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), o.random_seed);
  o.population_size =
      choose_parameter(get_parameter(np, internal_np::population_size_t()), o.population_size);
  o.max_generations =
      choose_parameter(get_parameter(np, internal_np::max_generations_t()), o.max_generations);
  o.target_fitness =
      choose_parameter(get_parameter(np, internal_np::target_fitness_t()), o.target_fitness);
  o.fitness_weights =
      choose_parameter(get_parameter(np, internal_np::fitness_weights_t()), o.fitness_weights);
  o.boundary_smoothing_iterations =
      choose_parameter(get_parameter(np, internal_np::boundary_smoothing_iterations_t()),
                       o.boundary_smoothing_iterations);
  o.use_rough_set_simplification =
      choose_parameter(get_parameter(np, internal_np::use_rough_set_simplification_t()),
                       o.use_rough_set_simplification);
  o.curvature_flow_iterations = choose_parameter(
      get_parameter(np, internal_np::curvature_flow_iterations_t()), o.curvature_flow_iterations);
  return o;
}

template <class Point>
std::array<double, 3> coordinates_of(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

/// The constraints of a `fill_constraints` parameter, in doubles.
template <class Point>
Fill_constraints<std::array<double, 3>> constraints_in_doubles(const Fill_constraints<Point>& c) {
  Fill_constraints<std::array<double, 3>> out;
  out.polyline_spacing = c.polyline_spacing;
  for (const Point& p : c.points) out.points.push_back(coordinates_of(p));
  for (const auto& line : c.polylines) {
    out.polylines.emplace_back();
    for (const Point& p : line) out.polylines.back().push_back(coordinates_of(p));
  }
  return out;
}

inline Fill_constraints<std::array<double, 3>> constraints_in_doubles(
    const CGAL::internal_np::Param_not_found&) {
  return {};
}

template <class NamedParameters>
Curvature_variation_fill_options curvature_variation_options_from(const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Curvature_variation_fill_options o;
  o.grid = choose_parameter(get_parameter(np, internal_np::topological_grid_t()), o.grid);
  o.density_control_factor = choose_parameter(
      get_parameter(np, CGAL::internal_np::density_control_factor), o.density_control_factor);
  o.objective =
      choose_parameter(get_parameter(np, internal_np::curvature_objective_t()), o.objective);
  o.nodes = choose_parameter(get_parameter(np, internal_np::objective_nodes_t()), o.nodes);
  o.density = choose_parameter(get_parameter(np, internal_np::force_density_t()), o.density);
  o.area_normalized_forces = choose_parameter(
      get_parameter(np, internal_np::area_normalized_forces_t()), o.area_normalized_forces);
  o.constraints = constraints_in_doubles(get_parameter(np, internal_np::fill_constraints_t()));
  o.deformation_report = choose_parameter(get_parameter(np, internal_np::deformation_report_t()),
                                          static_cast<Curvature_deformation_report*>(nullptr));
  return o;
}

template <class Filter>
std::function<bool(const Hole_description&)> hole_filter_from(const Filter& filter) {
  return filter;
}
inline std::function<bool(const Hole_description&)> hole_filter_from(
    const CGAL::internal_np::Param_not_found&) {
  return {};
}

/// Every hole-filling parameter of `np`, with the defaults of the named parameters.
template <class NamedParameters>
Fill_options fill_options_from(const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Fill_options o;
  o.method = choose_parameter(get_parameter(np, internal_np::fill_method_t()), o.method);
  o.max_hole_edges =
      choose_parameter(get_parameter(np, internal_np::max_hole_edges_t()), o.max_hole_edges);
  o.max_hole_size =
      choose_parameter(get_parameter(np, internal_np::max_hole_size_t()), o.max_hole_size);
  o.sheet_border_ratio = choose_parameter(get_parameter(np, internal_np::sheet_border_ratio_t()),
                                          o.sheet_border_ratio);
  o.hole_filter = hole_filter_from(get_parameter(np, internal_np::hole_filter_t()));
  o.detect_ring_holes =
      choose_parameter(get_parameter(np, internal_np::detect_ring_holes_t()), o.detect_ring_holes);
  o.check_self_intersections = choose_parameter(
      get_parameter(np, internal_np::check_self_intersections_t()), o.check_self_intersections);
  o.number_of_threads =
      choose_parameter(get_parameter(np, internal_np::number_of_threads_t()), o.number_of_threads);
  o.advancing_front = advancing_front_options_from(np);
  o.liepa = liepa_options_from(np);
  o.shape_prediction = shape_prediction_options_from(np);
  o.curvature_variation = curvature_variation_options_from(np);
  return o;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_FILL_OPTIONS_H
