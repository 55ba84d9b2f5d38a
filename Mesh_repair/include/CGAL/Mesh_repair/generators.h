// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_GENERATORS_H
#define CGAL_MESH_REPAIR_GENERATORS_H

/// \file generators.h
/// Meshes of known surfaces (sphere, torus, height fields such as the saddle of Chen et al.,
/// subdivided cube) with their exact distance functions. Tests, examples, the demo and
/// `mesh_repair bench holes` measure against these.

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

template <class PolygonMesh>
auto add_triangle(PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::vertex_descriptor a,
                  typename boost::graph_traits<PolygonMesh>::vertex_descriptor b,
                  typename boost::graph_traits<PolygonMesh>::vertex_descriptor c) {
  std::array<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, 3> face{a, b, c};
  return CGAL::Euler::add_face(face, pm);
}

}  // namespace internal

/// A closed sphere of `radius` around `center`: an icosahedron split `subdivisions` times
/// (each time every triangle into four), vertices projected onto the sphere. 20 * 4^s faces.
template <class PolygonMesh, class Point>
void make_sphere(PolygonMesh& pm, const Point& center, double radius, int subdivisions) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                               {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                               {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::size_t, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
    auto mid = [&](std::size_t a, std::size_t b) {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      std::array<double, 3> m;
      for (int k = 0; k < 3; ++k) m[k] = 0.5 * (points[a][k] + points[b][k]);
      points.push_back(m);
      midpoint.emplace(key, points.size() - 1);
      return points.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> refined;
    refined.reserve(4 * faces.size());
    for (const auto& f : faces) {
      const std::size_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      refined.push_back({f[0], ab, ca});
      refined.push_back({f[1], bc, ab});
      refined.push_back({f[2], ca, bc});
      refined.push_back({ab, bc, ca});
    }
    faces.swap(refined);
  }
  std::vector<vertex_descriptor> vertices;
  vertices.reserve(points.size());
  auto vpm = get(CGAL::vertex_point, pm);
  for (const auto& p : points) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    vertex_descriptor v = add_vertex(pm);
    put(vpm, v,
        Point(center.x() + radius * p[0] / n, center.y() + radius * p[1] / n,
              center.z() + radius * p[2] / n));
    vertices.push_back(v);
  }
  for (const auto& f : faces)
    internal::add_triangle(pm, vertices[f[0]], vertices[f[1]], vertices[f[2]]);
}

/// A closed torus around the z axis: `major_radius` R to the tube centre, `minor_radius` r, with
/// `major_segments` x `minor_segments` quads split into triangles.
template <class PolygonMesh, class Point>
void make_torus(PolygonMesh& pm, double major_radius, double minor_radius, int major_segments,
                int minor_segments) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  auto vpm = get(CGAL::vertex_point, pm);
  std::vector<vertex_descriptor> grid(std::size_t(major_segments) * minor_segments);
  const double two_pi = 2.0 * CGAL_PI;
  for (int i = 0; i < major_segments; ++i) {
    for (int j = 0; j < minor_segments; ++j) {
      const double u = two_pi * i / major_segments, v = two_pi * j / minor_segments;
      const double ring = major_radius + minor_radius * std::cos(v);
      vertex_descriptor vd = add_vertex(pm);
      put(vpm, vd, Point(ring * std::cos(u), ring * std::sin(u), minor_radius * std::sin(v)));
      grid[std::size_t(i) * minor_segments + j] = vd;
    }
  }
  auto at = [&](int i, int j) {
    return grid[std::size_t((i + major_segments) % major_segments) * minor_segments +
                (j + minor_segments) % minor_segments];
  };
  for (int i = 0; i < major_segments; ++i) {
    for (int j = 0; j < minor_segments; ++j) {
      internal::add_triangle(pm, at(i, j), at(i + 1, j), at(i + 1, j + 1));
      internal::add_triangle(pm, at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
}

/// An open height-field mesh z = height(x, y) over [x0,x1] x [y0,y1] with nx x ny cells, each split
/// into two triangles along alternating diagonals. With `height` = 0 a planar grid; with
/// x^2/10 - y^2/4 the saddle of Chen et al.
template <class PolygonMesh, class Point>
void make_height_field(PolygonMesh& pm, double x0, double x1, double y0, double y1, int nx, int ny,
                       const std::function<double(double, double)>& height) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  auto vpm = get(CGAL::vertex_point, pm);
  std::vector<vertex_descriptor> grid(std::size_t(nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double x = x0 + (x1 - x0) * i / nx, y = y0 + (y1 - y0) * j / ny;
      vertex_descriptor v = add_vertex(pm);
      put(vpm, v, Point(x, y, height(x, y)));
      grid[std::size_t(j) * (nx + 1) + i] = v;
    }
  }
  auto at = [&](int i, int j) { return grid[std::size_t(j) * (nx + 1) + i]; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if ((i + j) % 2 == 0) {
        internal::add_triangle(pm, at(i, j), at(i + 1, j), at(i + 1, j + 1));
        internal::add_triangle(pm, at(i, j), at(i + 1, j + 1), at(i, j + 1));
      } else {
        internal::add_triangle(pm, at(i, j), at(i + 1, j), at(i, j + 1));
        internal::add_triangle(pm, at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  }
}

/// A closed axis-aligned cube [0,size]^3 whose faces are n x n grids of triangles: 12 n^2 faces,
/// 8 corners and 12 sharp feature lines.
template <class PolygonMesh, class Point>
void make_subdivided_cube(PolygonMesh& pm, double size, int n) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  auto vpm = get(CGAL::vertex_point, pm);
  std::map<std::array<int, 3>, vertex_descriptor> lattice;
  auto vertex_at = [&](std::array<int, 3> key) {
    auto it = lattice.find(key);
    if (it != lattice.end()) return it->second;
    vertex_descriptor v = add_vertex(pm);
    put(vpm, v, Point(size * key[0] / n, size * key[1] / n, size * key[2] / n));
    lattice.emplace(key, v);
    return v;
  };
  // Each cube face: fixed axis, its value (0 or n), and the two other axes ordered so the
  // normal points outwards.
  const int faces[6][4] = {{0, 0, 2, 1}, {0, 1, 1, 2}, {1, 0, 0, 2},
                           {1, 1, 2, 0}, {2, 0, 1, 0}, {2, 1, 0, 1}};
  for (const auto& f : faces) {
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        auto corner = [&](int da, int db) {
          std::array<int, 3> key{};
          key[f[0]] = f[1] * n;
          key[f[2]] = a + da;
          key[f[3]] = b + db;
          return vertex_at(key);
        };
        internal::add_triangle(pm, corner(0, 0), corner(1, 0), corner(1, 1));
        internal::add_triangle(pm, corner(0, 0), corner(1, 1), corner(0, 1));
      }
    }
  }
}

/// Exact signed distances to the analytic surfaces, for fidelity measurements.
struct Analytic_distance {
  static double sphere(double x, double y, double z, double radius) {
    return std::sqrt(x * x + y * y + z * z) - radius;
  }
  static double torus(double x, double y, double z, double major_radius, double minor_radius) {
    const double q = std::sqrt(x * x + y * y) - major_radius;
    return std::sqrt(q * q + z * z) - minor_radius;
  }
};

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_GENERATORS_H
