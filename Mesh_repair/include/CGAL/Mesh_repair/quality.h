// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_QUALITY_H
#define CGAL_MESH_REPAIR_QUALITY_H

/// \file quality.h
/// Triangle and quad quality measures of the reference documents, in one place so that reports,
/// tests, benchmarks and the optimisers all measure the same thing:
/// - `alpha`: Chen, Hsu, Lin eq. 4, 2*sqrt(3)*|AB x AC| / (|AB|^2+|BC|^2+|CA|^2), 1 = equilateral;
/// - `aspect_ratio` Q: Pernot et al. eq. 1, 2*sqrt(3)*S / (h*p) (h longest edge, p half-perimeter);
/// - `shape_factor` f: thesis eq. 4.13-4.14, normalised to [0,1] as 1 - E / (2/3 pi^2) with
///   E = sum_j (theta_j - pi/3)^2 (the thesis' threshold 0.7 only makes sense normalised; see
///   doc/quality.md);
/// - minimum and maximum angles in degrees;
/// - `quad_beta`: Chen et al. eq. 6-7 (Knupp's algebraic shape metric), 1 = square.
/// Degenerate (zero-area) triangles get 0 for alpha, Q and f.

#include <CGAL/Mesh_repair/internal/vec3.h>
#include <CGAL/Mesh_repair/json_writer.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

namespace internal {
/// The points scaled by one power of two so that their largest coordinate magnitude is in
/// [0.5, 1): every measure here is scale-invariant, the scaling is exact, and coordinates up to
/// 1e308 then give no infinite differences or NaN products.
template <std::size_t N>
std::array<Vec3, N> scaled(std::array<Vec3, N> p) {
  double largest = 0;
  for (const auto& q : p)
    for (double x : q) largest = std::max(largest, std::abs(x));
  if (!(largest > 0) || !std::isfinite(largest)) return p;
  int exponent = 0;
  std::frexp(largest, &exponent);
  for (auto& q : p)
    for (double& x : q) x = std::ldexp(x, -exponent);
  return p;
}

template <class Point>
std::array<Vec3, 3> scaled_triangle(const Point& a, const Point& b, const Point& c) {
  return scaled<3>({to_array(a), to_array(b), to_array(c)});
}

/// Interior angles (radians) at a, b, c; zero-length edges give zero angles.
inline std::array<double, 3> interior_angles(const Vec3& a, const Vec3& b, const Vec3& c) {
  auto angle = [](const Vec3& u, const Vec3& v) {
    const double cross_norm = norm(cross(u, v));
    if (cross_norm == 0 && dot(u, v) == 0) return 0.0;
    return std::atan2(cross_norm, dot(u, v));
  };
  return {angle(sub(b, a), sub(c, a)), angle(sub(c, b), sub(a, b)), angle(sub(a, c), sub(b, c))};
}
}  // namespace internal

/// Chen et al. eq. 4: 1 for an equilateral triangle, 0 for a degenerate one.
template <class Point>
double alpha(const Point& a, const Point& b, const Point& c) {
  using namespace internal;
  const auto t = scaled_triangle(a, b, c);
  const auto &pa = t[0], &pb = t[1], &pc = t[2];
  const auto ab = sub(pb, pa), ac = sub(pc, pa), bc = sub(pc, pb);
  const double denominator = dot(ab, ab) + dot(bc, bc) + dot(ac, ac);
  if (denominator == 0) return 0;
  return 2.0 * std::sqrt(3.0) * norm(cross(ab, ac)) / denominator;
}

/// Pernot et al. eq. 1, the aspect ratio Q = 2*sqrt(3) * S / (h * p): 1 equilateral, 0 flat.
template <class Point>
double aspect_ratio(const Point& a, const Point& b, const Point& c) {
  using namespace internal;
  const auto t = scaled_triangle(a, b, c);
  const auto &pa = t[0], &pb = t[1], &pc = t[2];
  const double lab = norm(sub(pb, pa)), lbc = norm(sub(pc, pb)), lca = norm(sub(pa, pc));
  const double longest = std::max({lab, lbc, lca});
  const double half_perimeter = 0.5 * (lab + lbc + lca);
  if (longest == 0) return 0;
  const double area = 0.5 * norm(cross(sub(pb, pa), sub(pc, pa)));
  return 2.0 * std::sqrt(3.0) * area / (longest * half_perimeter);
}

/// Thesis eq. 4.13-4.14, normalised: 1 - E / (2/3 pi^2), 1 equilateral, 0 fully degenerate.
template <class Point>
double shape_factor(const Point& a, const Point& b, const Point& c) {
  using namespace internal;
  const auto t = scaled_triangle(a, b, c);
  const auto angles = interior_angles(t[0], t[1], t[2]);
  if (angles[0] + angles[1] + angles[2] == 0) return 0;
  double equilateral_factor = 0;
  for (double theta : angles) equilateral_factor += (theta - CGAL_PI / 3) * (theta - CGAL_PI / 3);
  const double worst = 2.0 / 3.0 * CGAL_PI * CGAL_PI;
  return std::max(0.0, 1.0 - equilateral_factor / worst);
}

/// Smallest and largest interior angle, in degrees.
template <class Point>
std::pair<double, double> min_max_angle_deg(const Point& a, const Point& b, const Point& c) {
  using namespace internal;
  const auto t = scaled_triangle(a, b, c);
  const auto angles = interior_angles(t[0], t[1], t[2]);
  const double to_deg = 180.0 / CGAL_PI;
  return {to_deg * *std::min_element(angles.begin(), angles.end()),
          to_deg * *std::max_element(angles.begin(), angles.end())};
}

