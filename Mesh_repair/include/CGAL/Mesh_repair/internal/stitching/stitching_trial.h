// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_STITCHING_STITCHING_TRIAL_H
#define CGAL_MESH_REPAIR_INTERNAL_STITCHING_STITCHING_TRIAL_H

// Stitching that adds no self-intersection (`stitch_gaps` with `check_self_intersections`, and
// the automatic repair's stitching trial). Merging border nodes moves them, and next to thin
// walls, with long border edges or with a tolerance wider than the edges along a crack, that can
// push faces through their neighbours. So the stitching is first run on a copy; while the copy
// has more intersecting pairs than the mesh had, the vertices of the intersecting faces are
// frozen (they neither move nor take T-junction nodes) and the copy is stitched again. The rest
// of the seam is still stitched with the full tolerance.

#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/stitching/run_gap_stitcher.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <iterator>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// What a stitching will do: the tolerance (negative: derived) and the vertices it must leave
/// alone.
template <class PolygonMesh>
struct Stitching_plan {
  double tolerance = -1;
  Vertex_list<PolygonMesh> frozen;
};

/// Stitches `pm` with `settings` at `tolerance` (negative: derived), leaving `frozen` vertices
/// alone; with `t_junction_run`, a second run splits the T-junctions the merges left (the
/// automatic repair's sequence; `stitch_gaps` alone is one run). The first result is the
/// merging run's, the second the T-junction run's (empty without it).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::pair<Stitch_result, Stitch_result> stitch_with_tolerance(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits, Stitch_settings settings,
    double tolerance, bool t_junction_run, const Vertex_list<PolygonMesh>& frozen,
    Any_visitor visitor) {
  std::pair<Stitch_result, Stitch_result> r;
  settings.merge_tolerance = tolerance;
  settings.merge_nodes = true;
  r.first = run_gap_stitcher(pm, vpm, traits, settings, visitor, frozen);
  if (r.first.cancelled || !t_junction_run) return r;
  settings.merge_nodes = false;
  r.second = run_gap_stitcher(pm, vpm, traits, settings, visitor, frozen);
  return r;
}

/// Stitches a copy of `pm` as planned; returns the stitching results, in `pairs` the
/// intersecting face pairs of the copy (0 when nothing changed) and in `intersecting` the
/// vertices of `pm` (frozen ones excluded) of the faces that intersect.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::pair<Stitch_result, Stitch_result> stitch_a_copy(
    const PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
    const Stitch_settings& settings, bool t_junction_run, const Stitching_plan<PolygonMesh>& plan,
    std::size_t& pairs, Vertex_list<PolygonMesh>& intersecting) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  PolygonMesh trial;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> copies;  // (original, copy)
  CGAL::copy_face_graph(pm, trial,
                        parameters::vertex_point_map(vpm).vertex_to_vertex_output_iterator(
                            std::back_inserter(copies)));
  const std::set<vertex_descriptor> frozen(plan.frozen.begin(), plan.frozen.end());
  auto original = get(CGAL::dynamic_vertex_property_t<vertex_descriptor>(), trial);
  for (vertex_descriptor v : vertices(trial))
    put(original, v, boost::graph_traits<PolygonMesh>::null_vertex());
  Vertex_list<PolygonMesh> frozen_copies;
  for (const auto& [v, copy] : copies) {
    put(original, copy, v);
    if (frozen.count(v)) frozen_copies.push_back(copy);
  }
  Default_visitor quiet;
  const auto stitched =
      stitch_with_tolerance(trial, get(CGAL::vertex_point, trial), traits, settings, plan.tolerance,
                            t_junction_run, frozen_copies, Any_visitor(quiet));
  const std::size_t changes = stitched.first.node_merges + stitched.first.t_junctions_split +
                              stitched.second.t_junctions_split;
  pairs = 0;
  intersecting.clear();
  if (changes == 0) return stitched;
  const auto found = bounded_self_intersections(trial).pairs;
  pairs = found.size();
  std::set<vertex_descriptor> seen;
  auto add = [&](vertex_descriptor w) {
    const vertex_descriptor v = get(original, w);  // null: a T-junction node of the copy
    if (v != boost::graph_traits<PolygonMesh>::null_vertex() && !frozen.count(v) &&
        seen.insert(v).second)
      intersecting.push_back(v);
  };
  for (const auto& [f, g] : found)
    for (face_descriptor face : {f, g})
      for (vertex_descriptor w : vertices_around_face(halfedge(face, trial), trial)) add(w);
  // Faces of frozen vertices and T-junction nodes only: the nodes that moved them are one ring
  // further (a T-junction node is merged with the node that hit its edge).
  if (intersecting.empty())
    for (const auto& [f, g] : found)
      for (face_descriptor face : {f, g})
        for (vertex_descriptor w : vertices_around_face(halfedge(face, trial), trial))
          for (vertex_descriptor u : vertices_around_target(halfedge(w, trial), trial)) add(u);
  return stitched;
}

