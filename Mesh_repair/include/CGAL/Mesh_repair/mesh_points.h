// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_MESH_POINTS_H
#define CGAL_MESH_REPAIR_MESH_POINTS_H

/// \file mesh_points.h
/// Meshing of a point set (Chen et al. 2.1): CGAL's advancing-front surface reconstruction, the
/// soup repaired and oriented, edges flipped for quality, optionally triangles paired into quads,
/// then MGA smoothing on the G1 surface through the points. See doc/mga_smooth.md.

#include <CGAL/Mesh_repair/mga_smooth.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/triangles_to_quads.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <chrono>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `mesh_points` built.
struct Mesh_points_result {
  std::size_t points = 0;               ///< input points
  std::size_t reconstructed_faces = 0;  ///< triangles of the reconstruction
  Edge_flip_result flips;
  Quad_conversion_result quads;  ///< empty unless `convert_to_quads`
  Mga_smooth_result smoothing;   ///< empty when `number_of_iterations` is 0
  double reconstruction_seconds = 0;
  bool cancelled = false;
};

namespace internal {

/// The options of `mesh_points`, read once from the named parameters.
struct Mesh_points_options {
  double feature_angle_deg = default_smoothing_feature_angle_deg;
  bool quads = false;
  unsigned iterations = 3;
  unsigned seed = 0;
  int threads = 0;
};

/// `mesh_points` on plain options, templated on the point and mesh types only (compiled once in
/// the core for Surface_mesh).
template <class Point, class PolygonMesh>
Mesh_points_result mesh_points_with_options(std::vector<Point> soup_points, PolygonMesh& pm,
                                            const Mesh_points_options& options,
                                            Any_visitor visitor) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Mesh_points_result result;
  result.points = soup_points.size();
  clear(pm);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction(soup_points.begin(), soup_points.end(),
                                               std::back_inserter(facets));
  result.reconstructed_faces = facets.size();
  if (facets.empty()) return result;
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& f : facets) polygons.push_back({f[0], f[1], f[2]});
  PMP::repair_polygon_soup(soup_points, polygons);
  PMP::orient_polygon_soup(soup_points, polygons);
  PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, pm);
  result.reconstruction_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto angle = parameters::feature_angle_deg(options.feature_angle_deg);
  result.flips = flip_edges_for_quality(pm, angle);
  if (options.quads) result.quads = triangles_to_quads(pm, angle);
  if (options.iterations > 0) {
    result.smoothing = mga_smooth(pm, angle.number_of_threads(options.threads)
                                          .random_seed(options.seed)
                                          .number_of_iterations(int(options.iterations))
                                          .surface_tangent_scale(1.0)
                                          .visitor(std::ref(visitor)));
    result.cancelled = result.smoothing.cancelled;
  }
  return result;
}

}  // namespace internal

/// Meshes `points` into `pm` (cleared first): advancing-front reconstruction (CGAL), soup
/// repair and orientation (CGAL), quality edge flips, optional quad conversion, and MGA
/// smoothing of the nodes on the G1 surface through the points (tangent scale 1, the paper's
/// mapping).
///
/// \tparam PointRange a range of `Point_3` of the mesh's kernel
/// \tparam PolygonMesh a model of `MutableFaceGraph`
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{convert_to_quads}
///     \cgalParamDescription{pair triangles into quads before smoothing (`triangles_to_quads`)}
///     \cgalParamType{bool} \cgalParamDefault{false}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{MGA sweeps; 0: no smoothing}
///     \cgalParamType{unsigned int} \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{feature_angle_deg, random_seed, number_of_threads, visitor}
///     \cgalParamDescription{passed to `flip_edges_for_quality`, `triangles_to_quads` and
///       `mga_smooth`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the counts of every stage; `pm` is empty when the reconstruction made no triangle.
template <class PointRange, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
Mesh_points_result mesh_points(const PointRange& points, PolygonMesh& pm,
                               const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Point = typename PointRange::value_type;
  internal::Mesh_points_options options;
  options.feature_angle_deg = choose_parameter(
      get_parameter(np, internal_np::feature_angle_deg_t()), default_smoothing_feature_angle_deg);
  options.quads = choose_parameter(get_parameter(np, internal_np::convert_to_quads_t()), false);
  options.iterations =
      choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 3u);
  options.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  options.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads_t()), 0);
  internal::Visitor_parameter<NamedParameters> visitor(np);
  return internal::mesh_points_with_options(std::vector<Point>(points.begin(), points.end()), pm,
                                            options, visitor.get());
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_MESH_POINTS
extern
#endif
    template Mesh_points_result
    mesh_points_with_options<Core_traits::Point_3, Core_mesh>(std::vector<Core_traits::Point_3>,
                                                              Core_mesh&,
                                                              const Mesh_points_options&,
                                                              Any_visitor);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_MESH_POINTS_H
