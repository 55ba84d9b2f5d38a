// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_QUADRIC_FIT_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_QUADRIC_FIT_H

// A quadric height field z = c0 + c1 x + c2 y + c3 x^2 + c4 xy + c5 y^2 over the plane of a hole,
// fitted by least squares to the vertices around the hole. The advancing front projects its new
// nodes onto it, so that a patch on a curved surface follows the curvature of its surroundings
// instead of the flat continuation of the tangent planes. See doc/advancing_front.md.

#include <CGAL/Mesh_repair/internal/hole_filling/ring_holes.h>

#include <CGAL/Mesh_repair/internal/least_squares.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

class Quadric_height_field {
 public:
  /// Fits over the plane (centroid, normal) to `points`, with coordinates scaled by `extent`.
  /// Invalid with fewer than 12 points or a rank-deficient system.
  Quadric_height_field(const std::vector<Vec3>& points, const Vec3& centroid, const Vec3& normal,
                       double extent)
      : frame_(centroid, normal), scale_(extent > 0 ? extent : 1.0) {
    if (points.size() < 12) return;
    Eigen::MatrixXd design(points.size(), 6);
    Eigen::VectorXd heights(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      const auto uv = local(points[k]);
      design.row(Eigen::Index(k)) << 1, uv[0], uv[1], uv[0] * uv[0], uv[0] * uv[1], uv[1] * uv[1];
      heights(Eigen::Index(k)) = frame_.height(points[k]) / scale_;
    }
    valid_ = solve_least_squares(design, heights, 6, coefficients_) && coefficients_.allFinite();
  }

  bool valid() const { return valid_; }

  /// The point of the height field above or below `p` along the plane's normal.
  Vec3 project(const Vec3& p) const {
    const auto uv = local(p);
    const Eigen::VectorXd& c = coefficients_;
    const double z = c(0) + c(1) * uv[0] + c(2) * uv[1] + c(3) * uv[0] * uv[0] +
                     c(4) * uv[0] * uv[1] + c(5) * uv[1] * uv[1];
    const double x = uv[0] * scale_, y = uv[1] * scale_;
    return add(frame_.origin,
               add(add(scale(frame_.u, x), scale(frame_.v, y)), scale(frame_.normal, z * scale_)));
  }

  /// Height-field normal at the point above `p`, for the validity of the fit.
  Vec3 normal_at(const Vec3& p) const {
    const auto uv = local(p);
    const Eigen::VectorXd& c = coefficients_;
    const double dx = c(1) + 2 * c(3) * uv[0] + c(4) * uv[1];
    const double dy = c(2) + c(4) * uv[0] + 2 * c(5) * uv[1];
    return normalized(sub(frame_.normal, add(scale(frame_.u, dx), scale(frame_.v, dy))));
  }

 private:
  std::array<double, 2> local(const Vec3& p) const {
    const Vec3 d = sub(p, frame_.origin);
    return {dot(d, frame_.u) / scale_, dot(d, frame_.v) / scale_};
  }

  Plane_frame frame_;
  double scale_;
  Eigen::VectorXd coefficients_ = Eigen::VectorXd::Zero(6);
  bool valid_ = false;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_QUADRIC_FIT_H
