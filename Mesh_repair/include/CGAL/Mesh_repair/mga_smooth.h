// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_MGA_SMOOTH_H
#define CGAL_MESH_REPAIR_MGA_SMOOTH_H

/// \file mga_smooth.h
/// Micro-genetic node smoothing of triangle and quad surface meshes on a smooth (G1) surface
/// rebuilt from the mesh itself (Chen, Hsu, Lin, sections 2.2 and 3), and the paper's
/// gradient-based baseline. See doc/mga_smooth.md.

#include <CGAL/Mesh_repair/internal/mga/node_smoothing.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `mga_smooth` and `conjugate_gradient_smooth` did. Quality is alpha (eq. 4) for
/// triangles and beta (eq. 7) for quads, over all triangles and quads of the mesh.
struct Mga_smooth_result {
  std::size_t free_nodes = 0;
  std::size_t border_nodes = 0;   ///< fixed: on a border
  std::size_t feature_nodes = 0;  ///< fixed: on a feature line (sharp edges, spurs excluded)
  std::size_t sliding_nodes =
      0;  ///< inside a feature line, sliding along it (`slide_feature_nodes`)
  std::size_t constrained_nodes =
      0;                           ///< fixed by `vertex_is_constrained_map` or a face of degree > 4
  std::size_t moves = 0;           ///< accepted node moves over all sweeps
  std::size_t rejected_folds = 0;  ///< best moves refused by the exact fold test
  int sweeps = 0;
  bool converged = false;  ///< the last sweep moved no node
  bool cancelled = false;  ///< the visitor asked to stop; the mesh is valid
  double worst_quality_before = 0, mean_quality_before = 0;
  double worst_quality_after = 0, mean_quality_after = 0;
};

namespace internal {

inline std::pair<double, double> worst_and_mean_quality(const Polygon_arrays& mesh) {
  double worst = 1, sum = 0;
  std::size_t count = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const int degree = mesh.degree(int(f));
    Vec3 corners[4];
    for (int i = 0; i < degree; ++i) corners[i] = mesh.points[mesh.faces[f][i]];
    const double q = element_quality(corners, degree);
    worst = std::min(worst, q);
    sum += q;
    ++count;
  }
  return count ? std::make_pair(worst, sum / double(count)) : std::make_pair(0.0, 0.0);
}

// A feature vertex inside a feature line: exactly two feature edges meet there, and the line
// turns there by less than 30 degrees (a sharper turn is a joint, which stays fixed, as corners
// and line ends do: "the points at the edges and joints have to be marked and fixed"). `path`
// receives the two neighbours along the line.
inline bool inside_feature_line(const G1_surface& surface, int v, std::array<int, 2>& path) {
  const std::vector<int> neighbours = surface.feature_neighbours(v);
  if (neighbours.size() != 2) return false;
  const Vec3& p = surface.points()[v];
  const Vec3 d0 = normalized(surface.points()[neighbours[0]] - p);
  const Vec3 d1 = normalized(surface.points()[neighbours[1]] - p);
  if (!(dot(d0, d1) < -std::cos(30.0 * CGAL_PI / 180.0))) return false;
  path = {neighbours[0], neighbours[1]};
  return true;
}

// Splits faces into the primary triangles of the G1 surface: quads along their shorter
// diagonal, larger faces as fans.
inline std::vector<std::array<int, 3>> primary_triangles(const Polygon_arrays& mesh,
                                                         const std::vector<std::vector<int>>& big) {
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& q = mesh.faces[f];
    if (mesh.degree(int(f)) == 3) {
      triangles.push_back({q[0], q[1], q[2]});
    } else if (norm(mesh.points[q[0]] - mesh.points[q[2]]) <=
               norm(mesh.points[q[1]] - mesh.points[q[3]])) {
      triangles.push_back({q[0], q[1], q[2]});
      triangles.push_back({q[0], q[2], q[3]});
    } else {
      triangles.push_back({q[0], q[1], q[3]});
      triangles.push_back({q[1], q[2], q[3]});
    }
  }
  for (const auto& polygon : big)
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
      triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
  return triangles;
}

