// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_H

// A surface for the advancing front to advance on when the hole is not a height field over its
// plane: CGAL's minimum-weight triangulation of the border polygon (no new vertex). Fronts that
// would pass each other in their own tangent planes meet on it. New nodes are moved to the
// closest point of the guide (AABB tree).

#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/utility.h>

#include <iterator>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

class Guide_surface {
  using Triangle = Epick::Triangle_3;
  using Primitive = CGAL::AABB_triangle_primitive<Epick, std::vector<Triangle>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, Primitive>>;

 public:
  /// Triangulates the closed polygon `border` (first point not repeated).
  explicit Guide_surface(const std::vector<Vec3>& border) {
    std::vector<Epick::Point_3> polyline;
    for (const Vec3& p : border) polyline.emplace_back(p[0], p[1], p[2]);
    std::vector<CGAL::Triple<int, int, int>> triples;
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polyline, std::back_inserter(triples));
    for (const auto& t : triples) {
      triangles_.emplace_back(polyline[std::size_t(t.first)], polyline[std::size_t(t.second)],
                              polyline[std::size_t(t.third)]);
    }
    if (triangles_.empty()) return;
    tree_.insert(triangles_.begin(), triangles_.end());
    tree_.accelerate_distance_queries();
  }

  bool valid() const { return !triangles_.empty(); }

  Vec3 project(const Vec3& p) const {
    const Epick::Point_3 q = tree_.closest_point(Epick::Point_3(p[0], p[1], p[2]));
    return {q.x(), q.y(), q.z()};
  }

 private:
  std::vector<Triangle> triangles_;
  Tree tree_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_H
