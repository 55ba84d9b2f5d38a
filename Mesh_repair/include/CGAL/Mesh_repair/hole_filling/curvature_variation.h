// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_CURVATURE_VARIATION_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_CURVATURE_VARIATION_H

/// \file curvature_variation.h
/// Pernot, Moraru, Veron, "Filling holes in meshes using a mechanical model to simulate the
/// curvature variation minimization" (sections 5-6): every hole is filled with a topological
/// grid (section 5), then a single force-density bar network on the whole mesh shapes all the
/// inner meshes at once by minimising the squared external forces (eq. 8) or their variation
/// between connected nodes (eq. 9), optionally under point and polyline constraints (6.4).
/// See doc/curvature_variation.md.

#include <CGAL/Mesh_repair/hole_filling/curvature_variation_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/deform.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/topological_grid.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

namespace internal {
namespace curvature_variation {

template <class PolygonMesh, class VertexPointMap>
Hole_fill_report describe_hole(const PolygonMesh& pm,
                               typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                               VertexPointMap vpm) {
  Hole_fill_report report;
  report.requested = report.used = Fill_method::curvature_variation;
  for (auto b : CGAL::halfedges_around_face(h, pm)) {
    ++report.border_edges;
    report.perimeter += std::sqrt(
        CGAL::to_double(CGAL::squared_distance(get(vpm, source(b, pm)), get(vpm, target(b, pm)))));
  }
  return report;
}

template <class PolygonMesh>
void remove_patch(PolygonMesh& pm, Fill_patch<PolygonMesh>& patch) {
  std::vector<bool> all_used(patch.vertices.size(), true);
  remove_partial_patch(pm, patch, all_used);
}

}  // namespace curvature_variation
}  // namespace internal

namespace internal {

/// `deform_patches_curvature_variation` on plain options.
template <class PolygonMesh, class VertexPointMap>
Curvature_deformation_report deform_patches_curvature_variation(
    PolygonMesh& pm, VertexPointMap vpm, const std::vector<Fill_patch<PolygonMesh>>& patches,
    const Curvature_variation_fill_options& cv_options, Any_visitor visitor) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  curvature_variation::System_options options;
  options.objective = cv_options.objective;
  options.nodes = cv_options.nodes;
  options.density = cv_options.density;
  options.area_normalized = cv_options.area_normalized_forces;
  // The initial grid is relaxed tangentially before its densities and areas are measured, and the
  // system is solved once with them (doc/curvature_variation.md, "Initial grid").
  options.initial_grid_relaxation = curvature_variation::default_initial_grid_relaxation;
  options.remeasure_weights = false;
  const Fill_constraints<std::array<double, 3>>& constraints = cv_options.constraints;

  std::vector<Vec3> targets;
  for (const auto& p : constraints.points) targets.push_back({p[0], p[1], p[2]});
  double spacing = constraints.polyline_spacing;
  if (spacing <= 0 && !constraints.polylines.empty()) {
    double sum = 0;
    std::size_t count = 0;
    for (const auto& patch : patches)
      for (auto f : patch.faces)
        for (auto h : CGAL::halfedges_around_face(halfedge(f, pm), pm)) {
          sum += std::sqrt(CGAL::to_double(
              CGAL::squared_distance(get(vpm, source(h, pm)), get(vpm, target(h, pm)))));
          ++count;
        }
    spacing = count > 0 ? sum / double(count) : 0.0;
  }
  std::vector<std::vector<Point>> polylines;
  for (const auto& line : constraints.polylines) {
    polylines.emplace_back();
    for (const auto& p : line) polylines.back().emplace_back(p[0], p[1], p[2]);
  }
  const auto samples = curvature_variation::discretise_polylines(polylines, spacing);
  targets.insert(targets.end(), samples.begin(), samples.end());
  return curvature_variation::deform_patches(pm, vpm, patches, options, targets, visitor);
}

