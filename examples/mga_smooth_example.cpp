// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Smooths a jittered saddle with the micro-GA, then converts it to quads and smooths again.
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/mga_smooth.h>
#include <CGAL/Mesh_repair/triangles_to_quads.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

int main() {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  using Mesh = CGAL::Surface_mesh<Point>;
  namespace MR = CGAL::Mesh_repair;

  auto saddle = [](double x, double y) { return x * x / 10 - y * y / 4; };
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, -2, 2, -2, 2, 20, 20, saddle);
  CGAL::Random random(1);
  for (auto v : vertices(mesh)) {
    if (is_border(v, mesh)) continue;
    const Point& p = mesh.point(v);
    const double x = p.x() + random.get_double(-0.06, 0.06),
                 y = p.y() + random.get_double(-0.06, 0.06);
    mesh.point(v) = Point(x, y, saddle(x, y));
  }

  const MR::Mga_smooth_result triangles =
      MR::mga_smooth(mesh, MR::parameters::number_of_threads(2).random_seed(7));
  std::cout << "triangles: mean alpha " << triangles.mean_quality_before << " -> "
            << triangles.mean_quality_after << " in " << triangles.sweeps << " sweeps\n";

  const MR::Quad_conversion_result conversion = MR::triangles_to_quads(mesh);
  const MR::Mga_smooth_result quads = MR::mga_smooth(mesh, CGAL::parameters::random_seed(7));
  std::cout << conversion.quads << " quads, " << conversion.remaining_triangles
            << " triangles: mean quality " << quads.mean_quality_before << " -> "
            << quads.mean_quality_after << "\n";
  return 0;
}
