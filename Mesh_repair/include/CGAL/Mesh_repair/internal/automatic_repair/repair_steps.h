// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_REPAIR_STEPS_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_REPAIR_STEPS_H

// The steps of automatic_repair, one function each, in the order of thesis Figure 3.2.

#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/closed_part_orientation.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/region_replacement.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/self_union.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/spike_relaxation.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/through_holes.h>
#include <CGAL/Mesh_repair/internal/clean_hole_contour/offending_faces.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/mesh_counts.h>
#include <CGAL/Mesh_repair/internal/stitching/run_gap_stitcher.h>
#include <CGAL/Mesh_repair/internal/stitching/stitching_trial.h>
#include <CGAL/Mesh_repair/repair_result.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Union_find.h>
#include <CGAL/boost/graph/helpers.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <numeric>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// The options of automatic_repair, read once from its named parameters.
struct Repair_options {
  double merge_tolerance = -1;  ///< negative: derived by stitch_gaps
  bool use_cubic_curves = true;
  bool keep_largest_component = false;
  bool detect_self_intersections = true;
  bool repair_self_intersections = true;
  bool merge_intersecting_solids = false;
  bool remove_hole_fragments = true;
  bool bridge_through_holes = true;
  bool orient_closed_parts = true;
  Fill_options fill;
};

/// A grown hole is kept only where every corner of the faces it removed lies within two mean
/// border edges of its patch and within 1% of the mesh's diagonal (the "nothing lost"):
/// the folded faces of a scanned border or the lip of a tube's end (railing models: within one
/// edge) go, while a part's shape rebuilt as a membrane does not (sweethome3d's antenna lost 15%
/// of its area to three rings, its concept sedan had panels moved by 2.4% of the diagonal).
constexpr double max_grown_deviation_in_border_edges = 2.0;
constexpr double max_grown_deviation_in_diagonals = 0.01;
/// Failed holes lose the offending faces along their border (folded, crossing, degenerate,
/// ears: offending_contour_faces) found within this many vertex rings, then are grown by 1, 2,
/// then 3 vertex rings (step_grow_failed_holes).
constexpr int contour_cleaning_rings = 2;
constexpr int max_hole_growth_rings = 3;
/// Holes with more border edges are not grown: growing is for the small holes of scanned
/// borders, and Liepa's triangulation of a long border is cubic in its length.
constexpr std::size_t max_grown_hole_edges = 300;
/// A hole is grown only over faces whose longest edge is at most this many times the longest
/// edge of its border. Scan borders are surrounded by faces of their own size; on CAD parts one
/// ring of long faces can be a whole tube wall or a side of a box, and rebuilding it with
/// Liepa's fairing replaces real geometry with a membrane.
constexpr double max_grown_face_to_border_edge = 4.0;
/// The remnant closings of the advancing front (advancing_front.md) get at most this many
/// visits over all the holes of the hole-filling step, shared out evenly, and at least the next
/// per hole (Advancing_front_options::remnant_visits_per_hole is the most per hole): on a model
/// with a hundred holes that no method fills (Debian's flowerBox: 101 of its 228 holes) the
/// per-hole budget alone made the step last over two minutes.
constexpr std::size_t max_remnant_visits_per_step = 600'000'000;
constexpr std::size_t min_remnant_visits_per_hole = 6'000'000;
/// A derived stitching tolerance moves no vertex farther than this fraction of the diagonal:
/// what the "nothing lost" allows; past it, the merge is undone and the gap is left to
/// hole filling.
constexpr double max_stitching_move_in_diagonals = 0.01;
/// Self-intersecting faces are removed with 1, 2, ... up to 6 vertex rings
/// (step_remove_self_intersections).
constexpr int max_self_intersection_rings = 6;
/// Past this fraction of the faces, self-intersecting faces are not removed: the mesh is not a
/// surface with local defects, and replacing most of it would lose its shape.
constexpr double max_self_intersecting_face_fraction = 0.2;
/// A region of self-intersecting faces with their rings is replaced only while it holds at most
/// this share of the faces or of the area of its part: on a coarse part a few rings reach
/// everywhere, and a patch over most of the part would replace the part, not its defect (a 448-face
/// open box of which 412 faces were replaced by 38).
constexpr double max_replaced_part_share = 0.25;
/// A closed part that still intersects itself after region replacement is autorefined (the pieces
/// inside its volume removed) only while the area removed from the mesh stays within this
/// fraction of its area, and no point of the part moves farther than the next fraction of the
/// bounding-box diagonal from the result: past that the fold is not a defect but a shape.
constexpr double max_autorefined_area_fraction = 0.01;
constexpr double max_autorefined_distance_fraction = 0.005;
/// The exact arrangement of a part is used even where rounding its points to doubles folds a few
/// faces across others, as long as those pairs are at most this share of the part's intersecting
/// pairs: the region replacement that follows removes them like the input's own.
constexpr double max_rounding_crossing_share = 0.25;
/// Spike vertices are moved back in at most this many rounds (a round moves the likeliest spike
/// of each intersecting pair; a spike hidden behind another shows in the next round).
constexpr int max_spike_relaxation_rounds = 6;

/// Times a step, reports it to the visitor (balanced start/end, also on cancellation) and
/// records it in the result.
class Step_timer {
 public:
  Step_timer(Repair_result& result, const char* name, Any_visitor visitor)
      : result_(result), visitor_(visitor) {
    step_.name = name;
    start_ = std::chrono::steady_clock::now();
    visitor_.start_step(name);
  }
  ~Step_timer() {
    step_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    visitor_.end_step(step_.name.c_str());
    result_.steps.push_back(std::move(step_));
  }
  Step_timer(const Step_timer&) = delete;
  Step_timer& operator=(const Step_timer&) = delete;
  Repair_step_report& step() { return step_; }
  void count(const std::string& key, double value) { step_.counts.emplace_back(key, value); }
  template <class Result>
  void details(const Result& r) {
    std::ostringstream out;
    Json_writer json(out, false);
    write_json(json, r);
    step_.details_json = out.str();
    if (!step_.details_json.empty() && step_.details_json.back() == '\n')
      step_.details_json.pop_back();
  }

 private:
  Repair_result& result_;
  Any_visitor visitor_;
  Repair_step_report step_;
  std::chrono::steady_clock::time_point start_;
};

/// The pairs of intersecting faces of `pm` up to the pair limit (internal/bounded_pairs.h): all
/// and those between two connected components; `truncated`: the counts are lower bounds.
struct Self_intersection_census {
  std::size_t all = 0, between = 0;
  bool truncated = false;
};

template <class PolygonMesh>
Self_intersection_census self_intersection_census(const PolygonMesh& pm);

/// Pairs inside the parts that the repair added, from the counts of `result` (0 when a count
/// stopped at the pair limit: the difference is unknown).
inline std::size_t pairs_added_within_parts(const Repair_result& result) {
  if (result.self_intersections_input_truncated || result.self_intersections_output_truncated)
    return 0;
  const auto within = [](std::size_t all, std::size_t between) {
    return all - std::min(all, between);
  };
  const std::size_t before =
      within(result.self_intersections_input, result.self_intersections_input_between_components) +
      result.self_intersections_joined_by_stitching;
  const std::size_t after =
      within(result.self_intersections_output, result.self_intersections_between_components);
  return after > before ? after - before : 0;
}

/// The pairs inside the parts that `census` counts beyond `within_before`: when a stitch joined
/// parts, pairs between them that are now inside one.
inline std::size_t pairs_moved_inside(const Self_intersection_census& census,
                                      std::size_t within_before) {
  const std::size_t within = census.all - std::min(census.all, census.between);
  return census.truncated || within <= within_before ? 0 : within - within_before;
}

/// Counts the output's pairs into `result`, and the pairs the repair added inside the parts.
/// With `parts_joined` (a stitch since the last count), the pairs that moved inside a part are
/// added to `self_intersections_joined_by_stitching`, less as many as the patches closing holes
/// against other parts added between parts since the stitching steps: those may be among them,
/// and they stay counted as added.
template <class PolygonMesh>
void set_output_self_intersections(const PolygonMesh& pm, Repair_result& result,
                                   bool parts_joined = false) {
  const Self_intersection_census census = self_intersection_census(pm);
  if (parts_joined && !result.self_intersections_output_truncated) {
    const std::size_t between = result.self_intersections_between_components;
    const std::size_t moved =
        pairs_moved_inside(census, result.self_intersections_output -
                                       std::min(result.self_intersections_output, between));
    const std::size_t stitched_between =
        result.self_intersections_input_between_components == 0
            ? 0
            : result.self_intersections_between_components_after_stitching;
    const std::size_t added_between = between > stitched_between ? between - stitched_between : 0;
    if (moved > added_between)
      result.self_intersections_joined_by_stitching += moved - added_between;
  }
  result.self_intersections_output = census.all;
  result.self_intersections_between_components = census.between;
  result.self_intersections_output_truncated = census.truncated;
  result.self_intersections_in_patches = pairs_added_within_parts(result);
}

/// After the stitching steps: the input's pairs between parts that stitching put inside one
/// part (only when the input has pairs between parts, else there is nothing to move).
template <class PolygonMesh>
void step_count_pairs_joined_by_stitching(const PolygonMesh& pm, Repair_result& result,
                                          Any_visitor visitor) {
  if (result.self_intersections_input_between_components == 0 ||
      result.self_intersections_input_truncated)
    return;
  Step_timer timer(result, "input pairs in stitched parts", visitor);
  const Self_intersection_census census = self_intersection_census(pm);
  result.self_intersections_joined_by_stitching = pairs_moved_inside(
      census, result.self_intersections_input - result.self_intersections_input_between_components);
  result.self_intersections_between_components_after_stitching = census.between;
  timer.count("pairs", double(census.all));
  timer.count("pairs_between_components", double(census.between));
  timer.count("pairs_joined_by_stitching", double(result.self_intersections_joined_by_stitching));
}

template <class PolygonMesh>
void step_exact_stitching(PolygonMesh& pm, Repair_result& result, Any_visitor visitor) {
  Step_timer timer(result, "exact stitching", visitor);
  const std::size_t before = count_border_halfedges(pm);
  const std::size_t stitched = CGAL::Polygon_mesh_processing::stitch_borders(pm);
  timer.count("halfedge_pairs_stitched", double(stitched));
  timer.count("border_edges_before", double(before));
  timer.count("border_edges_after", double(count_border_halfedges(pm)));
}

/// The settings of `stitch_gaps` (or, without node merging, `repair_t_junctions`) with
/// `tolerance` (negative: derived from the border edge lengths).
inline Stitch_settings stitch_settings(const Repair_options& options, double tolerance,
                                       bool merge_nodes) {
  Stitch_settings settings;
  settings.merge_tolerance = tolerance;
  settings.merge_nodes = merge_nodes;
  settings.use_cubic_curves = options.use_cubic_curves;
  settings.max_derived_move_in_diagonals = max_stitching_move_in_diagonals;
  return settings;
}

/// Tolerance stitching moves border nodes; on coarse CAD meshes, whose long border edges give a
/// large derived tolerance, and next to thin walls, that can push faces through their
/// neighbours (libcgal-demo's ALSTOM_TEST4: 518 new self-intersecting pairs). So when
/// self-intersections are checked, stitching is first tried on a copy. While it adds
/// self-intersections, the vertices of the intersecting faces are frozen (they neither move nor
/// take T-junction nodes) and the copy is stitched again, up to `max_freezing_rounds` times:
/// the rest of the seam is still stitched with the derived tolerance. Failing that, a quarter of
/// the smallest local tolerance is tried, and then the step is skipped (the gaps stay as holes
/// for the filling step).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Stitching_plan<PolygonMesh> plan_stitching(const PolygonMesh& pm, VertexPointMap vpm,
                                           const GeomTraits& traits, const Repair_options& options,
                                           Repair_result& result, Any_visitor visitor) {
  constexpr int max_freezing_rounds = 8;
  Stitching_plan<PolygonMesh> plan;
  plan.tolerance = options.merge_tolerance;
  if (!options.detect_self_intersections) return plan;
  Step_timer timer(result, "stitching trial", visitor);
  std::vector<Stitching_attempt> attempts;
  const Stitch_settings settings = stitch_settings(options, plan.tolerance, true);
  auto record = [&](std::size_t first) {
    for (std::size_t k = first; k < attempts.size(); ++k) {
      const std::string suffix = "_" + std::to_string(k);
      timer.count("tolerance" + suffix, attempts[k].tolerance);
      timer.count("frozen_vertices" + suffix, double(attempts[k].frozen_vertices));
      timer.count("added_self_intersections" + suffix, double(attempts[k].added_pairs));
      if (attempts[k].added_pairs > 0)
        timer.step().notes.push_back(
            "stitching with tolerance " + std::to_string(attempts[k].tolerance) + " and " +
            std::to_string(attempts[k].frozen_vertices) + " frozen vertices would add " +
            std::to_string(attempts[k].added_pairs) + " self-intersecting pair(s)");
    }
  };
  if (freeze_intersecting_stitches(pm, vpm, traits, settings, true, result.self_intersections_input,
                                   max_freezing_rounds, plan, attempts)) {
    record(0);
    return plan;
  }
  record(0);
  // A quarter of the smallest local tolerance of the first attempt (before any freezing), with
  // nothing frozen, once.
  plan.frozen.clear();
  plan.tolerance =
      0.25 * std::min(attempts.front().min_local_tolerance, attempts.front().tolerance);
  const std::size_t tried = attempts.size();
  const bool fallback = freeze_intersecting_stitches(
      pm, vpm, traits, settings, true, result.self_intersections_input, 0, plan, attempts);
  record(tried);
  if (fallback) return plan;
  timer.count("skipped", 1);
  timer.step().notes.push_back(
      "tolerance stitching skipped: every tried tolerance added self-intersections; the gaps are "
      "left to hole filling");
  plan.tolerance = std::numeric_limits<double>::quiet_NaN();
  return plan;
}

/// How the merge tolerance of a stitching run was obtained, for the report.
inline std::string tolerance_derivation(const Stitch_result& r, bool from_trial) {
  std::ostringstream out;
  if (from_trial)
    out << "merge tolerance " << r.merge_tolerance
        << ": a quarter of the smallest derived local tolerance, since the derived tolerance "
           "would add self-intersections (stitching trial)";
  else if (r.tolerance_derived)
    out << "merge tolerance derived per border vertex: half its shortest incident edge (from "
        << r.min_local_tolerance << " to " << r.merge_tolerance << ")";
  else
    out << "merge tolerance " << r.merge_tolerance << " as given";
  out << "; largest move " << r.max_displacement << " (" << r.max_move_to_shortest_edge
      << " of the vertex's shortest incident edge)";
  return out.str();
}

/// Says in the step's notes where the stitcher stopped at a limit (internal/bounded_pairs.h).
inline void add_stitch_limit_notes(const Stitch_result& stitched, Step_timer& timer) {
  if (stitched.node_pairs_truncated)
    timer.step().notes.push_back(
        "at least " + std::to_string(stitched.node_pairs_within_tolerance) +
        " border node pairs within tolerance (the pair limit): no node merged");
  if (stitched.t_junction_search_truncated)
    timer.step().notes.push_back(
        "the T-junction search met more candidate pairs than its limit: stopped, no split");
}

template <class PolygonMesh, class VertexPointMap, class GeomTraits>
void step_tolerance_stitching(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                              const Repair_options& options, Any_visitor visitor,
                              Repair_result& result) {
  const Stitching_plan<PolygonMesh> plan =
      plan_stitching(pm, vpm, traits, options, result, visitor);
  const double tolerance = plan.tolerance;
  if (std::isnan(tolerance)) return;
  {
    Step_timer timer(result, "tolerance stitching", visitor);
    const Stitch_result stitched = run_gap_stitcher(
        pm, vpm, traits, stitch_settings(options, tolerance, true), visitor, plan.frozen);
    timer.count("frozen_vertices", double(plan.frozen.size()));
    timer.count("node_merges", double(stitched.node_merges));
    timer.count("t_junctions_split", double(stitched.t_junctions_split));
    timer.count("edges_stitched", double(stitched.edges_stitched));
    timer.count("merge_tolerance", stitched.merge_tolerance);
    timer.count("max_displacement", stitched.max_displacement);
    timer.count("max_move_to_shortest_edge", stitched.max_move_to_shortest_edge);
    timer.count("merges_undone_by_move_limit", double(stitched.merges_undone_by_move_limit));
    timer.count("unglued_nodes_restored", double(stitched.unglued_nodes_restored));
    timer.count("t_junction_splits_undone", double(stitched.t_junction_splits_undone));
    const bool from_trial = options.merge_tolerance < 0 && tolerance >= 0;
    if (stitched.border_nodes > 0)
      timer.step().notes.push_back(tolerance_derivation(stitched, from_trial));
    if (!plan.frozen.empty())
      timer.step().notes.push_back(std::to_string(plan.frozen.size()) +
                                   " vertices left unstitched: stitching them made faces "
                                   "intersect (stitching trial)");
    add_stitch_limit_notes(stitched, timer);
    timer.details(stitched);
    if (stitched.cancelled) result.cancelled = true;
  }
  if (result.cancelled) return;
  Step_timer timer(result, "T-junctions", visitor);
  const Stitch_result repaired = run_gap_stitcher(
      pm, vpm, traits, stitch_settings(options, tolerance, false), visitor, plan.frozen);
  timer.count("t_junctions_split", double(repaired.t_junctions_split));
  timer.count("edges_stitched", double(repaired.edges_stitched));
  add_stitch_limit_notes(repaired, timer);
  timer.details(repaired);
  if (repaired.cancelled) result.cancelled = true;
}

/// Stitching can leave zero-area slits: border cycles whose vertices are all collinear (exact
/// predicate), such as a T-junction split next to a corner. No filling method can triangulate
/// them (every triangle would be flat); they are closed by a fan of flat triangles that the
/// degenerate-face step then collapses.
template <class PolygonMesh, class VertexPointMap>
void step_close_slits(PolygonMesh& pm, VertexPointMap vpm, Repair_result& result,
                      Any_visitor visitor) {
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  Step_timer timer(result, "zero-area slits", visitor);
  std::size_t slits = 0, faces_added = 0;
  for (halfedge_descriptor h : border_cycles(pm)) {
    std::vector<vertex_descriptor> cycle;
    for (halfedge_descriptor c : halfedges_around_face(h, pm)) cycle.push_back(target(c, pm));
    bool collinear = cycle.size() >= 3;
    for (std::size_t i = 2; i < cycle.size() && collinear; ++i)
      collinear =
          Kernel().collinear_3_object()(get(vpm, cycle[0]), get(vpm, cycle[1]), get(vpm, cycle[i]));
    if (!collinear) continue;
    // A fan from the cycle's first vertex, in the order of the border halfedges: the new faces
    // take those halfedges over.
    std::size_t added_here = 0;
    for (std::size_t i = cycle.size() - 1; i >= 2; --i) {
      std::array<vertex_descriptor, 3> face{cycle[0], cycle[i - 1], cycle[i]};
      if (!CGAL::Euler::can_add_face(face, pm)) break;
      CGAL::Euler::add_face(face, pm);
      ++added_here;
    }
    faces_added += added_here;
    slits += added_here > 0 ? 1 : 0;
  }
  timer.count("slits_closed", double(slits));
  timer.count("flat_faces_added", double(faces_added));
}

