// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_OPTIMIZATION_RESULT_H
#define CGAL_MESH_REPAIR_OPTIMIZATION_RESULT_H

/// \file optimization_result.h
/// The mode and the result of `optimize_mesh` (thesis chapter 7).

#include <cstddef>

namespace CGAL {
namespace Mesh_repair {

/// What `optimize_mesh()` does to the regions it removes.
enum class Optimization_mode {
  reduction,  ///< thesis 7.2.3(a): remove the triangles around the nodes of an element
  quality     ///< thesis 7.2.3(b): re-triangulate the element and its edge neighbours
};

/// What `optimize_mesh()` did.
struct Optimization_result {
  std::size_t input_faces = 0, output_faces = 0;
  std::size_t passes = 0;
  std::size_t regions_replaced = 0;
  // Regions left as they were, by reason:
  std::size_t regions_duplicate_edge = 0;     ///< a new edge would duplicate an existing one
  std::size_t regions_fold_or_crease = 0;     ///< a new normal would turn away, or a crease appear
  std::size_t regions_self_intersection = 0;  ///< a new triangle would cross the surroundings
  std::size_t regions_not_better = 0;         ///< the GA did not beat the old triangles
  std::size_t regions_too_far = 0;  ///< reduction: the patch would leave removed points too far
  std::size_t regions_without_triangulation = 0;
  std::size_t regions_refused_by_mesh = 0;  ///< rolled back
  std::size_t corner_nodes = 0;             ///< "vertex" nodes at the first classification
  std::size_t feature_edges = 0;            ///< at the first classification
  bool target_reached = false;
  bool cancelled = false;
  const char* stop_reason = "";
};

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_OPTIMIZATION_RESULT_H
