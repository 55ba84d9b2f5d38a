// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_PATCH_CHECKS_H
#define CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_PATCH_CHECKS_H

// Exact yes/no tests on a candidate re-triangulation before it replaces a region (thesis 7.3:
// no fold, no non-manifold element, no self-intersection). All decisions go through the kernel's
// filtered exact predicates; only the reference normal of the old region is a construction.

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace optimize {

/// Do two triangles, given by their vertex descriptors and points, intersect other than along
/// what they share? (The logic of CGAL's PMP `do_faces_intersect`, for faces not yet in a mesh.)
template <class GeomTraits, class Vertex, class Point>
bool triangles_intersect(const std::array<Vertex, 3>& tv, const std::array<Point, 3>& tp,
                         const std::array<Vertex, 3>& gv, const std::array<Point, 3>& gp,
                         const GeomTraits& gt) {
  int shared = 0, ti = -1, gi = -1, tj = -1, gj = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (tv[i] == gv[j]) {
        ++shared;
        if (ti < 0)
          ti = i, gi = j;
        else
          tj = i, gj = j;
      }
  if (shared == 3) return true;  // duplicated face
  auto segment = gt.construct_segment_3_object();
  auto triangle = gt.construct_triangle_3_object();
  auto do_intersect = gt.do_intersect_3_object();
  if (shared == 2) {
    const int t_other = 3 - ti - tj, g_other = 3 - gi - gj;
    return gt.coplanar_3_object()(tp[ti], tp[tj], tp[t_other], gp[g_other]) &&
           gt.coplanar_orientation_3_object()(tp[ti], tp[tj], tp[t_other], gp[g_other]) ==
               CGAL::POSITIVE;
  }
  const auto t = triangle(tp[0], tp[1], tp[2]);
  const auto g = triangle(gp[0], gp[1], gp[2]);
  if (shared == 1)
    return do_intersect(t, segment(gp[(gi + 1) % 3], gp[(gi + 2) % 3])) ||
           do_intersect(g, segment(tp[(ti + 1) % 3], tp[(ti + 2) % 3]));
  return do_intersect(t, g);
}

/// Dihedral-angle test across an edge (a, b) between triangles (a, b, c) and (b, a, d), exact:
/// when `crease_allowed` only a fold (d on c's side in their common plane, dihedral 0) fails;
/// otherwise the dihedral angle must not be below the feature angle, so no new crease appears.
template <class GeomTraits, class Point>
bool dihedral_acceptable(const Point& a, const Point& b, const Point& c, const Point& d,
                         bool crease_allowed, double feature_cosine, const GeomTraits& gt) {
  using FT = typename GeomTraits::FT;
  auto compare = gt.compare_dihedral_angle_3_object();
  if (crease_allowed) return compare(a, b, c, d, FT(1)) == CGAL::LARGER;
  return compare(a, b, c, d, FT(feature_cosine)) != CGAL::SMALLER;
}

}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif
