// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_VEC3_H
#define CGAL_MESH_REPAIR_INTERNAL_VEC3_H

// The one double 3-vector of the library's inner loops (hole filling, C1 surface, micro-GA,
// stitching, curvature variation, detection), with its operations and the one tangent-frame
// builder. Constructions only: every geometric decision still goes through the kernel's exact
// predicates. Kernel vectors are too slow where millions of evaluations per second are needed
// and carry number types that these loops do not want.
//
// `Vec3` is a `std::array<double, 3>` (indexing, comparison, use as a map key, range-for) that
// also models the point concept of quality.h (`x()`, `y()`, `z()`), so `alpha` and `quad_beta`
// measure it directly. Both styles of arithmetic are offered, operators (`a + b`, `s * a`) and
// named functions (`add`, `sub`, `scale`); each evaluates component by component in the same
// order (`dot` is a0*b0 + a1*b1 + a2*b2 from left to right), so switching styles changes no bit.

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

struct Vec3 : std::array<double, 3> {
  constexpr Vec3() : std::array<double, 3>{{0, 0, 0}} {}
  constexpr Vec3(double x, double y, double z) : std::array<double, 3>{{x, y, z}} {}
  constexpr Vec3(const std::array<double, 3>& a) : std::array<double, 3>(a) {}  // NOLINT: implicit

  double x() const { return (*this)[0]; }
  double y() const { return (*this)[1]; }
  double z() const { return (*this)[2]; }

  Vec3& operator+=(const Vec3& o) {
    for (int i = 0; i < 3; ++i) (*this)[i] += o[i];
    return *this;
  }
  Vec3& operator-=(const Vec3& o) {
    for (int i = 0; i < 3; ++i) (*this)[i] -= o[i];
    return *this;
  }
  Vec3& operator*=(double s) {
    for (int i = 0; i < 3; ++i) (*this)[i] *= s;
    return *this;
  }
};

/// The coordinates of any point or vector with x(), y(), z() (kernel number types included).
template <class Point>
Vec3 to_array(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator-(const Vec3& a) {
  return {-a[0], -a[1], -a[2]};
}
inline Vec3 operator*(double s, const Vec3& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
inline Vec3 operator*(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}

inline Vec3 add(const Vec3& a, const Vec3& b) {
  return a + b;
}
inline Vec3 sub(const Vec3& a, const Vec3& b) {
  return a - b;
}
inline Vec3 scale(const Vec3& a, double s) {
  return a * s;
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
/// No coordinate infinite or not a number: the only points an exact predicate may be given
/// (Epick's exact fallback converts them to GMP rationals, and GMP raises SIGFPE on a NaN).
inline bool is_finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}
/// `a` scaled by the reciprocal of its norm; a vector of zero (or not a number) norm maps to
/// the zero vector.
inline Vec3 normalized(const Vec3& a) {
  const double n = norm(a);
  return n > 0 ? scale(a, 1.0 / n) : Vec3{0, 0, 0};
}

/// The one tangent-frame builder: two unit vectors `t1`, `t2` completing the unit vector `n` to
/// a right-handed orthonormal frame (t1, t2, n), t1 = normalized(n x helper), t2 = n x t1. The
/// helper axis is x unless |n_x| reaches `helper_switch`, then y; any switch in (1/sqrt(3), 1)
/// keeps n x helper away from zero. Every frame of the library uses 0.6 except the projection of
/// the GA triangulation's chord table, which was built and measured with 0.9 and keeps it.
inline void tangent_frame(const Vec3& n, Vec3& t1, Vec3& t2, double helper_switch = 0.6) {
  const Vec3 helper = std::abs(n[0]) < helper_switch ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  t1 = normalized(cross(n, helper));
  t2 = cross(n, t1);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_VEC3_H
