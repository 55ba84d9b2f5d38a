// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_OVERLAPS_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_OVERLAPS_H

// Overlapping coplanar faces (thesis Table 4.1, rows 2-4): two triangles on one plane whose
// interiors overlap. Candidates come from CGAL's box_intersection_d on the face boxes; the
// decision is exact: Coplanar_3 for the four-point tests, then, in the coordinate plane where
// the triangles stay non-degenerate (dropping one coordinate is exact), the separating-line
// test with Orientation_2: convex interiors are disjoint iff an edge line of one triangle leaves
// the other on its outer closed side.

#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/detect_defects/mesh_access.h>

#include <CGAL/box_intersection_d.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

template <class Traits>
using Triangle_points = std::array<typename Traits::Point_3, 3>;

/// The coordinate to drop: the largest component of the (inexact) normal. Any choice keeps a
/// non-degenerate triangle non-degenerate unless that component is exactly zero, which the
/// largest one is not.
template <class Traits>
int dropped_axis(const Triangle_points<Traits>& t) {
  const auto n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
  const double x = std::abs(CGAL::to_double(n.x())), y = std::abs(CGAL::to_double(n.y())),
               z = std::abs(CGAL::to_double(n.z()));
  return (x >= y && x >= z) ? 0 : (y >= z ? 1 : 2);
}

template <class Traits>
typename Traits::Point_2 drop(const typename Traits::Point_3& p, int axis) {
  if (axis == 0) return {p.y(), p.z()};
  if (axis == 1) return {p.z(), p.x()};
  return {p.x(), p.y()};
}

template <class Traits>
bool separated_by_an_edge_of(const std::array<typename Traits::Point_2, 3>& a,
                             const std::array<typename Traits::Point_2, 3>& b,
                             const Traits& traits) {
  auto orientation = traits.orientation_2_object();
  const CGAL::Orientation inside = orientation(a[0], a[1], a[2]);
  for (int i = 0; i < 3; ++i) {
    bool all_outside = true;
    for (int k = 0; k < 3 && all_outside; ++k)
      all_outside = orientation(a[i], a[(i + 1) % 3], b[k]) != inside;
    if (all_outside) return true;
  }
  return false;
}

/// True when the two non-degenerate triangles are coplanar and their interiors overlap.
template <class Traits>
bool coplanar_interiors_overlap(const Triangle_points<Traits>& s, const Triangle_points<Traits>& t,
                                const Traits& traits) {
  auto coplanar = traits.coplanar_3_object();
  for (int k = 0; k < 3; ++k)
    if (!coplanar(s[0], s[1], s[2], t[k])) return false;
  const int axis = dropped_axis<Traits>(s);
  std::array<typename Traits::Point_2, 3> a, b;
  for (int k = 0; k < 3; ++k) {
    a[k] = drop<Traits>(s[k], axis);
    b[k] = drop<Traits>(t[k], axis);
  }
  if (traits.orientation_2_object()(b[0], b[1], b[2]) == CGAL::COLLINEAR) return false;
  return !separated_by_an_edge_of(a, b, traits) && !separated_by_an_edge_of(b, a, traits);
}

template <class Access>
std::array<typename Access::Point, 3> triangle_points(const Access& mesh,
                                                      typename Access::face_descriptor f) {
  const auto h = halfedge(f, mesh.pm);
  return {mesh.point(source(h, mesh.pm)), mesh.point(target(h, mesh.pm)),
          mesh.point(target(next(h, mesh.pm), mesh.pm))};
}

/// Overlapping coplanar faces among intersecting face pairs: every such pair intersects, so
/// when CGAL's self_intersections has run its pairs are the only candidates needed.
template <class Access, class FacePairs>
std::vector<Face_pair> overlapping_among(const Access& mesh, const FacePairs& intersecting,
                                         const std::vector<char>& zero_area) {
  std::vector<Face_pair> overlaps;
  for (const auto& p : intersecting) {
    if (zero_area[mesh.index(p.first)] || zero_area[mesh.index(p.second)]) continue;
    if (coplanar_interiors_overlap(triangle_points(mesh, p.first), triangle_points(mesh, p.second),
                                   mesh.gt))
      overlaps.push_back(mesh.face_pair(p.first, p.second));
  }
  return overlaps;
}

/// Overlapping coplanar faces by a box pass of their own, at most `limit` pairs (0: the
/// default limit of the face count, internal/bounded_pairs.h) and `candidate_limit` box pairs.
template <class Access>
Bounded_pairs<Face_pair> overlapping_coplanar_faces(const Access& mesh,
                                                    const std::vector<char>& zero_area,
                                                    std::size_t limit = 0) {
  using face_descriptor = typename Access::face_descriptor;
  using Box =
      CGAL::Box_intersection_d::Box_with_info_d<double, 3, face_descriptor,
                                                CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;
  std::vector<Box> boxes;
  boxes.reserve(num_faces(mesh.pm));
  for (face_descriptor f : faces(mesh.pm)) {
    if (!mesh.is_triangle_face(f) || zero_area[mesh.index(f)]) continue;
    CGAL::Bbox_3 box;
    for (auto v : vertices_around_face(halfedge(f, mesh.pm), mesh.pm)) box += mesh.point(v).bbox();
    boxes.emplace_back(box, f);
  }
  Bounded_pairs<Face_pair> overlaps;
  Bounded_collector<Face_pair> collector(overlaps, pair_limit(limit, num_faces(mesh.pm)));
  // At most `candidate_limit` box pairs: on a fan of thin triangles nearly every box meets
  // every other (50 M candidates for a {9998/3} star, 17 s); past it the count is a lower bound.
  Pair_budget budget(candidate_limit(boxes.size()));
  auto callback = [&](const Box* first, const Box* second) {
    budget.spend();
    if (coplanar_interiors_overlap(triangle_points(mesh, first->info()),
                                   triangle_points(mesh, second->info()), mesh.gt))
      collector.add(mesh.face_pair(first->info(), second->info()));
  };
  // Pointers and CGAL self_intersections' cutoff (brute force below 2000 boxes): the segment
  // tree then moves 8-byte pointers and stops recursing early, as on mesh-like box sets pays.
  // Sequential: CGAL's parallel box pass costs 2.7x the processor time on 1M faces, and
  // detect_defects runs this pass beside its other steps (see start_box_pass there).
  std::vector<const Box*> pointers;
  pointers.reserve(boxes.size());
  for (const Box& b : boxes) pointers.push_back(&b);
  const std::ptrdiff_t cutoff = 2000;
  budget.run([&] {
    collector.run([&](auto&) {
      CGAL::box_self_intersection_d<CGAL::Sequential_tag>(pointers.begin(), pointers.end(),
                                                          callback, cutoff);
    });
  });
  overlaps.truncated = overlaps.truncated || budget.exhausted();
  std::sort(overlaps.pairs.begin(), overlaps.pairs.end(),
            [](const Face_pair& p, const Face_pair& q) {
              return std::make_pair(p.first, p.second) < std::make_pair(q.first, q.second);
            });
  return overlaps;
}

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_OVERLAPS_H
