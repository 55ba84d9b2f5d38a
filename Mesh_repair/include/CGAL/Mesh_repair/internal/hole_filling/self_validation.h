// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_SELF_VALIDATION_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_SELF_VALIDATION_H

// Per-hole self-validation: the known surroundings choose the method. On a copy of the hole's
// neighbourhood the hole is enlarged by removing the faces within `rings` vertex rings of its
// border; each candidate fills the enlarged hole, and the removed faces, which are known, measure
// how well it predicted them. The candidates are then tried on the real hole in the order of
// that error (doc/fill_holes.md, "Self-validated choice"). No peer validates per hole: CGAL and
// pmp apply one fairing to every hole, and which fairing is best changes from hole to hole
// (issue 19: the per-case ratio of shape prediction to CGAL's C1 fairing spans 0.34 to 2.21).

#include <CGAL/Mesh_repair/hole_filling/fill_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/finite_distance_traits.h>
#include <CGAL/Mesh_repair/internal/hole_filling/local_region.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// One method with its fairing continuity (Liepa's; -1 for the method's own options). In a
/// sequence the advancing front hands a stuck front over to the next method, unless
/// `close_stuck_front` (then it closes the remnant itself, see doc/advancing_front.md).
struct Fill_candidate {
  Fill_method method;
  int continuity;
  bool close_stuck_front = false;
  std::string name() const {
    if (close_stuck_front) return std::string(to_string(method)) + " (remnant closed)";
    return continuity < 0 ? to_string(method)
                          : std::string(to_string(method)) + "_c" + std::to_string(continuity);
  }
  Fill_options options(const Fill_options& base) const {
    Fill_options o = base;
    if (continuity >= 0) o.liepa.fairing_continuity = continuity;
    return o;
  }
};

/// The candidates, in the order used where no validation is possible: the order of their median
/// errors on the tuning suite (doc/benchmarks.md, "Hole filling fidelity").
inline std::vector<Fill_candidate> self_validation_candidates() {
  return {{Fill_method::shape_prediction, -1},
          {Fill_method::liepa, 1},
          {Fill_method::curvature_variation, -1},
          {Fill_method::liepa, 2}};
}

/// A hole enlarged on a copy: the copy, a border halfedge of the enlarged hole, and points of
/// the removed (known) faces.
template <class Point>
struct Enlarged_hole {
  CGAL::Surface_mesh<Point> mesh;
  typename CGAL::Surface_mesh<Point>::Halfedge_index border;
  std::vector<Point> truth;
  int rings = 0;  ///< by how many rings the hole was enlarged
  bool usable = false;
};

/// True when the faces of `removed` around `v` (the hole's border counting as removed) form
/// two or more separate arcs: removing them would pinch the enlarged hole at `v`.
template <class Point, class FaceSet>
bool pinched_by(
    const CGAL::Surface_mesh<Point>& mesh, typename CGAL::Surface_mesh<Point>::Vertex_index v,
    const FaceSet& removed,
    const std::unordered_set<typename CGAL::Surface_mesh<Point>::Halfedge_index>& hole) {
  std::vector<bool> in;
  for (auto around : halfedges_around_target(halfedge(v, mesh), mesh))
    in.push_back(is_border(around, mesh) ? hole.count(around) > 0
                                         : removed.count(face(around, mesh)) > 0);
  std::size_t arcs = 0;
  for (std::size_t i = 0; i < in.size(); ++i)
    if (in[i] && !in[(i + in.size() - 1) % in.size()]) ++arcs;
  return arcs > 1;
}

