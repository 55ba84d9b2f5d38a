// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PLANAR_BORDERS_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PLANAR_BORDERS_H

// Holes that are missing planar faces of a solid: the border lies in one plane (exact
// predicates) and every face along it leaves that plane at a crease. CAD exports and furniture
// models lose such faces (a box without its bottom, a tube without its end cap); the designer's
// surface there is the plane itself, where the faired methods continue the walls into a bowl.

#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Every face along a planar border must make at least this angle with the border's plane for
/// the hole to count as a missing planar face: the walls of a box (90 degrees) or a chamfer
/// (45), not a sheet continuing in the plane (0), where any patch is flat anyway.
constexpr double min_planar_border_crease_deg = 45.0;

/// True when the border cycle of `h` lies in one plane, decided by the traits' exact
/// `Collinear_3` and `Coplanar_3`, and each face along it makes at least
/// `min_planar_border_crease_deg` with that plane.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
bool is_creased_planar_border(const PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                              typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  std::vector<Point> points;
  for (auto c : halfedges_around_face(h, pm)) points.push_back(get(vpm, target(c, pm)));
  if (points.size() < 3) return false;
  // A reference triangle as large as the border allows: the farthest point from the first,
  // then the point farthest from the line through both.
  const Vec3 a = to_array(points[0]);
  std::size_t far = 0, apex = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (norm(to_array(points[i]) - a) > norm(to_array(points[far]) - a)) far = i;
  const Vec3 axis = to_array(points[far]) - a;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (norm(cross(axis, to_array(points[i]) - a)) > norm(cross(axis, to_array(points[apex]) - a)))
      apex = i;
  if (traits.collinear_3_object()(points[0], points[far], points[apex])) return false;
  const auto coplanar = traits.coplanar_3_object();
  for (const Point& p : points)
    if (!coplanar(points[0], points[far], points[apex], p)) return false;
  const Vec3 plane_normal = normalized(cross(axis, to_array(points[apex]) - a));
  const double max_cosine = std::cos(min_planar_border_crease_deg * std::acos(-1.0) / 180.0);
  for (auto c : halfedges_around_face(h, pm)) {
    const auto o = opposite(c, pm);
    if (is_border(o, pm)) return false;
    const Vec3 n = normalized(triangle_normal(get(vpm, source(o, pm)), get(vpm, target(o, pm)),
                                              get(vpm, target(next(o, pm), pm))));
    if (!(std::abs(dot(n, plane_normal)) <= max_cosine)) return false;
  }
  return true;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PLANAR_BORDERS_H
