// Speed of automatic_repair on a large scan-like mesh: a sphere of 1,310,720 faces (icosahedron
// split 8 times) jittered like a scan, with 100 disc holes punched at deterministic places.
// Prints time per step and peak memory for 1 and 2 threads, as markdown rows.
//   build/bin/bench_repair [subdivisions=8] [holes=100]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>
#include <sys/resource.h>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

Mesh holed_sphere(int subdivisions, int holes) {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, subdivisions);
  std::mt19937 random(7);
  std::normal_distribution<double> jitter(0.0, 1e-4);
  for (auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    const double s = 1.0 + jitter(random);
    mesh.point(v) = Point(p.x() * s, p.y() * s, p.z() * s);
  }
  // Hole centres: a Fibonacci lattice on the sphere, so holes never touch each other.
  const double radius = 0.06;
  std::vector<Mesh::Face_index> doomed;
  std::vector<Point> centres;
  for (int i = 0; i < holes; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / holes, r = std::sqrt(1 - z * z);
    const double phi = i * CGAL_PI * (3.0 - std::sqrt(5.0));
    centres.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  for (auto f : mesh.faces()) {
    const Point& p = mesh.point(mesh.target(mesh.halfedge(f)));
    for (const Point& c : centres)
      if (CGAL::squared_distance(p, c) < radius * radius) {
        doomed.push_back(f);
        break;
      }
  }
  for (auto f : doomed) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  mesh.collect_garbage();
  return mesh;
}

/// Same vertex positions and same faces (corners by index), element for element.
bool same_mesh(const Mesh& a, const Mesh& b) {
  if (a.number_of_vertices() != b.number_of_vertices() ||
      a.number_of_faces() != b.number_of_faces())
    return false;
  for (auto v : a.vertices())
    if (a.point(v) != b.point(v)) return false;
  for (auto f : a.faces()) {
    auto corner = vertices_around_face(b.halfedge(f), b).begin();
    for (auto v : vertices_around_face(a.halfedge(f), a))
      if (v != *corner++) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const int subdivisions = argc > 1 ? std::atoi(argv[1]) : 8;
  const int holes = argc > 2 ? std::atoi(argv[2]) : 100;
  const Mesh input = holed_sphere(subdivisions, holes);
  std::cout << "input: " << num_faces(input) << " faces, " << holes << " holes\n\n";
  Mesh one_thread;
  for (int threads : {1, 2}) {
    Mesh mesh = input;
    const auto start = std::chrono::steady_clock::now();
    const auto result = MR::automatic_repair(mesh, MR::parameters::number_of_threads(threads));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "threads " << threads << ": " << seconds << " s total, " << result.holes.filled
              << " holes filled, " << (result.closed ? "closed" : "open") << ", "
              << (result.valid ? "valid" : "INVALID") << ", peak memory " << peak_memory_mib()
              << " MiB\n| step | seconds |\n|---|---|\n";
    std::size_t in_place = 0;  // patches of the parallel copies rejected in the mesh
    for (const auto& hole : result.holes.holes)
      for (const auto& note : hole.notes)
        if (note.find("filled in place") != note.npos && in_place++ == 0)
          std::cout << "first: " << note << '\n';
    std::cout << in_place << " hole(s) refilled in place\n";
    for (const auto& step : result.steps)
      std::cout << "| " << step.name << " | " << step.seconds << " |\n";
    std::cout << '\n';
    if (threads == 1)
      one_thread = mesh;
    else
      std::cout << "2 threads " << (same_mesh(one_thread, mesh) ? "identical to" : "DIFFER from")
                << " 1 thread\n";
  }
  return 0;
}
