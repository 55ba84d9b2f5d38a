// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PROJECTED_TRIANGULATION_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PROJECTED_TRIANGULATION_H

// The triangulation of a hole whose border, seen along its normal, is a simple polygon: the
// constrained Delaunay triangulation of the projected border. Scans lose whole flat sides (the
// bottom a scanned object stood on, the back of a relief), and their borders are jagged and fold
// over in places; Liepa's minimum-weight triangulation of such a border (weights in 3D) crosses
// itself over the folds, and every faired patch built on it does too. The projection's
// triangles cannot overlap one another, whatever the border's small folds out of the plane.
// CGAL's own planar option of `triangulate_hole` is no help here: it averages the fan normals
// after flipping each by the sign of its x component, which cancels them on borders whose plane
// is nearly axis-aligned, the common case of a cut-off scan.
//
// Where the surface itself dips below its outline (terrain around a building, a relief whose
// ground is lower in places than its edge) any surface spanning the outline crosses it. The
// outline is then extruded along its normal, away from the surface, to a flat base just beyond
// the surface's farthest point on that side, and the base is triangulated the same way: the
// plinth a user printing the model would add by hand.

#include <CGAL/Mesh_repair/internal/face_triangulation.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/polygon_projection.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Closes the hole of the border halfedge `h` with the constrained Delaunay triangulation of
/// its border projected along the border's normal (the hole made one face, then CGAL's
/// `triangulate_face`, which projects along that face's normal), when the projection is a
/// simple polygon (exact predicates). Appends the new faces to `faces` and returns an empty
/// string; else returns why not, the mesh unchanged.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::string triangulate_projected_border(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
    std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& faces) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<typename boost::property_traits<VertexPointMap>::value_type> corners;
  for (auto c : halfedges_around_face(h, pm)) corners.push_back(get(vpm, target(c, pm)));
  if (corners.size() < 3) return "the border has fewer than three vertices";
  CGAL::Euler::fill_hole(h, pm);
  const auto f = face(h, pm);
  const auto np = CGAL::parameters::vertex_point_map(vpm).geom_traits(traits);
  const auto normal = PMP::compute_face_normal(f, pm, np);
  if (!projection_is_simple(corners, normal)) {
    CGAL::Euler::remove_face(h, pm);
    return "the border seen along its normal is not a simple polygon";
  }
  if (!triangulate_face_in_fixed_order(f, pm, vpm, traits, faces)) {
    CGAL::Euler::remove_face(h, pm);
    return "no constrained Delaunay triangulation of the projected border";
  }
  return {};
}

/// The offset along `normal` from `centre` of the base of `extrude_border_to_base`: `margin`
/// beyond the farthest vertex over the footprint of `ring` (its bounding rectangle in the plane),
/// on the side away from most of them.
template <class PolygonMesh, class VertexPointMap, class VertexRange>
double base_offset(const PolygonMesh& pm, VertexPointMap vpm, const VertexRange& ring,
                   const Vec3& centre, const Vec3& normal, double margin) {
  // The walls and the base must pass below every vertex over the footprint.
  Vec3 t1, t2;
  tangent_frame(normal, t1, t2);
  double u_min = 0, u_max = 0, v_min = 0, v_max = 0;
  for (auto v : ring) {
    const Vec3 d = to_array(get(vpm, v)) - centre;
    u_min = std::min(u_min, dot(d, t1)), u_max = std::max(u_max, dot(d, t1));
    v_min = std::min(v_min, dot(d, t2)), v_max = std::max(v_max, dot(d, t2));
  }
  double lowest = 0, highest = 0, balance = 0;
  for (auto v : vertices(pm)) {
    const Vec3 d = to_array(get(vpm, v)) - centre;
    const double u = dot(d, t1), w = dot(d, t2), s = dot(d, normal);
    if (!(u >= u_min && u <= u_max && w >= v_min && w <= v_max)) continue;
    lowest = std::min(lowest, s), highest = std::max(highest, s), balance += s;
  }
  return balance >= 0 ? lowest - margin : highest + margin;
}

/// Extrudes the border of the hole of `h` along the border's normal, away from the side where
/// most of the mesh over the border's footprint lies, to a plane one mean border edge beyond its
/// farthest point there (wall triangles), then closes the extruded ring with
/// `triangulate_projected_border`. Appends the new faces and the ring's vertices; returns why not
/// (the caller rolls back).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::string extrude_border_to_base(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
    std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& faces,
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& vertices) {
  using GT = boost::graph_traits<PolygonMesh>;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  std::vector<typename GT::vertex_descriptor> ring;
  for (auto c : halfedges_around_face(h, pm)) ring.push_back(source(c, pm));
  if (ring.size() < 3) return "the border has fewer than three vertices";
  const Border_cycle_geometry g = cycle_geometry(h, pm, vpm);
  const Vec3 centre = g.centroid, normal = normalized(g.vector_area);
  if (!is_finite(normal) || norm(normal) == 0) return "the border has no normal";
  const double base = base_offset(pm, vpm, ring, centre, normal, g.mean_edge_length);
  std::vector<typename GT::vertex_descriptor> extruded;
  for (auto v : ring) {
    const Vec3 p = to_array(get(vpm, v));
    const Vec3 q = p + (base - dot(p - centre, normal)) * normal;
    if (!is_finite(q)) return "the base lies beyond the range of the coordinates";
    extruded.push_back(add_vertex(pm));
    put(vpm, extruded.back(), Point(q[0], q[1], q[2]));
    vertices.push_back(extruded.back());
  }
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const std::size_t j = (i + 1) % ring.size();
    for (const auto& triangle :
         {std::vector<typename GT::vertex_descriptor>{ring[i], ring[j], extruded[j]},
          std::vector<typename GT::vertex_descriptor>{ring[i], extruded[j], extruded[i]}}) {
      faces.push_back(CGAL::Euler::add_face(triangle, pm));
      if (faces.back() == GT::null_face()) {
        faces.pop_back();
        return "the walls of the base could not be added";
      }
    }
  }
  const auto inner = halfedge(extruded[0], extruded[1], pm);
  if (!inner.second || !is_border(inner.first, pm)) return "the base ring is not a border";
  return triangulate_projected_border(pm, vpm, traits, inner.first, faces);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PROJECTED_TRIANGULATION_H
