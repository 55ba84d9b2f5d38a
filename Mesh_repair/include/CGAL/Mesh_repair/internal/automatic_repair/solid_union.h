// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_H

// CGAL's corefinement on closed parts: the union of parts that intersect one another (an
// assembly of touching or interpenetrating solids; automatic_repair keeps such parts as separate
// solids unless asked to merge them, `merge_intersecting_solids`), and the autorefinement of one
// part that intersects itself (the faces inside its volume removed). The solids travel as
// triangle soups of doubles so that CGAL's corefinement is compiled once, on the core's
// Surface_mesh, for every mesh type of the caller.

#include <CGAL/Mesh_repair/internal/compiled_core.h>
#include <CGAL/Mesh_repair/internal/core_inline.h>
#include <CGAL/Mesh_repair/polygon_soup.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// A part of a mesh as triangles of the core's points.
using Triangle_soup = Polygon_soup<Core_traits::Point_3>;

/// Writes into `out` the union of `solids` (at least two), computed in pairs, then pairs of
/// their unions, and so on, with CGAL's `corefine_and_compute_union`. Each solid must be a closed,
/// valid triangle mesh free of self-intersections that bounds a volume. Returns an empty string on
/// success, else why the union was not computed (then `out` is unspecified).
CGAL_MESH_REPAIR_CORE_INLINE std::string union_of_solids(const std::vector<Triangle_soup>& solids,
                                                         Triangle_soup& out);

/// What `remove_self_intersections_of_solid` did to a part.
struct Solid_autorefinement {
  double area_before = 0;
  double area_after = 0;
  /// Largest distance from a point of the part to the result.
  double largest_distance = 0;
  /// Vertices where the result touched itself, given a point of their own per fan of faces
  /// and moved apart (`separate_touching_fans`).
  std::size_t touching_vertices_separated = 0;
  /// Pairs of faces of the result that cross once rounded to doubles, when the limits accept
  /// some (`Self_union_limits::max_rounding_crossing_share`).
  std::size_t rounding_crossings = 0;
  /// Closed components of the result thinner than its separation distance (slivers between
  /// faces that nearly meet) that crossed other faces once rounded, dropped.
  std::size_t thin_solids_dropped = 0;
};

/// Writes into `out` the closed part `solid` (a closed triangle mesh that may intersect itself)
/// with its self-intersections removed by CGAL's
/// `experimental::autorefine_and_remove_self_intersections`: the faces are cut along the
/// intersections and the pieces inside the volume removed. An inward part is turned outward
/// first. Returns an empty string when the result is closed, valid, free of self-intersections
/// and bounds a volume, else why not (then `out` is unspecified).
CGAL_MESH_REPAIR_CORE_INLINE std::string remove_self_intersections_of_solid(
    const Triangle_soup& solid, Triangle_soup& out, Solid_autorefinement& measures);

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_H
