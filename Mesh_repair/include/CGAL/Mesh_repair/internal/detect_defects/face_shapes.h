// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_FACE_SHAPES_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_FACE_SHAPES_H

// Badly shaped faces: degenerate ones (exactly zero area by the Collinear_3 predicate), needles
// and caps (CGAL's thresholds) and slivers (shape factor f, thesis eq. 4.13-4.14, or aspect ratio
// Q, Pernot eq. 1, below their thresholds). Faces are classified in parallel when TBB is available.

#include <CGAL/Mesh_repair/internal/detect_defects/mesh_access.h>
#include <CGAL/Mesh_repair/quality.h>

#include <CGAL/Polygon_mesh_processing/shape_predicates.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

struct Shape_thresholds {
  double needle_ratio = 10;    ///< longest / shortest edge
  double cap_angle_deg = 160;  ///< largest angle
  double shape_factor = 0.7;   ///< thesis 4.5: f below it is a sliver
  double aspect_ratio = 0.25;  ///< Pernot 4.1: Q below it is degenerated
};

/// What one face is: 0 fine, 1 badly shaped (zero area, needle or cap), 2 sliver; plus its
/// measures.
struct Face_shape {
  int verdict = 0;
  Degeneracy kind = Degeneracy::zero_area;
  double ratio = 0, max_angle = 0, shape_factor = 1, aspect_ratio = 1;
};

template <class Access>
Face_shape classify_face(const Access& mesh, typename Access::face_descriptor f,
                         const Shape_thresholds& thresholds) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Face_shape shape;
  const auto h = halfedge(f, mesh.pm);
  const auto& a = mesh.point(source(h, mesh.pm));
  const auto& b = mesh.point(target(h, mesh.pm));
  const auto& c = mesh.point(target(next(h, mesh.pm), mesh.pm));
  const auto lengths = std::array<double, 3>{
      std::sqrt(CGAL::to_double(mesh.gt.compute_squared_distance_3_object()(a, b))),
      std::sqrt(CGAL::to_double(mesh.gt.compute_squared_distance_3_object()(b, c))),
      std::sqrt(CGAL::to_double(mesh.gt.compute_squared_distance_3_object()(c, a)))};
  const double shortest = std::min({lengths[0], lengths[1], lengths[2]});
  const double longest = std::max({lengths[0], lengths[1], lengths[2]});
  shape.ratio = shortest > 0 ? longest / shortest : std::numeric_limits<double>::infinity();
  if (mesh.gt.collinear_3_object()(a, b, c)) {
    shape.max_angle = min_max_angle_deg(a, b, c).second;
    shape.verdict = 1;
    shape.kind = Degeneracy::zero_area;
    return shape;
  }
  const auto np = CGAL::parameters::vertex_point_map(mesh.vpm).geom_traits(mesh.gt);
  const auto null = boost::graph_traits<typename Access::Mesh>::null_halfedge();
  if (PMP::is_needle_triangle_face(f, mesh.pm, thresholds.needle_ratio, np) != null) {
    shape.max_angle = min_max_angle_deg(a, b, c).second;
    shape.verdict = 1;
    shape.kind = Degeneracy::needle;
    return shape;
  }
  const double cap_cosine = std::cos(thresholds.cap_angle_deg * CGAL_PI / 180.0);
  if (PMP::is_cap_triangle_face(f, mesh.pm, cap_cosine, np) != null) {
    shape.max_angle = min_max_angle_deg(a, b, c).second;
    shape.verdict = 1;
    shape.kind = Degeneracy::cap;
    return shape;
  }
  shape.shape_factor = Mesh_repair::shape_factor(a, b, c);
  shape.aspect_ratio = Mesh_repair::aspect_ratio(a, b, c);
  if (shape.shape_factor < thresholds.shape_factor || shape.aspect_ratio < thresholds.aspect_ratio)
    shape.verdict = 2;
  return shape;
}

/// Classifies every triangle; fills the report and marks zero-area faces (by face index), which
/// the overlap test must skip.
template <class Access>
void classify_faces(const Access& mesh, const Shape_thresholds& thresholds, Defect_report& report,
                    std::vector<char>& zero_area) {
  std::vector<typename Access::face_descriptor> all(faces(mesh.pm).begin(), faces(mesh.pm).end());
  std::vector<Face_shape> shapes(all.size());
  auto classify_range = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (mesh.is_triangle_face(all[i])) shapes[i] = classify_face(mesh, all[i], thresholds);
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, all.size(), 4096),
      [&](const tbb::blocked_range<std::size_t>& r) { classify_range(r.begin(), r.end()); });
#else
  classify_range(0, all.size());
#endif
  zero_area.assign(num_faces(mesh.pm), 0);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Face_shape& s = shapes[i];
    if (s.verdict == 1) {
      report.badly_shaped_faces.push_back(
          {mesh.index(all[i]), s.kind, mesh.centroid(all[i]), s.ratio, s.max_angle});
      if (s.kind == Degeneracy::zero_area) zero_area[mesh.index(all[i])] = 1;
    } else if (s.verdict == 2) {
      report.slivers.push_back(
          {mesh.index(all[i]), mesh.centroid(all[i]), s.shape_factor, s.aspect_ratio});
    }
  }
}

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_FACE_SHAPES_H
