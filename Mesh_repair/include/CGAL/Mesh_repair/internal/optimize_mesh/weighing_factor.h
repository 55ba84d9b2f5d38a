// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_WEIGHING_FACTOR_H
#define CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_WEIGHING_FACTOR_H

// Thesis eq. 7.1-7.4: the weighing factor of a chosen element with unit normal A against the
// unit normals B_i of the affected elements: d_i = |B_i - A|, d = d_avg + (d_max - d_min).
// Small d = nearly planar neighbourhood = removed first.

#include <CGAL/Mesh_repair/internal/vec3.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace optimize {

inline double normal_deviation(const Vec3& a, const Vec3& b) {
  return norm(b - a);  // eq. 7.1-7.2
}

/// Eq. 7.3-7.4 over `affected` (0 when there is none).
inline double weighing_factor(const Vec3& chosen, const std::vector<Vec3>& affected) {
  if (affected.empty()) return 0;
  double sum = 0, lowest = 4, highest = 0;
  for (const Vec3& b : affected) {
    const double d = normal_deviation(chosen, b);
    sum += d;
    lowest = std::min(lowest, d);
    highest = std::max(highest, d);
  }
  return sum / double(affected.size()) + (highest - lowest);
}

}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif
