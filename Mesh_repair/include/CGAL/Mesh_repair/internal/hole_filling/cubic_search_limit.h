// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_CUBIC_SEARCH_LIMIT_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_CUBIC_SEARCH_LIMIT_H

// CGAL's minimum-weight triangulation of a border polygon (triangulate_hole_polyline, used by
// Liepa's filling and the advancing front's guide surface) falls back to an exhaustive search,
// O(n^3) in time and O(n^2) in memory, wherever its Delaunay search space holds no
// triangulation. `do_not_use_cubic_algorithm` only skips the last fallback: the Delaunay pass
// itself runs the exhaustive search on any range it cannot close, the whole border included
// (a self-overlapping 3000-edge star: minutes and 2.5 GB). CGAL's hole-filling visitor is told
// the size of every exhaustive search before it starts; this one stops the call there.
// Before any search, CGAL adds every triangle on each border edge its Delaunay triangulation
// lacks (O(n) per edge, no visitor call): on a planar border that crosses itself nearly every
// edge is missing, so such borders are not given to CGAL at all (`crosses_itself_in_its_plane`):
// they have no triangulation without overlapping triangles anyway.

#include <CGAL/Mesh_repair/internal/polygon_projection.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Border polygons with more vertices are not searched exhaustively: about 1.7e8 weight
/// evaluations at this size (4 s here); the cost grows with the cube.
constexpr std::size_t max_cubic_search_edges = 1000;

/// The number of weight evaluations CGAL announces for an exhaustive search over
/// `max_cubic_search_edges` vertices (n^3 / 6, its own count).
constexpr double max_cubic_search_triples = double(max_cubic_search_edges) *
                                            double(max_cubic_search_edges) *
                                            double(max_cubic_search_edges) / 6.0;

/// Thrown by `Cubic_search_limit` before an exhaustive search past the limit; the caller of
/// CGAL's triangulation catches it and reports the hole as not triangulated.
struct Cubic_search_too_large {};

/// CGAL's hole-filling visitor that refuses exhaustive searches over more than
/// `max_cubic_search_edges` polygon vertices. CGAL announces the number of triples it will
/// weigh (an int: negative when it overflowed, which is past the limit too).
struct Cubic_search_limit : CGAL::Polygon_mesh_processing::Hole_filling::Default_visitor {
  void start_cubic_phase(int triples) const {
    if (triples < 0 || double(triples) > max_cubic_search_triples) throw Cubic_search_too_large();
  }
};

/// Why CGAL's triangulation is not called on the border polygon `corners`, or empty.
template <class Point>
std::string cgal_triangulation_refusal(const std::vector<Point>& corners) {
  if (!large_planar_polygon_crosses_itself(corners)) return {};
  return "the border (" + std::to_string(corners.size()) +
         " edges) is planar and crosses itself: every triangulation overlaps itself, and CGAL's "
         "search for one is quadratic on it; not run";
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_CUBIC_SEARCH_LIMIT_H
