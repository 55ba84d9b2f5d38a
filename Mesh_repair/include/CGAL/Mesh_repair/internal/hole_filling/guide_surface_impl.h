// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_IMPL_H

#include <CGAL/Mesh_repair/internal/hole_filling/cubic_search_limit.h>
#include <CGAL/Mesh_repair/internal/hole_filling/guide_surface.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/utility.h>

#include <cfloat>
#include <iterator>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

CGAL_MESH_REPAIR_CORE_INLINE Guide_surface::Guide_surface(const std::vector<Vec3>& border) {
  std::vector<Epick::Point_3> polyline;
  for (const Vec3& p : border) polyline.emplace_back(p[0], p[1], p[2]);
  if (!cgal_triangulation_refusal(polyline).empty()) return;  // no guide: valid() is false
  std::vector<CGAL::Triple<int, int, int>> triples;
  Cubic_search_limit limit;  // past it, no guide (valid() is false)
  try {
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polyline, std::back_inserter(triples),
                                                             CGAL::parameters::visitor(limit));
  } catch (const Cubic_search_too_large&) {
    return;
  }
  for (const auto& t : triples) {
    triangles_.emplace_back(polyline[std::size_t(t.first)], polyline[std::size_t(t.second)],
                            polyline[std::size_t(t.third)]);
  }
  if (triangles_.empty() || !squares_are_representable()) {
    triangles_.clear();  // no guide: valid() is false
    return;
  }
  tree_.insert(triangles_.begin(), triangles_.end());
  tree_.accelerate_distance_queries();
}

CGAL_MESH_REPAIR_CORE_INLINE bool Guide_surface::squares_are_representable() const {
  const auto underflows = [](const Epick::Vector_3& v) {
    return (v.x() != 0 || v.y() != 0 || v.z() != 0) && !(v.squared_length() >= DBL_MIN);
  };
  for (const Epick::Triangle_3& t : triangles_) {
    if (underflows(t[1] - t[0]) || underflows(t[2] - t[1]) || underflows(t[0] - t[2]) ||
        underflows(CGAL::cross_product(t[1] - t[0], t[2] - t[0])))
      return false;
  }
  return true;
}

CGAL_MESH_REPAIR_CORE_INLINE Vec3 Guide_surface::project(const Vec3& p) const {
  const Epick::Point_3 q = tree_.closest_point(Epick::Point_3(p[0], p[1], p[2]));
  return {q.x(), q.y(), q.z()};
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_IMPL_H
