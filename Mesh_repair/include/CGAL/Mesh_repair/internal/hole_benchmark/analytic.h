// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_ANALYTIC_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_ANALYTIC_H

// The analytic surfaces of the hole benchmark: their meshes (generators.h) and exact distances.

#include <CGAL/Mesh_repair/generators.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace CGAL {
namespace Mesh_repair {

/// Known surfaces the benchmark measures against with exact distance.
enum class Analytic_surface { sphere, torus, saddle };

inline const char* to_string(Analytic_surface surface) {
  switch (surface) {
    case Analytic_surface::sphere:
      return "sphere";
    case Analytic_surface::torus:
      return "torus";
    case Analytic_surface::saddle:
      return "saddle";
  }
  return "unknown";
}

inline bool analytic_surface_from_string(const std::string& name, Analytic_surface& surface) {
  for (Analytic_surface s :
       {Analytic_surface::sphere, Analytic_surface::torus, Analytic_surface::saddle}) {
    if (name == to_string(s)) {
      surface = s;
      return true;
    }
  }
  return false;
}

namespace internal {
namespace hole_benchmark {

// Dimensions of the benchmark's analytic meshes (about 20k, 8k and 8k triangles).
constexpr double sphere_radius = 1.0;
constexpr int sphere_subdivisions = 5;
constexpr double torus_major = 1.0, torus_minor = 0.4;
constexpr int torus_major_segments = 96, torus_minor_segments = 40;
constexpr double saddle_half_width = 3.0;
constexpr int saddle_cells = 64;

// Chen et al.'s saddle z = x^2/10 - y^2/4.
inline double saddle_height(double x, double y) {
  return x * x / 10.0 - y * y / 4.0;
}

// Distance from (px, py, pz) to the saddle: Newton's method on the squared distance to
// (u, v, h(u, v)), started below the point. The Hessian is positive definite near the foot point
// for the points the benchmark asks about (within a small fraction of the curvature radius).
inline double saddle_distance(double px, double py, double pz) {
  double u = px, v = py;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double h = saddle_height(u, v) - pz;
    const double hu = u / 5.0, hv = -v / 2.0;
    const double gu = (u - px) + h * hu, gv = (v - py) + h * hv;
    const double huu = 1.0 + hu * hu + h / 5.0, hvv = 1.0 + hv * hv - h / 2.0, huv = hu * hv;
    const double det = huu * hvv - huv * huv;
    double du, dv;
    if (det > 1e-12 && huu > 0) {
      du = (hvv * gu - huv * gv) / det;
      dv = (huu * gv - huv * gu) / det;
    } else {
      du = 0.5 * gu;
      dv = 0.5 * gv;
    }
    u -= du;
    v -= dv;
    if (std::abs(du) + std::abs(dv) < 1e-14) break;
  }
  const double dz = saddle_height(u, v) - pz;
  return std::sqrt((u - px) * (u - px) + (v - py) * (v - py) + dz * dz);
}

}  // namespace hole_benchmark
}  // namespace internal

/// Builds the benchmark mesh of `surface`: a sphere of radius 1 (icosphere, 20,480 triangles), a
/// torus with radii 1 and 0.4 (96 x 40 quads split, 7,680 triangles), or the saddle
/// z = x^2/10 - y^2/4 over [-3,3]^2 (64 x 64 cells, 8,192 triangles, open).
template <class PolygonMesh>
void make_analytic_mesh(PolygonMesh& pm, Analytic_surface surface) {
  using namespace internal::hole_benchmark;
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  switch (surface) {
    case Analytic_surface::sphere:
      make_sphere(pm, Point(0, 0, 0), sphere_radius, sphere_subdivisions);
      break;
    case Analytic_surface::torus:
      make_torus<PolygonMesh, Point>(pm, torus_major, torus_minor, torus_major_segments,
                                     torus_minor_segments);
      break;
    case Analytic_surface::saddle:
      make_height_field<PolygonMesh, Point>(pm, -saddle_half_width, saddle_half_width,
                                            -saddle_half_width, saddle_half_width, saddle_cells,
                                            saddle_cells, saddle_height);
      break;
  }
}

/// The exact unsigned distance from a point to `surface` (as built by `make_analytic_mesh`).
template <class Point>
std::function<double(const Point&)> analytic_distance(Analytic_surface surface) {
  using namespace internal::hole_benchmark;
  switch (surface) {
    case Analytic_surface::sphere:
      return [](const Point& p) {
        return std::abs(Analytic_distance::sphere(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                                  CGAL::to_double(p.z()), sphere_radius));
      };
    case Analytic_surface::torus:
      return [](const Point& p) {
        return std::abs(Analytic_distance::torus(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                                 CGAL::to_double(p.z()), torus_major, torus_minor));
      };
    case Analytic_surface::saddle:
      return [](const Point& p) {
        return saddle_distance(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                               CGAL::to_double(p.z()));
      };
  }
  return {};
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_ANALYTIC_H