/// Chen et al. eq. 6-7 for a (possibly non-planar) quad p0 p1 p2 p3: beta = 8 / sum_k
/// (1 + r_k^2) / (r_k sin theta_k), with r_k = |p_k p_{k+3}| / |p_k p_{k+1}| and theta_k the angle
/// at p_k. 1 for a square, 0 when an angle reaches 0 or 180 degrees.
template <class Point>
double quad_beta(const Point& p0, const Point& p1, const Point& p2, const Point& p3) {
  using namespace internal;
  const std::array<Vec3, 4> p = scaled<4>({to_array(p0), to_array(p1), to_array(p2), to_array(p3)});
  // Signed sines relative to the quad's mean normal, so a reflex (non-convex) corner counts as bad.
  Vec3 normal{0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const auto c = cross(sub(p[(k + 1) % 4], p[k]), sub(p[(k + 3) % 4], p[k]));
    for (int i = 0; i < 3; ++i) normal[i] += c[i];
  }
  const double normal_length = norm(normal);
  if (normal_length == 0) return 0;
  double sum = 0;
  for (int k = 0; k < 4; ++k) {
    const auto e1 = sub(p[(k + 1) % 4], p[k]), e3 = sub(p[(k + 3) % 4], p[k]);
    const double l1 = norm(e1), l3 = norm(e3);
    if (l1 == 0 || l3 == 0) return 0;
    const double sine = dot(cross(e1, e3), normal) / (normal_length * l1 * l3);
    if (sine <= 1e-12) return 0;
    const double r = l3 / l1;
    sum += (1 + r * r) / (r * sine);
  }
  return 8.0 / sum;
}

/// Per-face quality of a triangle mesh, with histograms over [0,1] (angles over [0,180]).
struct Quality_statistics {
  std::size_t triangles = 0;
  double min_alpha = 1, mean_alpha = 0;
  double min_aspect_ratio = 1, mean_aspect_ratio = 0;
  double min_shape_factor = 1, mean_shape_factor = 0;
  double min_angle_deg = 180, max_angle_deg = 0;
  std::vector<std::size_t> alpha_histogram, aspect_ratio_histogram, shape_factor_histogram;
  std::vector<std::size_t> min_angle_histogram;  ///< bins over [0, 60] degrees
};

/// Writes the summary figures of `q` as a JSON object (the `quality_before` and `quality_after`
/// members of `mesh_repair optimize`'s report; the histograms are left out).
inline void write_json(Json_writer& json, const Quality_statistics& q) {
  json.begin_object();
  json.field("triangles", q.triangles).field("min_angle_deg", q.min_angle_deg);
  json.field("min_alpha", q.min_alpha).field("mean_alpha", q.mean_alpha);
  json.field("mean_shape_factor", q.mean_shape_factor);
  json.end_object();
}

/// Quality statistics over the triangles of `pm` (faces with other degrees are skipped).
template <class PolygonMesh, class VertexPointMap>
Quality_statistics quality_statistics(const PolygonMesh& pm, VertexPointMap vpm, int bins = 10) {
  Quality_statistics s;
  s.alpha_histogram.assign(bins, 0);
  s.aspect_ratio_histogram.assign(bins, 0);
  s.shape_factor_histogram.assign(bins, 0);
  s.min_angle_histogram.assign(bins, 0);
  // NaN (a non-finite input point) goes to the first bin; the cast sees only [0, bins].
  auto bin = [bins](double value, double range) {
    const double x = value / range * bins;
    if (!(x > 0)) return std::size_t(0);
    return std::size_t(std::min<double>(x, bins - 1));
  };
  for (auto f : faces(pm)) {
    auto h = halfedge(f, pm);
    if (next(next(next(h, pm), pm), pm) != h) continue;
    const auto& a = get(vpm, source(h, pm));
    const auto& b = get(vpm, target(h, pm));
    const auto& c = get(vpm, target(next(h, pm), pm));
    const double al = alpha(a, b, c), q = aspect_ratio(a, b, c), sf = shape_factor(a, b, c);
    const auto angles = min_max_angle_deg(a, b, c);
    ++s.triangles;
    s.min_alpha = std::min(s.min_alpha, al);
    s.mean_alpha += al;
    s.min_aspect_ratio = std::min(s.min_aspect_ratio, q);
    s.mean_aspect_ratio += q;
    s.min_shape_factor = std::min(s.min_shape_factor, sf);
    s.mean_shape_factor += sf;
    s.min_angle_deg = std::min(s.min_angle_deg, angles.first);
    s.max_angle_deg = std::max(s.max_angle_deg, angles.second);
    ++s.alpha_histogram[bin(al, 1.0)];
    ++s.aspect_ratio_histogram[bin(q, 1.0)];
    ++s.shape_factor_histogram[bin(sf, 1.0)];
    ++s.min_angle_histogram[bin(angles.first, 60.0)];
  }
  if (s.triangles > 0) {
    s.mean_alpha /= double(s.triangles);
    s.mean_aspect_ratio /= double(s.triangles);
    s.mean_shape_factor /= double(s.triangles);
  } else {
    s.min_alpha = s.min_aspect_ratio = s.min_shape_factor = 0;
    s.min_angle_deg = 0;
  }
  return s;
}

template <class PolygonMesh>
Quality_statistics quality_statistics(const PolygonMesh& pm, int bins = 10) {
  return quality_statistics(pm, get(CGAL::vertex_point, pm), bins);
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_QUALITY_H
