// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_TOPOLOGICAL_GRID_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_TOPOLOGICAL_GRID_H

// Pernot et al. section 5: the topology of the inner mesh, decoupled from its geometry. Either a
// unit disc with as many border vertices as the contour, its interior vertices connected by a
// 2D Delaunay triangulation, stretched onto the contour; or Liepa's triangulation refined to the
// surrounding density (CGAL's triangulate_and_refine_hole), as the paper proposes for holes that
// do not look like a disc.

#include <CGAL/Mesh_repair/internal/core_inline.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/cubic_search_limit.h>
#include <CGAL/Mesh_repair/internal/hole_filling/remembered_triangulation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

/// Vertices of a border cycle, as the targets of its halfedges in cycle order.
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> border_cycle_vertices(
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    const PolygonMesh& pm) {
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> cycle;
  for (auto h : CGAL::halfedges_around_face(border_halfedge, pm)) cycle.push_back(target(h, pm));
  return cycle;
}

/// Points of the unit disc: the contour at angles proportional to its arc length (so that the
/// stretched grid keeps the contour's edge-length ratios), interior points on a hexagonal
/// lattice whose spacing is the mean boundary chord, kept away from the circle by half a spacing.
CGAL_MESH_REPAIR_CORE_INLINE std::vector<std::array<double, 2>> disc_grid_points(
    const std::vector<double>& edge_lengths, std::size_t& border_count);

/// Triangles (indices into the disc points) of the Delaunay triangulation of the disc points,
/// counter-clockwise, ordered by breadth-first distance from the circle so that adding them to
/// the mesh one by one always extends a connected patch from the hole's border.
CGAL_MESH_REPAIR_CORE_INLINE std::vector<std::array<std::size_t, 3>> disc_grid_triangles(
    const std::vector<std::array<double, 2>>& points);

/// Removes the faces of a partially added patch, newest first. `CGAL::Euler::remove_face`
/// removes the vertices it leaves isolated; vertices that no face used are removed here.
template <class PolygonMesh>
void remove_partial_patch(PolygonMesh& pm, Fill_patch<PolygonMesh>& patch,
                          const std::vector<bool>& vertex_used) {
  for (auto it = patch.faces.rbegin(); it != patch.faces.rend(); ++it)
    CGAL::Euler::remove_face(halfedge(*it, pm), pm);
  for (std::size_t i = 0; i < patch.vertices.size(); ++i)
    if (!vertex_used[i]) remove_vertex(patch.vertices[i], pm);
  patch = Fill_patch<PolygonMesh>();
}

/// The disc point (r, theta) stretched onto the contour: centroid + r (gamma(theta) - centroid),
/// gamma the contour parametrised by arc length like the grid's border. Only an initial position
/// (the deformation computes the final one); it gives cotangent force densities a meaningful
/// shape to be measured on.
template <class VertexRange, class VertexPointMap>
std::array<double, 3> stretched_position(const std::array<double, 2>& disc_point,
                                         const VertexRange& contour,
                                         const std::vector<double>& lengths,
                                         const std::array<double, 3>& centroid,
                                         VertexPointMap vpm) {
  const double radius = std::sqrt(disc_point[0] * disc_point[0] + disc_point[1] * disc_point[1]);
  double angle = std::atan2(disc_point[1], disc_point[0]);
  if (angle < 0) angle += 2 * CGAL_PI;
  double perimeter = 0;
  for (double l : lengths) perimeter += l;
  double arc = angle / (2 * CGAL_PI) * perimeter;
  std::size_t k = 0;
  while (k + 1 < lengths.size() && arc > lengths[k]) arc -= lengths[k++];
  const double t = lengths[k] > 0 ? std::min(1.0, arc / lengths[k]) : 0.0;
  const auto& a = get(vpm, contour[k]);
  const auto& b = get(vpm, contour[(k + 1) % contour.size()]);
  std::array<double, 3> result;
  const double ga[3] = {CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(a.z())};
  const double gb[3] = {CGAL::to_double(b.x()), CGAL::to_double(b.y()), CGAL::to_double(b.z())};
  for (int c = 0; c < 3; ++c)
    result[c] = centroid[c] + radius * ((1 - t) * ga[c] + t * gb[c] - centroid[c]);
  return result;
}