/// Every option of `mga_smooth` but the mesh's maps, read once from the named parameters.
struct Mga_smooth_options {
  Node_smoothing_settings settings;
  double feature_angle_deg = default_smoothing_feature_angle_deg;
  double tangent_scale = default_surface_tangent_scale;
  bool slide_feature_nodes = false;
};

template <class NamedParameters>
Mga_smooth_options mga_smooth_options_from(const NamedParameters& np, Node_optimizer optimizer) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Mga_smooth_options o;
  Node_smoothing_settings& settings = o.settings;
  settings.optimizer = optimizer;
  settings.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  settings.max_sweeps =
      int(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 3));
  settings.threads =
      int(choose_parameter(get_parameter(np, internal_np::number_of_threads_t()), 0));
  settings.ga.population_size =
      int(choose_parameter(get_parameter(np, internal_np::population_size_t()), 5));
  settings.ga.max_generations =
      int(choose_parameter(get_parameter(np, internal_np::max_generations_t()), 3));
  o.feature_angle_deg = choose_parameter(get_parameter(np, internal_np::feature_angle_deg_t()),
                                         default_smoothing_feature_angle_deg);
  // `cubic_surface_weight` is the deprecated name of the same number (it blended a C0 cubic
  // surface with the flat triangles; the G1 surface shortens its tangents instead).
  o.tangent_scale =
      choose_parameter(get_parameter(np, internal_np::surface_tangent_scale_t()),
                       choose_parameter(get_parameter(np, internal_np::cubic_surface_weight_t()),
                                        default_surface_tangent_scale));
  o.slide_feature_nodes =
      choose_parameter(get_parameter(np, internal_np::slide_feature_nodes_t()), false);
  return o;
}

/// The smoothing on plain options, templated on the mesh and its maps only (compiled once in the
/// core for Surface_mesh): `constrained(v)` tells whether the user fixed vertex v.
template <class PolygonMesh, class VertexPointMap, class GT>
Mga_smooth_result smooth_with_options(
    PolygonMesh& pm, VertexPointMap vpm, const GT& traits,
    const std::function<bool(typename boost::graph_traits<PolygonMesh>::vertex_descriptor)>&
        constrained,
    const Mga_smooth_options& options, Any_visitor visitor) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename GT::Point_3;
  const Node_smoothing_settings& settings = options.settings;
  const Node_optimizer optimizer = settings.optimizer;
  const double feature_angle_deg = options.feature_angle_deg;
  const double tangent_scale = options.tangent_scale;
  const bool slide_feature_nodes = options.slide_feature_nodes;

  // Index arrays of the mesh.
  visitor.start_step("G1 surface");
  auto index = CGAL::get_initialized_vertex_index_map(pm);
  std::vector<vertex_descriptor> vertex_of(num_vertices(pm));
  Polygon_arrays mesh;
  mesh.points.resize(num_vertices(pm));
  for (vertex_descriptor v : vertices(pm)) {
    const std::size_t i = get(index, v);
    vertex_of[i] = v;
    const Point& p = get(vpm, v);
    mesh.points[i] = Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  std::vector<bool> fixed(mesh.points.size(), false);
  std::vector<std::vector<int>> big_faces;
  Mga_smooth_result result;
  std::vector<int> polygon;
  mesh.faces.reserve(num_faces(pm));
  for (auto f : faces(pm)) {
    polygon.clear();
    for (vertex_descriptor v : vertices_around_face(halfedge(f, pm), pm))
      polygon.push_back(int(get(index, v)));
    if (polygon.size() == 3 || polygon.size() == 4) {
      mesh.faces.push_back(
          {polygon[0], polygon[1], polygon[2], polygon.size() == 4 ? polygon[3] : -1});
    } else {
      for (int v : polygon) fixed[v] = true;
      big_faces.push_back(polygon);
    }
  }
  mesh.build_incidence();
  const G1_surface surface(mesh.points, primary_triangles(mesh, big_faces), feature_angle_deg,
                           std::min(1.0, std::max(0.0, tangent_scale)));
  std::vector<std::array<int, 2>> feature_path(slide_feature_nodes ? mesh.points.size() : 0,
                                               std::array<int, 2>{-1, -1});
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (mesh.incidence_start[v] == mesh.incidence_start[v + 1]) {
      fixed[v] = true;  // isolated vertex: nothing to smooth
    } else if (surface.is_border_vertex(int(v))) {
      fixed[v] = true, ++result.border_nodes;
    } else if (surface.is_feature_vertex(int(v))) {
      if (slide_feature_nodes && !fixed[v] && !constrained(vertex_of[v]) &&
          inside_feature_line(surface, int(v), feature_path[v])) {
        ++result.sliding_nodes;
      } else {
        fixed[v] = true, ++result.feature_nodes;
      }
    } else if (fixed[v] || constrained(vertex_of[v])) {
      fixed[v] = true, ++result.constrained_nodes;
    } else {
      ++result.free_nodes;
    }
  }
  visitor.end_step("G1 surface");

  std::tie(result.worst_quality_before, result.mean_quality_before) = worst_and_mean_quality(mesh);
  visitor.start_step(optimizer == Node_optimizer::micro_ga ? "micro-GA smoothing"
                                                           : "conjugate-gradient smoothing");
  Node_smoother<GT> smoother(mesh, surface, fixed, settings, traits, std::move(feature_path));
  const Node_smoothing_statistics statistics =
      smoother.run([&](double fraction) { return bool(visitor.progress(fraction)); });
  visitor.end_step(optimizer == Node_optimizer::micro_ga ? "micro-GA smoothing"
                                                         : "conjugate-gradient smoothing");
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (!fixed[v])
      put(vpm, vertex_of[v], Point(mesh.points[v][0], mesh.points[v][1], mesh.points[v][2]));

  std::tie(result.worst_quality_after, result.mean_quality_after) = worst_and_mean_quality(mesh);
  result.moves = statistics.moves;
  result.rejected_folds = statistics.rejected_folds;
  result.sweeps = statistics.sweeps;
  result.converged = statistics.converged;
  result.cancelled = statistics.cancelled;
  return result;
}

