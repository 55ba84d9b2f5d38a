// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_REMOVE_OVERLAPS_H
#define CGAL_MESH_REPAIR_REMOVE_OVERLAPS_H

/// \file remove_overlaps.h
/// Removal of duplicated faces and of coplanar faces whose interiors overlap (thesis Table 4.1,
/// rows 2-4), keeping one layer. Small overlaps between border strips are closed by
/// `stitch_gaps()` like gaps. See doc/stitch_gaps.md.

#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/parameters.h>

#include <CGAL/Box_intersection_d/Box_with_handle_d.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <array>
#include <set>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `remove_overlaps()` found and removed.
struct Overlap_result {
  std::size_t candidate_pairs = 0;            ///< face pairs with intersecting bounding boxes
  std::size_t duplicated_faces_removed = 0;   ///< faces with the same three points as another
  std::size_t overlapping_faces_removed = 0;  ///< coplanar faces whose interiors overlap another
  bool valid = true;
};

inline void write_json(Json_writer& json, const Overlap_result& r) {
  json.begin_object()
      .field("candidate_pairs", r.candidate_pairs)
      .field("duplicated_faces_removed", r.duplicated_faces_removed)
      .field("overlapping_faces_removed", r.overlapping_faces_removed)
      .field("valid", r.valid)
      .end_object();
}

namespace internal {

/// Exact test of two coplanar, non-degenerate triangles: their interiors overlap iff no edge line
/// of either separates them (separating axis theorem in their plane; touching counts as apart).
template <class Point, class GeomTraits>
bool coplanar_interiors_overlap(const std::array<Point, 3>& t1, const std::array<Point, 3>& t2,
                                const GeomTraits& gt) {
  auto side = gt.coplanar_orientation_3_object();
  auto separates = [&](const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
    for (int i = 0; i < 3; ++i) {
      const Point& p = a[i];
      const Point& q = a[(i + 1) % 3];
      const Point& r = a[(i + 2) % 3];
      bool all_outside = true;
      for (const Point& s : b)
        if (side(p, q, r, s) == CGAL::POSITIVE) all_outside = false;
      if (all_outside) return true;
    }
    return false;
  };
  return !separates(t1, t2) && !separates(t2, t1);
}

}  // namespace internal

/// \ingroup Mesh_repair
/// Removes duplicated faces (the same three points as another face) and coplanar faces whose
/// interior overlaps another face's, found with exact predicates (`Coplanar_3`,
/// `Coplanar_orientation_3`) among the face pairs whose bounding boxes intersect. Of each pair the
/// face of the smaller connected component goes (a stray layer), then the one with more border
/// edges, so one consistent layer stays. Faces are removed with `CGAL::Euler::remove_face`.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` with triangle faces
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Overlap_result remove_overlaps(TriangleMesh& tm,
                               const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Geom_traits = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Point = typename Geom_traits::Point_3;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  const Geom_traits gt =
      choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  Overlap_result result;

  auto corners = [&](face_descriptor f) {
    std::array<Point, 3> p;
    int k = 0;
    for (auto v : vertices_around_face(halfedge(f, tm), tm)) {
      if (k < 3) p[k] = get(vpm, v);
      ++k;
    }
    return p;
  };
  std::vector<face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < face_list.size(); ++i) {
    const auto p = corners(face_list[i]);
    boxes.emplace_back(p[0].bbox() + p[1].bbox() + p[2].bbox(), i);
  }
  std::vector<std::pair<std::size_t, std::size_t>> duplicated, overlapping;
  auto coplanar = gt.coplanar_3_object();
  auto collinear = gt.collinear_3_object();
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    ++result.candidate_pairs;
    const auto t1 = corners(face_list[a.info()]), t2 = corners(face_list[b.info()]);
    if (std::is_permutation(t1.begin(), t1.end(), t2.begin())) {
      duplicated.emplace_back(a.info(), b.info());
      return;
    }
    if (collinear(t1[0], t1[1], t1[2]) || collinear(t2[0], t2[1], t2[2])) return;
    for (const Point& s : t2)
      if (!coplanar(t1[0], t1[1], t1[2], s)) return;
    if (internal::coplanar_interiors_overlap(t1, t2, gt))
      overlapping.emplace_back(a.info(), b.info());
  });

  // Which face of a pair goes: the one in the smaller component, then the one with more borders.
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const std::size_t component_count =
      CGAL::Polygon_mesh_processing::connected_components(tm, component);
  std::vector<std::size_t> component_size(component_count, 0);
  for (face_descriptor f : face_list) ++component_size[get(component, f)];
  auto border_edges = [&](face_descriptor f) {
    int count = 0;
    for (auto h : halfedges_around_face(halfedge(f, tm), tm))
      if (is_border(opposite(h, tm), tm)) ++count;
    return count;
  };
  std::vector<bool> removed(face_list.size(), false);
  auto remove_one = [&](std::size_t i, std::size_t j, std::size_t& counter) {
    if (removed[i] || removed[j]) return;
    const auto key = [&](std::size_t k) {
      return std::make_tuple(component_size[get(component, face_list[k])],
                             -border_edges(face_list[k]), k);
    };
    const std::size_t loser = key(i) < key(j) ? i : j;
    removed[loser] = true;
    CGAL::Euler::remove_face(halfedge(face_list[loser], tm), tm);
    ++counter;
  };
  for (const auto& [i, j] : duplicated) remove_one(i, j, result.duplicated_faces_removed);
  for (const auto& [i, j] : overlapping) remove_one(i, j, result.overlapping_faces_removed);
  result.valid = CGAL::is_valid_polygon_mesh(tm);
  return result;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_REMOVE_OVERLAPS_H