/// Connected components made only of degenerate faces (a lone flat triangle of a soup, closed by
/// the slit step into a flat pillow) carry no surface and are left alone by CGAL's
/// `remove_degenerate_faces`: they are removed here and their faces counted.
template <class PolygonMesh, class VertexPointMap>
std::size_t remove_degenerate_components(PolygonMesh& pm, VertexPointMap vpm) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<face_descriptor> seeds;
  for (face_descriptor f : faces(pm))
    if (PMP::is_degenerate_triangle_face(f, pm, CGAL::parameters::vertex_point_map(vpm)))
      seeds.push_back(f);
  std::set<face_descriptor> doomed;
  for (face_descriptor seed : seeds) {
    if (doomed.count(seed)) continue;
    std::vector<face_descriptor> component;
    PMP::connected_component(seed, pm, std::back_inserter(component));
    bool all_degenerate = true;
    for (face_descriptor f : component)
      all_degenerate = all_degenerate && PMP::is_degenerate_triangle_face(
                                             f, pm, CGAL::parameters::vertex_point_map(vpm));
    if (all_degenerate) doomed.insert(component.begin(), component.end());
  }
  for (face_descriptor f : doomed) CGAL::Euler::remove_face(halfedge(f, pm), pm);
  return doomed.size();
}

template <class PolygonMesh>
void step_non_manifold_vertices(PolygonMesh& pm, Repair_result& result, Any_visitor visitor) {
  Step_timer timer(result, "non-manifold vertices", visitor);
  const std::size_t duplicated = CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(pm);
  timer.count("vertices_duplicated", double(duplicated));
}

template <class PolygonMesh, class VertexPointMap>
void step_degenerate_faces(PolygonMesh& pm, VertexPointMap vpm, Repair_result& result,
                           Any_visitor visitor) {
  Step_timer timer(result, "degenerate faces", visitor);
  const std::size_t faces_before = count_faces(pm), vertices_before = count_vertices(pm);
  const bool all_removed = CGAL::Polygon_mesh_processing::remove_degenerate_faces(
      pm, CGAL::parameters::vertex_point_map(vpm));
  timer.count("flat_component_faces_removed", double(remove_degenerate_components(pm, vpm)));
  timer.count("faces_removed", double(faces_before) - double(count_faces(pm)));
  timer.count("vertices_removed", double(vertices_before) - double(count_vertices(pm)));
  if (!all_removed) timer.step().notes.push_back("some degenerate faces could not be removed");
}

/// Scans leave fragments of a face or a few inside their holes, attached to the hole's border
/// at a single vertex; the soup repair and the non-manifold step split them off as components of
/// their own. Every patch of the hole meets them, and each would stay open as the outline of a
/// sheet. A fragment is an open component of at most `max_fragment_faces` faces and at most
/// `1 / max_fragment_share` of the faces of a part, with a vertex at the exact position of a
/// border vertex of one of that part's holes (not outlines of open sheets, not islands of ring
/// holes, which the filling bridges). Fragments are removed before the holes are filled, and
/// counted; closed components and larger open ones are parts, never removed. Fragments floating
/// free in a hole are kept: small CAD parts sit in the boxes of holes too.
template <class PolygonMesh, class VertexPointMap>
void step_remove_hole_fragments(PolygonMesh& pm, VertexPointMap vpm, const Repair_options& options,
                                Any_visitor visitor, Repair_result& result) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  constexpr std::size_t max_fragment_share = 100, max_fragment_faces = 10;
  const auto groups = hole_groups(pm, vpm, options.fill.detect_ring_holes);
  if (groups.size() < 2) return;
  Step_timer timer(result, "fragments in holes", visitor);
  const auto component = face_components(pm);
  std::size_t count = 0;
  for (const auto& entry : component) count = (std::max)(count, entry.second + 1);
  std::vector<std::vector<face_descriptor>> members(count);
  for (auto f : faces(pm)) members[component.at(f)].push_back(f);
  // The part of every border vertex of a hole; which components are open, which islands.
  const std::vector<double> ratios = sheet_border_ratios(pm, vpm, groups);
  std::vector<bool> open(count, false), island(count, false);
  std::multimap<Point, std::size_t> hole_vertex_part;
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const std::size_t part = component.at(face(opposite(groups[k].outer, pm), pm));
    open[part] = true;
    for (auto cycle : groups[k].islands)
      open[component.at(face(opposite(cycle, pm), pm))] =
          island[component.at(face(opposite(cycle, pm), pm))] = true;
    if (ratios[k] > options.fill.sheet_border_ratio) continue;
    for (auto h : halfedges_around_face(groups[k].outer, pm))
      hole_vertex_part.emplace(get(vpm, target(h, pm)), part);
  }
  std::size_t fragments = 0, faces_removed = 0;
  const std::size_t vertices_before = count_vertices(pm);
  for (std::size_t c = 0; c < count; ++c) {
    const std::size_t size = members[c].size();
    if (!open[c] || island[c] || size > max_fragment_faces) continue;
    bool touches = false;
    for (auto f : members[c])
      for (auto v : vertices_around_face(halfedge(f, pm), pm)) {
        const auto range = hole_vertex_part.equal_range(get(vpm, v));
        for (auto it = range.first; it != range.second; ++it)
          touches = touches ||
                    (it->second != c && size * max_fragment_share <= members[it->second].size());
      }
    if (!touches) continue;
    ++fragments;
    faces_removed += size;
    for (face_descriptor f : members[c]) CGAL::Euler::remove_face(halfedge(f, pm), pm);
  }
  timer.count("fragments_removed", double(fragments));
  timer.count("faces_removed", double(faces_removed));
  timer.count("vertices_removed", double(vertices_before) - double(count_vertices(pm)));
}

/// Step 9c: the through-holes of a part whose wall is missing get it, before any cap is tried
/// (internal/automatic_repair/through_holes.h).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
void step_bridge_through_holes(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                               Any_visitor visitor, Repair_result& result) {
  if (border_cycles(pm).size() < 2) return;
  Step_timer timer(result, "through holes bridged", visitor);
  const std::size_t vertices_before = count_vertices(pm);
  const Through_hole_report report = bridge_through_holes(pm, vpm, traits);
  CGAL_assertion(count_vertices(pm) == vertices_before);
  CGAL_USE(vertices_before);
  timer.count("matching_pairs", double(report.pairs));
  timer.count("tubes_added", double(report.bridged));
  timer.count("tubes_rejected", double(report.rejected));
  timer.count("faces_added", double(report.faces_added));
}

/// Step 14, after the coincident elements (whose stitch closes parts): closed parts that face
/// inward are turned outward, with the parts inside them
/// (internal/automatic_repair/closed_part_orientation.h). Reversing faces changes none of the
/// verification's figures.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
void step_orient_closed_parts(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                              Any_visitor visitor, Repair_result& result) {
  Step_timer timer(result, "orientation of closed parts", visitor);
  const Closed_part_orientation oriented = orient_closed_parts(pm, vpm, traits);
  result.closed_parts_reversed_outward = oriented.reversed_outward;
  result.closed_parts_reversed_with_container = oriented.reversed_with_container;
  timer.count("closed_parts", double(oriented.closed_parts));
  timer.count("reversed_outward", double(oriented.reversed_outward));
  timer.count("nested_parts", double(oriented.nested));
  timer.count("reversed_with_container", double(oriented.reversed_with_container));
  timer.count("crossing_parts", double(oriented.crossing_parts));
  if (oriented.budget_reached)
    timer.step().notes.push_back("the nesting tests reached their budget (" +
                                 std::to_string(nesting_tests_per_face) +
                                 " vertex tests per face); the parts not tested count as not "
                                 "nested");
}

template <class PolygonMesh>
void step_largest_component(PolygonMesh& pm, Repair_result& result, Any_visitor visitor) {
  Step_timer timer(result, "largest component", visitor);
  const std::size_t faces_before = count_faces(pm);
  const std::size_t removed =
      CGAL::Polygon_mesh_processing::keep_largest_connected_components(pm, 1);
  result.components_removed = removed;
  result.faces_removed_with_components = faces_before - count_faces(pm);
  timer.count("components_removed", double(removed));
  timer.count("faces_removed", double(result.faces_removed_with_components));
}

/// The filling of the regions that automatic_repair removes (grown holes, self-intersections):
/// CGAL's Liepa triangulation and fairing, which takes milliseconds on such holes, where the
/// other methods' fallbacks take seconds on the holes they cannot fill; with `last_resorts`,
/// the coarser last resorts after it (Liepa_options::then_last_resorts).
inline Fill_options replacement_fill_options(const Fill_options& fill, bool last_resorts) {
  Fill_options options = fill;
  options.method = Fill_method::liepa;
  options.liepa.then_last_resorts = last_resorts;
  return options;
}

/// What a region replacement may change (Region_replacer's bounds) and how it fills.
struct Replacement_bounds {
  double max_deviation_in_border_edges = 0;  ///< 0: no bound
  double max_deviation = std::numeric_limits<double>::infinity();
  double max_part_share = 1;
  /// Only where the deviation is bounded: a last resort (a triangulation of the border alone,
  /// a base) stands for the faces it replaces only if it stays near them.
  bool last_resorts = false;
};

/// One round of region replacement with `replacement_fill_options`; adds its counts to `total`.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Region_replacement_report replace_regions(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits, const Repair_options& options,
    Any_visitor visitor,
    const std::vector<std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>>&
        regions,
    Region_replacement_report& total, const Replacement_bounds& bounds) {
  const Fill_options fill = replacement_fill_options(options.fill, bounds.last_resorts);
  Region_replacer<PolygonMesh, VertexPointMap, GeomTraits> replacer(pm, vpm, traits, fill, visitor);
  replacer.max_deviation_in_border_edges = bounds.max_deviation_in_border_edges;
  replacer.max_deviation = bounds.max_deviation;
  replacer.max_part_share = bounds.max_part_share;
  const Region_replacement_report round = replacer.replace(regions);
  total.regions_replaced += round.regions_replaced;
  total.faces_removed += round.faces_removed;
  total.faces_added += round.faces_added;
  total.faces_not_restored += round.faces_not_restored;
  total.regions_too_far += round.regions_too_far;
  total.regions_too_large += round.regions_too_large;
  return round;
}

