// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_VEC3_H
#define CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_VEC3_H

// A plain double 3-vector for the inner loops of the C1 surface and of the micro-GA: millions of
// patch evaluations per second need no kernel number types. It models the point concept of
// quality.h (x(), y(), z()), so `alpha` and `quad_beta` measure it directly.

#include <cmath>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

struct Vec3 {
  double c[3] = {0, 0, 0};
  Vec3() = default;
  Vec3(double x, double y, double z) : c{x, y, z} {}
  double x() const { return c[0]; }
  double y() const { return c[1]; }
  double z() const { return c[2]; }
  double operator[](int i) const { return c[i]; }
  Vec3& operator+=(const Vec3& o) {
    for (int i = 0; i < 3; ++i) c[i] += o.c[i];
    return *this;
  }
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a.c[0] + b.c[0], a.c[1] + b.c[1], a.c[2] + b.c[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a.c[0] - b.c[0], a.c[1] - b.c[1], a.c[2] - b.c[2]};
}
inline Vec3 operator*(double s, const Vec3& a) {
  return {s * a.c[0], s * a.c[1], s * a.c[2]};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a.c[0] * b.c[0] + a.c[1] * b.c[1] + a.c[2] * b.c[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.c[1] * b.c[2] - a.c[2] * b.c[1], a.c[2] * b.c[0] - a.c[0] * b.c[2],
          a.c[0] * b.c[1] - a.c[1] * b.c[0]};
}
inline double length(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 normalized(const Vec3& a) {
  const double l = length(a);
  return l > 0 ? (1.0 / l) * a : a;
}

/// Two unit vectors completing `n` (unit) to an orthonormal frame.
inline void tangent_frame(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 helper = std::abs(n.c[0]) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  t1 = normalized(cross(n, helper));
  t2 = cross(n, t1);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_VEC3_H