/// `fill_holes_curvature_variation` on plain options.
template <class PolygonMesh, class VertexPointMap>
Fill_result fill_holes_curvature_variation(
    PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>&
        border_halfedges,
    std::vector<Fill_patch<PolygonMesh>>& patches,
    const Curvature_variation_fill_options& cv_options, Any_visitor visitor) {
  namespace cv = internal::curvature_variation;
  const Topological_grid grid = cv_options.grid;
  const double density_control_factor = cv_options.density_control_factor;
  Curvature_deformation_report* report_out = cv_options.deformation_report;

  Fill_result result;
  patches.assign(border_halfedges.size(), Fill_patch<PolygonMesh>());
  std::vector<double> grid_seconds(border_halfedges.size(), 0.0);
  visitor.start_step("curvature variation: topological grids");
  for (std::size_t i = 0; i < border_halfedges.size(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    result.holes.push_back(cv::describe_hole(pm, border_halfedges[i], vpm));
    std::string failure;
    const bool inserted =
        grid == Topological_grid::disc
            ? cv::fill_with_disc_grid(pm, border_halfedges[i], vpm, patches[i], failure)
            : cv::fill_with_refined_liepa(pm, border_halfedges[i], vpm, density_control_factor,
                                          patches[i], failure);
    if (!inserted) result.holes.back().failure = failure;
    grid_seconds[i] = cv::seconds_since(start);
    if (!visitor.progress(double(i + 1) / double(border_halfedges.size()))) {
      result.cancelled = true;
      break;
    }
  }
  visitor.end_step("curvature variation: topological grids");

  Curvature_deformation_report deformation;
  if (!result.cancelled) {
    deformation = deform_patches_curvature_variation(pm, vpm, patches, cv_options, visitor);
    result.cancelled = deformation.cancelled;
  }
  if (report_out != nullptr) *report_out = deformation;
  const double solve_seconds =
      deformation.assembly_seconds + deformation.factorization_seconds + deformation.solve_seconds;
  std::size_t total_free = 0;
  for (const auto& patch : patches) total_free += patch.vertices.size();
  for (std::size_t i = 0; i < result.holes.size(); ++i) {
    Hole_fill_report& hole = result.holes[i];
    const bool had_patch = !patches[i].faces.empty();
    if (had_patch && !deformation.solved) {
      cv::remove_patch(pm, patches[i]);
      hole.failure = result.cancelled ? "cancelled" : "deformation: " + deformation.failure;
    }
    hole.filled = had_patch && deformation.solved;
    if (hole.filled)
      hole.notes.push_back("curvature variation: " + std::to_string(deformation.free_vertices) +
                           " free vertices of all holes in one system, " +
                           std::to_string(deformation.system_nonzeros) + " nonzeros");
    hole.faces_created = patches[i].faces.size();
    hole.vertices_created = patches[i].vertices.size();
    const double share =
        total_free > 0 ? double(patches[i].vertices.size()) / double(total_free) : 0.0;
    hole.seconds = grid_seconds[i] + share * solve_seconds;
    if (hole.filled)
      ++result.filled;
    else
      ++result.failed;
  }
  for (std::size_t i = result.holes.size(); i < border_halfedges.size(); ++i) {
    Hole_fill_report hole = cv::describe_hole(pm, border_halfedges[i], vpm);
    hole.failure = "cancelled";
    result.holes.push_back(hole);
    ++result.failed;
  }
  return result;
}

}  // namespace internal

/// \ingroup PkgMeshRepairHoleFilling
/// Shapes the interior vertices of already inserted patches with Pernot's force-density bar
/// network (section 6), all patches in one sparse solve. Patch vertices move; every other vertex
/// (including the hole contours) is blocked. The connectivity is not changed. On failure no
/// vertex moves and the report says why.
///
/// \param pm a triangle mesh holding the patches
/// \param patches the faces and the interior (free) vertices of each patch
/// \param np the named parameters `curvature_objective`, `objective_nodes`, `force_density`,
///           `fill_constraints`, `vertex_point_map`, `visitor`, as in
///           `fill_holes_curvature_variation()`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Curvature_deformation_report deform_patches_curvature_variation(
    PolygonMesh& pm, const std::vector<Fill_patch<PolygonMesh>>& patches,
    const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  internal::Visitor_parameter<NamedParameters> visitor(np);
  return internal::deform_patches_curvature_variation(
      pm, vpm, patches, internal::curvature_variation_options_from(np), visitor.get());
}

