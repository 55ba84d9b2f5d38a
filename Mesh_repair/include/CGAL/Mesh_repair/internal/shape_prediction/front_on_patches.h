// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_FRONT_ON_PATCHES_H
#define CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_FRONT_ON_PATCHES_H

// Thesis 5.6: the shared advancing front (internal/hole_filling/advancing_front_core.h) run with
// the Bezier patch network as its projection: every new node is located on the network by its
// normal projection (eq. 5.31) and moved to the patch point on that normal line
// (`Bezier_patch_network::map`); the edge length follows the border's edges, so the density is
// that of the surrounding mesh (eq. 5.32-5.33 take the two front edges at the node, which
// shrink layer after layer); close nodes are merged; the closing relaxation (umbrella flow)
// maps every move back onto the patches and is tested exactly like the front's fans.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/advancing_front_core.h>
#include <CGAL/Mesh_repair/internal/hole_filling/front_mesh.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/hole_polygon.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/shape_estimate.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace shape_prediction {

template <class Point>
Vec3 as_vec3(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

/// Thesis 5.6 step 8: umbrella (uniform mean-curvature) flow of the new nodes with the patches
/// as guiding surface: each node moves half-way to its neighbours' centroid and is projected
/// back onto the patches by `onto_patches(point, hint)` (`hint`: the node's own slot, which the
/// projection may use to start from where the node's previous projection ended). A move is kept
/// only when every triangle around the node keeps its orientation (its normal turns by less than 60
/// degrees), so the flow cannot fold the patch, and when the smallest angle of those triangles does
/// not decrease (a "smart" Laplacian: the flow can only improve the worst triangle around each
/// node, and the patch's smallest angle never decreases).
template <class Project>
void guided_curvature_flow(std::vector<Vec3>& points,
                           const std::vector<std::array<std::size_t, 3>>& triangles,
                           std::size_t first, const Project& onto_patches, int iterations) {
  const std::size_t count = points.size();
  if (iterations <= 0 || count == first) return;
  std::vector<std::vector<std::size_t>> neighbours(count - first), around(count - first);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < first) continue;
      around[tri[k] - first].push_back(t);
      auto& list = neighbours[tri[k] - first];
      for (int j = 1; j < 3; ++j)
        if (std::find(list.begin(), list.end(), tri[(k + j) % 3]) == list.end())
          list.push_back(tri[(k + j) % 3]);
    }
  }
  auto unit_normal = [&](std::size_t t) {
    const auto& tri = triangles[t];
    const Vec3& a = points[tri[0]];
    return normalized(cross(sub(points[tri[1]], a), sub(points[tri[2]], a)));
  };
  // 1 - cos of the triangle's smallest angle (increasing with that angle).
  auto smallest_angle_measure = [&](std::size_t t) {
    const auto& tri = triangles[t];
    double worst = 2;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e1 = normalized(sub(points[tri[(k + 1) % 3]], points[tri[k]]));
      const Vec3 e2 = normalized(sub(points[tri[(k + 2) % 3]], points[tri[k]]));
      worst = std::min(worst, 1 - dot(e1, e2));
    }
    return worst;
  };
  std::vector<Vec3> before;
  // Per node: the patch of its last projection, where the next one starts.
  std::vector<std::size_t> hints(count - first, std::size_t(-1));
  for (int iteration = 0; iteration < iterations; ++iteration) {
    for (std::size_t p = first; p < count; ++p) {
      const auto& list = neighbours[p - first];
      if (list.empty()) continue;
      Vec3 centroid{0, 0, 0};
      for (std::size_t q : list) centroid = add(centroid, points[q]);
      centroid = scale(centroid, 1.0 / double(list.size()));
      const Vec3 old = points[p];
      before.clear();
      double quality_before = 2;
      for (std::size_t t : around[p - first]) {
        before.push_back(unit_normal(t));
        quality_before = std::min(quality_before, smallest_angle_measure(t));
      }
      points[p] = onto_patches(scale(add(old, centroid), 0.5), hints[p - first]);
      double quality_after = 2;
      bool keep = true;
      for (std::size_t k = 0; k < before.size() && keep; ++k) {
        const std::size_t t = around[p - first][k];
        quality_after = std::min(quality_after, smallest_angle_measure(t));
        keep = dot(before[k], unit_normal(t)) >= 0.5;
      }
      if (!keep || quality_after < quality_before) points[p] = old;
    }
  }
}