/// The vertices of the cycles of `group`.
template <class PolygonMesh, class Group>
std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> group_vertices(
    const PolygonMesh& pm, const Group& group) {
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vertices;
  auto add = [&](auto cycle) {
    for (auto h : halfedges_around_face(cycle, pm)) vertices.push_back(target(h, pm));
  };
  add(group.outer);
  for (auto island : group.islands) add(island);
  return vertices;
}

/// What growth round `rings` removes around a hole, for the notes (round 0: the contour's
/// offending faces).
inline std::string grown_region_name(int rings) {
  return rings == 0 ? "the folded, crossing, degenerate or ear faces along its border"
                    : "the faces within " + std::to_string(rings) + " vertex ring(s) of its border";
}

/// The faces round 0 of step_grow_failed_holes removes around `group`: its contour's offending
/// faces within `contour_cleaning_rings` vertex rings, those that reach its border through one
/// another (by shared vertices): removed alone, the others would open a hole of their own and
/// leave this one as it was. None for a ring hole (its islands may keep all their faces and then
/// stay apart from the cleaned hole, open) nor where they reach another border (part of that
/// hole's cycle would be cut off and left open): the rings take every cycle they meet.
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Group>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> contour_cleaning_region(
    const PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits, const Group& group) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  if (!group.islands.empty()) return {};
  const std::vector<vertex_descriptor> border = group_vertices(pm, group);
  std::vector<int> ring_of;
  const auto range = faces_within_rings(pm, border, contour_cleaning_rings, &ring_of);
  auto offending = offending_contour_faces(pm, vpm, traits, range, ring_of);
  const std::unordered_set<vertex_descriptor> on_border(border.begin(), border.end());
  std::unordered_set<vertex_descriptor> reached = on_border;
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> region;
  for (bool grew = true; grew;) {
    grew = false;
    for (auto& f : offending) {
      if (f == boost::graph_traits<PolygonMesh>::null_face()) continue;
      const auto corners = vertices_around_face(halfedge(f, pm), pm);
      if (std::none_of(corners.begin(), corners.end(), [&](auto v) { return reached.count(v); }))
        continue;
      for (auto v : corners) {
        if (is_border(v, pm) && !on_border.count(v)) return {};
        reached.insert(v);
      }
      region.push_back(f);
      f = boost::graph_traits<PolygonMesh>::null_face();
      grew = true;
    }
  }
  return region;
}

/// Records in `hole` the region replacement `j` of `round` that closed it: the faces removed
/// around it and the patch that replaced them (shared with the holes its region merged with).
inline void record_grown_fill(Hole_fill_report& hole, int rings,
                              const Region_replacement_report& round, std::size_t j) {
  std::string note =
      "filled after removing the " + std::to_string(round.region_faces_removed[j]) +
      (rings == 0 ? " folded, crossing, degenerate or ear face(s) along its border"
                  : " face(s) within " + std::to_string(rings) + " vertex ring(s) of its border");
  if (round.regions_merged[j] > 1)
    note += " (one region with " + std::to_string(round.regions_merged[j] - 1) +
            " other hole(s); the counts are the region's)";
  hole.notes.push_back(note + ": " + hole.failure);
  hole.used = round.region_method[j];
  hole.faces_created = round.region_faces_added[j];
  hole.vertices_created = round.region_vertices_added[j];
}

/// Whether every face of `region` has its longest edge within `max_grown_face_to_border_edge`
/// times the longest edge of the cycles of `group`.
template <class PolygonMesh, class VertexPointMap, class Group>
bool faces_fit_the_border(
    const PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& region,
    const Group& group) {
  auto squared_length = [&](auto h) {
    return CGAL::to_double(
        CGAL::squared_distance(get(vpm, source(h, pm)), get(vpm, target(h, pm))));
  };
  double border = 0;
  auto add = [&](auto cycle) {
    for (auto h : halfedges_around_face(cycle, pm)) border = (std::max)(border, squared_length(h));
  };
  add(group.outer);
  for (auto island : group.islands) add(island);
  const double bound = max_grown_face_to_border_edge * max_grown_face_to_border_edge * border;
  for (auto f : region)
    for (auto h : halfedges_around_face(halfedge(f, pm), pm))
      if (squared_length(h) > bound) return false;
  return true;
}

/// Holes whose every patch was rejected (on scans: folded, overlapping and needle faces along a
/// jagged border make every patch meet the border's own faces) lose first only those faces
/// (offending_contour_faces, Pernot's contour cleaning as a choice of faces), then every face
/// within 1, then 2, then 3 vertex rings of their border, and are filled again; a grown hole that
/// still cannot be filled gets its faces back (Region_replacer). `border_points` holds a border
/// point of each hole of `result.holes.holes` (the exact position finds the hole again after its
/// halfedges were removed and put back); only the holes `eligible` marks are grown (all when it
/// is empty). `step` names the step in the report; `max_deviation_in_border_edges` bounds how
/// far the removed faces may lie from the patch, in mean border edges and in
/// `max_deviation_in_diagonals` of the mesh's bounding box (Region_replacer; 0: no bound).
/// A grown hole whose Liepa patch is rejected gets the last resorts of the fill sequences
/// (Replacement_bounds::last_resorts).
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Point>
void step_grow_failed_holes(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                            const Repair_options& options, const std::vector<Point>& border_points,
                            const std::vector<bool>& eligible, const char* step,
                            Any_visitor visitor, Repair_result& result,
                            double max_deviation_in_border_edges,
                            double max_deviation_in_diagonals) {
  using Group = Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::vector<std::size_t> failed;
  std::vector<Point> keys;
  std::vector<std::string> put_back;  // per failed hole: why its last grown region was put back
  for (std::size_t k = 0; k < result.holes.holes.size(); ++k) {
    const Hole_fill_report& hole = result.holes.holes[k];
    if (hole.filled || hole.skipped || (!eligible.empty() && !eligible[k])) continue;
    if (hole.border_edges > max_grown_hole_edges) continue;
    failed.push_back(k);
    keys.push_back(border_points[k]);
    put_back.emplace_back();
  }
  if (failed.empty()) return;
  Step_timer timer(result, step, visitor);
  timer.count("holes", double(failed.size()));
  const double max_deviation = max_deviation_in_diagonals > 0
                                   ? max_deviation_in_diagonals * mesh_bbox_diagonal(pm, vpm)
                                   : std::numeric_limits<double>::infinity();
  Region_replacement_report total;
  std::size_t not_grown = 0;
  // Round 0 removes only the offending faces along the border (offending_contour_faces), then
  // rounds 1 to 3 every face within that many vertex rings.
  for (int rings = 0; rings <= max_hole_growth_rings && !failed.empty(); ++rings) {
    // The groups again: a grown hole put back has new halfedges; its key point finds it.
    std::map<Point, Group> group_at;
    for (const Group& group : hole_groups(pm, vpm, options.fill.detect_ring_holes))
      for (auto h : halfedges_around_face(group.outer, pm))
        group_at.emplace(get(vpm, target(h, pm)), group);
    std::vector<std::vector<face_descriptor>> regions;
    std::vector<std::size_t> in_round;
    std::vector<bool> too_long(failed.size(), false);  // stays failed, not grown any further
    for (std::size_t i = 0; i < failed.size(); ++i) {
      auto it = group_at.find(keys[i]);
      if (it == group_at.end()) continue;
      std::vector<face_descriptor> region =
          rings == 0 ? contour_cleaning_region(pm, vpm, traits, it->second)
                     : faces_within_rings(pm, group_vertices(pm, it->second), rings);
      if (rings == 0 && (region.empty() || !faces_fit_the_border(pm, vpm, region, it->second)))
        continue;
      if (!faces_fit_the_border(pm, vpm, region, it->second)) {
        result.holes.holes[failed[i]].notes.push_back(
            "not grown: the faces within " + std::to_string(rings) +
            " vertex ring(s) of its border are longer than " +
            std::to_string(int(max_grown_face_to_border_edge)) +
            "x its longest border edge (not a scanned border; growing would rebuild them)");
        ++not_grown;
        too_long[i] = true;
        continue;
      }
      regions.push_back(std::move(region));
      in_round.push_back(i);
    }
    Replacement_bounds bounds;
    bounds.max_deviation_in_border_edges = max_deviation_in_border_edges;
    bounds.max_deviation = max_deviation;
    bounds.last_resorts = true;
    const Region_replacement_report round =
        replace_regions(pm, vpm, traits, options, visitor, regions, total, bounds);
    std::vector<std::size_t> still_failed;
    std::vector<Point> still_keys;
    std::vector<std::string> still_put_back;
    std::vector<std::size_t> region_of(failed.size(), std::size_t(-1));
    for (std::size_t j = 0; j < in_round.size(); ++j) {
      if (round.replaced[j]) region_of[in_round[j]] = j;
      if (!round.replaced[j])
        put_back[in_round[j]] =
            grown_region_name(rings) + " were removed and put back: " + round.region_failure[j];
    }
    std::size_t filled_now = 0;
    for (std::size_t i = 0; i < failed.size(); ++i) {
      Hole_fill_report& hole = result.holes.holes[failed[i]];
      if (too_long[i]) continue;
      const std::size_t j = region_of[i];
      if (j == std::size_t(-1)) {
        still_failed.push_back(failed[i]);
        still_keys.push_back(keys[i]);
        still_put_back.push_back(put_back[i]);
        continue;
      }
      record_grown_fill(hole, rings, round, j);
      hole.failure.clear();
      hole.filled = true;
      --result.holes.failed;
      ++result.holes.filled;
      ++filled_now;
    }
    if (rings > 0 || filled_now > 0)
      timer.count(rings == 0 ? std::string("filled_with_contour_cleaned")
                             : "filled_with_rings_" + std::to_string(rings),
                  double(filled_now));
    failed.swap(still_failed);
    keys.swap(still_keys);
    put_back.swap(still_put_back);
  }
  for (std::size_t i = 0; i < failed.size(); ++i) {
    std::vector<std::string>& notes = result.holes.holes[failed[i]].notes;
    // The second grow step (against other parts) often puts back for the same reason.
    if (!put_back[i].empty() && (notes.empty() || notes.back() != put_back[i]))
      notes.push_back(put_back[i]);
  }
  timer.count("faces_removed", double(total.faces_removed));
  timer.count("faces_added", double(total.faces_added));
  timer.count("still_failed", double(failed.size() + not_grown));
  if (not_grown > 0) timer.count("not_grown_faces_too_long", double(not_grown));
  if (total.regions_too_far > 0) timer.count("patches_too_far", double(total.regions_too_far));
  if (total.faces_not_restored > 0) {
    timer.count("faces_not_restored", double(total.faces_not_restored));
    timer.step().notes.push_back(std::to_string(total.faces_not_restored) +
                                 " face(s) around holes that stayed open could not be put back");
  }
}

