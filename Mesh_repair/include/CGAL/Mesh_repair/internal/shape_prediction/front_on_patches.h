// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_FRONT_ON_PATCHES_H
#define CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_FRONT_ON_PATCHES_H

// Thesis 5.6: the shared advancing front (internal/hole_filling/advancing_front_core.h) run with
// the Bezier patch network as its projection: every new node is located on the network by its
// normal projection and barycentric coordinates (eq. 5.31) and moved to the patch point
// (eq. 5.17); the edge length is the mean of the two front edges at the node (eq. 5.32-5.33),
// so the density follows the surrounding mesh; nodes closer than a quarter edge are merged; the
// closing relaxation (umbrella flow) maps every move back onto the patches.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/advancing_front_core.h>
#include <CGAL/Mesh_repair/internal/hole_filling/front_mesh.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/hole_polygon.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/shape_estimate.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
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
void guided_curvature_flow(Front_triangulation& front, const Project& onto_patches,
                           int iterations) {
  const std::size_t count = front.points.size(), first = front.border_points;
  if (iterations <= 0 || count == first) return;
  std::vector<std::vector<std::size_t>> neighbours(count - first), around(count - first);
  for (std::size_t t = 0; t < front.triangles.size(); ++t) {
    const auto& tri = front.triangles[t];
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
    const auto& tri = front.triangles[t];
    const Vec3& a = front.points[tri[0]];
    return normalized(cross(sub(front.points[tri[1]], a), sub(front.points[tri[2]], a)));
  };
  // 1 - cos of the triangle's smallest angle (increasing with that angle).
  auto smallest_angle_measure = [&](std::size_t t) {
    const auto& tri = front.triangles[t];
    double worst = 2;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e1 = normalized(sub(front.points[tri[(k + 1) % 3]], front.points[tri[k]]));
      const Vec3 e2 = normalized(sub(front.points[tri[(k + 2) % 3]], front.points[tri[k]]));
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
      for (std::size_t q : list) centroid = add(centroid, front.points[q]);
      centroid = scale(centroid, 1.0 / double(list.size()));
      const Vec3 old = front.points[p];
      before.clear();
      double quality_before = 2;
      for (std::size_t t : around[p - first]) {
        before.push_back(unit_normal(t));
        quality_before = std::min(quality_before, smallest_angle_measure(t));
      }
      front.points[p] = onto_patches(scale(add(old, centroid), 0.5), hints[p - first]);
      double quality_after = 2;
      bool keep = true;
      for (std::size_t k = 0; k < before.size() && keep; ++k) {
        const std::size_t t = around[p - first][k];
        quality_after = std::min(quality_after, smallest_angle_measure(t));
        keep = dot(before[k], unit_normal(t)) >= 0.5;
      }
      if (!keep || quality_after < quality_before) front.points[p] = old;
    }
  }
}

/// The front's layers compress (as in fill_hole_advancing_front, doc/advancing_front.md,
/// "Patch density"): asked for the border's mean edge, the patches of the 126 holes of the
/// "Hole filling I" table had a median 1.06 faces per face removed. Asking for 1.08 times it
/// gives 1.00, the density of the surroundings, with a lower median Einf (0.00607 against
/// 0.00624) in 0.80 of the time; 1.15 (the flat front's factor) gave 0.77, too coarse
/// (doc/shape_prediction.md, "Patch density").
constexpr double patch_front_spacing_factor = 1.08;

/// The advancing front over the patch network of `estimate`, then the guided flow. The edge
/// length is eq. 5.32-5.33's times `size_factor`; `close_remnant` closes the loops of a stuck
/// front with the front's checked minimum-area triangulation.
template <class Kernel>
Front_triangulation mesh_on_patches(const Shape_estimate<Kernel>& estimate,
                                    const Front_input& input, double mean_length,
                                    int flow_iterations, double size_factor = 1.0,
                                    bool close_remnant = false) {
  using Point_3 = typename Kernel::Point_3;
  const Bezier_patch_network<Kernel>& network = *estimate.patches;
  // New nodes of the front: eq. 5.31 then 5.17 (`map`).
  Front_projection onto_patches = [&network](const Vec3& p, const Vec3&) {
    return as_vec3(network.map(Point_3(p[0], p[1], p[2])));
  };
  // Eq. 5.32-5.33: the mean of the two front edges at the node, bounded as in advancing_front
  // so that the density stays that of the surrounding mesh.
  Front_size front_edges_mean = [mean_length, size_factor](const Vec3&, double adjacent) {
    return patch_front_spacing_factor * size_factor *
           std::clamp(adjacent, 0.5 * mean_length, 2.0 * mean_length);
  };
  Front_options front_options;
  // Thesis 5.6 step 4 merges within a quarter edge; with the shared front that lets facing
  // fronts pass each other without merging (the sphere of Fig. 5.15 does not close), so the
  // front's own half edge is kept.
  front_options.merge_factor = 0.5;
  front_options.smoothing_iterations = 0;  // the guided flow below replaces it
  front_options.close_remnant = close_remnant;
  Front_triangulation front = advance_front(input, onto_patches, front_edges_mean, front_options);
  if (front.closed)
    // Foot points on the patches: `map` would move a node that is already on them (by the
    // difference between a patch and its flat triangle's parametrisation) and the nodes would
    // drift a little at every pass.
    guided_curvature_flow(
        front,
        [&network](const Vec3& p, std::size_t& hint) {
          return as_vec3(network.project(Point_3(p[0], p[1], p[2]), hint));
        },
        flow_iterations);
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
template <class Kernel, class PolygonMesh, class VertexPointMap>
Hole_fill_report fill_hole(PolygonMesh& pm, VertexPointMap vpm,
                           typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                           Fill_patch<PolygonMesh>& patch, const Shape_estimate_options& options,
                           int flow_iterations) {
  Hole_fill_report report;
  report.requested = report.used = Fill_method::shape_prediction;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> border, point_vertices;
  const Hole_polygon<Kernel> hole = read_hole_polygon<Kernel>(h, pm, vpm, border);
  const Front_input input = front_input_from_border(pm, vpm, h, point_vertices);
  const double mean_length = cycle_geometry(h, pm, vpm).mean_edge_length;

  Shape_estimate_options attempt = options;
  Front_triangulation front;
  std::optional<Shape_estimate<Kernel>> estimate;
  for (int round = 0; round < 2; ++round) {
    estimate.emplace(estimate_shape(hole, attempt));
    if (!estimate->ok) {
      report.failure = "shape estimate: " + estimate->failure;
      return report;
    }
    report.notes.push_back(describe_estimate(*estimate, hole.points.size()));
    front = mesh_on_patches(*estimate, input, mean_length, flow_iterations);
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
      front = mesh_on_patches(*estimate, input, mean_length, flow_iterations, r.factor, r.remnant);
      if (front.closed) {
        report.notes.push_back("front on the patches stuck (" + first_failure + "); closed " +
                               (r.remnant ? std::string("with its last loops triangulated")
                                          : "with edge length x " + std::to_string(r.factor)));
        break;
      }
    }
  }
  if (!front.closed) {
    report.failure = "advancing front on the patches: " + front.failure;
    return report;
  }
  if (!insert_front_triangulation(pm, vpm, front, point_vertices, patch)) {
    report.failure = "a triangle of the front could not be added (non-manifold)";
    return report;
  }
  report.filled = true;
  report.faces_created = patch.faces.size();
  report.vertices_created = patch.vertices.size();
  return report;
}

}  // namespace shape_prediction
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_FRONT_ON_PATCHES_H