/// One attempt of `freeze_intersecting_stitches`: its tolerance, how many vertices were frozen
/// and how many intersecting pairs it would add.
struct Stitching_attempt {
  double tolerance = 0;
  double min_local_tolerance = 0;
  std::size_t frozen_vertices = 0;
  std::size_t added_pairs = 0;
};

/// Tries the stitching of `plan` on copies of `pm`, freezing the vertices of the faces that
/// intersect, up to `max_rounds` times, until a copy has no more intersecting pairs than
/// `pairs_before`. Returns whether one did (`plan.frozen` then holds the vertices to leave
/// alone); `attempts` records every try.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
bool freeze_intersecting_stitches(const PolygonMesh& pm, VertexPointMap vpm,
                                  const GeomTraits& traits, const Stitch_settings& settings,
                                  bool t_junction_run, std::size_t pairs_before, int max_rounds,
                                  Stitching_plan<PolygonMesh>& plan,
                                  std::vector<Stitching_attempt>& attempts) {
  Vertex_list<PolygonMesh> intersecting;
  for (int round = 0; round <= max_rounds; ++round) {
    std::size_t pairs = 0;
    const auto stitched =
        stitch_a_copy(pm, vpm, traits, settings, t_junction_run, plan, pairs, intersecting);
    Stitching_attempt attempt;
    attempt.tolerance = stitched.first.merge_tolerance;
    attempt.min_local_tolerance = stitched.first.min_local_tolerance;
    attempt.frozen_vertices = plan.frozen.size();
    attempt.added_pairs = pairs > pairs_before ? pairs - pairs_before : 0;
    attempts.push_back(attempt);
    if (attempt.added_pairs == 0) return true;
    if (round == max_rounds || intersecting.empty()) return false;
    plan.frozen.insert(plan.frozen.end(), intersecting.begin(), intersecting.end());
  }
  return false;
}

/// The stitcher on `pm` with the vertex point map, traits and visitor of `np`. With
/// `check_self_intersections` (`stitch_gaps`' parameter): the freezing rounds on copies, then
/// `pm` stitched with the vertices they froze left alone, or left unchanged when every round
/// added intersecting pairs.
template <class PolygonMesh, class NamedParameters>
Stitch_result run_gap_stitcher(PolygonMesh& pm, const Stitch_settings& settings,
                               const NamedParameters& np, bool check_self_intersections) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Geom_traits = typename GetGeomTraits<PolygonMesh, NamedParameters>::type;
  constexpr int max_freezing_rounds = 8;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, pm));
  const Geom_traits traits =
      choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  Visitor_parameter<NamedParameters> visitor(np);
  if (!check_self_intersections) return run_gap_stitcher(pm, vpm, traits, settings, visitor.get());
  const std::size_t pairs_before =
      bounded_self_intersections(faces(pm), pm, 0, parameters::vertex_point_map(vpm)).pairs.size();
  Stitching_plan<PolygonMesh> plan;
  plan.tolerance = settings.merge_tolerance;
  std::vector<Stitching_attempt> attempts;
  const bool found = freeze_intersecting_stitches(pm, vpm, traits, settings, false, pairs_before,
                                                  max_freezing_rounds, plan, attempts);
  Stitch_result result;
  if (found) result = run_gap_stitcher(pm, vpm, traits, settings, visitor.get(), plan.frozen);
  result.self_intersection_rounds = attempts.size();
  result.frozen_vertices = plan.frozen.size();
  result.self_intersections_avoided = attempts.front().added_pairs;
  result.check_failed = !found;
  if (!found) {
    result.merge_tolerance = attempts.front().tolerance;
    result.valid = CGAL::is_valid_polygon_mesh(pm);
  }
  return result;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_STITCHING_STITCHING_TRIAL_H
