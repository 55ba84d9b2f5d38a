// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_FINITE_DISTANCE_TRAITS_H
#define CGAL_MESH_REPAIR_INTERNAL_FINITE_DISTANCE_TRAITS_H

// The traits of every AABB tree we query for distances or closest points. CGAL 5.5 constructs
// the closest point on a triangle in double precision (projection on its supporting plane, then
// on a side); on triangles whose normal's squared length underflows (corners 1e-139 apart
// beside one 2e-59 away; meshes spanning 1e-98) that point is NaN, and the filtered predicate
// comparing distances to it falls back to exact numbers, where GMP raises SIGFPE on the NaN (found
// by fuzzing). Here a primitive whose closest point is not finite is passed over: the distance is
// that to the other primitives.

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <cmath>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

template <class GeomTraits, class Primitive>
class Finite_distance_traits : public CGAL::AABB_traits<GeomTraits, Primitive> {
  using Base = CGAL::AABB_traits<GeomTraits, Primitive>;

 public:
  using Point_3 = typename Base::Point_3;

  class Closest_point {
   public:
    explicit Closest_point(const Finite_distance_traits& traits) : traits_(traits) {}

    Point_3 operator()(const Point_3& p, const Primitive& primitive, const Point_3& bound) const {
      const GeomTraits geom_traits;
      const Point_3 q = geom_traits.construct_projected_point_3_object()(
          CGAL::internal::Primitive_helper<Base>::get_datum(primitive, traits_), p);
      if (!(std::isfinite(CGAL::to_double(q.x())) && std::isfinite(CGAL::to_double(q.y())) &&
            std::isfinite(CGAL::to_double(q.z()))))
        return bound;
      return geom_traits.compare_distance_3_object()(p, q, bound) == CGAL::LARGER ? bound : q;
    }

   private:
    const Finite_distance_traits& traits_;
  };

  Closest_point closest_point_object() const { return Closest_point(*this); }
};

/// An AABB tree of `Primitive`s for distance and closest-point queries.
template <class GeomTraits, class Primitive>
using Distance_tree = CGAL::AABB_tree<Finite_distance_traits<GeomTraits, Primitive>>;

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_FINITE_DISTANCE_TRAITS_H