/// `guided_curvature_flow` on a closed front.
template <class Project>
void guided_curvature_flow(Front_triangulation& front, const Project& onto_patches,
                           int iterations) {
  guided_curvature_flow(front.points, front.triangles, front.border_points, onto_patches,
                        iterations);
}

/// The front's layers compress (as in fill_hole_advancing_front, doc/advancing_front.md,
/// "Patch density"). Asking for 1.08 times the border's edge lengths gives 1.00 faces per face
/// removed on the 126 holes of the "Hole filling I" table, the density of the surroundings;
/// 1.15 (the flat front's factor) gave 0.96 with a higher median Einf (0.00661 against
/// 0.00625; doc/shape_prediction.md, "Normal-line mapping").
constexpr double patch_front_spacing_factor = 1.08;

/// The advancing front over the patch network of `estimate`, then the guided flow. The edge
/// length is the border's (`border_density`) times `size_factor`; `close_remnant` closes the
/// loops of a stuck front with the front's checked minimum-area triangulation.
template <class Kernel>
Front_triangulation mesh_on_patches(const Shape_estimate<Kernel>& estimate,
                                    const Front_input& input, int flow_iterations,
                                    double size_factor = 1.0, bool close_remnant = false) {
  using Point_3 = typename Kernel::Point_3;
  const Bezier_patch_network<Kernel>& network = *estimate.patches;
  // New nodes of the front: eq. 5.31, then the patch point on the normal line (`map`).
  Front_projection onto_patches = [&network](const Vec3& p, const Vec3&) {
    return as_vec3(network.map(Point_3(p[0], p[1], p[2])));
  };
  // Eq. 5.32-5.33 take the mean of the two front edges at the node; those shrink layer after
  // layer on a closing front, so the size follows the border's edge lengths instead, as in
  // fill_hole_advancing_front (doc/shape_prediction.md, "Normal-line mapping").
  const Front_size size = border_density(input, patch_front_spacing_factor * size_factor);
  Front_options front_options;
  // Thesis 5.6 step 4 merges within a quarter edge; with the shared front that lets facing
  // fronts pass each other without merging (the sphere of Fig. 5.15 does not close), so the
  // front's own half edge is kept.
  front_options.merge_factor = 0.5;
  // Thesis 5.6 step 8 as the front's relaxation, so that the front tests the smoothed patch
  // again (exactly, against itself and the mesh around the hole) and puts the nodes back where
  // it created them if the flow made two triangles meet: the patch stays exactly checked.
  // Foot points on the patches (`project`, warm-started per node) rather than `map`: a move
  // goes to the nearest point of the patches, not along the normal of a flat triangle.
  front_options.smoothing_iterations = flow_iterations;
  front_options.relaxation = [&network, flow_iterations](
                                 std::vector<Vec3>& points,
                                 const std::vector<std::array<std::size_t, 3>>& triangles,
                                 std::size_t first_new) {
    guided_curvature_flow(
        points, triangles, first_new,
        [&network](const Vec3& p, std::size_t& hint) {
          return as_vec3(network.project(Point_3(p[0], p[1], p[2]), hint));
        },
        flow_iterations);
  };
  front_options.undo_failed_relaxation = true;
  front_options.close_remnant = close_remnant;
  front_options.size_from_position_only = true;
  Front_triangulation front = advance_front(input, onto_patches, size, front_options);
  return front;
}

template <class Kernel>
std::string describe_estimate(const Shape_estimate<Kernel>& estimate, std::size_t border_nodes) {
  std::ostringstream note;
  note << "GA on " << estimate.essential.size() << " of " << border_nodes
       << " border nodes: fitness " << estimate.ga.fitness << " (seed " << estimate.ga.seed_fitness
       << ") after " << estimate.ga.generations << " generations";
  return note.str();
}