/// The fill options of the retries against other parts: other parts are no obstacle, and the
/// stuck fronts get no second budget (each hole already had one: a hole no loop of which has a
/// valid triangulation spent it once more, 5 s each, 134 s over the 101 holes of a Debian
/// furniture model, where none was closed so). The first rounds of each closing still run.
inline Fill_options other_parts_no_obstacle(Fill_options fill) {
  fill.other_parts_are_obstacles = false;
  fill.advancing_front.remnant_visits_per_hole = 0;
  return fill;
}

/// The holes still open are filled once more with the faces of other parts no obstacle
/// (`Fill_options::other_parts_are_obstacles`): a tube trimmed against a post has its open end on
/// the post's face, and a table top open underneath has the legs reaching in through its hole;
/// every patch meets the other part. Every method already failed with that part an obstacle, the
/// minimal-area triangulation included, so the other part lies across the hole's span, not
/// beside it: the contact is the input's, closed or not. The patch still may not meet its own
/// part nor lie on another part's patch; the contact is kept like any other (counted in the
/// verification as `pairs_between_components_added`, listed in `kept`), and
/// `merge_intersecting_solids` can then unite the closed parts.
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Point>
std::vector<bool> fill_meeting_other_parts(PolygonMesh& pm, VertexPointMap vpm,
                                           const GeomTraits& traits, const Repair_options& options,
                                           const std::vector<Point>& border_points,
                                           Any_visitor visitor, Repair_result& result) {
  // The holes of parts in contact that this step retried and could not fill.
  std::vector<bool> still_failed(result.holes.holes.size(), false);
  std::map<Point, std::size_t> failed_at;  // a border point of each hole still open
  for (std::size_t k = 0; k < result.holes.holes.size(); ++k)
    if (!result.holes.holes[k].filled && !result.holes.holes[k].skipped)
      failed_at.emplace(border_points[k], k);
  if (failed_at.empty()) return still_failed;
  Step_timer timer(result, "failed holes filled against other parts", visitor);
  const auto component = face_components(pm);
  const bool one_part = std::all_of(component.begin(), component.end(),
                                    [](const auto& entry) { return entry.second == 0; });
  if (one_part) return still_failed;
  const auto groups = hole_groups(pm, vpm, options.fill.detect_ring_holes);
  std::vector<typename decltype(groups)::value_type> retried;
  std::vector<std::size_t> hole_of;
  for (const auto& group : groups) {
    for (auto h : halfedges_around_face(group.outer, pm)) {
      const auto found = failed_at.find(get(vpm, target(h, pm)));
      if (found == failed_at.end()) continue;
      retried.push_back(group);
      hole_of.push_back(found->second);
      failed_at.erase(found);
      break;
    }
  }
  if (retried.empty()) return still_failed;
  const Fill_options fill = other_parts_no_obstacle(options.fill);
  std::vector<Fill_patch<PolygonMesh>> patches;
  const Fill_result again =
      fill_hole_groups(pm, vpm, traits, retried, patches, fill, visitor, false);
  std::size_t filled = 0, faces_added = 0;
  for (std::size_t j = 0; j < retried.size(); ++j) {
    if (!again.holes[j].filled) continue;
    faces_added += again.holes[j].faces_created;
    Hole_fill_report& hole = result.holes.holes[hole_of[j]];
    hole.notes.push_back(
        "filled by " + std::string(to_string(again.holes[j].used)) +
        " with other parts no obstacle (the patch meets another part): " + hole.failure);
    hole.failure.clear();
    hole.filled = true;
    hole.used = again.holes[j].used;
    hole.faces_created = again.holes[j].faces_created;
    hole.vertices_created = again.holes[j].vertices_created;
    hole.seconds += again.holes[j].seconds;
    --result.holes.failed;
    ++result.holes.filled;
    ++filled;
  }
  if (again.cancelled) result.cancelled = true;
  timer.count("holes", double(retried.size()));
  timer.count("filled", double(filled));
  timer.count("faces_added", double(faces_added));
  for (std::size_t j = 0; j < retried.size(); ++j)
    still_failed[hole_of[j]] = !again.holes[j].filled;
  return still_failed;
}

/// `fill_meeting_other_parts`, then the holes it could not fill grown against other parts: the
/// open end of a tube that reaches into a post, folded out into a flat lip (Debian's railing and
/// furniture models), is closed only once the lip is gone, and then its cap lies in the post. The
/// same rule: a patch may meet other parts and their patches, never its own part, nor lie on
/// another part's patch in one plane.
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Point>
void step_fill_meeting_other_parts(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                                   const Repair_options& options,
                                   const std::vector<Point>& border_points, Any_visitor visitor,
                                   Repair_result& result) {
  const std::vector<bool> still_failed =
      fill_meeting_other_parts(pm, vpm, traits, options, border_points, visitor, result);
  if (result.cancelled ||
      std::none_of(still_failed.begin(), still_failed.end(), [](bool failed) { return failed; }))
    return;
  Repair_options grown = options;
  grown.fill = other_parts_no_obstacle(options.fill);
  step_grow_failed_holes(pm, vpm, traits, grown, border_points, still_failed,
                         "failed holes grown against other parts", visitor, result,
                         max_grown_deviation_in_border_edges, max_grown_deviation_in_diagonals);
}

/// Fills the holes, grows the failed ones, fills what is left against other parts; returns a
/// border point of each hole of `result.holes`, which finds it again after later steps.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::vector<typename boost::property_traits<VertexPointMap>::value_type> step_fill_holes(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits, const Repair_options& options,
    Any_visitor visitor, Repair_result& result) {
  const std::size_t faces_before = count_faces(pm), vertices_before = count_vertices(pm);
  const auto groups = hole_groups(pm, vpm, options.fill.detect_ring_holes);
  {
    Step_timer timer(result, "hole filling", visitor);
    std::vector<Fill_patch<PolygonMesh>> patches;
    Fill_options fill = options.fill;
    std::size_t& visits = fill.advancing_front.remnant_visits_per_hole;
    visits = std::min(
        visits, std::max(min_remnant_visits_per_hole,
                         max_remnant_visits_per_step / (std::max)(groups.size(), std::size_t(1))));
    result.holes = fill_hole_groups(pm, vpm, traits, groups, patches, fill, visitor, true);
    result.sheet_borders_left_open = result.holes.sheet_borders;
    result.holes_too_large = result.holes.skipped - result.holes.sheet_borders;
    if (result.holes.cancelled) result.cancelled = true;
    timer.count("holes", double(result.holes.holes.size()));
    timer.count("filled", double(result.holes.filled));
    timer.count("failed", double(result.holes.failed));
    timer.count("left_open_too_large", double(result.holes_too_large));
    timer.count("left_open_sheet_borders", double(result.sheet_borders_left_open));
    timer.count("faces_added", double(count_faces(pm)) - double(faces_before));
    // The vertices of the patches kept; a hole whose border touched itself at coincident
    // vertices was filled with them welded into one (internal/hole_filling/pinches.h), which the
    // net change of the vertex count hides (-1 on a file with one such hole and a flat patch).
    double created = 0;
    for (const Hole_fill_report& hole : result.holes.holes)
      if (hole.filled) created += double(hole.vertices_created);
    timer.count("vertices_added", created);
    const double welded = created - (double(count_vertices(pm)) - double(vertices_before));
    if (welded != 0) timer.count("coincident_border_vertices_welded", welded);
  }
  // A border point of each hole finds it again after patches were added and rolled back.
  std::vector<typename boost::property_traits<VertexPointMap>::value_type> border_points;
  for (const auto& group : groups) border_points.push_back(get(vpm, target(group.outer, pm)));
  if (!result.cancelled)
    step_grow_failed_holes(pm, vpm, traits, options, border_points, {}, "failed holes grown",
                           visitor, result, max_grown_deviation_in_border_edges,
                           max_grown_deviation_in_diagonals);
  // Against other parts last: a hole whose grown border leaves the other part is closed cleanly
  // by the growth; what is left meets the other part wherever it is closed.
  if (!result.cancelled && options.fill.check_self_intersections)
    step_fill_meeting_other_parts(pm, vpm, traits, options, border_points, visitor, result);
  return border_points;
}

template <class PolygonMesh>
Self_intersection_census self_intersection_census(const PolygonMesh& pm) {
  const auto found = bounded_self_intersections(pm);
  const auto component = face_components(pm);
  Self_intersection_census census;
  census.all = found.pairs.size();
  census.truncated = found.truncated;
  for (const auto& pair : found.pairs)
    census.between += component.at(pair.first) != component.at(pair.second);
  return census;
}

