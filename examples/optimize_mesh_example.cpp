// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Reduces a subdivided cube to a tenth of its faces, keeping its corners and feature lines, then
// improves the shape of the remaining triangles.
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/optimize_mesh.h>
#include <CGAL/Mesh_repair/quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

int main() {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  namespace MR = CGAL::Mesh_repair;

  Mesh mesh;
  MR::make_subdivided_cube<Mesh, Kernel::Point_3>(mesh, 1.0, 10);
  const MR::Optimization_result reduced = MR::optimize_mesh(
      mesh, MR::parameters::target_face_ratio(0.1).feature_angle_deg(135.0).random_seed(1u));
  const MR::Optimization_result improved =
      MR::optimize_mesh(mesh, MR::parameters::optimization_mode(MR::Optimization_mode::quality));
  mesh.collect_garbage();
  const MR::Quality_statistics quality = MR::quality_statistics(mesh);
  std::cout << "faces " << reduced.input_faces << " -> " << reduced.output_faces << " ("
            << reduced.corner_nodes << " corners kept), then " << improved.regions_replaced
            << " regions re-triangulated for quality; smallest angle " << quality.min_angle_deg
            << " deg, valid " << CGAL::is_valid_polygon_mesh(mesh) << "\n";
  return CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh) ? 0 : 1;
}