/// The faces within `rings` vertex rings of the cycle of `h`, grown by the whole star of every
/// vertex they would pinch, and never a face touching another border, so that the enlarged hole
/// stays one simple cycle on irregular and jagged borders and beside other holes. (Without
/// the growth and the stop, 22 of the 90 disc holes of the tuning suite could not be enlarged
/// by 2 rings, and none by 4; with them, 6 are left.)
template <class Point>
std::unordered_set<typename CGAL::Surface_mesh<Point>::Face_index> faces_within_rings(
    const CGAL::Surface_mesh<Point>& mesh, typename CGAL::Surface_mesh<Point>::Halfedge_index h,
    int rings) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using vertex_descriptor = typename Mesh::Vertex_index;
  std::unordered_set<typename Mesh::Face_index> removed;
  std::unordered_set<typename Mesh::Halfedge_index> hole;
  std::unordered_set<vertex_descriptor> reached, on_other_border;
  std::vector<vertex_descriptor> layer;
  for (auto b : cycle_halfedges(h, mesh)) {
    hole.insert(b);
    if (reached.insert(target(b, mesh)).second) layer.push_back(target(b, mesh));
  }
  for (auto b : halfedges(mesh))
    if (is_border(b, mesh) && !hole.count(b)) on_other_border.insert(target(b, mesh));
  // Faces touching another border (a neighbouring hole, the edge of the copy) stay: the
  // enlarged hole must not merge with it.
  const auto removable = [&](typename Mesh::Face_index f) {
    for (vertex_descriptor w : vertices_around_face(halfedge(f, mesh), mesh))
      if (on_other_border.count(w)) return false;
    return true;
  };
  // Removes the star of `v`; the corners of its faces go to `next` (new ones only, unless
  // `all`, since removing faces changes the arcs around every corner).
  const auto remove_star = [&](vertex_descriptor v, std::vector<vertex_descriptor>& next,
                               bool all) {
    for (auto f : faces_around_target(halfedge(v, mesh), mesh))
      if (f != Mesh::null_face() && removable(f) && removed.insert(f).second)
        for (vertex_descriptor w : vertices_around_face(halfedge(f, mesh), mesh))
          if (reached.insert(w).second || all) next.push_back(w);
  };
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<vertex_descriptor> next;
    for (vertex_descriptor v : layer) remove_star(v, next, false);
    layer.swap(next);
  }
  // Every star removed for a pinch removes at least one face, and queues at most three corners
  // per face: the work is linear in the copy's size.
  std::vector<vertex_descriptor> queue(reached.begin(), reached.end());
  while (!queue.empty()) {
    const vertex_descriptor v = queue.back();
    queue.pop_back();
    if (pinched_by(mesh, v, removed, hole)) remove_star(v, queue, true);
  }
  return removed;
}

/// Removes the faces within `rings` vertex rings of the border of the cycle of `h`
/// (`faces_within_rings`); records the removed vertices and face centroids in `truth`. False
/// when the enlarged hole is not one simple cycle apart from the other borders of the copy (it
/// met another border, enclosed kept faces, or pinched).
template <class Point>
bool remove_border_rings(CGAL::Surface_mesh<Point>& mesh,
                         typename CGAL::Surface_mesh<Point>::Halfedge_index& h, int rings,
                         std::vector<Point>& truth) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using vertex_descriptor = typename Mesh::Vertex_index;
  const std::size_t other_border = count_border_halfedges(mesh) - cycle_halfedges(h, mesh).size();
  const auto within = faces_within_rings(mesh, h, rings);
  std::vector<typename Mesh::Face_index> faces(within.begin(), within.end());
  std::sort(faces.begin(), faces.end());  // the same truth, summed in the same order, anywhere
  std::vector<vertex_descriptor> touched;
  for (auto f : faces) {
    typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 sum(0, 0, 0);
    int n = 0;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) {
      sum = sum + (mesh.point(v) - CGAL::ORIGIN);
      touched.push_back(v);
      ++n;
    }
    truth.push_back(CGAL::ORIGIN + sum / double(n));
  }
  std::vector<Point> positions;
  for (vertex_descriptor v : touched) positions.push_back(mesh.point(v));
  for (auto f : faces) CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
  h = Mesh::null_halfedge();
  std::unordered_set<vertex_descriptor> recorded;
  for (std::size_t i = 0; i < touched.size(); ++i) {
    const vertex_descriptor v = touched[i];
    if (mesh.is_removed(v)) {
      if (recorded.insert(v).second) truth.push_back(positions[i]);
    } else if (h == Mesh::null_halfedge()) {
      for (auto around : halfedges_around_target(v, mesh))
        if (is_border(around, mesh)) h = around;
    }
  }
  if (h == Mesh::null_halfedge()) return false;
  const std::vector<typename Mesh::Halfedge_index> cycle = cycle_halfedges(h, mesh);
  if (count_border_halfedges(mesh) != other_border + cycle.size()) return false;
  std::unordered_set<vertex_descriptor> on_cycle;
  for (auto b : cycle)
    if (!on_cycle.insert(target(b, mesh)).second) return false;  // pinched
  return true;
}

