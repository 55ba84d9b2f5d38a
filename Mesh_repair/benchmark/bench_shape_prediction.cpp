// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Timing of shape prediction (thesis chapter 5): (1) the GA triangulation against the polygon
// size, (2) the whole fill against CGAL's triangulate_refine_and_fair_hole as the hole grows.
// Prints markdown rows for doc/benchmarks.md (section shape_prediction).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/hole_filling/liepa.h>
#include <CGAL/Mesh_repair/hole_filling/shape_prediction.h>
#include <CGAL/Mesh_repair/internal/genetic/ga_triangulation.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;
namespace ga = CGAL::Mesh_repair::internal::genetic;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void ga_rows() {
  std::cout << "| polygon nodes | valid chords | chord table s | DP seed s | GA 500 gen s | "
               "seed fitness | GA fitness |\n|---|---|---|---|---|---|---|\n";
  for (int n : {50, 100, 200, 400}) {
    std::vector<Point> points;
    std::vector<Vector> outside;
    for (int i = 0; i < n; ++i) {
      const double t = 2 * CGAL_PI * i / n, r = 1 + 0.25 * std::cos(3 * t);
      const double x = r * std::cos(t), y = r * std::sin(t);
      points.emplace_back(x, y, 0.5 * (x * x - y * y));
    }
    for (int i = 0; i < n; ++i) {
      const Point m = CGAL::midpoint(points[i], points[(i + 1) % n]);
      const Vector nrm(-m.x(), m.y(), 1);
      outside.push_back(nrm / std::sqrt(nrm.squared_length()));
    }
    auto start = Clock::now();
    const ga::Chord_table table = ga::valid_chords<K>(points);
    const double t_table = seconds_since(start);
    start = Clock::now();
    ga::min_dihedral_triangulation<K>(points, outside, table);
    const double t_dp = seconds_since(start);
    ga::Ga_options options;
    options.target_fitness = 1.0;  // never reached: all 500 generations
    options.stall_generations = 0;
    start = Clock::now();
    const auto r = ga::ga_triangulate<K>(points, outside, table, ga::Smoothness_fitness(), options);
    const double t_ga = seconds_since(start) - t_dp;
    std::cout << "| " << n << " | " << table.chords.size() << " | " << t_table << " | " << t_dp
              << " | " << t_ga << " | " << r.seed_fitness << " | " << r.fitness << " |\n";
  }
}

Mesh::Halfedge_index sphere_cap(Mesh& mesh, double degrees) {
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 5);
  std::vector<Mesh::Face_index> cap;
  for (auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Point c = CGAL::centroid(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                   mesh.point(mesh.target(mesh.next(h))));
    if (c.z() > std::cos(degrees * CGAL_PI / 180) * std::sqrt((c - CGAL::ORIGIN).squared_length()))
      cap.push_back(f);
  }
  for (auto f : cap) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  for (auto h : mesh.halfedges())
    if (mesh.is_border(h)) return h;
  return Mesh::null_halfedge();
}

double einf(const Mesh& mesh, const MR::Fill_patch<Mesh>& patch) {
  double worst = 0;
  for (auto v : patch.vertices)
    worst =
        std::max(worst, std::abs(std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length()) - 1));
  return worst / (2 * std::sqrt(3.0));
}

void growth_rows() {
  std::cout << "\n| cap half-angle | border edges | shape_prediction s | Einf/diag | "
               "liepa C1 s | Einf/diag | time ratio |\n|---|---|---|---|---|---|---|\n";
  for (double degrees : {10.0, 20.0, 30.0, 45.0, 60.0}) {
    Mesh a, b;
    const auto ha = sphere_cap(a, degrees), hb = sphere_cap(b, degrees);
    std::size_t edges = 0;
    for (auto h : halfedges_around_face(ha, a)) edges += h != Mesh::null_halfedge() ? 1 : 0;
    MR::Fill_patch<Mesh> pa, pb;
    auto start = Clock::now();
    const auto ra = MR::fill_hole_shape_prediction(a, ha, pa);
    const double ta = seconds_since(start);
    start = Clock::now();
    const auto rb = MR::fill_hole_liepa(b, hb, pb);
    const double tb = seconds_since(start);
    std::cout << "| " << degrees << " | " << edges << " | " << ta << (ra.filled ? "" : " (failed)")
              << " | " << einf(a, pa) << " | " << tb << (rb.filled ? "" : " (failed)") << " | "
              << einf(b, pb) << " | " << ta / tb << " |\n";
  }
}

}  // namespace

int main() {
  ga_rows();
  growth_rows();
  return 0;
}
