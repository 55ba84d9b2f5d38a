// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of hole filling: the advancing front (hole_filling/advancing_front.h) against CGAL's
// triangulate_refine_and_fair_hole (Liepa) on the same holes, for 50 to 2000 border edges.
// The hole is the inner border of a curved annulus (z = 0.15 (x^2 + y^2), three rings of
// triangles around a circle of N border vertices), so both methods see the same border and the
// same surroundings and the mesh copy outside the timed region is cheap. Each method is timed
// alone (no dispatcher check), on a fresh copy per iteration; `fill_hole_advancing_front` checks
// its own patch exactly (it must, to choose between its fallbacks): by the front's own exact
// tests when they cover the patch (`Front_triangulation::exactly_checked`, the case here), by
// the whole-mesh check otherwise. BM_advancing_front_unchecked turns the whole-mesh check off
// (so it differs only when the front's tests do not cover the patch). CGAL's function is called
// directly: its time contains nothing of ours.
// Results and the command: doc/benchmarks.md, section "fill_holes (advancing front vs Liepa)".
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/hole_filling/advancing_front.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <iterator>
#include <vector>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

/// Three rings of triangles outside a circle of radius 1 with `n` vertices on each ring; the
/// inner circle is the hole's border. Returns a border halfedge of the hole.
Mesh::Halfedge_index make_curved_annulus(Mesh& mesh, int n) {
  const double step = 2 * CGAL_PI / n;
  const int rings = 4;
  std::vector<std::vector<Mesh::Vertex_index>> ring(rings);
  for (int k = 0; k < rings; ++k) {
    const double radius = 1.0 + k * step;
    for (int i = 0; i < n; ++i) {
      const double angle = (i + 0.5 * (k % 2)) * step;
      const double x = radius * std::cos(angle), y = radius * std::sin(angle);
      ring[k].push_back(mesh.add_vertex(Point(x, y, 0.15 * (x * x + y * y))));
    }
  }
  for (int k = 0; k + 1 < rings; ++k) {
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      if (k % 2 == 0) {
        mesh.add_face(ring[k][i], ring[k + 1][i], ring[k][j]);
        mesh.add_face(ring[k][j], ring[k + 1][i], ring[k + 1][j]);
      } else {
        mesh.add_face(ring[k][i], ring[k + 1][j], ring[k][j]);
        mesh.add_face(ring[k][i], ring[k + 1][i], ring[k + 1][j]);
      }
    }
  }
  const auto h = mesh.halfedge(ring[0][0], ring[0][1]);
  return mesh.is_border(h) ? h : mesh.opposite(h);
}

/// Mean length of the patch's edges over the mean length of the hole's border edges: 1 when the
/// patch is as dense as its surroundings (thesis 4.4), below 1 when it is denser.
double mean_edge_ratio(const Mesh& filled, const std::vector<Mesh::Face_index>& faces,
                       const Mesh& original, Mesh::Halfedge_index border) {
  const auto length = [](const Mesh& m, Mesh::Halfedge_index h) {
    return std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))));
  };
  double border_sum = 0, patch_sum = 0;
  std::size_t border_count = 0, patch_count = 0;
  for (auto h : CGAL::halfedges_around_face(border, original)) {
    border_sum += length(original, h);
    ++border_count;
  }
  for (auto f : faces) {
    for (auto h : CGAL::halfedges_around_face(filled.halfedge(f), filled)) {
      patch_sum += length(filled, h);
      ++patch_count;
    }
  }
  if (patch_count == 0) return 0;
  return (patch_sum / double(patch_count)) / (border_sum / double(border_count));
}

template <class Fill>
void run(benchmark::State& state, Fill fill) {
  Mesh original;
  const auto border = make_curved_annulus(original, int(state.range(0)));
  std::vector<Mesh::Face_index> faces;
  Mesh mesh;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = original;
    state.ResumeTiming();
    faces = fill(mesh, border);
    benchmark::DoNotOptimize(faces.data());
  }
  state.counters["border_edges"] = double(state.range(0));
  state.counters["faces_created"] = double(faces.size());
  state.counters["edge_ratio"] = mean_edge_ratio(mesh, faces, original, border);
}

void BM_advancing_front(benchmark::State& state) {
  run(state, [](Mesh& mesh, Mesh::Halfedge_index border) {
    MR::Fill_patch<Mesh> patch;
    const auto report = MR::fill_hole_advancing_front(mesh, border, patch);
    return report.filled ? patch.faces : std::vector<Mesh::Face_index>();
  });
}

// The front alone, without the final exact self-intersection check of the patch (the per-triangle
// exact tests of the front stay): what the dispatcher's own check would then cover.
void BM_advancing_front_unchecked(benchmark::State& state) {
  run(state, [](Mesh& mesh, Mesh::Halfedge_index border) {
    MR::Fill_patch<Mesh> patch;
    const auto report = MR::fill_hole_advancing_front(
        mesh, border, patch, MR::parameters::check_self_intersections(false));
    return report.filled ? patch.faces : std::vector<Mesh::Face_index>();
  });
}

void BM_liepa(benchmark::State& state) {
  run(state, [](Mesh& mesh, Mesh::Halfedge_index border) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole(
        mesh, border, std::back_inserter(faces), std::back_inserter(vertices));
    return faces;
  });
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {50, 100, 200, 500, 1000, 2000}) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.5);
}

}  // namespace

BENCHMARK(BM_advancing_front)->Apply(sizes);
BENCHMARK(BM_advancing_front_unchecked)->Apply(sizes);
BENCHMARK(BM_liepa)->Apply(sizes);
BENCHMARK_MAIN();
