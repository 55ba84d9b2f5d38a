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
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point = typename PointRange::value_type;
  const double feature_angle = choose_parameter(
      get_parameter(np, internal_np::feature_angle_deg_t()), default_smoothing_feature_angle_deg);
  const bool quads = choose_parameter(get_parameter(np, internal_np::convert_to_quads_t()), false);
  const unsigned iterations =
      choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 3u);
  const unsigned seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const int threads = choose_parameter(get_parameter(np, internal_np::number_of_threads_t()), 0);
  internal::Visitor_parameter<NamedParameters> visitor(np);

  Mesh_points_result result;
  result.points = points.size();
  clear(pm);
  const auto start = std::chrono::steady_clock::now();
  std::vector<Point> soup_points(points.begin(), points.end());
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

  const auto angle = parameters::feature_angle_deg(feature_angle);
  result.flips = flip_edges_for_quality(pm, angle);
  if (quads) result.quads = triangles_to_quads(pm, angle);
  if (iterations > 0) {
    Any_visitor any = visitor.get();
    result.smoothing = mga_smooth(pm, angle.number_of_threads(threads)
                                          .random_seed(seed)
                                          .number_of_iterations(int(iterations))
                                          .surface_tangent_scale(1.0)
                                          .visitor(std::ref(any)));
    result.cancelled = result.smoothing.cancelled;
  }
  return result;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_MESH_POINTS_H
