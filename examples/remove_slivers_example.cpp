// remove_slivers: a flat grid with one node pushed next to its neighbour (slivers with a short
// edge, collapsed) and another pushed almost onto a diagonal (a cap, removed by an edge swap).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/remove_slivers.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

int main() {
  Mesh grid;
  MR::make_height_field<Mesh, Point>(grid, 0, 8, 0, 8, 8, 8, [](double, double) { return 0.0; });
  for (auto v : vertices(grid)) {
    const Point& p = grid.point(v);
    if (p == Point(3, 3, 0)) grid.point(v) = Point(3.96, 3, 0);    // short edge: Figure 4.13
    if (p == Point(6, 5, 0)) grid.point(v) = Point(6.45, 4.6, 0);  // cap: Figure 4.14
  }
  const MR::Sliver_result result = MR::remove_slivers(
      grid, MR::parameters::shape_factor_threshold(0.7).feature_angle_deg(135.0));
  std::cout << "slivers " << result.slivers_before << " -> " << result.slivers_after << ": "
            << result.collapsed << " collapsed, " << result.flipped
            << " swapped, worst shape factor " << result.min_shape_factor_before << " -> "
            << result.min_shape_factor_after << ", " << (result.valid ? "valid" : "INVALID")
            << "\n";
  return result.valid && result.slivers_after < result.slivers_before ? 0 : 1;
}
