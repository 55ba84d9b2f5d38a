// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Fills a large hole in a sphere by shape prediction (thesis chapter 5) and prints how far the
// new vertices lie from the true sphere.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

int main() {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  // Remove a cap of 35 degrees around the north pole.
  std::vector<Mesh::Face_index> cap;
  for (auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Point c = CGAL::centroid(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                   mesh.point(mesh.target(mesh.next(h))));
    if (c.z() > std::cos(35.0 * CGAL_PI / 180)) cap.push_back(f);
  }
  for (auto f : cap) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);

  std::vector<MR::Fill_patch<Mesh>> patches;
  const MR::Fill_result result = MR::fill_holes(
      mesh, patches,
      MR::parameters::fill_method(MR::Fill_method::shape_prediction).random_seed(42u));
  for (std::size_t k = 0; k < result.holes.size(); ++k) {
    const MR::Hole_fill_report& hole = result.holes[k];
    double worst = 0;
    for (auto v : patches[k].vertices)
      worst =
          std::max(worst, std::abs(std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length()) - 1));
    std::cout << "hole " << k << ": " << (hole.filled ? "filled" : "open") << " with "
              << MR::to_string(hole.used) << ", " << hole.faces_created << " faces, "
              << hole.vertices_created << " new vertices, farthest from the sphere " << worst
              << " (" << worst / (2 * std::sqrt(3.0)) << " of the diagonal)\n";
    for (const auto& note : hole.notes) std::cout << "  " << note << "\n";
  }
  std::cout << (CGAL::is_closed(mesh) ? "closed" : "still open") << "\n";
  return result.all_filled() ? 0 : 1;
}
