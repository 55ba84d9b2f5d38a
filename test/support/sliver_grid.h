// A parallelogram grid whose cells are split along their long diagonal: every triangle is a
// sliver although the short diagonals would give good ones. Shared by test_optimize_mesh and
// test_named_parameters.
#ifndef MESH_REPAIR_TEST_SLIVER_GRID_H
#define MESH_REPAIR_TEST_SLIVER_GRID_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>
#include <vector>

/// n x n cells in the plane z = 0, or, with `bump` > 0, on the surface
/// z = bump sin(0.6 x) cos(2 y) (so that re-triangulations also differ in smoothness).
inline CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> sliver_grid(
    int n, double bump = 0) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  CGAL::Surface_mesh<Point> mesh;
  std::vector<CGAL::Surface_mesh<Point>::Vertex_index> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = i + 0.85 * j, y = 0.25 * j;
      v.push_back(mesh.add_vertex(Point(x, y, bump * std::sin(0.6 * x) * std::cos(2.0 * y))));
    }
  auto at = [&](int i, int j) { return v[std::size_t(j) * std::size_t(n + 1) + std::size_t(i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return mesh;
}

#endif  // MESH_REPAIR_TEST_SLIVER_GRID_H
