// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Quartic triangular Bezier patches of Walton and Meek (thesis 5.5).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/bezier_patches.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/box_hierarchy.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Patch = CGAL::Mesh_repair::internal::shape_prediction::Quartic_triangle_patch<K>;

Vector unit(const Vector& v) {
  return v / std::sqrt(v.squared_length());
}

Point on_sphere(double theta, double phi) {
  return Point(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

Patch sphere_patch(const Point& a, const Point& b, const Point& c) {
  return Patch({a, b, c}, {a - CGAL::ORIGIN, b - CGAL::ORIGIN, c - CGAL::ORIGIN});
}

// Unit normal of a patch at (u, v, 0), from one-sided differences along the edge w = 0 and
// into the patch.
Vector normal_on_edge(const Patch& patch, double u) {
  const double h = 1e-6;
  const Point p = patch(u, 1 - u, 0);
  const Vector along = patch(u + h, 1 - u - h, 0) - p;
  const Vector inward = patch(u - h / 2, 1 - u - h / 2, h) - p;
  return unit(CGAL::cross_product(along, inward));
}

TEST(BezierPatches, PatchInterpolatesItsCornersAndReproducesAPlaneExactly) {
  const Vector n = unit(Vector(0.3, 0.2, -1));
  auto plane_point = [](double x, double y) { return Point(x, y, 0.3 * x + 0.2 * y + 1); };
  const Point a = plane_point(0, 0), b = plane_point(2, 0.2), c = plane_point(0.7, 1.5);
  const Patch tilted({a, b, c}, {n, n, n});
  EXPECT_LT(std::sqrt(CGAL::squared_distance(tilted(1, 0, 0), a)), 1e-14);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(tilted(0, 1, 0), b)), 1e-14);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(tilted(0, 0, 1), c)), 1e-14);
  const K::Plane_3 plane(a, b, c);
  for (double u = 0; u <= 1.0; u += 0.1)
    for (double v = 0; u + v <= 1.0; v += 0.1) {
      const Point p = tilted(u, v, 1 - u - v);
      EXPECT_LT(std::sqrt(CGAL::squared_distance(p, plane)), 1e-13);
    }
  // In the plane z = 0 every construction stays exactly in the plane.
  const Vector z(0, 0, 1);
  const Patch flat({Point(0, 0, 0), Point(1, 0, 0), Point(0.2, 0.9, 0)}, {z, z, z});
  for (double u = 0; u <= 1.0; u += 0.125)
    for (double v = 0; u + v <= 1.0; v += 0.125) EXPECT_EQ(flat(u, v, 1 - u - v).z(), 0.0);
}

TEST(BezierPatches, NeighbouringPatchesShareTheirEdgeAndTangentPlane) {
  // Triangles (a, b, c) and (b, a, d) on the unit sphere share the edge a-b (w = 0 in both).
  const Point a = on_sphere(0.9, 0.0), b = on_sphere(1.1, 0.8), c = on_sphere(0.4, 0.5),
              d = on_sphere(1.5, 0.2);
  const Patch first = sphere_patch(a, b, c);
  const Patch second = sphere_patch(b, a, d);
  double worst_gap = 0, worst_sine = 0;
  for (double u = 0.05; u < 1.0; u += 0.05) {
    worst_gap = std::max(
        worst_gap, std::sqrt(CGAL::squared_distance(first(u, 1 - u, 0), second(1 - u, u, 0))));
    const Vector n1 = normal_on_edge(first, u);
    const Vector n2 = normal_on_edge(second, 1 - u);
    worst_sine = std::max(worst_sine, std::sqrt(CGAL::cross_product(n1, n2).squared_length()));
  }
  EXPECT_LT(worst_gap, 1e-12);
  EXPECT_LT(worst_sine, 1e-4);  // G1: finite differences of step 1e-6
}

TEST(BezierPatches, NormalsAtCornersAreTheGivenNormals) {
  const Point a = on_sphere(0.9, 0.0), b = on_sphere(1.1, 0.8), c = on_sphere(0.4, 0.5);
  const Patch patch = sphere_patch(a, b, c);
  const double h = 1e-6;
  const Vector du = patch(1 - h, h, 0) - patch(1, 0, 0);
  const Vector dw = patch(1 - h, 0, h) - patch(1, 0, 0);
  const Vector n = unit(CGAL::cross_product(du, dw));
  EXPECT_LT(std::sqrt(CGAL::cross_product(n, a - CGAL::ORIGIN).squared_length()), 1e-4);
}

