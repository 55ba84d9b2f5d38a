// Fills the holes of a mesh (default: a sphere with two holes punched) with the advancing front,
// CGAL's Liepa and the automatic choice, and prints what each did.
//   fill_holes_example [IN.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

int main(int argc, char** argv) {
  Mesh input;
  if (argc > 1) {
    MR::Soup_repair_report soup;
    const std::string error = MR::read_mesh(argv[1], input, soup);
    if (!error.empty()) {
      std::cerr << error << "\n";
      return 2;
    }
  } else {
    MR::make_sphere(input, Point(0, 0, 0), 1.0, 4);
    std::vector<Mesh::Face_index> doomed;  // two caps around the poles
    for (auto f : faces(input)) {
      double z = 0;
      for (auto v : vertices_around_face(halfedge(f, input), input)) z += input.point(v).z() / 3;
      if (z > 0.85 || z < -0.9) doomed.push_back(f);
    }
    for (auto f : doomed) CGAL::Euler::remove_face(halfedge(f, input), input);
  }

  for (MR::Fill_method method :
       {MR::Fill_method::advancing_front, MR::Fill_method::liepa, MR::Fill_method::automatic}) {
    Mesh mesh = input;
    const MR::Fill_result result = MR::fill_holes(mesh, MR::parameters::fill_method(method));
    std::cout << MR::to_string(method) << ": " << result.filled << " filled, " << result.failed
              << " failed; closed: " << std::boolalpha << CGAL::is_closed(mesh) << "\n";
    for (const MR::Hole_fill_report& hole : result.holes) {
      std::cout << "  " << hole.border_edges << " border edges -> "
                << (hole.filled ? std::to_string(hole.faces_created) + " faces by " +
                                      MR::to_string(hole.used)
                                : "open: " + hole.failure)
                << "\n";
    }
  }
  return 0;
}