template <class PolygonMesh, class NamedParameters>
Mga_smooth_result smooth_with(PolygonMesh& pm, const NamedParameters& np,
                              Node_optimizer optimizer) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = typename GetGeomTraits<PolygonMesh, NamedParameters>::type;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  const GT traits = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, pm));
  using Constrained_default = CGAL::Static_boolean_property_map<vertex_descriptor, false>;
  auto constrained = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                      Constrained_default());
  internal::Visitor_parameter<NamedParameters> visitor_parameter(np);
  return smooth_with_options(
      pm, vpm, traits, [constrained](vertex_descriptor v) { return bool(get(constrained, v)); },
      mga_smooth_options_from(np, optimizer), visitor_parameter.get());
}

}  // namespace internal

/// Smooths the free nodes of a triangle, quad or mixed surface mesh with the micro-genetic
/// algorithm of Chen, Hsu, Lin (section 3): for each free node and each adjacent element, a
/// micro-GA over the design variables (r1, r2) of eq. 1-3 maximises the sum of alpha (eq. 4-5,
/// triangles) and beta (eq. 7-8, quads) of the node's elements, each trial position being mapped
/// onto a tangent-plane continuous (G1) surface of quartic Bezier patches rebuilt from the input
/// mesh and its estimated vertex normals (section 2.2), by default with its boundary curves'
/// tangents shortened to 0.45 so that it bulges about half as far off the input triangles
/// (`surface_tangent_scale`, doc/mga_smooth.md); the best
/// position over the elements is taken if it raises the fitness and folds no element (exact
/// orientation test).
/// Trial positions that would lower the node's worst element below min(its current quality, 0.5)
/// are infeasible, so the worst quality is protected (the paper's sum alone lets it drop).
/// A move must raise the node's fitness by at least 1e-3; a node is searched again only after it
/// or a node of its elements moved; sweeps repeat until no node moves. Border nodes, nodes on
/// feature lines and constrained nodes never move (a sharp spur of one or two edges that no other
/// sharp edge continues is noise, not a feature line); the connectivity never changes.
/// Reproducible for a seed, and identical for any number of threads.
///
/// \tparam PolygonMesh a model of `FaceListGraph` (faces of degree 3 or 4; the vertices of larger
///         faces are kept fixed)
/// \param pm the mesh, smoothed in place
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{random_seed} \cgalParamDescription{seed of the micro-GA}
///     \cgalParamType{unsigned int} \cgalParamDefault{0} \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations} \cgalParamDescription{maximum number of sweeps}
///     \cgalParamType{unsigned int} \cgalParamDefault{3} \cgalParamNEnd
///   \cgalParamNBegin{population_size} \cgalParamDescription{micro-GA population (paper: 5)}
///     \cgalParamType{int} \cgalParamDefault{5} \cgalParamNEnd
///   \cgalParamNBegin{max_generations} \cgalParamDescription{generations per element and sweep,
///     restarts included} \cgalParamType{int} \cgalParamDefault{3} \cgalParamNEnd
///   \cgalParamNBegin{feature_angle_deg} \cgalParamDescription{an edge whose dihedral angle is
///     below this is a feature edge; its nodes are fixed} \cgalParamType{double}
///     \cgalParamDefault{120} \cgalParamNEnd
///   \cgalParamNBegin{surface_tangent_scale} \cgalParamDescription{where trial positions are
///     mapped: the G1 surface whose boundary curves have their end tangents scaled by s (same
///     directions, so still G1 with the same vertex normals); it lies about s times as far off
///     the input triangles as the full surface. 0 = the input triangles, 1 = the full Walton-Meek
///     surface (the paper's mapping onto the smooth surface, closest to the surface the input
///     samples); the default is as far from the input triangles as from the true surface on the
///     saddles of doc/mga_smooth.md} \cgalParamType{double in [0, 1]} \cgalParamDefault{0.45}
///     \cgalParamExtra{`cubic_surface_weight` is its deprecated name (read when
///     `surface_tangent_scale` is absent).} \cgalParamNEnd
///   \cgalParamNBegin{slide_feature_nodes} \cgalParamDescription{nodes inside a feature line
///     (two sharp edges meeting at less than a 30 degree turn) slide along the line's curve, at
///     most half-way to their neighbours, instead of staying fixed; line ends, joints and corners
///     stay fixed. Off by default: the paper fixes every feature node}
///     \cgalParamType{bool} \cgalParamDefault{false} \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map} \cgalParamDescription{nodes that must not move}
///     \cgalParamType{readable vertex property map to bool} \cgalParamDefault{none} \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads} \cgalParamDescription{threads (TBB) over independent
///     node sets; the result is the same for any number} \cgalParamType{int}
///     \cgalParamDefault{0: TBB's default (all cores), as every operator} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd \cgalParamNBegin{geom_traits} \cgalParamDescription{provides `Point_3` and the
///   exact
///     `Orientation_3`} \cgalParamDefault{from the point type} \cgalParamNEnd
///   \cgalParamNBegin{visitor} \cgalParamDescription{progress and cancellation (visitor.h)}
///     \cgalParamDefault{`Default_visitor`} \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Mga_smooth_result mga_smooth(PolygonMesh& pm,
                             const NamedParameters& np = parameters::default_values()) {
  return internal::smooth_with(pm, np, internal::Node_optimizer::micro_ga);
}

/// The paper's baseline (Table 2, after Garimella et al.): the same sweeps, fitness, surface
/// mapping, fixed nodes and fold test as `mga_smooth`, but each node follows a Polak-Ribiere
/// conjugate-gradient search over its tangent plane (central-difference gradient, backtracking
/// line search). Deterministic. Same named parameters as `mga_smooth`; `max_generations` bounds
/// the CG iterations per node and sweep (default 3); `random_seed` and `population_size` are
/// unused.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Mga_smooth_result conjugate_gradient_smooth(
    PolygonMesh& pm, const NamedParameters& np = parameters::default_values()) {
  return internal::smooth_with(pm, np, internal::Node_optimizer::conjugate_gradient);
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_MGA_SMOOTH
extern
#endif
    template Mga_smooth_result
    smooth_with_options<Core_mesh, Core_vpm, Core_traits>(
        Core_mesh&, Core_vpm, const Core_traits&,
        const std::function<bool(boost::graph_traits<Core_mesh>::vertex_descriptor)>&,
        const Mga_smooth_options&, Any_visitor);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_MGA_SMOOTH_H
