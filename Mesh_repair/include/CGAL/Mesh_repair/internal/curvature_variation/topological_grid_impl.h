// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_TOPOLOGICAL_GRID_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_TOPOLOGICAL_GRID_IMPL_H

#include <CGAL/Mesh_repair/internal/curvature_variation/topological_grid.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <map>
#include <queue>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

CGAL_MESH_REPAIR_CORE_INLINE std::vector<std::array<double, 2>> disc_grid_points(
    const std::vector<double>& edge_lengths, std::size_t& border_count) {
  const std::size_t n = edge_lengths.size();
  double perimeter = 0;
  for (double l : edge_lengths) perimeter += l;
  std::vector<std::array<double, 2>> points;
  double arc = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = perimeter > 0 ? 2 * CGAL_PI * arc / perimeter : 2 * CGAL_PI * k / n;
    points.push_back({std::cos(angle), std::sin(angle)});
    arc += edge_lengths[k];
  }
  border_count = n;
  const double spacing = 2 * std::sin(CGAL_PI / double(n));
  const double row_height = spacing * std::sqrt(3.0) / 2;
  const double keep_radius = 1.0 - 0.5 * spacing;
  const int rows = int(std::ceil(1.0 / row_height));
  for (int r = -rows; r <= rows; ++r) {
    const double y = r * row_height;
    const double shift = (r % 2 == 0) ? 0.0 : 0.5 * spacing;
    const int columns = int(std::ceil(1.0 / spacing)) + 1;
    for (int c = -columns; c <= columns; ++c) {
      const double x = c * spacing + shift;
      if (x * x + y * y < keep_radius * keep_radius) points.push_back({x, y});
    }
  }
  return points;
}

CGAL_MESH_REPAIR_CORE_INLINE std::vector<std::array<std::size_t, 3>> disc_grid_triangles(
    const std::vector<std::array<double, 2>>& points) {
  using K2 = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K2>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Delaunay = CGAL::Delaunay_triangulation_2<K2, Tds>;
  std::vector<std::pair<K2::Point_2, std::size_t>> input;
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(K2::Point_2(points[i][0], points[i][1]), i);
  Delaunay dt(input.begin(), input.end());
  std::map<Delaunay::Face_handle, std::size_t> order;
  std::vector<Delaunay::Face_handle> faces;
  std::queue<Delaunay::Face_handle> queue;
  for (auto f : dt.finite_face_handles()) {
    for (int i = 0; i < 3; ++i) {
      if (dt.is_infinite(f->neighbor(i)) && order.emplace(f, faces.size()).second) {
        faces.push_back(f);
        queue.push(f);
      }
    }
  }
  while (!queue.empty()) {
    auto f = queue.front();
    queue.pop();
    for (int i = 0; i < 3; ++i) {
      auto g = f->neighbor(i);
      if (dt.is_infinite(g) || !order.emplace(g, faces.size()).second) continue;
      faces.push_back(g);
      queue.push(g);
    }
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  for (auto f : faces)
    triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return triangles;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_TOPOLOGICAL_GRID_IMPL_H
