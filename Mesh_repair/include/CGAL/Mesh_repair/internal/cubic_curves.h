// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CUBIC_CURVES_H
#define CGAL_MESH_REPAIR_INTERNAL_CUBIC_CURVES_H

// Cubic point-normal boundary curves of thesis 4.3.1 (eq. 4.1-4.7, after Walton and Meek):
// a cubic Bezier curve from Q0 to Q1 whose tangent at each end is orthogonal to the surface normal
// there, so that new nodes placed on it follow the surface instead of the chord. Shared by gap
// stitching (T-junction nodes placed on curved gaps) and shape prediction (boundary curves).

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// The four control vertices 3v_{i,0..3} of a boundary curve.
template <class Point>
struct Cubic_boundary_curve {
  std::array<Point, 4> control;

  Point operator()(double t) const {
    const double s = 1.0 - t;
    const double w[4] = {s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t};
    double xyz[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      xyz[0] += w[k] * CGAL::to_double(control[k].x());
      xyz[1] += w[k] * CGAL::to_double(control[k].y());
      xyz[2] += w[k] * CGAL::to_double(control[k].z());
    }
    return Point(xyz[0], xyz[1], xyz[2]);
  }

  /// First derivative dC/dt.
  template <class Vector>
  Vector derivative(double t) const {
    const double s = 1.0 - t;
    const Vector d0 = control[1] - control[0], d1 = control[2] - control[1],
                 d2 = control[3] - control[2];
    return 3 * s * s * d0 + 6 * s * t * d1 + 3 * t * t * d2;
  }
};

/// Eq. 4.1: node normal as the angle-weighted mean of the unit normals of the attached triangles.
/// `faces` are (unit normal, subtended angle) pairs; returns a unit vector (zero if degenerate).
template <class Vector, class Range>
Vector angle_weighted_normal(const Range& faces) {
  Vector sum(0, 0, 0);
  double weight = 0;
  for (const auto& normal_and_angle : faces) {
    sum = sum + normal_and_angle.second * normal_and_angle.first;
    weight += normal_and_angle.second;
  }
  if (weight <= 0) return Vector(0, 0, 0);
  sum = sum / weight;
  const double length = std::sqrt(CGAL::to_double(sum.squared_length()));
  return length > 0 ? sum / length : Vector(0, 0, 0);
}

/// Eq. 4.2-4.7: control vertices of the curve from `q0` (unit normal `n0`, unit tangent `t0`) to
/// `q1` (`n1`, `t1`). With `t0 = t1 =` the chord direction this is Walton and Meek's formula; the
/// thesis passes one nodal tangent per node instead so consecutive curves share their tangent.
template <class Point, class Vector>
Cubic_boundary_curve<Point> make_cubic_boundary_curve(const Point& q0, const Vector& n0,
                                                      const Vector& t0, const Point& q1,
                                                      const Vector& n1, const Vector& t1) {
  const double d = std::sqrt(CGAL::to_double((q1 - q0).squared_length()));
  const double a = CGAL::to_double(n0 * n1);
  const double a0 = CGAL::to_double(n0 * t0);
  const double a1 = CGAL::to_double(n1 * t1);
  // 4 - a^2 >= 3 for unit normals; guard only against non-unit input.
  const double denominator = std::max(4.0 - a * a, 1e-12);
  const double rho = 6.0 * (2.0 * a0 + a * a1) / denominator;
  const double sigma = 6.0 * (2.0 * a1 + a * a0) / denominator;
  Cubic_boundary_curve<Point> curve;
  curve.control[0] = q0;
  curve.control[3] = q1;
  curve.control[1] = q0 + d * (6.0 * t0 - 2.0 * rho * n0 + sigma * n1) / 18.0;
  curve.control[2] = q1 - d * (6.0 * t1 + rho * n0 - 2.0 * sigma * n1) / 18.0;
  return curve;
}

/// Parameter of the point of `curve` closest to `p`, by Newton steps on (C(t) - p) . C'(t) = 0
/// from `t_start`, kept inside [0, 1].
template <class Point>
double closest_curve_parameter(const Cubic_boundary_curve<Point>& curve, const Point& p,
                               double t_start) {
  using Vector = typename Kernel_traits<Point>::Kernel::Vector_3;
  double t = std::clamp(t_start, 0.0, 1.0);
  for (int iteration = 0; iteration < 8; ++iteration) {
    const Vector offset = curve(t) - p;
    const Vector first = curve.template derivative<Vector>(t);
    const double s = 1.0 - t;
    const Vector d0 = curve.control[1] - curve.control[0];
    const Vector d1 = curve.control[2] - curve.control[1];
    const Vector d2 = curve.control[3] - curve.control[2];
    const Vector second = 6 * s * (d1 - d0) + 6 * t * (d2 - d1);
    const double g = CGAL::to_double(offset * first);
    const double h = CGAL::to_double(first * first + offset * second);
    if (h <= 0) break;
    const double next_t = std::clamp(t - g / h, 0.0, 1.0);
    if (std::abs(next_t - t) < 1e-12) break;
    t = next_t;
  }
  return t;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CUBIC_CURVES_H