/// The faces of `group` as a triangle soup of the core's points (`union_of_solids`).
template <class PolygonMesh, class VertexPointMap, class FaceRange>
Triangle_soup soup_of_faces(const PolygonMesh& pm, VertexPointMap vpm, const FaceRange& group) {
  std::unordered_map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, std::size_t>
      index;
  Triangle_soup soup;
  for (auto f : group) {
    std::vector<std::size_t> triangle;
    for (auto v : vertices_around_face(halfedge(f, pm), pm)) {
      auto at = index.emplace(v, soup.points.size());
      if (at.second) {
        const Vec3 p = to_array(get(vpm, v));
        soup.points.emplace_back(p[0], p[1], p[2]);
      }
      triangle.push_back(at.first->second);
    }
    soup.polygons.push_back(std::move(triangle));
  }
  return soup;
}

/// Adds the triangles of `soup` (a closed part, possibly pinched at a vertex) to `pm`, with
/// vertices of their own. A face that cannot be added yet (it would make a vertex non-manifold
/// until its neighbours are in) is tried again after the others. Returns false, with nothing
/// added, when some face cannot be added at all.
template <class PolygonMesh, class VertexPointMap>
bool add_soup(PolygonMesh& pm, VertexPointMap vpm, const Triangle_soup& soup) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::vector<vertex_descriptor> vertices;
  vertices.reserve(soup.points.size());
  for (const auto& p : soup.points) {
    vertices.push_back(add_vertex(pm));
    put(vpm, vertices.back(), Point(p.x(), p.y(), p.z()));
  }
  std::vector<face_descriptor> added;
  std::vector<std::size_t> waiting(soup.polygons.size());
  std::iota(waiting.begin(), waiting.end(), std::size_t(0));
  while (!waiting.empty()) {
    std::vector<std::size_t> failed;
    for (std::size_t i : waiting) {
      const auto& t = soup.polygons[i];
      const face_descriptor f = CGAL::Euler::add_face(
          std::array<vertex_descriptor, 3>{vertices[t[0]], vertices[t[1]], vertices[t[2]]}, pm);
      if (f == boost::graph_traits<PolygonMesh>::null_face())
        failed.push_back(i);
      else
        added.push_back(f);
    }
    if (failed.size() == waiting.size()) break;
    waiting = std::move(failed);
  }
  if (waiting.empty()) return true;
  for (face_descriptor f : added) CGAL::Euler::remove_face(halfedge(f, pm), pm);
  for (vertex_descriptor v : vertices)
    if (halfedge(v, pm) == boost::graph_traits<PolygonMesh>::null_halfedge()) remove_vertex(v, pm);
  return false;
}

/// True when the faces `f` and `g` lie in one plane (exact orientation predicate). CGAL 5.5's
/// corefinement can crash on coplanar faces of two parts (a null dereference in its coplanar
/// case, found on a furniture model), so such parts are not merged.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
bool coplanar_faces(const PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                    typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                    typename boost::graph_traits<PolygonMesh>::face_descriptor g) {
  std::vector<typename boost::property_traits<VertexPointMap>::value_type> plane;
  for (auto v : vertices_around_face(halfedge(f, pm), pm)) plane.push_back(get(vpm, v));
  const auto orientation = traits.orientation_3_object();
  for (auto v : vertices_around_face(halfedge(g, pm), pm))
    if (orientation(plane[0], plane[1], plane[2], get(vpm, v)) != CGAL::COPLANAR) return false;
  return true;
}

/// True when no face of `part` has a border edge.
template <class PolygonMesh, class FaceRange>
bool part_is_closed(const PolygonMesh& pm, const FaceRange& part) {
  for (auto f : part)
    for (auto h : halfedges_around_face(halfedge(f, pm), pm))
      if (is_border(opposite(h, pm), pm)) return false;
  return true;
}

/// The faces of every component, by the component numbers of `component`.
template <class PolygonMesh, class ComponentMap>
std::vector<std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>>
faces_by_component(const PolygonMesh& pm, const ComponentMap& component) {
  std::size_t components = 0;
  for (const auto& c : component) components = std::max(components, c.second + 1);
  std::vector<std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>> faces_of(
      components);
  for (auto f : faces(pm)) faces_of[component.at(f)].push_back(f);
  return faces_of;
}

/// The components (by `component`) where three faces intersect one another pairwise, according
/// to `pairs`: there the intersection curves may cross inside a face, which CGAL 5.5's
/// autorefinement does not handle (it throws, or on symmetric inputs crashes).
template <class PairRange, class ComponentMap>
std::set<std::size_t> components_with_triple_intersections(const PairRange& pairs,
                                                           const ComponentMap& component) {
  using face_descriptor = typename std::decay_t<decltype(pairs.begin()->first)>;
  std::unordered_map<face_descriptor, std::unordered_set<face_descriptor>> crossing;
  for (const auto& pair : pairs) {
    crossing[pair.first].insert(pair.second);
    crossing[pair.second].insert(pair.first);
  }
  std::set<std::size_t> found;
  for (const auto& pair : pairs) {
    const auto& second = crossing[pair.second];
    for (face_descriptor third : crossing[pair.first])
      if (third != pair.second && second.count(third)) {
        found.insert(component.at(pair.first));
        break;
      }
  }
  return found;
}

/// Closed parts that still intersect themselves are replaced by their outer surface, within the
/// bounds above: CGAL's autorefinement (`remove_self_intersections_of_solid`) where it applies,
/// else, and where it fails, the exact arrangement of `outer_surface_of_solid` (parts with
/// coplanar intersecting faces or three faces intersecting pairwise, which CGAL 5.5's
/// corefinement does not handle reliably). Returns the number of parts replaced.
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class PairRange>
std::size_t autorefine_self_intersecting_parts(PolygonMesh& pm, VertexPointMap vpm,
                                               const GeomTraits& traits, const PairRange& pairs,
                                               Step_timer& timer) {
  const auto component = face_components(pm);
  std::set<std::size_t> candidates;
  std::set<std::size_t> degenerate = components_with_triple_intersections(pairs, component);
  for (const auto& pair : pairs) {
    candidates.insert(component.at(pair.first));
    if (coplanar_faces(pm, vpm, traits, pair.first, pair.second))
      degenerate.insert(component.at(pair.first));
  }
  const auto faces_of = faces_by_component(pm, component);
  double area_budget = max_autorefined_area_fraction *
                       CGAL::Polygon_mesh_processing::area(
                           pm, CGAL::parameters::vertex_point_map(vpm).geom_traits(traits));
  const double distance_bound = max_autorefined_distance_fraction * mesh_bbox_diagonal(pm, vpm);
  std::size_t replaced = 0, refused = 0, removed = 0, added = 0, open = 0, exact = 0, separated = 0,
              rounding_crossings = 0, thin_dropped = 0;
  double area_removed = 0;
  // The region replacement that follows takes the few faces that the rounding of the exact
  // arrangement folds across others.
  Self_union_limits arrangement_limits;
  arrangement_limits.max_rounding_crossing_share = max_rounding_crossing_share;
  std::string last_reason;
  for (std::size_t c : candidates) {
    if (!part_is_closed(pm, faces_of[c])) {
      ++open;
      continue;
    }
    Triangle_soup refined;
    Solid_autorefinement measures;
    const Triangle_soup part = soup_of_faces(pm, vpm, faces_of[c]);
    std::string why = degenerate.count(c)
                          ? std::string("not for CGAL")
                          : remove_self_intersections_of_solid(part, refined, measures);
    const bool by_arrangement = !why.empty();
    if (by_arrangement) {
      measures = Solid_autorefinement();
      why = outer_surface_of_solid(part, refined, measures, arrangement_limits);
    }
    const double area_lost = measures.area_before - measures.area_after;
    if (why.empty() && area_lost > area_budget)
      why = "it would remove more than " +
            std::to_string(int(100 * max_autorefined_area_fraction)) + "% of the mesh's area";
    if (why.empty() && measures.largest_distance > distance_bound)
      why = "a point would move farther than " +
            std::to_string(int(1000 * max_autorefined_distance_fraction)) +
            " per mille of the diagonal";
    if (!why.empty()) {
      ++refused;
      last_reason = why;
      continue;
    }
    if (!add_soup(pm, vpm, refined)) {
      ++refused;
      last_reason = "its autorefinement cannot be put in the mesh";
      continue;
    }
    area_budget -= std::max(0.0, area_lost);
    for (auto f : faces_of[c]) CGAL::Euler::remove_face(halfedge(f, pm), pm);
    removed += faces_of[c].size();
    added += refined.polygons.size();
    area_removed += area_lost;
    ++replaced;
    if (by_arrangement) ++exact;
    separated += measures.touching_vertices_separated;
    rounding_crossings += measures.rounding_crossings;
    thin_dropped += measures.thin_solids_dropped;
  }
  timer.count("parts_autorefined", double(replaced));
  timer.count("autorefined_faces_removed", double(removed));
  timer.count("autorefined_faces_added", double(added));
  timer.count("autorefined_area_removed", area_removed);
  if (exact > 0) timer.count("parts_autorefined_exactly", double(exact));
  if (separated > 0) timer.count("touching_vertices_separated", double(separated));
  if (thin_dropped > 0) timer.count("thin_solids_dropped", double(thin_dropped));
  if (rounding_crossings > 0)
    timer.count("rounding_crossings_left_to_patches", double(rounding_crossings));
  if (open > 0)
    timer.step().notes.push_back(std::to_string(open) +
                                 " self-intersecting open part(s) not autorefined (only a closed "
                                 "part has an inside to remove)");
  if (refused > 0)
    timer.step().notes.push_back(
        std::to_string(refused) +
        " self-intersecting closed part(s) not autorefined (last: " + last_reason + ")");
  return replaced;
}

/// The intersecting pairs of faces of one connected component; `between` counts the others,
/// `truncated` says the enumeration stopped at its limit.
template <class PolygonMesh>
std::vector<std::pair<typename boost::graph_traits<PolygonMesh>::face_descriptor,
                      typename boost::graph_traits<PolygonMesh>::face_descriptor>>
