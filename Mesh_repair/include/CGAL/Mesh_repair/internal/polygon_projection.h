// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_POLYGON_PROJECTION_H
#define CGAL_MESH_REPAIR_INTERNAL_POLYGON_PROJECTION_H

// Whether a closed polygon of 3D points crosses itself when seen along its normal. CGAL's
// triangulations of one polygon (triangulate_face's constrained Delaunay triangulation with
// exact intersections; triangulate_hole_polyline's Delaunay search space, extended by every
// triangle on each border edge it lacks) cost O(n^2) time and memory on a polygon whose sides
// cross everywhere (a self-overlapping {n/k} star), and then fail. This O(n log n) sweep (CGAL's
// `is_simple_2` with exact predicates of the projection traits) tells such polygons apart first.

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Projection_traits_3.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Polygons with at most this many sides are not checked: their crossings stay few. (At 1,000,
/// a {1000/7} star went to CGAL's triangulation and its repair took 37 s instead of 7 s.)
constexpr std::size_t max_unchecked_polygon_sides = 100;

/// True when the projection of `corners` (a closed polygon, first point not repeated) along
/// `normal` is a simple polygon; false too when `normal` is zero or not finite.
template <class Point, class Vector>
bool projection_is_simple(const std::vector<Point>& corners, const Vector& normal) {
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  const double nx = CGAL::to_double(normal.x()), ny = CGAL::to_double(normal.y()),
               nz = CGAL::to_double(normal.z());
  if (!(std::isfinite(nx) && std::isfinite(ny) && std::isfinite(nz)) ||
      (nx == 0 && ny == 0 && nz == 0))
    return false;
  const CGAL::Projection_traits_3<Kernel> projection(normal);
  return CGAL::is_simple_2(corners.begin(), corners.end(), projection);
}

/// True when the projection of `corners` along its Newell normal is a simple polygon.
template <class Point>
bool projection_is_simple(const std::vector<Point>& corners) {
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  double nx = 0, ny = 0, nz = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Point& p = corners[k];
    const Point& q = corners[(k + 1) % corners.size()];
    const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y()),
                 pz = CGAL::to_double(p.z()), qx = CGAL::to_double(q.x()),
                 qy = CGAL::to_double(q.y()), qz = CGAL::to_double(q.z());
    nx += (py - qy) * (pz + qz);
    ny += (pz - qz) * (px + qx);
    nz += (px - qx) * (py + qy);
  }
  return projection_is_simple(corners, typename Kernel::Vector_3(nx, ny, nz));
}

/// True when `corners` has more than `max_unchecked_polygon_sides` sides, lies in one plane
/// (exact `coplanar` test of every corner against three corners spanning the plane) and crosses
/// itself in that plane: no triangulation of it without overlapping triangles exists, and
/// CGAL's attempts are quadratic.
template <class Point>
bool large_planar_polygon_crosses_itself(const std::vector<Point>& corners) {
  if (corners.size() <= max_unchecked_polygon_sides) return false;
  std::size_t second = 1, third = 0;
  while (second < corners.size() && corners[second] == corners[0]) ++second;
  for (std::size_t k = second + 1; k < corners.size() && third == 0; ++k)
    if (!CGAL::collinear(corners[0], corners[second], corners[k])) third = k;
  if (second >= corners.size() || third == 0) return false;
  for (const Point& p : corners)
    if (!CGAL::coplanar(corners[0], corners[second], corners[third], p)) return false;
  return !projection_is_simple(corners);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_POLYGON_PROJECTION_H
