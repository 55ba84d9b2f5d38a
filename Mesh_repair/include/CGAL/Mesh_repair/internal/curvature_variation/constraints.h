// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_CONSTRAINTS_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_CONSTRAINTS_H

// Pernot 6.4: point constraints, and polylines discretised into point constraints. A target
// point is attached to the closest point of the unconstrained inner mesh (the paper obtains the
// points on the mesh "by projection"); the attachment is a barycentric combination of the three
// vertices of that face, hence linear in the free positions: one row of A in A x_f = t.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

/// Barycentric coordinates of the point of triangle abc closest to p (Ericson, Real-Time
/// Collision Detection 5.1.5): a construction, so inexact arithmetic is fine.
inline Vec3 closest_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denominator = va + vb + vc;
  if (denominator == 0) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  const double v = vb / denominator, w = vc / denominator;
  return {1 - v - w, v, w};
}

/// The constraint polylines resampled every `spacing` (at least their vertices).
template <class Point>
std::vector<Vec3> discretise_polylines(const std::vector<std::vector<Point>>& polylines,
                                       double spacing) {
  std::vector<Vec3> samples;
  auto as_vec = [](const Point& p) {
    return Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  for (const auto& polyline : polylines) {
    if (polyline.empty()) continue;
    samples.push_back(as_vec(polyline.front()));
    for (std::size_t k = 1; k < polyline.size(); ++k) {
      const Vec3 a = as_vec(polyline[k - 1]), b = as_vec(polyline[k]);
      const double length = std::sqrt(dot(b - a, b - a));
      const int pieces = spacing > 0 ? std::max(1, int(std::ceil(length / spacing))) : 1;
      for (int s = 1; s <= pieces; ++s) {
        const double t = double(s) / pieces;
        samples.push_back(
            {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
      }
    }
  }
  return samples;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_CONSTRAINTS_H
