// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_MESH_POINTS_H
#define CGAL_MESH_REPAIR_MESH_POINTS_H

/// \file mesh_points.h
/// Meshing of a point set (Chen et al. 2.1): CGAL's advancing-front surface reconstruction, the
/// soup repaired and oriented, edges flipped for quality, optionally triangles paired into quads,
/// then MGA smoothing on the G1 surface through the points. See doc/mga_smooth.md.

#include <CGAL/Mesh_repair/internal/soup_validation.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/json_writer.h>
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
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `mesh_points` built.
struct Mesh_points_result {
  std::size_t points = 0;               ///< input points
  std::size_t reconstructed_faces = 0;  ///< triangles of the reconstruction
  Edge_flip_result flips;
  Quad_conversion_result quads;         ///< empty unless `convert_to_quads`
  Mga_smooth_result smoothing;          ///< empty when `number_of_iterations` is 0
  std::size_t vertices = 0, faces = 0;  ///< of the mesh made
  double reconstruction_seconds = 0;
  double seconds = 0;  ///< the whole call
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

/// The stages of `mesh_points_with_options`, filling `result`.
template <class Point, class PolygonMesh>
void mesh_points_stages(std::vector<Point> soup_points, PolygonMesh& pm,
                        const Mesh_points_options& options, Any_visitor visitor,
                        Mesh_points_result& result) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  result.points = soup_points.size();
  clear(pm);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction(soup_points.begin(), soup_points.end(),
                                               std::back_inserter(facets));
  result.reconstructed_faces = facets.size();
  if (facets.empty()) return;
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
}

/// `mesh_points` on plain options, templated on the point and mesh types only (compiled once in
/// the core for Surface_mesh).
template <class Point, class PolygonMesh>
Mesh_points_result mesh_points_with_options(std::vector<Point> soup_points, PolygonMesh& pm,
                                            const Mesh_points_options& options,
                                            Any_visitor visitor) {
  Mesh_points_result result;
  const auto start = std::chrono::steady_clock::now();
  mesh_points_stages(std::move(soup_points), pm, options, visitor, result);
  result.vertices = vertices(pm).size();  // num_vertices counts removed ones too
  result.faces = faces(pm).size();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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

/// Reads the points of a point file into `points` with the project's strict readers: XYZ
/// (`.xyz`, `.pwn`: a point per line, then any numbers, left out) or the vertices of an OFF,
/// OBJ, STL or PLY file (faces, when there are any, are read and left out). The points are
/// checked as a mesh's vertices are (finite, at most 1e60) and there must be at least three.
/// Returns an empty string on success, else one line naming the file, the place and the
/// reason. Never throws; never modifies the file.
template <class Point>
std::string read_point_file(const std::string& filename, std::vector<Point>& points) {
  points.clear();
  std::string error = internal::precheck_file(filename);
  if (!error.empty()) return error;
  const std::string extension = internal::lower_extension(filename);
  const std::string format = internal::format_name(filename);
  if (format.empty() && extension != "xyz" && extension != "pwn")
    return filename + ": unknown point file format '" + extension +
           "' (expected .xyz, .pwn, .off, .obj, .stl or .ply)";
  std::vector<std::vector<std::size_t>> polygons;  // read and left out
  internal::readers::Read_counts counts;
  error = internal::read_file_bytes(filename, [&](internal::readers::Byte_reader& in) {
    return internal::readers::read_soup(in, format.empty() ? "XYZ" : format, filename, points,
                                        polygons, counts);
  });
  if (error.empty() && points.size() < 3)
    error = filename + ": " + std::to_string(points.size()) + " point(s), at least 3 are needed";
  if (error.empty()) error = internal::validate_points(filename, points);
  if (!error.empty()) std::vector<Point>().swap(points);
  return error;
}

/// Writes the report of `mesh_repair mesh-points --report` (doc/mga_smooth.md): `input`, `output`
/// (null when `output` is empty: no file was written), the counts and times of `result`, and the
/// quality before and after the smoothing.
inline void write_report(Json_writer& json, const std::string& input, const std::string& output,
                         const Mesh_points_result& result) {
  json.begin_object().field("input", input);
  if (output.empty())
    json.key("output").raw("null");
  else
    json.field("output", output);
  json.field("points", result.points);
  json.field("vertices", result.vertices).field("faces", result.faces);
  json.field("reconstruction_seconds", result.reconstruction_seconds);
  json.field("seconds", result.seconds);
  json.field("edge_flips", result.flips.flips).field("quads", result.quads.quads);
  json.field("remaining_triangles", result.quads.remaining_triangles);
  const Mga_smooth_result& smoothing = result.smoothing;
  json.field("worst_quality_before", smoothing.worst_quality_before);
  json.field("mean_quality_before", smoothing.mean_quality_before);
  json.field("worst_quality_after", smoothing.worst_quality_after);
  json.field("mean_quality_after", smoothing.mean_quality_after);
  json.field("sweeps", smoothing.sweeps).field("moves", smoothing.moves);
  json.end_object();
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
// The point file reader, for the tool's mesh-points command and the Python module.
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_MESH_POINTS
extern
#endif
    template std::string
    read_point_file<internal::Core_traits::Point_3>(const std::string&,
                                                    std::vector<internal::Core_traits::Point_3>&);
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_MESH_POINTS_H
