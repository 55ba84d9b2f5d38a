// automatic_repair: the whole repair pipeline (thesis Fig. 3.2-3.3) in one call. Reads a mesh the
// way the tool does (polygon soup repaired and counted), or builds a defective one, repairs it,
// prints what every step did and what is left, and writes the result.
//   automatic_repair_example [IN.off [OUT.off]]
// Without an argument: a sphere with two disc holes punched, a cap cut off and moved by a small
// gap, and a lone zero-area triangle; written to automatic_repair_out.off.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

namespace {

Point centroid(const Mesh& mesh, Mesh::Face_index f) {
  double c[3] = {0, 0, 0};
  for (auto v : vertices_around_face(mesh.halfedge(f), mesh))
    for (int k = 0; k < 3; ++k) c[k] += mesh.point(v)[k] / 3;
  return Point(c[0], c[1], c[2]);
}

// Removes the faces whose centroid lies within `radius` of `center`: a disc-shaped hole.
void punch_hole(Mesh& mesh, const Point& center, double radius) {
  std::vector<Mesh::Face_index> doomed;
  for (auto f : mesh.faces())
    if (CGAL::squared_distance(centroid(mesh, f), center) < radius * radius) doomed.push_back(f);
  for (auto f : doomed) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
}

// A sphere with the defects automatic_repair is made for: two holes, a cap above z = 0.7 cut
// loose (its border vertices duplicated) and lifted by 0.002 (a gap for tolerance stitching),
// and an isolated flat triangle (removed by the degenerate-face step).
Mesh defective_sphere() {
  Mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 4);
  punch_hole(sphere, Point(1, 0, 0), 0.3);
  punch_hole(sphere, Point(0, -1, 0), 0.25);

  Mesh mesh;
  std::vector<Mesh::Vertex_index> below(num_vertices(sphere)), above(num_vertices(sphere));
  for (auto v : sphere.vertices()) {
    const Point& p = sphere.point(v);
    below[v] = mesh.add_vertex(p);
    above[v] = mesh.add_vertex(Point(p.x(), p.y(), p.z() + 0.002));
  }
  for (auto f : sphere.faces()) {
    const bool cap = centroid(sphere, f).z() > 0.7;
    std::vector<Mesh::Vertex_index> corners;
    for (auto v : vertices_around_face(sphere.halfedge(f), sphere))
      corners.push_back(cap ? above[v] : below[v]);
    mesh.add_face(corners);
  }
  const auto a = mesh.add_vertex(Point(3, 0, 0)), b = mesh.add_vertex(Point(3.5, 0, 0)),
             c = mesh.add_vertex(Point(4, 0, 0));
  mesh.add_face(a, b, c);
  // Drop the vertices no face uses (every sphere vertex got a copy on both sides of the cut).
  std::vector<Mesh::Vertex_index> unused;
  for (auto v : mesh.vertices())
    if (mesh.is_isolated(v)) unused.push_back(v);
  for (auto v : unused) mesh.remove_vertex(v);
  mesh.collect_garbage();
  return mesh;
}

void print_summary(const MR::Repair_result& r) {
  std::cout << "input: " << r.input_vertices << " vertices, " << r.input_faces << " faces\n";
  std::cout << "steps:\n";
  for (const MR::Repair_step_report& step : r.steps) {
    std::cout << "  " << step.name << " (" << step.seconds << " s)";
    bool first = true;
    for (const auto& count : step.counts) {
      if (count.second == 0) continue;
      std::cout << (first ? ": " : ", ") << count.first << ' ' << count.second;
      first = false;
    }
    std::cout << '\n';
    for (const std::string& note : step.notes) std::cout << "    note: " << note << '\n';
  }
  std::cout << "holes: " << r.holes.holes.size() << " (" << r.holes.filled << " filled, "
            << r.holes.failed << " failed, " << r.holes_too_large << " left open as too large)\n";
  for (const MR::Hole_fill_report& hole : r.holes.holes)
    std::cout << "  " << hole.border_edges << " border edges -> "
              << (hole.filled
                      ? std::to_string(hole.faces_created) + " faces by " + MR::to_string(hole.used)
                      : "open: " + hole.failure)
              << '\n';
  std::cout << "output: " << r.output_vertices << " vertices, " << r.output_faces << " faces, "
            << (r.valid ? "valid" : "INVALID") << ", " << (r.closed ? "closed" : "open") << ", "
            << (r.manifold ? "manifold" : "non-manifold");
  if (r.self_intersections_checked)
    std::cout << ", " << r.self_intersections_output << " self-intersecting pairs (input "
              << r.self_intersections_input << ")";
  std::cout << '\n';
  std::cout << "status: " << CGAL::Mesh_repair::to_string(r.status()) << '\n';
  if (!r.remaining.empty()) std::cout << "left:\n";
  for (const std::string& line : r.remaining) std::cout << "  " << line << '\n';
  if (!r.kept.empty()) std::cout << "kept on purpose:\n";
  for (const std::string& line : r.kept) std::cout << "  " << line << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  Mesh mesh;
  if (argc > 1) {
    MR::Soup_repair_report soup;
    const std::string error = MR::read_mesh(argv[1], mesh, soup);
    if (!error.empty()) {
      std::cerr << error << '\n';
      return 2;
    }
  } else {
    mesh = defective_sphere();
  }
  const std::string output = argc > 2 ? argv[2] : "automatic_repair_out.off";

  // Every parameter has a default (doc/automatic_repair.md); the two given here are defaults too,
  // spelled out: the automatic method sequence (with its fallbacks) per hole, and the counts of
  // self-intersections before and after that guard stitching and filling.
  const MR::Repair_result result = MR::automatic_repair(
      mesh,
      MR::parameters::fill_method(MR::Fill_method::automatic).detect_self_intersections(true));
  print_summary(result);

  const std::string error = MR::write_mesh(output, mesh);
  if (!error.empty()) {
    std::cerr << error << '\n';
    return 2;
  }
  std::cout << "written: " << output << '\n';
  return result.complete() ? 0 : 1;
}
