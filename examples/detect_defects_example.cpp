// detect_defects: read a mesh the way the tool does (polygon soup repaired and counted), find
// every defect, print the summary and the JSON report.
//   detect_defects_example [IN.off]
// Without an argument, a sphere with one face removed: one border cycle of three edges.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

/// Prints each step as it starts: the visitor interface of every Mesh_repair operator.
struct Printing_visitor : MR::Default_visitor {
  void start_step(const char* name) { std::cerr << "  step: " << name << '\n'; }
};

int main(int argc, char** argv) {
  Mesh mesh;
  MR::Soup_repair_report soup;
  if (argc > 1) {
    const std::string error = MR::read_mesh(argv[1], mesh, soup);
    if (!error.empty()) {
      std::cerr << error << '\n';
      return 2;
    }
  } else {
    MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 2);
    CGAL::Euler::remove_face(halfedge(*faces(mesh).begin(), mesh), mesh);
    mesh.collect_garbage();
  }

  Printing_visitor visitor;
  MR::Defect_report report = MR::detect_defects(
      mesh, MR::parameters::shape_factor_threshold(0.7).detect_self_intersections(true).visitor(
                std::ref(visitor)));
  if (argc > 1) MR::add_soup_repair_report(report, soup, mesh);

  std::cout << MR::summary(report) << '\n';
  MR::Json_writer json(std::cout);
  MR::write_json(json, report);
  return MR::counts(report).any() ? 1 : 0;
}
