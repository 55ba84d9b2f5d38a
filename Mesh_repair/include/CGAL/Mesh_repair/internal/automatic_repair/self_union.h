// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SELF_UNION_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SELF_UNION_H

// The outer surface of a closed part that intersects itself, computed on exact constructions:
// the mesh arrangement of the part (every face cut along its intersections with the others,
// coplanar overlaps included) and, for each piece, the winding numbers of the part on its two
// sides; the pieces between winding zero and a non-zero winding are the outer surface. This
// handles what CGAL 5.5's autorefinement does not (coplanar intersecting faces, three faces
// intersecting one another, where it throws or crashes); automatic_repair uses it there.

#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Limits of `outer_surface_of_solid`, so that its time stays bounded.
struct Self_union_limits {
  /// Parts with more faces are refused.
  std::size_t max_faces = 200000;
  /// Parts with more intersecting face pairs are refused.
  std::size_t max_pairs = 100000;
  /// Refused when a face is cut by more intersection segments...
  std::size_t max_cuts_per_face = 32;
  /// ... or when the sum over the faces of their segment counts squared (a bound on the
  /// crossings of segments inside faces) exceeds this.
  double max_cut_work = 200000;
  /// Refused when (pieces to classify) x (faces) exceeds this (each classification casts a ray
  /// against every face whose box it may cross).
  double max_ray_tests = 2e8;
  /// A result whose faces cross one another once its exact points are rounded to doubles (needle
  /// pieces of nearly parallel cuts, folded by the rounding) is accepted when its crossing pairs
  /// are at most this share of the part's intersecting pairs, for a caller that replaces them
  /// by patches next (`Solid_autorefinement::rounding_crossings`); 0: refused.
  double max_rounding_crossing_share = 0;
};

/// Writes into `out` the outer surface of the closed part `solid` (a closed triangle mesh that
/// intersects itself, in either orientation): the parts of its faces that separate points where
/// the part's winding number is zero from points where it is not, oriented towards the zero
/// side. Intersection points are computed exactly and rounded to doubles at the end. Returns an
/// empty string when the result is closed, valid, free of self-intersections and bounds a
/// volume (or crosses itself within `limits.max_rounding_crossing_share`), else why not (then
/// `out` is unspecified); `measures` as for `remove_self_intersections_of_solid`.
CGAL_MESH_REPAIR_CORE_INLINE std::string outer_surface_of_solid(
    const Triangle_soup& solid, Triangle_soup& out, Solid_autorefinement& measures,
    const Self_union_limits& limits = Self_union_limits());

/// Writes into `out` the union of `solids` (at least two closed parts, each valid, free of
/// self-intersections and bounding a volume, in either orientation) as the outer surface of
/// the parts turned outward, for the groups that CGAL's corefinement does not take (coplanar
/// faces that meet). Returns an empty string on success, else why not; `measures` as for
/// `outer_surface_of_solid`.
CGAL_MESH_REPAIR_CORE_INLINE std::string union_of_solids_exactly(
    const std::vector<Triangle_soup>& solids, Triangle_soup& out, Solid_autorefinement& measures,
    const Self_union_limits& limits = Self_union_limits());

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/automatic_repair/self_union_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SELF_UNION_H
