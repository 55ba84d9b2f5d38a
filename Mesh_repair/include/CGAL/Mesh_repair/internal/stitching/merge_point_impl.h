// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_STITCHING_MERGE_POINT_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_STITCHING_MERGE_POINT_IMPL_H

#include <CGAL/Mesh_repair/internal/stitching/merge_point.h>

#include <Eigen/Dense>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

CGAL_MESH_REPAIR_CORE_INLINE Vec3 merge_point(const std::vector<Merge_node>& nodes,
                                              double tolerance, bool* used_planes) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Merge_node& node : nodes)
    centroid += Eigen::Vector3d(node.position[0], node.position[1], node.position[2]);
  centroid /= double(nodes.size());
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right_hand_side = Eigen::Vector3d::Zero();
  for (const Merge_node& node : nodes) {
    const Eigen::Vector3d n(node.normal[0], node.normal[1], node.normal[2]);
    const Eigen::Vector3d p(node.position[0], node.position[1], node.position[2]);
    normal_matrix += n * n.transpose();
    right_hand_side += n * n.dot(p - centroid);
  }
  if (used_planes) *used_planes = false;
  const auto to_array = [](const Eigen::Vector3d& v) { return Vec3{v[0], v[1], v[2]}; };
  if (nodes.size() < 2) return to_array(centroid);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(normal_matrix);
  // Two unit normals at angle theta give eigenvalues 1 +- cos(theta): drop the directions whose
  // eigenvalue says the planes are closer to parallel than near_parallel_planes_deg.
  const double threshold = 1.0 - std::cos(near_parallel_planes_deg * std::acos(-1.0) / 180.0);
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  bool any_direction = false;
  for (int k = 0; k < 3; ++k) {
    const double eigenvalue = solver.eigenvalues()[k];
    if (eigenvalue < threshold) continue;
    const Eigen::Vector3d direction = solver.eigenvectors().col(k);
    offset += direction * (direction.dot(right_hand_side) / eigenvalue);
    any_direction = true;
  }
  // A single plane direction means all planes are near-parallel: the thesis takes the midpoint.
  const bool planes_intersect = any_direction && solver.eigenvalues()[1] >= threshold;
  if (!planes_intersect || offset.norm() > tolerance) return to_array(centroid);
  if (used_planes) *used_planes = true;
  return to_array(centroid + offset);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_STITCHING_MERGE_POINT_IMPL_H