/// Fills the hole of `border_halfedge` with the disc grid stretched onto the contour.
/// On failure the mesh is unchanged and `failure` says why.
template <class PolygonMesh, class VertexPointMap>
bool fill_with_disc_grid(PolygonMesh& pm,
                         typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border,
                         VertexPointMap vpm, Fill_patch<PolygonMesh>& patch, std::string& failure) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  const auto contour = border_cycle_vertices(border, pm);
  const std::size_t n = contour.size();
  std::vector<double> lengths(n);
  double cx = 0, cy = 0, cz = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const auto& p = get(vpm, contour[k]);
    const auto& q = get(vpm, contour[(k + 1) % n]);
    lengths[k] = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
    cx += CGAL::to_double(p.x());
    cy += CGAL::to_double(p.y());
    cz += CGAL::to_double(p.z());
  }
  std::size_t border_count = 0;
  const auto points = disc_grid_points(lengths, border_count);
  const auto triangles = disc_grid_triangles(points);
  std::vector<vertex_descriptor> vertex_of(points.size());
  for (std::size_t k = 0; k < n; ++k) vertex_of[k] = contour[k];
  const std::array<double, 3> centroid{cx / n, cy / n, cz / n};
  for (std::size_t i = n; i < points.size(); ++i) {
    vertex_of[i] = add_vertex(pm);
    const auto p = stretched_position(points[i], contour, lengths, centroid, vpm);
    put(vpm, vertex_of[i], Point(p[0], p[1], p[2]));
    patch.vertices.push_back(vertex_of[i]);
  }
  std::vector<bool> vertex_used(patch.vertices.size(), false);
  for (const auto& t : triangles) {
    std::array<vertex_descriptor, 3> face{vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]};
    auto f = CGAL::Euler::add_face(face, pm);
    if (f == boost::graph_traits<PolygonMesh>::null_face()) {
      remove_partial_patch(pm, patch, vertex_used);
      failure = "the disc grid could not be connected to the contour (non-manifold contour)";
      return false;
    }
    patch.faces.push_back(f);
    for (std::size_t i : t)
      if (i >= n) vertex_used[i - n] = true;
  }
  return true;
}

/// Fills the hole with Liepa's triangulation refined to the surrounding density, under the
/// bounds of `fill_hole_liepa` (cubic_search_limit.h): no planar self-crossing border, no
/// exhaustive search past `max_cubic_search_edges`.
template <class PolygonMesh, class VertexPointMap>
bool fill_with_refined_liepa(PolygonMesh& pm,
                             typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border,
                             VertexPointMap vpm, double density_control_factor,
                             Fill_patch<PolygonMesh>& patch, std::string& failure) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<typename boost::property_traits<VertexPointMap>::value_type> corners;
  for (auto h : CGAL::halfedges_around_face(border, pm)) corners.push_back(get(vpm, target(h, pm)));
  failure = cgal_triangulation_refusal(corners);
  if (!failure.empty()) return false;
  Cubic_search_limit limit;
  try {
    const bool exhaustive_search_allowed = corners.size() <= max_cubic_search_edges;
    const auto np = CGAL::parameters::vertex_point_map(vpm)
                        .density_control_factor(density_control_factor)
                        .do_not_use_cubic_algorithm(!exhaustive_search_allowed)
                        .visitor(limit);
    // CGAL's triangulate_and_refine_hole, with the triangulation remembered per thread (Liepa's
    // fills of the same hole ask for it too).
    std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> triangles;
    triangulate_hole_remembered(pm, border, vpm, exhaustive_search_allowed, triangles, np);
    patch.faces.insert(patch.faces.end(), triangles.begin(), triangles.end());
    PMP::refine(pm, triangles, std::back_inserter(patch.faces), std::back_inserter(patch.vertices),
                np);
  } catch (const Cubic_search_too_large&) {
    failure = "CGAL's triangulation needs an exhaustive search over more than " +
              std::to_string(max_cubic_search_edges) + " border vertices (O(n^3)); not run";
    return false;
  }
  if (patch.faces.empty()) {
    failure = "Liepa's triangulation found no valid triangulation of the contour";
    return false;
  }
  return true;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/curvature_variation/topological_grid_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_TOPOLOGICAL_GRID_H
