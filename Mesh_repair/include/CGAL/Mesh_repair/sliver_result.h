// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_SLIVER_RESULT_H
#define CGAL_MESH_REPAIR_SLIVER_RESULT_H

/// \file sliver_result.h
/// The result of `remove_slivers`: what it found and changed, and what it refused and why.

#include <CGAL/Mesh_repair/json_writer.h>

#include <cstddef>

namespace CGAL {
namespace Mesh_repair {

/// What `remove_slivers()` found and changed.
struct Sliver_result {
  double shape_factor_threshold = 0.7;
  double tolerance_edge_length = 0;  ///< used (given, or derived: see the documentation)
  double feature_angle_deg = 135;
  std::size_t slivers_before = 0;  ///< triangles with f below the threshold on entry
  std::size_t slivers_after = 0;
  std::size_t collapsed = 0;                  ///< short edges collapsed (Figure 4.13)
  std::size_t flipped = 0;                    ///< edges swapped (Figure 4.14)
  std::size_t kept_for_features = 0;          ///< no change possible without moving a feature
  std::size_t refused_topology = 0;           ///< link condition, border pinch, existing edge
  std::size_t refused_fold = 0;               ///< change would reverse or flatten a triangle
  std::size_t refused_self_intersection = 0;  ///< change would make triangles intersect
  std::size_t refused_no_improvement = 0;     ///< a flip that would not raise the worst f
  double min_shape_factor_before = 1, min_shape_factor_after = 1;
  bool cancelled = false;
  bool valid = true;
};

inline void write_json(Json_writer& json, const Sliver_result& r) {
  json.begin_object()
      .field("shape_factor_threshold", r.shape_factor_threshold)
      .field("tolerance_edge_length", r.tolerance_edge_length)
      .field("feature_angle_deg", r.feature_angle_deg)
      .field("slivers_before", r.slivers_before)
      .field("slivers_after", r.slivers_after)
      .field("collapsed", r.collapsed)
      .field("flipped", r.flipped)
      .field("kept_for_features", r.kept_for_features)
      .field("refused_topology", r.refused_topology)
      .field("refused_fold", r.refused_fold)
      .field("refused_self_intersection", r.refused_self_intersection)
      .field("refused_no_improvement", r.refused_no_improvement)
      .field("min_shape_factor_before", r.min_shape_factor_before)
      .field("min_shape_factor_after", r.min_shape_factor_after)
      .field("cancelled", r.cancelled)
      .field("valid", r.valid)
      .end_object();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_SLIVER_RESULT_H