/// The hole of `outer` enlarged on a copy of its neighbourhood by `rings` rings, or by fewer
/// where that many would not give one simple cycle (holes a ring or two apart, as in scans).
template <class PolygonMesh, class VertexPointMap, class Point>
void enlarge_hole(const PolygonMesh& pm, VertexPointMap vpm,
                  typename boost::graph_traits<PolygonMesh>::halfedge_descriptor outer, int rings,
                  Enlarged_hole<Point>& enlarged) {
  Local_region<PolygonMesh, Point> region;
  Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> group{outer, {}};
  const Face_box_cache<PolygonMesh, VertexPointMap>* no_obstacles = nullptr;
  copy_local_region(pm, vpm, group, no_obstacles, region, local_region_ring_depth + rings);
  if (!region.usable) return;
  for (int r = rings; r >= 1 && !enlarged.usable; --r) {
    enlarged.mesh = region.mesh;
    enlarged.border = region.group.outer;
    enlarged.truth.clear();
    enlarged.rings = r;
    enlarged.usable = remove_border_rings(enlarged.mesh, enlarged.border, r, enlarged.truth);
  }
}

/// Root mean square distance of `truth` to the faces of `patch`.
template <class Point>
double rms_distance_to_patch(
    const CGAL::Surface_mesh<Point>& mesh,
    const std::vector<typename CGAL::Surface_mesh<Point>::Face_index>& patch,
    const std::vector<Point>& truth) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  Distance_tree<Kernel, Primitive> tree(patch.begin(), patch.end(), mesh);
  double sum = 0;
  for (const Point& p : truth) sum += CGAL::to_double(tree.squared_distance(p));
  return std::sqrt(sum / double(std::max<std::size_t>(1, truth.size())));
}

/// `candidates` sorted by `error` (stable: ties keep the default order); `note` lists them.
inline std::vector<Fill_candidate> order_by_error(const std::vector<Fill_candidate>& candidates,
                                                  const std::vector<double>& error,
                                                  const std::string& heading, std::string& note) {
  std::vector<std::size_t> order(candidates.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return error[a] < error[b]; });
  std::vector<Fill_candidate> ranked;
  note = heading;
  for (std::size_t k : order) {
    ranked.push_back(candidates[k]);
    char value[32];
    std::snprintf(value, sizeof value, " %.3g", error[k]);
    note += " " + candidates[k].name() + (std::isfinite(error[k]) ? value : " (failed)");
  }
  return ranked;
}

/// The candidates in increasing order of their error on the enlarged hole; candidates that could
/// not fill it come last, in their default order. `note` says what was measured.
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class FillOneHole>
std::vector<Fill_candidate> rank_fill_candidates(
    const PolygonMesh& pm, VertexPointMap vpm, const GeomTraits&,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor outer,
    const Fill_options& options, int rings, const FillOneHole& fill_one, std::string& note) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Local_mesh = CGAL::Surface_mesh<Point>;
  std::vector<Fill_candidate> candidates = self_validation_candidates();
  Enlarged_hole<Point> enlarged;
  enlarge_hole(pm, vpm, outer, rings, enlarged);
  if (!enlarged.usable) {
    note = "self-validation: the hole could not be enlarged by 1 to " + std::to_string(rings) +
           " ring(s) (it meets another border or pinches); default order";
    return candidates;
  }
  std::vector<double> error(candidates.size(), std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    Local_mesh trial = enlarged.mesh;
    Fill_patch<Local_mesh> patch;
    const Hole_fill_report report =
        fill_one(candidates[k], trial, enlarged.border, candidates[k].options(options), patch);
    if (report.filled && !patch.faces.empty())
      error[k] = rms_distance_to_patch(trial, patch.faces, enlarged.truth);
  }
  return order_by_error(candidates, error,
                        "self-validation on the hole enlarged by " +
                            std::to_string(enlarged.rings) + " ring(s), RMS error:",
                        note);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_SELF_VALIDATION_H
