// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Meshing of a point set (Chen et al. 2.1): points on a sphere are reconstructed into a
// triangle mesh and smoothed with the micro-GA; prints the quality before and after.
//   mesh_points_example [OUT.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/mesh_points.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/point_generators_3.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

int main(int argc, char** argv) {
  CGAL::Random random(1);
  CGAL::Random_points_on_sphere_3<Point> on_sphere(1.0, random);
  std::vector<Point> points;
  for (int k = 0; k < 2000; ++k) points.push_back(*on_sphere++);

  Mesh mesh;
  const MR::Mesh_points_result result = MR::mesh_points(points, mesh);
  std::cout << result.points << " points -> " << mesh.number_of_faces() << " faces ("
            << result.flips.flips << " quality flips); closed: " << std::boolalpha
            << CGAL::is_closed(mesh) << "\n"
            << "mean quality " << result.smoothing.mean_quality_before << " -> "
            << result.smoothing.mean_quality_after << ", worst "
            << result.smoothing.worst_quality_before << " -> "
            << result.smoothing.worst_quality_after << "\n";
  if (argc > 1) {
    const std::string error = MR::write_mesh(argv[1], mesh);
    if (!error.empty()) {
      std::cerr << error << "\n";
      return 1;
    }
  }
  return result.reconstructed_faces > 0 ? 0 : 1;
}
