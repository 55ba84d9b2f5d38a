// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_STITCHING_MERGE_POINT_H
#define CGAL_MESH_REPAIR_INTERNAL_STITCHING_MERGE_POINT_H

// The merge point of nodes that are stitched together (thesis 4.2, Figure 4.2).
//
// The thesis intersects the tangent planes of the two nodes, projects both nodes onto that line
// and takes the midpoint of the projections. Projection onto a line is affine, so that midpoint is
// the projection of the nodes' midpoint onto the line: the point of the line closest to the
// centroid. We compute it as the minimiser of sum_i (n_i . (x - p_i))^2 nearest to the centroid
// (pseudo-inverse), which is the same point for two nodes and extends to three or more nodes (a
// corner where three patches meet, where it is the intersection of the three planes). The thesis'
// fallbacks are kept: directions in which the planes are near-parallel are dropped (for two nodes,
// parallel planes give the midpoint), and when the point lies farther than the merge tolerance
// from the centroid ("the line is too far away") the centroid is used.

#include <CGAL/Mesh_repair/internal/core_inline.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Two tangent planes whose normals make less than this angle are treated as parallel.
constexpr double near_parallel_planes_deg = 15.0;

/// A node to merge: its position and unit tangent-plane normal (zero when unknown).
struct Merge_node {
  Vec3 position;
  Vec3 normal;
};

/// The merge point of `nodes` (see the file comment); `tolerance` bounds its distance to the
/// centroid. `used_planes` tells whether the tangent-plane rule applied (false: centroid).
CGAL_MESH_REPAIR_CORE_INLINE Vec3 merge_point(const std::vector<Merge_node>& nodes,
                                              double tolerance, bool* used_planes = nullptr);

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/stitching/merge_point_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_STITCHING_MERGE_POINT_H