/// The whole method on one hole (see hole_filling/shape_prediction.h). When the front does not
/// close over the patches of the simplified estimate, the estimate is rebuilt from every border
/// node (the simplified polygon's long chords can make thin patches) and the front runs again.
template <class Kernel, class PolygonMesh, class VertexPointMap, class FaceBoxCache>
Hole_fill_report fill_hole(PolygonMesh& pm, VertexPointMap vpm,
                           typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                           Fill_patch<PolygonMesh>& patch, const Shape_estimate_options& options,
                           int flow_iterations, FaceBoxCache* face_boxes) {
  Hole_fill_report report;
  report.requested = report.used = Fill_method::shape_prediction;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> border, point_vertices;
  const Hole_polygon<Kernel> hole = read_hole_polygon<Kernel>(h, pm, vpm, border);
  const Front_input input = front_input_from_border(pm, vpm, h, point_vertices, face_boxes);

  Shape_estimate_options attempt = options;
  Front_triangulation front;
  std::optional<Shape_estimate<Kernel>> estimate;
  // Where the time goes, for the report: estimates (GA and patches) and fronts on the patches.
  using Clock = std::chrono::steady_clock;
  Clock::duration estimate_time{}, front_time{};
  auto timed = [](Clock::duration& total, auto&& step) {
    const auto start = Clock::now();
    step();
    total += Clock::now() - start;
  };
  auto run_front = [&](double factor, bool remnant) {
    timed(front_time,
          [&] { front = mesh_on_patches(*estimate, input, flow_iterations, factor, remnant); });
  };
  auto time_note = [&] {  // as long whatever the times (see seconds_text in fill_holes.h)
    char note[96];
    std::snprintf(note, sizeof note, "time: shape estimate %.2e s, front on the patches %.2e s",
                  std::chrono::duration<double>(estimate_time).count(),
                  std::chrono::duration<double>(front_time).count());
    return std::string(note);
  };
  for (int round = 0; round < 2; ++round) {
    timed(estimate_time, [&] { estimate.emplace(estimate_shape(hole, attempt)); });
    if (!estimate->ok) {
      report.failure = "shape estimate: " + estimate->failure;
      return report;
    }
    report.notes.push_back(describe_estimate(*estimate, hole.points.size()));
    run_front(1.0, false);
    if (front.closed || !attempt.simplify) break;
    report.notes.push_back("front on the simplified estimate failed (" + front.failure +
                           "); estimate rebuilt from every border node");
    attempt.simplify = false;
  }
  if (!front.closed) {
    // A stuck front depends on where its layers happened to meet: other edge lengths meet
    // elsewhere; finally the last loops are closed by the front's checked minimum-area
    // triangulation (then smoothed on the patches like the rest).
    struct Retry {
      double factor;
      bool remnant;
    };
    const std::string first_failure = front.failure;
    for (const Retry& r : {Retry{0.7, false}, Retry{1.4, false}, Retry{1.0, true}}) {
      run_front(r.factor, r.remnant);
      if (front.closed) {
        report.notes.push_back("front on the patches stuck (" + first_failure + "); closed " +
                               (r.remnant ? std::string("with its last loops triangulated")
                                          : "with edge length x " + std::to_string(r.factor)));
        break;
      }
    }
  }
  report.notes.push_back(time_note());
  if (!front.closed) {
    report.failure = "advancing front on the patches: " + front.failure;
    return report;
  }
  if (!insert_front_triangulation(pm, vpm, front, point_vertices, patch)) {
    report.failure = "a triangle of the front could not be added (non-manifold)";
    return report;
  }
  report.filled = true;
  report.exactly_checked = front.exactly_checked;
  report.faces_created = patch.faces.size();
  report.vertices_created = patch.vertices.size();
  return report;
}

}  // namespace shape_prediction
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_FRONT_ON_PATCHES_H
