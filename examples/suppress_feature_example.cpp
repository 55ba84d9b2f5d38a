// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Feature suppression (thesis 6.1): removes a bump from a flat plate and fills the opening
// with shape prediction, then takes the patch out as an implant (thesis 6.2).
//   suppress_feature_example [OUT.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/implant_patch.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/suppress_feature.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

int main(int argc, char** argv) {
  // A 2 x 2 plate with a bump of height 0.3 around its centre: the feature.
  Mesh mesh;
  MR::make_height_field<Mesh, Point>(mesh, -1, 1, -1, 1, 24, 24, [](double x, double y) {
    const double r2 = x * x + y * y;
    return r2 < 0.16 ? 0.3 * std::cos(std::sqrt(r2) / 0.4 * CGAL_PI / 2) : 0.0;
  });
  std::vector<Mesh::Face_index> bump;
  for (auto f : faces(mesh)) {
    double z = 0;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) z += mesh.point(v).z() / 3;
    if (z > 1e-9) bump.push_back(f);
  }

  auto result = MR::suppress_feature(mesh, bump);  // shape prediction by default
  std::cout << "removed " << result.faces_removed << " faces, opened " << result.holes_opened
            << " hole(s), filled " << result.holes_filled << "\n";
  double highest = 0;
  for (auto v : vertices(mesh)) highest = std::max(highest, std::abs(mesh.point(v).z()));
  std::cout << "largest |z| after suppression: " << highest << " (the bump was 0.3)\n";
  if (result.holes_filled > 0) {
    const Mesh implant = MR::extract_patch(mesh, result.patches.front().faces);
    std::cout << "implant: " << implant.number_of_faces() << " faces\n";
  }
  mesh.collect_garbage();
  if (argc > 1) {
    const std::string error = MR::write_mesh(argv[1], mesh);
    if (!error.empty()) {
      std::cerr << error << "\n";
      return 1;
    }
  }
  return result.all_filled() ? 0 : 1;
}