/// \ingroup PkgMeshRepairHoleFilling
/// Fills every hole given by `border_halfedges` with Pernot's method: a topological grid per hole
/// (section 5), then ONE deformation step (section 6) that positions the interior vertices of all
/// grids together by solving one sparse symmetric system. The hole contours do not move.
/// A hole whose grid cannot be inserted is left open and reported; if the common solve fails,
/// every inserted grid is removed (the mesh is as before the call) and every hole reports it.
///
/// \param pm a triangle mesh
/// \param border_halfedges one border halfedge per hole (`face(h, pm) == null_face()`), distinct
/// holes \param patches receives one entry per hole, in the same order (empty when not filled)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{curvature_objective}
///     \cgalParamDescription{`Curvature_objective::forces` (eq. 8) or `force_variation` (eq. 9)}
///     \cgalParamDefault{`Curvature_objective::force_variation`}
///   \cgalParamNEnd
///   \cgalParamNBegin{objective_nodes}
///     \cgalParamDescription{nodes whose forces are summed: `Objective_nodes::free_nodes` or
///       `free_and_contour_nodes` (one more ring of the surrounding mesh, Fig. 9)}
///     \cgalParamDefault{`Objective_nodes::free_and_contour_nodes`}
///   \cgalParamNEnd
///   \cgalParamNBegin{topological_grid}
///     \cgalParamDescription{`Topological_grid::disc` (Pernot 5) or `refined_liepa` (CGAL's
///       `triangulate_and_refine_hole`, the alternative Pernot 5 suggests for non-disc holes)}
///     \cgalParamDefault{`Topological_grid::refined_liepa`}
///   \cgalParamNEnd
///   \cgalParamNBegin{force_density}
///     \cgalParamDescription{force densities q of the bars: `Force_density::uniform` (q = 1, the
///       paper's choice), `inverse_length` or `cotangent` (measured on the initial grid)}
///     \cgalParamDefault{`Force_density::cotangent`}
///   \cgalParamNEnd
///   \cgalParamNBegin{area_normalized_forces}
///     \cgalParamDescription{sum f_i / A_i (A_i a third of the area around node i) instead of
///       f_i in eq. 8-9: with cotangent densities, the mean-curvature normal itself}
///     \cgalParamType{bool}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fill_constraints}
///     \cgalParamDescription{points and polylines the inner meshes must pass through (6.4)}
///     \cgalParamType{`Fill_constraints<Point_3>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{density_control_factor}
///     \cgalParamDescription{CGAL's refinement density, for `refined_liepa`}
///     \cgalParamDefault{\f$\sqrt{2}\f$}
///   \cgalParamNEnd
///   \cgalParamNBegin{deformation_report}
///     \cgalParamDescription{receives the sizes, timings and constraint residual of the solve}
///     \cgalParamType{`Curvature_deformation_report*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress and cancellation, see visitor.h}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Fill_result fill_holes_curvature_variation(
    PolygonMesh& pm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>&
        border_halfedges,
    std::vector<Fill_patch<PolygonMesh>>& patches,
    const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  internal::Visitor_parameter<NamedParameters> visitor(np);
  return internal::fill_holes_curvature_variation(pm, vpm, border_halfedges, patches,
                                                  internal::curvature_variation_options_from(np),
                                                  visitor.get());
}

/// \ingroup PkgMeshRepairHoleFilling
/// One hole: `fill_holes_curvature_variation()` with a single border halfedge.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Hole_fill_report fill_hole_curvature_variation(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const NamedParameters& np = parameters::default_values()) {
  std::vector<Fill_patch<PolygonMesh>> patches;
  const Fill_result result = fill_holes_curvature_variation(
      pm,
      std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>{border_halfedge},
      patches, np);
  patch = patches.front();
  return result.holes.front();
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_CURVATURE_VARIATION
extern
#endif
    template Fill_result
    fill_holes_curvature_variation<Core_mesh, Core_vpm>(Core_mesh&, Core_vpm,
                                                        const std::vector<Core_halfedge>&,
                                                        std::vector<Fill_patch<Core_mesh>>&,
                                                        const Curvature_variation_fill_options&,
                                                        Any_visitor);
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_CURVATURE_VARIATION
extern
#endif
    template Curvature_deformation_report
    deform_patches_curvature_variation<Core_mesh, Core_vpm>(
        Core_mesh&, Core_vpm, const std::vector<Fill_patch<Core_mesh>>&,
        const Curvature_variation_fill_options&, Any_visitor);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_CURVATURE_VARIATION_H