TEST(BezierPatches, SpherePatchStaysCloseToTheSphere) {
  const Point a = on_sphere(0.9, 0.0), b = on_sphere(1.1, 0.8), c = on_sphere(0.4, 0.5);
  const Patch patch = sphere_patch(a, b, c);
  double flat_error = 0, patch_error = 0;
  for (double u = 0; u <= 1.0; u += 0.05)
    for (double v = 0; u + v <= 1.0; v += 0.05) {
      const double w = 1 - u - v;
      const Point p = patch(u, v, w);
      patch_error =
          std::max(patch_error, std::abs(std::sqrt((p - CGAL::ORIGIN).squared_length()) - 1));
      const Vector q = u * (a - CGAL::ORIGIN) + v * (b - CGAL::ORIGIN) + w * (c - CGAL::ORIGIN);
      flat_error = std::max(flat_error, std::abs(std::sqrt(q.squared_length()) - 1));
    }
  EXPECT_LT(patch_error, 0.1 * flat_error);
}

// Largest distance from the unit circle of the cubic with control points c, sampled.
double circle_error(const std::array<Point, 4>& c) {
  double worst = 0;
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0, s = 1 - t;
    const Vector p = s * s * s * (c[0] - CGAL::ORIGIN) + 3 * s * s * t * (c[1] - CGAL::ORIGIN) +
                     3 * s * t * t * (c[2] - CGAL::ORIGIN) + t * t * t * (c[3] - CGAL::ORIGIN);
    worst = std::max(worst, std::abs(std::sqrt(p.squared_length()) - 1));
  }
  return worst;
}

TEST(BezierPatches, CircularBoundaryCubicReproducesACircularArc) {
  for (double half_angle : {20.0, 45.0, 60.0}) {
    const double a = half_angle * CGAL_PI / 180;
    // An arc of the unit circle, tilted out of the coordinate planes; normals are radial.
    const Vector tilt = Vector(0.3, 0.2, 1) / std::sqrt(1.13);
    const Vector e1 = Vector(1, 0, -0.3) / std::sqrt(1.09);
    const Vector e2 = CGAL::cross_product(tilt, e1);
    const Point q0 = CGAL::ORIGIN + (-std::sin(a) * e1 + std::cos(a) * e2);
    const Point q1 = CGAL::ORIGIN + (std::sin(a) * e1 + std::cos(a) * e2);
    const Vector n0 = q0 - CGAL::ORIGIN, n1 = q1 - CGAL::ORIGIN;
    const double walton_meek = circle_error(Patch::boundary_cubic(q0, n0, q1, n1));
    const auto circular = Patch::circular_boundary_cubic(q0, n0, q1, n1);
    // The cubic arc's own error (4/3 tan(theta/4) rule): 2.7e-4 for 90 degrees, 1.3e-3 for 120.
    EXPECT_LT(circle_error(circular), 2e-3) << half_angle;
    EXPECT_LT(circle_error(circular), 0.5 * walton_meek) << half_angle;
    // The same curve when the edge is walked the other way (neighbouring patches share it).
    const auto reversed = Patch::circular_boundary_cubic(q1, n1, q0, n0);
    for (int k = 0; k < 4; ++k)
      EXPECT_LT(std::sqrt(CGAL::squared_distance(circular[k], reversed[3 - k])), 1e-14);
    RecordProperty("walton_meek_error_" + std::to_string(int(half_angle)),
                   std::to_string(walton_meek));
  }
}

