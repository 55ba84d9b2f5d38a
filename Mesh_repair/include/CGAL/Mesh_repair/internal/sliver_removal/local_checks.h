// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SLIVER_REMOVAL_LOCAL_CHECKS_H
#define CGAL_MESH_REPAIR_INTERNAL_SLIVER_REMOVAL_LOCAL_CHECKS_H

// Exact checks of a tentative local change (edge collapse or flip) before it is made, so that
// nothing has to be rolled back: the triangles the change would create are tested for
// degeneracy, folds (normal reversal) and intersection with the triangles around them, all with
// the kernel's exact predicates (Collinear_3, Orientation_3, Coplanar_3, Do_intersect_3).
// New positions are constructed (inexactly); every yes/no decision on them is exact.

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// A triangle as three vertex identities and their points (the identities tell which corners two
/// triangles share, which decides how their intersection is tested).
template <class Vertex, class Point>
struct Labelled_triangle {
  std::array<Vertex, 3> vertex;
  std::array<Point, 3> point;
};

/// Why a tentative change was refused.
enum class Local_check { ok, degenerate, fold, self_intersection };

/// Whether two triangles meet other than along the corners and edge they share (exact).
template <class GeomTraits, class Vertex, class Point>
bool intersect_improperly(const Labelled_triangle<Vertex, Point>& t1,
                          const Labelled_triangle<Vertex, Point>& t2, const GeomTraits& gt) {
  using Triangle = typename GeomTraits::Triangle_3;
  using Segment = typename GeomTraits::Segment_3;
  auto do_intersect = gt.do_intersect_3_object();
  std::vector<std::pair<int, int>> shared;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t1.vertex[i] == t2.vertex[j]) shared.emplace_back(i, j);
  const Triangle tri1(t1.point[0], t1.point[1], t1.point[2]);
  const Triangle tri2(t2.point[0], t2.point[1], t2.point[2]);
  if (shared.empty()) return do_intersect(tri1, tri2);
  if (shared.size() == 1) {
    // Sharing one corner: they overlap elsewhere iff an opposite edge meets the other triangle.
    const int i = shared[0].first, j = shared[0].second;
    const Segment opposite1(t1.point[(i + 1) % 3], t1.point[(i + 2) % 3]);
    const Segment opposite2(t2.point[(j + 1) % 3], t2.point[(j + 2) % 3]);
    return do_intersect(opposite1, tri2) || do_intersect(opposite2, tri1);
  }
  if (shared.size() == 2) {
    // Sharing an edge: they overlap iff coplanar with the third corners on the same side.
    const int i0 = shared[0].first, i1 = shared[1].first;
    const int j0 = shared[0].second, j1 = shared[1].second;
    const Point& a = t1.point[i0];
    const Point& b = t1.point[i1];
    const Point& c = t1.point[3 - i0 - i1];
    const Point& d = t2.point[3 - j0 - j1];
    if (!gt.coplanar_3_object()(a, b, c, d)) return false;
    return gt.coplanar_orientation_3_object()(a, b, c, d) == CGAL::POSITIVE;
  }
  return true;  // the same triangle twice
}

/// Checks the triangles `created` that would replace `removed` faces: none degenerate, each
/// oriented like the face it replaces (`reference_normal` of the same index: a point offset
/// along the old normal must stay on the positive side), and none intersecting another created
/// triangle or a triangle of `neighbours` improperly.
template <class GeomTraits, class Vertex, class Point, class Vector>
Local_check check_new_triangles(const std::vector<Labelled_triangle<Vertex, Point>>& created,
                                const std::vector<Vector>& reference_normal,
                                const std::vector<Labelled_triangle<Vertex, Point>>& neighbours,
                                const GeomTraits& gt) {
  auto collinear = gt.collinear_3_object();
  auto orientation = gt.orientation_3_object();
  for (std::size_t k = 0; k < created.size(); ++k) {
    const auto& p = created[k].point;
    if (collinear(p[0], p[1], p[2])) return Local_check::degenerate;
    if (orientation(p[0], p[1], p[2], p[0] + reference_normal[k]) != CGAL::POSITIVE)
      return Local_check::fold;
  }
  for (std::size_t k = 0; k < created.size(); ++k) {
    for (std::size_t l = k + 1; l < created.size(); ++l)
      if (intersect_improperly(created[k], created[l], gt)) return Local_check::self_intersection;
    for (const auto& other : neighbours)
      if (intersect_improperly(created[k], other, gt)) return Local_check::self_intersection;
  }
  return Local_check::ok;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SLIVER_REMOVAL_LOCAL_CHECKS_H
