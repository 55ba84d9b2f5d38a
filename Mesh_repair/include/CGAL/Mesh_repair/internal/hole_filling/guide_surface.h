// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_H

// A surface for the advancing front to advance on when the hole is not a height field over its
// plane: CGAL's minimum-weight triangulation of the border polygon (no new vertex). Fronts that
// would pass each other in their own tangent planes meet on it. New nodes are moved to the
// closest point of the guide (AABB tree).

#include <CGAL/Mesh_repair/internal/core_inline.h>
#include <CGAL/Mesh_repair/internal/finite_distance_traits.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

class Guide_surface {
  using Triangle = Epick::Triangle_3;
  using Primitive = CGAL::AABB_triangle_primitive<Epick, std::vector<Triangle>::const_iterator>;
  using Tree = Distance_tree<Epick, Primitive>;

 public:
  /// Triangulates the closed polygon `border` (first point not repeated).
  CGAL_MESH_REPAIR_CORE_INLINE explicit Guide_surface(const std::vector<Vec3>& border);

  bool valid() const { return !triangles_.empty(); }

  /// The closest point of the guide to `p`.
  CGAL_MESH_REPAIR_CORE_INLINE Vec3 project(const Vec3& p) const;

 private:
  /// Closest points on a triangle divide by its squared edge lengths and area: where one of
  /// them underflows to zero while the vector is not zero (edges of 1e-216 beside edges of 1, a
  /// fuzzed STL), the tree's constructions give NaN, which its exact comparisons cannot take
  /// (GMP raises SIGFPE). Such a triangulation is no guide.
  CGAL_MESH_REPAIR_CORE_INLINE bool squares_are_representable() const;

  std::vector<Triangle> triangles_;
  Tree tree_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/hole_filling/guide_surface_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_GUIDE_SURFACE_H