pairs_within_components(const PolygonMesh& pm, std::size_t& between, bool& truncated) {
  std::vector<std::pair<typename boost::graph_traits<PolygonMesh>::face_descriptor,
                        typename boost::graph_traits<PolygonMesh>::face_descriptor>>
      within;
  const auto found = bounded_self_intersections(pm);
  truncated = found.truncated;
  const auto component = face_components(pm);
  between = 0;
  for (const auto& pair : found.pairs) {
    if (component.at(pair.first) == component.at(pair.second))
      within.push_back(pair);
    else
      ++between;
  }
  return within;
}

/// The spikes among the vertices of the intersecting `pairs` are moved back to the centre of
/// their neighbours (spike_relaxation.h), round after round while a round moves one;
/// `find_pairs` gives the pairs left after each round.
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class PairVector,
          class FindPairs>
void relax_spikes(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits, PairVector& pairs,
                  FindPairs&& find_pairs, Step_timer& timer) {
  Spike_relaxer<PolygonMesh, VertexPointMap> relaxer(pm, vpm);
  Spike_relaxation_report report;
  for (int round = 0; round < max_spike_relaxation_rounds && !pairs.empty(); ++round) {
    if (relaxer.relax(pairs, traits, report) == 0) break;
    pairs = find_pairs();
  }
  if (report.vertices_moved == 0) return;
  timer.count("spike_vertices_moved", double(report.vertices_moved));
  timer.count("spike_largest_move", report.largest_move);
}

/// Before the holes are filled: a spike beside a hole makes every patch of the hole meet it.
/// Only in the parts with a border (a closed part is autorefined first, in
/// step_remove_self_intersections, which keeps its surface as it is), and only where the input
/// intersects itself inside a part; vertices on a border are left to the relaxation after the
/// filling, when they are no longer on one.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
void step_relax_spikes(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                       Any_visitor visitor, Repair_result& result) {
  if (result.self_intersections_input_truncated ||
      result.self_intersections_input <= result.self_intersections_input_between_components)
    return;
  Step_timer timer(result, "spikes", visitor);
  auto pairs_in_open_parts = [&pm] {
    std::size_t between = 0;
    bool truncated = false;
    auto pairs = pairs_within_components(pm, between, truncated);
    if (truncated) pairs.clear();
    const auto component = face_components(pm);
    std::unordered_set<std::size_t> open;
    for (auto h : halfedges(pm))
      if (is_border(h, pm)) open.insert(component.at(face(opposite(h, pm), pm)));
    pairs.erase(
        std::remove_if(pairs.begin(), pairs.end(),
                       [&](const auto& pair) { return !open.count(component.at(pair.first)); }),
        pairs.end());
    return pairs;
  };
  auto pairs = pairs_in_open_parts();
  relax_spikes(pm, vpm, traits, pairs, pairs_in_open_parts, timer);
}

/// Self-intersections inside one connected component are removed: the intersecting faces and
/// the faces within 1, then 2 vertex rings are replaced by checked patches (Region_replacer),
/// all or nothing per region. Intersections between two components (an assembly of touching
/// solids) are kept: each part stays a solid of its own and nothing is lost (doc:
/// automatic_repair.md, "Self-intersections").
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
void step_remove_self_intersections(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                                    const Repair_options& options, Any_visitor visitor,
                                    Repair_result& result) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  Step_timer timer(result, "self-intersection removal", visitor);
  bool truncated = false;
  auto within_component_pairs = [&](std::size_t& between) {
    return pairs_within_components(pm, between, truncated);
  };
  std::size_t between = 0;
  auto pairs = within_component_pairs(between);
  timer.count("pairs_within_components_before", double(pairs.size()));
  timer.count("pairs_between_components_kept", double(between));
  if (truncated) {
    // Past the pair limit the mesh intersects itself nearly everywhere: no local replacement
    // or autorefinement applies, and both would cost as much as the pairs.
    timer.count("pairs_truncated", 1.0);
    timer.step().notes.push_back("at least " + std::to_string(pairs.size() + between) +
                                 " self-intersecting pairs (the pair limit): not removed");
    result.self_intersections_between_components = between;
    return;
  }
  // Closed parts first: their autorefinement keeps the surface as it is outside the volume,
  // where region replacement would cut a part that crosses itself and cap the ends.
  if (!pairs.empty() && autorefine_self_intersecting_parts(pm, vpm, traits, pairs, timer) > 0)
    pairs = within_component_pairs(between);
  // Then spikes: moved back, a spike keeps every face, where region replacement would remove
  // its rings.
  if (!pairs.empty())
    relax_spikes(
        pm, vpm, traits, pairs, [&] { return within_component_pairs(between); }, timer);
  std::unordered_set<face_descriptor> involved;
  for (const auto& pair : pairs) involved.insert({pair.first, pair.second});
  Region_replacement_report total;
  if (double(involved.size()) > max_self_intersecting_face_fraction * double(count_faces(pm)))
    timer.step().notes.push_back(std::to_string(involved.size()) +
                                 " self-intersecting faces, over " +
                                 std::to_string(int(100 * max_self_intersecting_face_fraction)) +
                                 "% of the faces: not replaced by patches");
  else
    for (int rings = 1; rings <= max_self_intersection_rings && !pairs.empty(); ++rings) {
      if (!visitor.progress(0.5 * (rings - 1))) {
        result.cancelled = true;
        break;
      }
      std::vector<std::vector<face_descriptor>> regions;
      for (const auto& pair : pairs) {
        std::vector<vertex_descriptor> seeds;
        for (face_descriptor f : {pair.first, pair.second})
          for (vertex_descriptor v : vertices_around_face(halfedge(f, pm), pm)) seeds.push_back(v);
        regions.push_back(faces_within_rings(pm, seeds, rings));
      }
      Replacement_bounds bounds;
      bounds.max_part_share = max_replaced_part_share;
      replace_regions(pm, vpm, traits, options, visitor, regions, total, bounds);
      pairs = within_component_pairs(between);
    }
  timer.count("regions_replaced", double(total.regions_replaced));
  timer.count("faces_removed", double(total.faces_removed));
  timer.count("faces_added", double(total.faces_added));
  if (total.regions_too_large > 0)
    timer.count("regions_too_large", double(total.regions_too_large));
  timer.count("pairs_within_components_after", double(pairs.size()));
  result.self_intersections_between_components = between;
  if (total.faces_not_restored > 0) {
    timer.count("faces_not_restored", double(total.faces_not_restored));
    timer.step().notes.push_back(std::to_string(total.faces_not_restored) +
                                 " face(s) of regions that could not be refilled could not be put "
                                 "back");
  }
}

/// With `merge_intersecting_solids`, closed parts that intersect one another (an assembly of
/// interpenetrating solids) are replaced by their union (CGAL's corefinement,
/// solid_union.h), one union per group of parts linked by intersections; where two parts have
/// coplanar faces that meet (`coplanar_faces`), or the corefinement fails, by the exact
/// arrangement of self_union.h. A group with a part that is open, intersects itself or bounds no
/// volume keeps its parts, and a note says why.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
void step_merge_intersecting_solids(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                                    Any_visitor visitor, Repair_result& result) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  Step_timer timer(result, "intersecting solids merged", visitor);
  auto pairs = bounded_self_intersections(pm).pairs;
  const auto component = face_components(pm);
  std::size_t components = 0;
  for (const auto& c : component) components = std::max(components, c.second + 1);
  CGAL::Union_find<std::size_t> linked;
  std::vector<CGAL::Union_find<std::size_t>::handle> handle;
  for (std::size_t c = 0; c < components; ++c) handle.push_back(linked.make_set(c));
  std::vector<bool> involved(components, false), coplanar(components, false);
  for (const auto& pair : pairs) {
    const std::size_t a = component.at(pair.first), b = component.at(pair.second);
    if (a == b) continue;
    involved[a] = involved[b] = true;
    linked.unify_sets(handle[a], handle[b]);
    if (coplanar_faces(pm, vpm, traits, pair.first, pair.second)) coplanar[a] = true;
  }
  const auto faces_of = faces_by_component(pm, component);
  std::map<std::size_t, std::vector<std::size_t>> groups;  // by the group's first part
  for (std::size_t c = 0; c < components; ++c)
    if (involved[c]) groups[*linked.find(handle[c])].push_back(c);
  std::size_t merged = 0, unions = 0, refused = 0, removed = 0, added = 0, exact_unions = 0,
              touching_separated = 0, thin_dropped = 0;
  for (const auto& group : groups) {
    std::vector<Triangle_soup> solids;
    for (std::size_t c : group.second) solids.push_back(soup_of_faces(pm, vpm, faces_of[c]));
    Triangle_soup united;
    const bool flat_contact = std::any_of(group.second.begin(), group.second.end(),
                                          [&](std::size_t c) { return coplanar[c]; });
    std::string why = flat_contact ? "two of them have coplanar faces that meet, which "
                                     "CGAL's corefinement does not handle reliably"
                                   : union_of_solids(solids, united);
    if (!why.empty()) {
      // The exact arrangement takes coplanar contacts, and what the corefinement refused.
      Solid_autorefinement measures;
      const std::string exact_why = union_of_solids_exactly(solids, united, measures);
      why = exact_why.empty() ? std::string() : why + "; the exact arrangement: " + exact_why;
      exact_unions += exact_why.empty();
      if (exact_why.empty()) {
        touching_separated += measures.touching_vertices_separated;
        thin_dropped += measures.thin_solids_dropped;
      }
    }
    if (!why.empty()) {
      ++refused;
      timer.step().notes.push_back(std::to_string(group.second.size()) +
                                   " intersecting parts kept apart: " + why);
      continue;
    }
    if (!add_soup(pm, vpm, united)) {
      ++refused;
      timer.step().notes.push_back(std::to_string(group.second.size()) +
                                   " intersecting parts kept apart: their union cannot be put in "
                                   "the mesh");
      continue;
    }
    for (std::size_t c : group.second) {
      for (face_descriptor f : faces_of[c]) CGAL::Euler::remove_face(halfedge(f, pm), pm);
      removed += faces_of[c].size();
    }
    added += united.polygons.size();
    merged += group.second.size();
    ++unions;
  }
  result.solids_merged = merged;
  if (unions > 0) {
    pairs = bounded_self_intersections(pm).pairs;
    const auto after = face_components(pm);
    std::size_t between = 0;
    for (const auto& pair : pairs) between += after.at(pair.first) != after.at(pair.second);
    result.self_intersections_between_components = between;
  }
  timer.count("groups_of_intersecting_parts", double(groups.size()));
  timer.count("parts_merged", double(merged));
  timer.count("unions", double(unions));
  if (exact_unions > 0) timer.count("unions_by_exact_arrangement", double(exact_unions));
  if (touching_separated > 0)
    timer.count("touching_vertices_separated", double(touching_separated));
  if (thin_dropped > 0) timer.count("thin_solids_dropped", double(thin_dropped));
  timer.count("groups_kept_apart", double(refused));
  timer.count("faces_removed", double(removed));
  timer.count("faces_added", double(added));
}