TEST(BezierPatches, NetworkMapsPointsAlongTheNormalOfTheirTriangle) {
  const std::vector<Point> points = {on_sphere(0.9, 0.0), on_sphere(1.1, 0.8), on_sphere(0.4, 0.5),
                                     on_sphere(1.5, 0.2)};
  std::vector<Vector> normals;
  for (const Point& p : points) normals.push_back(p - CGAL::ORIGIN);
  const CGAL::Mesh_repair::internal::shape_prediction::Bezier_patch_network<K> network(
      points, normals, {{0, 1, 2}, {1, 0, 3}});
  // Eq. 5.31 as written: the patch point at the coordinates of the foot, which lies aside of the
  // triangle's normal line through the point.
  const Point centroid = CGAL::centroid(points[0], points[1], points[2]);
  const Vector normal = CGAL::normal(points[0], points[1], points[2]);
  const Point at_foot = network.map_at_foot_coordinates(centroid);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(at_foot, network.patch(0)(1.0 / 3, 1.0 / 3, 1.0 / 3))),
            1e-12);
  const auto sine_to_normal = [&normal](const Vector& d) {
    return std::sqrt(CGAL::cross_product(d, normal).squared_length() /
                     (d.squared_length() * normal.squared_length()));
  };
  EXPECT_GT(sine_to_normal(at_foot - centroid), 1e-3);
  // `map`: the patch point on that normal line, still on the sphere.
  const Point mapped = network.map(centroid);
  EXPECT_LT(sine_to_normal(mapped - centroid), 1e-8);
  EXPECT_LT(std::abs(std::sqrt((mapped - CGAL::ORIGIN).squared_length()) - 1), 0.01);
  // A point of the network stays where it is, also near the shared edge (0, 1), where the
  // normal line from the nearest triangle meets the other patch.
  double moved = 0;
  for (std::size_t t : {0u, 1u})
    for (double near_edge : {0.02, 0.1, 0.3})
      for (double along : {0.2, 0.5, 0.7}) {
        // Corners 0 and 1 of triangle 0 are points 0 and 1; of triangle 1, points 1 and 0.
        const double a = (1 - near_edge) * along, b = (1 - near_edge) * (1 - along);
        const Point on = network.patch(t)(a, b, near_edge);
        moved = std::max(moved, std::sqrt(CGAL::squared_distance(network.map(on), on)));
      }
  EXPECT_LT(moved, 1e-7);
}

// The hierarchy must return what a linear scan returns (the first of equal distances), or the
// fronts on the patches would change: random triangles of very different sizes (long GA chords
// beside small ones), points near and far, and exact ties (two copies of a triangle, and points
// on a shared corner).
TEST(BoxHierarchy, NearestItemIsTheLinearScansIncludingTies) {
  using CGAL::Mesh_repair::internal::shape_prediction::Box_hierarchy;
  CGAL::Random random(11);
  std::vector<std::array<Point, 3>> triangles;
  for (int k = 0; k < 300; ++k) {
    const Point a(random.get_double(-1, 1), random.get_double(-1, 1), random.get_double(-1, 1));
    const double size = k % 10 == 0 ? 1.0 : 0.05;
    auto near_a = [&] {
      return a + Vector(random.get_double(-size, size), random.get_double(-size, size),
                        random.get_double(-size, size));
    };
    triangles.push_back({a, near_a(), near_a()});
  }
  triangles.push_back(triangles[17]);  // an exact tie with item 17, found second by the scan
  triangles.push_back({triangles[5][0], triangles[40][1], triangles[90][2]});  // shares corners
  std::vector<Box_hierarchy::Box> boxes;
  for (const auto& t : triangles) {
    Box_hierarchy::Box box;
    for (int d = 0; d < 3; ++d) {
      box[d] = std::min({t[0][d], t[1][d], t[2][d]});
      box[d + 3] = std::max({t[0][d], t[1][d], t[2][d]});
    }
    boxes.push_back(box);
  }
  const Box_hierarchy hierarchy(boxes);
  std::vector<Point> queries{triangles[17][0], triangles[5][0],
                             CGAL::centroid(triangles[17][0], triangles[17][1], triangles[17][2])};
  for (int k = 0; k < 2000; ++k)
    queries.emplace_back(random.get_double(-2, 2), random.get_double(-2, 2),
                         random.get_double(-2, 2));
  for (const Point& q : queries) {
    const auto distance = [&](std::size_t i) {
      return CGAL::to_double(CGAL::squared_distance(
          q, K::Triangle_3(triangles[i][0], triangles[i][1], triangles[i][2])));
    };
    std::size_t scan = 0;
    double scan_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      if (distance(i) < scan_distance) scan_distance = distance(i), scan = i;
    }
    const double p[3] = {q.x(), q.y(), q.z()};
    double found_distance = -1;
    const std::size_t found = hierarchy.nearest(p, distance, found_distance);
    EXPECT_EQ(found, scan);
    EXPECT_EQ(found_distance, scan_distance);
  }
}

}  // namespace