/// Holes that the filling left open (failed, too large, outlines of sheets) whose border is gone
/// from the output: a later step replaced or removed the faces around them (the growth of a
/// neighbouring failed hole, the self-intersection removal). The report must say what the
/// written mesh shows, so they are counted as closed later, with a note.
template <class PolygonMesh, class VertexPointMap, class Point>
void reconcile_open_holes(const PolygonMesh& pm, VertexPointMap vpm,
                          const std::vector<Point>& border_points, const std::string& cause,
                          Step_timer& timer, Repair_result& result) {
  std::set<Point> on_border;
  for (auto h : halfedges(pm))
    if (is_border(h, pm)) on_border.insert(get(vpm, target(h, pm)));
  std::size_t closed_later = 0;
  Fill_result& holes = result.holes;
  for (std::size_t k = 0; k < holes.holes.size() && k < border_points.size(); ++k) {
    Hole_fill_report& hole = holes.holes[k];
    if (hole.filled || on_border.count(border_points[k])) continue;
    hole.notes.push_back("no longer open in the output: " + cause + " (before: " + hole.failure +
                         ")");
    if (hole.skipped) {
      --holes.skipped;
      if (hole.sheet_border) --holes.sheet_borders;
    } else {
      --holes.failed;
    }
    hole.failure.clear();
    hole.skipped = hole.sheet_border = false;
    hole.filled = true;
    ++holes.filled;
    ++closed_later;
  }
  result.sheet_borders_left_open = holes.sheet_borders;
  result.holes_too_large = holes.skipped - holes.sheet_borders;
  if (closed_later > 0) timer.count("open_holes_closed_later", double(closed_later));
}

/// Faces of all filled patches and their one-ring are not known here (regions were copied
/// back), so the verification counts self-intersections of the whole output and compares with
/// the input count: new pairs can only come from the repair.
template <class PolygonMesh, class VertexPointMap, class Point>
void step_verify(const PolygonMesh& pm, VertexPointMap vpm, const std::vector<Point>& border_points,
                 const Repair_options& options, Repair_result& result, Any_visitor visitor) {
  Step_timer timer(result, "verification", visitor);
  result.valid = CGAL::is_valid_polygon_mesh(pm);
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> non_manifold;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(pm, std::back_inserter(non_manifold));
  result.manifold = non_manifold.empty();
  result.border_cycles_left = border_cycles(pm).size();
  result.closed = result.border_cycles_left == 0;
  reconcile_open_holes(pm, vpm, border_points,
                       "a later step (the growth of a failed hole, the self-intersection "
                       "removal) replaced or removed the faces around it",
                       timer, result);
  if (options.detect_self_intersections) {
    set_output_self_intersections(pm, result);
    result.self_intersections_checked = true;
    if (result.self_intersections_between_components >
        result.self_intersections_input_between_components)
      timer.count("pairs_between_components_added",
                  double(result.self_intersections_between_components -
                         result.self_intersections_input_between_components));
  }
  result.output_vertices = count_vertices(pm);
  result.output_faces = count_faces(pm);
  timer.count("valid", result.valid);
  timer.count("manifold", result.manifold);
  timer.count("border_cycles_left", double(result.border_cycles_left));
  timer.count("self_intersections", double(result.self_intersections_output));
}

/// One line per thing left undone, for `Repair_result::remaining`.
inline void list_remaining(Repair_result& result) {
  auto add = [&](bool condition, const std::string& line) {
    if (condition) result.remaining.push_back(line);
  };
  add(!result.valid, "the output is not a valid polygon mesh");
  add(!result.manifold, "non-manifold vertices remain");
  add(result.holes.failed > 0,
      std::to_string(result.holes.failed) + " hole(s) could not be filled");
  add(result.holes_too_large > 0,
      std::to_string(result.holes_too_large) + " hole(s) larger than the size limit left open");
  add(result.sheet_borders_left_open > 0,
      std::to_string(result.sheet_borders_left_open) +
          " outline(s) of open sheets left open (sheet_border_ratio)");
  add(!result.closed && result.holes.failed == 0 && result.holes_too_large == 0 &&
          result.sheet_borders_left_open == 0,
      std::to_string(result.border_cycles_left) + " border cycle(s) remain");
  add(result.self_intersections_in_patches > 0,
      std::to_string(result.self_intersections_in_patches) +
          " self-intersecting face pair(s) more than in the input");
  const std::size_t between =
      std::min(result.self_intersections_between_components, result.self_intersections_output);
  add(result.self_intersections_checked && result.self_intersections_output > between &&
          result.self_intersections_in_patches == 0,
      std::string(result.self_intersections_output_truncated ? "at least " : "") +
          std::to_string(result.self_intersections_output - between) +
          " self-intersecting face pair(s) (already in the input" +
          (result.self_intersections_joined_by_stitching > 0
               ? "; " +
                     std::to_string(std::min(result.self_intersections_joined_by_stitching,
                                             result.self_intersections_output - between)) +
                     " of them between parts that stitching joined)"
               : ")"));
  add(result.self_intersections_checked && between > 0 && result.self_intersections_in_patches == 0,
      std::to_string(between) +
          " self-intersecting face pair(s) between separate components (each stays a solid of its "
          "own)");
  // A count stopped at its limit proves nothing about the pairs it did not reach: the output
  // is not shown free of self-intersections (300 concentric spheres: 0 pairs found before the
  // candidate limit, and "complete").
  add(result.self_intersections_checked && result.self_intersections_output_truncated,
      "the self-intersection count of the output stopped at its limit (internal/bounded_pairs.h): "
      "the faces it did not reach are not checked");
  for (const std::string& step : result.unavailable_steps)
    result.remaining.push_back(step + " is not available for this mesh type");
  add(result.cancelled, "cancelled before the end");
}

/// The pipeline of `automatic_repair` on plain options, up to the verification; `hole_points`
/// receives a border point of each hole the filling met (for later reconciliations).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Repair_result run_repair_pipeline(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits, const Repair_options& options,
    Any_visitor visitor,
    std::vector<typename boost::property_traits<VertexPointMap>::value_type>& hole_points) {
#ifdef CGAL_LINKED_WITH_TBB
  // The parallel steps (self-intersection counts, hole filling) run on TBB's pool; the limit holds
  // for the duration of the call.
  std::unique_ptr<tbb::global_control> limit;
  if (options.fill.number_of_threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  std::size_t(options.fill.number_of_threads));
#endif
  Repair_result result;
  result.input_vertices = count_vertices(pm);
  result.input_faces = count_faces(pm);
  if (options.detect_self_intersections) {
    Step_timer timer(result, "input self-intersections", visitor);
    const auto census = self_intersection_census(pm);
    result.self_intersections_input = census.all;
    result.self_intersections_input_between_components = census.between;
    result.self_intersections_input_truncated = census.truncated;
    timer.count("pairs", double(result.self_intersections_input));
    timer.count("pairs_between_components",
                double(result.self_intersections_input_between_components));
    if (census.truncated) timer.count("pairs_truncated", 1.0);
  }
  step_exact_stitching(pm, result, visitor);
  step_tolerance_stitching(pm, vpm, traits, options, visitor, result);
  if (!result.cancelled && options.detect_self_intersections)
    step_count_pairs_joined_by_stitching(pm, result, visitor);
  if (!result.cancelled) step_non_manifold_vertices(pm, result, visitor);
  if (!result.cancelled) step_close_slits(pm, vpm, result, visitor);
  if (!result.cancelled) step_degenerate_faces(pm, vpm, result, visitor);
  if (!result.cancelled && options.keep_largest_component)
    step_largest_component(pm, result, visitor);
  if (!result.cancelled && options.remove_hole_fragments)
    step_remove_hole_fragments(pm, vpm, options, visitor, result);
  if (!result.cancelled && options.bridge_through_holes)
    step_bridge_through_holes(pm, vpm, traits, visitor, result);
  if (!result.cancelled && options.repair_self_intersections && options.detect_self_intersections)
    step_relax_spikes(pm, vpm, traits, visitor, result);
  hole_points.clear();
  if (!result.cancelled) hole_points = step_fill_holes(pm, vpm, traits, options, visitor, result);
  if (!result.cancelled && options.repair_self_intersections)
    step_remove_self_intersections(pm, vpm, traits, options, visitor, result);
  if (!result.cancelled && options.merge_intersecting_solids)
    step_merge_intersecting_solids(pm, vpm, traits, visitor, result);
  step_verify(pm, vpm, hole_points, options, result, visitor);
  list_remaining(result);
  return result;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_REPAIR_STEPS_H
