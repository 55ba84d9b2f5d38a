// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_FILL_HOLES_H
#define CGAL_MESH_REPAIR_FILL_HOLES_H

/// \file fill_holes.h
/// The hole-filling dispatcher: `fill_hole` fills one hole, `fill_holes` every selected hole,
/// with the method named by `fill_method`. Whatever the method, every patch is checked with exact
/// predicates (no self-intersection with itself, its surrounding ring or any other face of the
/// mesh near it, earlier patches included; the hole closed) and a
/// patch that fails is rolled back and reported, never left in the mesh. Ring holes (a hole with
/// island cycles inside) are detected and bridged into one simple hole first. Independent holes
/// are filled at the same time (TBB), each on a copy of its surroundings, and the patches are
/// spliced and checked in hole order, so the mesh is the same for any number of threads. See
/// doc/fill_holes.md and doc/automatic_repair.md ("Parallelism").

#include <CGAL/Mesh_repair/hole_filling/fill_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/hole_filling/advancing_front.h>
#include <CGAL/Mesh_repair/hole_filling/curvature_variation.h>
#include <CGAL/Mesh_repair/hole_filling/liepa.h>
#include <CGAL/Mesh_repair/hole_filling/shape_prediction.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/hole_filling/local_region.h>
#include <CGAL/Mesh_repair/internal/hole_filling/open_sheets.h>
#include <CGAL/Mesh_repair/internal/hole_filling/patch_check.h>
#include <CGAL/Mesh_repair/internal/hole_filling/pinches.h>
#include <CGAL/Mesh_repair/internal/hole_filling/planar_borders.h>
#include <CGAL/Mesh_repair/internal/hole_filling/ring_holes.h>
#include <CGAL/Mesh_repair/internal/hole_filling/self_validation.h>
#include <CGAL/Mesh_repair/internal/mesh_counts.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// The `hole_filter` used when none is given: every hole is selected.
struct Accept_every_hole {
  bool operator()(const Hole_description&) const { return true; }
};

namespace internal {

template <class halfedge_descriptor>
using Hole_list = std::vector<halfedge_descriptor>;

/// "1.23e-02 s": a duration for the reports, three significant digits, always as long: text
/// whose length follows the clock would make the heap's layout, and with it the order in which
/// CGAL's triangulations visit their elements (by address), differ from run to run.
template <class Duration>
std::string seconds_text(Duration duration) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e s", std::chrono::duration<double>(duration).count());
  return text;
}

/// "2.4": a ratio for the reports, `decimals` decimals.
inline std::string fixed_text(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

/// A patch whose new vertices reach farther than this from the centroid of its border, in
/// border radii (`patch_reach_in_border_radii`), is rejected. No surface a border predicts
/// reaches that far: a cap on a round border reaches 1, the front's regrown tip of a limb cut
/// across (punched holes of 0.12 diagonal on libcgal-demo's elephant and femur) 2.2-2.3. A front
/// that must go around something standing in its hole grows a bag instead: 3.4-4.1 radii on
/// holes of 5-15 edges of libcgal-demo's b9_mesh, twice a Debian cardboard box's height below a
/// slot of its lid (doc/fill_holes.md).
constexpr double max_patch_reach_in_border_radii = 3.0;

inline Hole_fill_report method_not_available(Fill_method method) {
  Hole_fill_report report;
  report.requested = report.used = method;
  report.failure = std::string("method ") + to_string(method) + " is not available in this build";
  return report;
}

// ---------------------------------------------------------------------------------------------
// The method table. How to add a method:
//  - Give it an options struct in hole_filling/fill_options.h (a member of `Fill_options`, read
//    from the named parameters by `fill_options_from`).
//  - A method that fills one hole at a time: write hole_filling/<method>.h with
//      namespace internal {
//      template <class PolygonMesh, class VertexPointMap, class GeomTraits>
//      Hole_fill_report fill_hole_<method>(PolygonMesh& pm, VertexPointMap vpm,
//          const GeomTraits& traits, halfedge_descriptor border_halfedge,
//          Fill_patch<PolygonMesh>& patch, const <Method>_options& options,
//          Face_box_cache<PolygonMesh, VertexPointMap>* face_boxes);
//      }
//    plus the public `fill_hole_<method>(pm, border_halfedge, patch, np)` that reads `np`
//    into its options; include it at the top of this file and return its result from its case
//    in `fill_one_hole`.
//  - A method that solves all selected holes together (one sparse system): the same with
//      std::vector<Hole_fill_report> fill_holes_<method>(PolygonMesh& pm, VertexPointMap vpm,
//          const std::vector<halfedge_descriptor>& border_halfedges,
//          std::vector<Fill_patch<PolygonMesh>>& patches, const <Method>_options& options,
//          Any_visitor visitor);
//    (`patches` has one entry per hole, reports in the same order), return it from its case in
//    `fill_all_holes`, and return true for it in `fills_all_holes_at_once`.
// The contract of a method: each hole is one border cycle (ring holes are already bridged); it
// appends every face and vertex it creates to the hole's `Fill_patch`, even when it fails, and
// may move only those new vertices and the hole's border vertices and their neighbours; it sets
// `filled` when it believes the hole closed, `failure` otherwise. It neither checks nor rolls
// back: the dispatcher verifies every patch (closed, no self-intersection, exact predicates)
// and removes rejected ones. (The advancing front tries several placements and keeps the first
// that passes the same exact check, through the dispatcher's `face_boxes`; it rolls back only
// its own rejected attempts.) It reads the mesh only
// within two rings of the border and, through `face_boxes`, the faces near the hole: holes
// are filled on copies holding those (internal/hole_filling/local_region.h), from several
// threads, so a method keeps no shared mutable state and draws random numbers only from
// `random_seed`.
// ---------------------------------------------------------------------------------------------

/// True for the methods that take every selected hole at once.
inline bool fills_all_holes_at_once(Fill_method method) {
  return method == Fill_method::curvature_variation;
}

template <class PolygonMesh, class VertexPointMap>
std::vector<Hole_fill_report> fill_all_holes(
    Fill_method method, PolygonMesh& pm, VertexPointMap vpm,
    const Hole_list<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& holes,
    std::vector<Fill_patch<PolygonMesh>>& patches, const Fill_options& options,
    Any_visitor visitor) {
  switch (method) {
    case Fill_method::curvature_variation:
      return fill_holes_curvature_variation(pm, vpm, holes, patches, options.curvature_variation,
                                            visitor)
          .holes;
    default:
      break;
  }
  return std::vector<Hole_fill_report>(holes.size(), method_not_available(method));
}

/// One hole with one method; `face_boxes`: the boxes of the faces near the hole, or null.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Hole_fill_report fill_one_hole(Fill_method method, PolygonMesh& pm, VertexPointMap vpm,
                               const GeomTraits& traits,
                               typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                               Fill_patch<PolygonMesh>& patch, const Fill_options& options,
                               Face_box_cache<PolygonMesh, VertexPointMap>* face_boxes) {
  if (fills_all_holes_at_once(method)) {
    std::vector<Fill_patch<PolygonMesh>> patches(1);
    Default_visitor quiet;
    const auto reports = fill_all_holes(method, pm, vpm, {h}, patches, options, Any_visitor(quiet));
    patch = patches.front();
    return reports.front();
  }
  switch (method) {
    case Fill_method::advancing_front:
      return fill_hole_advancing_front(pm, vpm, traits, h, patch, options.advancing_front,
                                       face_boxes);
    case Fill_method::liepa:
      return fill_hole_liepa(pm, vpm, traits, h, patch, options.liepa);
    case Fill_method::shape_prediction:
      return fill_hole_shape_prediction(pm, vpm, traits, h, patch, options.shape_prediction,
                                        face_boxes);
    case Fill_method::curvature_variation:
    case Fill_method::automatic:
    case Fill_method::self_validated:
      break;
  }
  return method_not_available(method);
}

/// The methods `automatic` tries, in order, on each hole: the first patch that passes the check
/// is kept. Advancing front is fast and matches the surrounding density; CGAL's Liepa
/// triangulation succeeds on the holes where the front gets stuck (very non-planar borders).
/// Shape prediction falls back to Liepa, then the advancing front. The issue ("Hole filling
/// II") orders the two the other way, but where shape prediction fails (its front on the
/// patches stuck, or no triangulation has valid chords) the advancing front stuck too on 28 of
/// 35 held-out holes, after up to 18 placements (median 0.035 s, up to 0.23 s), and 5 of the 7
/// patches it made were farther from the truth than Liepa's; Liepa takes milliseconds
/// (doc/shape_prediction.md, "Fallback order"). The front still comes before the last resort.
/// Both sequences end with Liepa at C0 (see `Hole_filler::fill`).
inline std::vector<Fill_candidate> shape_prediction_sequence() {
  return {{Fill_method::shape_prediction, -1},
          {Fill_method::liepa, -1},
          {Fill_method::advancing_front, -1}};
}
inline std::vector<Fill_candidate> automatic_sequence() {
  return {{Fill_method::advancing_front, -1}, {Fill_method::liepa, -1}};
}

/// Vertex rings removed around a hole to validate the methods on (self_validation.h). More
/// rings, or rings in proportion to the hole's radius, were tried on the three suites of
/// doc/fill_holes.md: better on one, worse on another (fewer cases won against CGAL's C1).
constexpr int self_validation_rings = 2;
/// Larger holes are not validated, and only the last resorts (Liepa C0, refined, triangulated)
/// fill them: four fills of the enlarged hole would cost more than the fill itself, the front
/// and the C1/C2 fairings took minutes each on 1,200- to 2,828-edge borders (and failed there),
/// and such borders are rarely holes in a smooth surface (doc/fill_holes.md, "Large holes").
constexpr std::size_t max_self_validation_edges = 1000;
/// The same for holes whose patch would hold more triangles at the border's edge length: the
/// cost of the methods grows with the patch (a 1,000-edge circle at 0.006 spacing: 180,000
/// triangles, 190 s over the whole sequence; at 100,000 and below, under 20 s).
constexpr std::size_t max_faired_patch_triangles = 100000;

/// Triangles of a patch with the border's mean edge length over the larger of the border's
/// flat area and a strip one edge wide along it (equilateral triangles: 0.433 l^2 each).
inline double expected_patch_triangles(const Border_cycle_geometry& g) {
  const double l = g.mean_edge_length;
  if (!(l > 0)) return 0;
  return std::max(norm(g.vector_area), g.perimeter * l) / (0.433 * l * l);
}

/// Fills the hole groups of one mesh: bridges, calls the methods, checks and rolls back.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
class Hole_filler {
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using Group = Hole_group<halfedge_descriptor>;
  using Patch = Fill_patch<PolygonMesh>;
  using Transaction = Patch_transaction<PolygonMesh, VertexPointMap>;
  using Clock = std::chrono::steady_clock;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Region = Local_region<PolygonMesh, Point>;
  using Local_mesh = typename Region::Mesh;

 public:
  /// What the task of one hole computes on its own copy of the hole's surroundings.
  struct Local_fill {
    Region region;
    Fill_patch<Local_mesh> patch;
    Hole_fill_report report;
  };
  Hole_filler(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
              const Fill_options& options, Any_visitor visitor)
      : pm_(pm),
        vpm_(vpm),
        traits_(traits),
        check_(options.check_self_intersections),
        options_(options),
        visitor_(visitor),
        near_faces_(pm, vpm, options.other_parts_are_obstacles) {}

  Hole_description describe(const Group& group) const {
    Hole_description d;
    const Border_cycle_geometry g = cycle_geometry(group.outer, pm_, vpm_);
    d.border_edges = g.edges;
    d.perimeter = g.perimeter;
    d.diameter = g.diameter;
    d.island_cycles = group.islands.size();
    for (halfedge_descriptor island : group.islands)
      d.island_edges += cycle_halfedges(island, pm_).size();
    return d;
  }

  /// Fills one group with `method` (`automatic`: each method of `automatic_sequence` in turn).
  Hole_fill_report fill(const Group& group, Fill_method method, Patch& patch) {
    const auto start_time = Clock::now();
    if (check_) near_faces_.build();
    const Border_cycle_geometry outer = cycle_geometry(group.outer, pm_, vpm_);
    Hole_fill_report report;
    std::vector<std::string> fallbacks, notes;
    // Each rejected attempt is listed with its time: on a hard hole the fill's time is the sum.
    auto rejected = [&fallbacks](const std::string& name, const Hole_fill_report& failed,
                                 Clock::time_point since) {
      fallbacks.push_back(name + " (" + seconds_text(Clock::now() - since) +
                          "): " + failed.failure);
    };
    if (method == Fill_method::liepa && options_.liepa.then_last_resorts) {
      report = attempt(group, method, patch);
      if (!report.filled) {
        rejected(Fill_candidate{method, int(options_.liepa.fairing_continuity)}.name(), report,
                 start_time);
        report = last_resorts(group, patch, rejected);
        report.fallbacks = fallbacks;
      }
    } else if (method != Fill_method::automatic && method != Fill_method::shape_prediction &&
               method != Fill_method::self_validated) {
      report = attempt(group, method, patch);
    } else {
      for (const Fill_candidate& candidate : sequence(group, method, notes)) {
        const auto attempt_start = Clock::now();
        // In a sequence, a stuck front hands over to the next method: the remnant closing
        // (a triangulation without interior nodes) is far from the surface on the holes that
        // need it (doc/advancing_front.md), where Liepa's fairing is not.
        report = candidate.method == Fill_method::advancing_front && !candidate.close_stuck_front
                     ? attempt(group, candidate.method, patch, without_remnant_closing())
                     : attempt(group, candidate.method, patch, candidate.options(options_));
        if (report.filled) break;
        rejected(candidate.name(), report, attempt_start);
      }
      if (!report.filled) report = last_resorts(group, patch, rejected);
      report.fallbacks = fallbacks;
      report.notes.insert(report.notes.begin(), notes.begin(), notes.end());
    }
    report.requested = method;
    report.border_edges = outer.edges;
    report.perimeter = outer.perimeter;
    report.seconds = std::chrono::duration<double>(Clock::now() - start_time).count();
    return report;
  }

  /// The last resorts of a sequence, coarsest last. A membrane (C0) patch lies in the convex
  /// hull of its border (maximum principle), so it cannot bulge into a facing patch or a nearby
  /// sheet the way the C1/C2 patches can. When its fairing, then its refinement, folds the
  /// patch (large or saddle-shaped borders: a 1,000-edge circle, a bowl's rim), CGAL's
  /// triangulation of the border alone closes the hole with the border's vertices only. Where
  /// Liepa's triangulation itself crosses over the folds of a jagged, nearly flat border (a
  /// scan's cut-off side), the same three stages start from the border's projected
  /// triangulation. Where the surface dips below its outline, the outline is extruded to a flat
  /// base (projected_triangulation.h), not refined: CGAL's refinement flips the edges between
  /// the walls and the base, folding them into the mesh.
  template <class Rejected>
  Hole_fill_report last_resorts(const Group& group, Patch& patch, Rejected& rejected) {
    using T = Hole_triangulation;
    struct Stage {
      Liepa_stage stage;
      Hole_triangulation triangulation;
      const char* name;
    };
    const Stage stages[] = {
        {Liepa_stage::fair, T::minimum_weight, "liepa (C0)"},
        {Liepa_stage::refine, T::minimum_weight, "liepa (refined, not faired)"},
        {Liepa_stage::triangulate, T::minimum_weight, "liepa (triangulated only)"},
        {Liepa_stage::fair, T::projected, "projected triangulation, refined and faired (C0)"},
        {Liepa_stage::refine, T::projected, "projected triangulation, refined"},
        {Liepa_stage::triangulate, T::projected, "projected triangulation"},
        {Liepa_stage::triangulate, T::projected_base, "base"}};
    Hole_fill_report report, shown;
    for (const Stage& stage : stages) {
      // A base reaches past the mesh; through another part it would join the two.
      if (stage.triangulation == T::projected_base && !options_.other_parts_are_obstacles) continue;
      const auto attempt_start = Clock::now();
      Fill_options options = Fill_candidate{Fill_method::liepa, 0}.options(options_);
      options.liepa.last_stage = stage.stage;
      options.liepa.triangulation = stage.triangulation;
      report = attempt(group, Fill_method::liepa, patch, options);
      if (report.filled) {
        report.notes.push_back(std::string("filled by ") + stage.name +
                               ": the patches of the methods before it were rejected");
        return report;
      }
      rejected(stage.name, report, attempt_start);
      // The failure shown is Liepa's; the projected ones are in the fallbacks.
      if (stage.triangulation == T::minimum_weight) shown = report;
    }
    return shown;
  }

  /// Takes the faces of the mesh as the obstacles of every hole (before the first patch).
  void build_face_boxes() { near_faces_.build(); }

  /// Fills `group` on a copy of its surroundings (local_region.h). Only reads the mesh and the
  /// face boxes, so the tasks of several holes run at the same time; `build_face_boxes()`
  /// comes first.
  void fill_locally(const Group& group, Fill_method method, Local_fill& local) const {
    copy_local_region(pm_, vpm_, group, &near_faces_, local.region);
    if (!local.region.usable) return;
    auto local_vpm = get(CGAL::vertex_point, local.region.mesh);
    Default_visitor quiet;  // tasks of several threads: no progress from inside a hole
    Hole_filler<Local_mesh, decltype(local_vpm), GeomTraits> filler(
        local.region.mesh, local_vpm, traits_, options_, Any_visitor(quiet));
    local.report = filler.fill(local.region.group, method, local.patch);
  }

  /// Adds the patch of `fill_locally` to the mesh and checks it against the whole mesh like
  /// any patch. A hole the copy could not hold, or whose patch meets the mesh away from the
  /// copy, is filled in place by `fill`; a hole no method could fill on the copy is reported
  /// unfilled (the copy holds every face the methods and their checks look at).
  Hole_fill_report splice(const Group& group, Fill_method method, Local_fill& local, Patch& patch) {
    if (!local.region.usable) return fill(group, method, patch);
    Hole_fill_report report = local.report;
    report.faces_created = report.vertices_created = 0;
    if (!report.filled) return report;
    Transaction transaction(pm_, vpm_, all_cycles(group));
    if (!splice_local_patch(pm_, vpm_, local.region, local.patch, movable_vertices(group), patch)) {
      report.filled = false;
      report.failure = "the patch could not be attached to the hole's border";
    }
    std::vector<Pinch_weld<PolygonMesh>> no_welds;
    report = verify(report, group, patch, transaction, no_welds);
    if (report.filled) return report;
    Hole_fill_report in_place = fill(group, method, patch);
    in_place.notes.push_back("the patch computed on a copy of the hole's surroundings was " +
                             std::string("rejected in the mesh (") + report.failure +
                             "); filled in place");
    return in_place;
  }

  /// Fills every group with a method that takes all holes at once.
  std::vector<Hole_fill_report> fill_together(const std::vector<Group>& groups, Fill_method method,
                                              std::vector<Patch>& patches) {
    const auto start = Clock::now();
    if (check_) near_faces_.build();
    std::vector<Transaction> transactions;
    std::vector<std::vector<Pinch_weld<PolygonMesh>>> welds(groups.size());
    std::vector<std::size_t> bridge_faces(groups.size(), 0);
    std::vector<Hole_fill_report> reports(groups.size());
    std::vector<halfedge_descriptor> holes;
    std::vector<std::size_t> hole_group;
    std::vector<Border_cycle_geometry> outer;
    for (const Group& group : groups) outer.push_back(cycle_geometry(group.outer, pm_, vpm_));
    for (std::size_t k = 0; k < groups.size(); ++k) {
      transactions.emplace_back(pm_, vpm_, all_cycles(groups[k]));
      const halfedge_descriptor h = bridge(groups[k], patches[k], reports[k]);
      if (h == GT::null_halfedge()) {
        transactions.back().rollback(patches[k]);
        continue;
      }
      bridge_faces[k] = patches[k].faces.size();
      for (halfedge_descriptor cycle : weld_pinches(pm_, vpm_, h, welds[k])) {
        holes.push_back(cycle);
        hole_group.push_back(k);
      }
    }
    // A hole that the welds turned into slits only is closed by zipping them, with no patch.
    std::vector<bool> attempted(groups.size(), false);
    std::vector<Hole_fill_report> combined(groups.size());
    for (std::size_t k = 0; k < groups.size(); ++k)
      if (!welds[k].empty() &&
          std::find(hole_group.begin(), hole_group.end(), k) == hole_group.end())
        attempted[k] = combined[k].filled = true;
    std::vector<Patch> method_patches(holes.size());
    const std::vector<Hole_fill_report> method_reports =
        fill_all_holes(method, pm_, vpm_, holes, method_patches, options_, visitor_);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (std::size_t j = 0; j < holes.size(); ++j) {
      const std::size_t k = hole_group[j];
      append(patches[k], method_patches[j]);
      Hole_fill_report& report = combined[k];
      if (!attempted[k]) report.filled = true;
      attempted[k] = true;
      report.notes.insert(report.notes.end(), method_reports[j].notes.begin(),
                          method_reports[j].notes.end());
      if (!method_reports[j].filled && report.filled) {
        report.filled = false;
        report.failure = method_reports[j].failure;
      }
    }
    std::size_t attempted_count = 0;
    for (std::size_t k = 0; k < groups.size(); ++k) attempted_count += attempted[k] ? 1 : 0;
    for (std::size_t k = 0; k < groups.size(); ++k) {
      if (!attempted[k]) continue;
      combined[k].used = method;
      reports[k] = verify(combined[k], groups[k], patches[k], transactions[k], welds[k], false,
                          bridge_faces[k]);
      reports[k].seconds = seconds / double(attempted_count);
    }
    for (std::size_t k = 0; k < groups.size(); ++k) {
      reports[k].requested = method;
      reports[k].border_edges = outer[k].edges;
      reports[k].perimeter = outer[k].perimeter;
    }
    return reports;
  }

 private:
  std::vector<halfedge_descriptor> all_cycles(const Group& group) const {
    std::vector<halfedge_descriptor> cycles{group.outer};
    cycles.insert(cycles.end(), group.islands.begin(), group.islands.end());
    return cycles;
  }

  /// The vertices a method may move: the border vertices and their neighbours.
  std::unordered_set<typename GT::vertex_descriptor> movable_vertices(const Group& group) const {
    std::unordered_set<typename GT::vertex_descriptor> movable;
    for (halfedge_descriptor cycle : all_cycles(group))
      for (halfedge_descriptor h : halfedges_around_face(cycle, pm_))
        for (halfedge_descriptor around : halfedges_around_target(target(h, pm_), pm_))
          movable.insert(source(around, pm_)), movable.insert(target(around, pm_));
    return movable;
  }

  static void append(Patch& to, const Patch& from) {
    to.faces.insert(to.faces.end(), from.faces.begin(), from.faces.end());
    to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  }

  /// Bridges the islands of `group` into its outer cycle; returns a border halfedge of the
  /// resulting single cycle, or null (with `report.failure`) when an island cannot be bridged.
  halfedge_descriptor bridge(const Group& group, Patch& patch, Hole_fill_report& report) {
    halfedge_descriptor h = group.outer;
    report.island_cycles = group.islands.size();
    for (halfedge_descriptor island : group.islands) {
      const double edge_length = cycle_geometry(h, pm_, vpm_).mean_edge_length;
      h = bridge_island(pm_, vpm_, h, island, edge_length, patch);
      if (h == GT::null_halfedge()) {
        report.failure = "no valid bridge between the hole and one of its islands";
        return h;
      }
    }
    return h;
  }

  /// The methods a sequence tries on `group`, in order. `self_validated` ranks the faired
  /// methods by their error on the hole enlarged by `self_validation_rings` rings (on a copy),
  /// then the front; ring holes keep the default order (the enlarged hole would merge the
  /// islands). A missing planar face (`is_creased_planar_border`) is filled flat first: the
  /// enlarged hole reaches up the walls, where the faired candidates continue them into a bowl.
  std::vector<Fill_candidate> sequence(const Group& group, Fill_method method,
                                       std::vector<std::string>& notes) const {
    if (method == Fill_method::automatic) return automatic_sequence();
    if (method == Fill_method::shape_prediction) return shape_prediction_sequence();
    std::vector<Fill_candidate> ranked = self_validation_candidates();
    const Border_cycle_geometry g = cycle_geometry(group.outer, pm_, vpm_);
    const double triangles = expected_patch_triangles(g);
    if (g.edges > max_self_validation_edges || triangles > double(max_faired_patch_triangles)) {
      notes.push_back("a large hole (" + std::to_string(g.edges) + " border edges, about " +
                      std::to_string(std::llround(triangles)) + " patch triangles; limits " +
                      std::to_string(max_self_validation_edges) + " and " +
                      std::to_string(max_faired_patch_triangles) +
                      "): only Liepa's C0 fairing and its coarser stages are tried");
      return {};
    } else if (group.islands.empty() && is_creased_planar_border(pm_, vpm_, traits_, group.outer)) {
      // No front: where the flat membrane fails, something crosses the plane, and a front that
      // goes around it grows a bag (doc/fill_holes.md, "A missing planar face").
      notes.push_back(
          "a missing planar face: the border lies in one plane and every face along it leaves the "
          "plane at a crease; the flat membrane (Liepa C0) first, then the faired methods in the "
          "default order, no advancing front");
      ranked.insert(ranked.begin(), Fill_candidate{Fill_method::liepa, 0});
      return ranked;
    } else if (group.islands.empty()) {
      std::string note;
      const auto fill_one = [this](const Fill_candidate& candidate, auto& mesh, auto border,
                                   const Fill_options& options, auto& patch) {
        return fill_one_hole(
            candidate.method, mesh, get(CGAL::vertex_point, mesh), traits_, border, patch, options,
            static_cast<Face_box_cache<std::decay_t<decltype(mesh)>,
                                       decltype(get(CGAL::vertex_point, mesh))>*>(nullptr));
      };
      ranked = rank_fill_candidates(pm_, vpm_, traits_, group.outer, options_,
                                    self_validation_rings, fill_one, note);
      notes.push_back(note);
    } else {
      notes.push_back("self-validation: not done on a ring hole; default order");
    }
    // The front last, first handing a stuck front on, then closing its remnant: near other
    // sheets (close components) the faired patches bulge into them where the front does not.
    ranked.push_back({Fill_method::advancing_front, -1});
    ranked.push_back({Fill_method::advancing_front, -1, true});
    return ranked;
  }

  /// In a sequence, a stuck front hands over to the next method instead of closing its remnant.
  Fill_options without_remnant_closing() const {
    Fill_options options = options_;
    options.advancing_front.close_stuck_front = false;
    return options;
  }

  Hole_fill_report attempt(const Group& group, Fill_method method, Patch& patch) {
    return attempt(group, method, patch, options_);
  }

  Hole_fill_report attempt(const Group& group, Fill_method method, Patch& patch,
                           const Fill_options& options) {
    Transaction transaction(pm_, vpm_, all_cycles(group));
    Hole_fill_report report;
    report.requested = report.used = method;
    const halfedge_descriptor h = bridge(group, patch, report);
    if (h == GT::null_halfedge()) {
      transaction.rollback(patch);
      return report;
    }
    const std::size_t bridge_faces = patch.faces.size();
    std::vector<Pinch_weld<PolygonMesh>> welds;
    const std::vector<halfedge_descriptor> cycles = weld_pinches(pm_, vpm_, h, welds);
    report.filled = true;
    // A single patch that its method tested exactly against the mesh as it is now needs no
    // second test; with several (bridged islands, welded pinches) the face-box cache the methods
    // test against does not hold the parts added before.
    bool self_checked = cycles.size() == 1 && group.islands.empty() && welds.empty();
    for (halfedge_descriptor cycle : cycles) {
      Patch method_patch;
      const Hole_fill_report part = fill_one_hole(method, pm_, vpm_, traits_, cycle, method_patch,
                                                  options, check_ ? &near_faces_ : nullptr);
      append(patch, method_patch);
      report.notes.insert(report.notes.end(), part.notes.begin(), part.notes.end());
      self_checked = self_checked && part.exactly_checked;
      if (!part.filled) {
        report.filled = false;
        report.failure = part.failure;
        break;
      }
    }
    return verify(report, group, patch, transaction, welds, self_checked, bridge_faces);
  }

  /// Keeps the patch when the method filled the hole, the hole is closed and the patch meets
  /// neither itself nor its ring (not tested again when `self_checked`: see `attempt`);
  /// otherwise rolls it back. Completes the report's counts.
  Hole_fill_report verify(Hole_fill_report report, const Group& group, Patch& patch,
                          Transaction& transaction, std::vector<Pinch_weld<PolygonMesh>>& welds,
                          bool self_checked = false, std::size_t bridge_faces = 0) {
    report.island_cycles = group.islands.size();
    if (report.filled && patch.faces.empty() && welds.empty()) {
      report.filled = false;
      report.failure = "the method created no face";
    }
    if (report.filled && !closed(patch)) {
      report.filled = false;
      report.failure = "the patch leaves border edges open";
    }
    if (report.filled && check_) {
      const double reach = patch_reach_in_border_radii(pm_, patch, vpm_);
      if (reach > max_patch_reach_in_border_radii) {
        report.filled = false;
        report.failure = "the patch reaches " + fixed_text(reach, 1) +
                         " border radii from the border's centre (at most " +
                         fixed_text(max_patch_reach_in_border_radii, 1) + ")";
      }
    }
    if (report.filled && check_ && !self_checked) {
      const std::size_t pairs =
          patch_intersections_with_mesh(pm_, patch, vpm_, traits_, near_faces_);
      if (pairs > 0) {
        report.filled = false;
        report.failure =
            "the patch self-intersects (" + std::to_string(pairs) + " pairs of intersecting faces)";
      }
    }
    if (!report.filled) {
      if (report.failure.empty()) report.failure = "the method reported failure";
      roll_back(patch, bridge_faces, transaction, welds);
    } else if (check_) {
      near_faces_.keep(patch, transaction.moved_vertices());
    }
    if (report.filled && !welds.empty()) {
      const std::size_t pinches = welds.size();
      const std::size_t zipped = commit_pinches(pm_, welds);
      report.notes.push_back(
          "welded " + std::to_string(pinches) + " pinch(es) where the border touched itself" +
          (zipped > 0 ? ", zipped " + std::to_string(zipped) + " two-edge slit(s) into single edges"
                      : std::string()));
    }
    report.faces_created = patch.faces.size();
    report.vertices_created = patch.vertices.size();
    return report;
  }

  /// Undoes a fill in the reverse order of its making: the method's faces (added after the
  /// welds), the welds, then the `bridge_faces` first faces of `patch`, which bridged the islands
  /// before the welds. Removing a bridge face next to a welded vertex first changes the fans
  /// whose halfedges the weld swaps back, and leaves a vertex whose halfedges circle forever.
  void roll_back(Patch& patch, std::size_t bridge_faces, Transaction& transaction,
                 std::vector<Pinch_weld<PolygonMesh>>& welds) {
    Patch bridges;
    if (!welds.empty() && bridge_faces > 0) {
      bridges.faces.assign(patch.faces.begin(), patch.faces.begin() + bridge_faces);
      patch.faces.erase(patch.faces.begin(), patch.faces.begin() + bridge_faces);
    }
    transaction.rollback(patch);
    unweld_pinches(pm_, welds);
    if (!bridges.faces.empty()) transaction.rollback(bridges);
  }

  bool closed(const Patch& patch) const {
    for (auto f : patch.faces) {
      for (halfedge_descriptor c : halfedges_around_face(halfedge(f, pm_), pm_)) {
        if (is_border(opposite(c, pm_), pm_)) return false;
      }
    }
    return true;
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  GeomTraits traits_;
  bool check_;
  const Fill_options& options_;
  Any_visitor visitor_;
  Face_box_cache<PolygonMesh, VertexPointMap> near_faces_;
};

/// Runs `task(0)` ... `task(n - 1)` on `threads` threads of TBB (0: TBB's default), or one
/// after the other without TBB or with one thread.
template <class Task>
void for_each_index(std::size_t n, int threads, const Task& task) {
#ifdef CGAL_LINKED_WITH_TBB
  if (threads != 1 && n > 1) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] { tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { task(i); }); });
    return;
  }
#endif
  (void)threads;
  for (std::size_t i = 0; i < n; ++i) task(i);
}

/// Holes whose patches are computed together before they are spliced. A fixed number, not one
/// per thread: a batch's copies see the patches of the batches before it, so the result must
/// not depend on how many threads there are.
constexpr std::size_t hole_batch_size = 32;

/// Fills the `selected` groups by batches: each hole of a batch is filled on a copy of its
/// surroundings, in parallel, then the patches are spliced into the mesh and checked one after
/// the other in hole order. Whatever `threads`, each hole's patch is the same function of the
/// mesh and the splices happen in the same order: the result is the same. Returns false when
/// the visitor cancelled (the holes not spliced are reported skipped).
template <class Filler, class Group, class Visitor, class PolygonMesh>
bool fill_in_batches(Filler& filler, const std::vector<Group>& groups,
                     const std::vector<std::size_t>& selected, Fill_method method, int threads,
                     Visitor& visitor, Fill_result& result,
                     std::vector<Fill_patch<PolygonMesh>>& patches) {
  filler.build_face_boxes();
  for (std::size_t begin = 0; begin < selected.size(); begin += hole_batch_size) {
    const std::size_t end = std::min(selected.size(), begin + hole_batch_size);
    std::vector<typename Filler::Local_fill> local(end - begin);
    for_each_index(end - begin, threads, [&](std::size_t i) {
      filler.fill_locally(groups[selected[begin + i]], method, local[i]);
    });
    for (std::size_t j = begin; j < end; ++j) {
      if (!visitor.progress(double(j) / double(selected.size()))) {
        for (std::size_t rest = j; rest < selected.size(); ++rest) {
          result.holes[selected[rest]].skipped = true;
          result.holes[selected[rest]].failure = "cancelled";
        }
        return false;
      }
      const std::size_t k = selected[j];
      result.holes[k] = filler.splice(groups[k], method, local[j - begin], patches[k]);
    }
  }
  return true;
}

/// The remnant closings of the advancing front (`Advancing_front_options::
/// remnant_visits_per_hole`) visit at most this many stored triangles per hole and per face of
/// the mesh: a budget proportional to the input. Meshes of 3,000 faces and more keep the whole 60
/// million; small meshes whose holes have no valid closing no longer spend it all (the fuzzed
/// files and figures are in doc/fuzzing.md).
constexpr std::size_t remnant_visits_per_mesh_face = 20000;

/// Fills `groups` (all selected unless `apply_selection` is false); reports in group order.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Fill_result fill_hole_groups(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
    const std::vector<Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>>&
        groups,
    std::vector<Fill_patch<PolygonMesh>>& patches, const Fill_options& options, Any_visitor visitor,
    bool apply_selection) {
  const Fill_method method = options.method;
  using Filler = Hole_filler<PolygonMesh, VertexPointMap, GeomTraits>;
  // Taken from the whole mesh before any hole is filled (a hole may be filled in a local copy),
  // so that the result does not depend on the number of threads.
  Fill_options bounded = options;
  std::size_t& visits = bounded.advancing_front.remnant_visits_per_hole;
  visits = (std::min)(visits, remnant_visits_per_mesh_face * count_faces(pm));
  Filler filler(pm, vpm, traits, bounded, visitor);
  const double diagonal = mesh_bbox_diagonal(pm, vpm);

  Fill_result result;
  result.holes.resize(groups.size());
  patches.assign(groups.size(), Fill_patch<PolygonMesh>());
  std::vector<std::size_t> selected;
  const std::vector<double> sheet_ratios = sheet_border_ratios(pm, vpm, groups);
  for (std::size_t k = 0; k < groups.size(); ++k) {
    Hole_description d = filler.describe(groups[k]);
    d.relative_size = diagonal > 0 ? d.diameter / diagonal : 0;
    d.sheet_ratio = sheet_ratios[k];
    Hole_fill_report& report = result.holes[k];
    report.requested = report.used = method;
    report.border_edges = d.border_edges;
    report.island_cycles = d.island_cycles;
    report.perimeter = d.perimeter;
    const bool selected_by_size = d.border_edges + d.island_edges <= options.max_hole_edges &&
                                  d.relative_size <= options.max_hole_size &&
                                  (!options.hole_filter || options.hole_filter(d));
    if (apply_selection && d.sheet_ratio > options.sheet_border_ratio) {
      report.skipped = report.sheet_border = true;
      report.failure = "the outline of an open sheet: its vector area is " +
                       two_decimals(d.sheet_ratio) + " of its component's area (above " +
                       "sheet_border_ratio " + two_decimals(options.sheet_border_ratio) + ")";
    } else if (apply_selection && !selected_by_size) {
      report.skipped = true;
      report.failure = "not selected";
    } else {
      selected.push_back(k);
    }
  }

  visitor.start_step("fill holes");
  if (fills_all_holes_at_once(method)) {
    std::vector<Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>> chosen;
    for (std::size_t k : selected) chosen.push_back(groups[k]);
    std::vector<Fill_patch<PolygonMesh>> chosen_patches(chosen.size());
    const auto reports = filler.fill_together(chosen, method, chosen_patches);
    for (std::size_t j = 0; j < selected.size(); ++j) {
      result.holes[selected[j]] = reports[j];
      patches[selected[j]] = chosen_patches[j];
    }
    visitor.progress(1.0);
  } else {
    result.cancelled = !fill_in_batches(filler, groups, selected, method, options.number_of_threads,
                                        visitor, result, patches);
    if (!result.cancelled) visitor.progress(1.0);
  }
  visitor.end_step("fill holes");

  for (const Hole_fill_report& report : result.holes) {
    if (report.skipped) {
      ++result.skipped;
      if (report.sheet_border) ++result.sheet_borders;
    } else if (report.filled) {
      ++result.filled;
    } else {
      ++result.failed;
    }
  }
  return result;
}

template <class PolygonMesh, class VertexPointMap>
std::vector<Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>> hole_groups(
    const PolygonMesh& pm, VertexPointMap vpm, bool detect_ring_holes) {
  return group_ring_holes(pm, vpm, border_cycles(pm), detect_ring_holes);
}

/// `fill_holes` on plain options: the function the public one calls (and the compiled core
/// instantiates once per mesh type).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Fill_result fill_holes_with_options(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                                    const Fill_options& options, Any_visitor visitor,
                                    std::vector<Fill_patch<PolygonMesh>>& patches) {
  return fill_hole_groups(pm, vpm, traits, hole_groups(pm, vpm, options.detect_ring_holes), patches,
                          options, visitor, true);
}

/// `fill_hole` on plain options.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Hole_fill_report fill_hole_with_options(
    PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    const Fill_options& options, Any_visitor visitor, Fill_patch<PolygonMesh>& patch) {
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  std::unordered_set<halfedge_descriptor> cycle;
  for (halfedge_descriptor h : halfedges_around_face(border_halfedge, pm)) cycle.insert(h);
  Hole_group<halfedge_descriptor> group{border_halfedge, {}};
  for (const auto& candidate : hole_groups(pm, vpm, options.detect_ring_holes)) {
    if (cycle.count(candidate.outer)) group.islands = candidate.islands;
  }
  std::vector<Fill_patch<PolygonMesh>> patches;
  Fill_result result = fill_hole_groups(pm, vpm, traits, {group}, patches, options, visitor, false);
  patch = patches.front();
  return result.holes.front();
}

/// The vertex point map and traits of a pack, as every public function of this file reads them.
template <class PolygonMesh, class NamedParameters>
struct Fill_parameters {
  using GeomTraits = typename CGAL::GetGeomTraits<PolygonMesh, NamedParameters>::type;
  using Vpm = typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::type;
  Fill_parameters(PolygonMesh& pm, const NamedParameters& np)
      : vpm(parameters::choose_parameter(
            parameters::get_parameter(np, CGAL::internal_np::vertex_point),
            get_property_map(CGAL::vertex_point, pm))),
        traits(parameters::choose_parameter<GeomTraits>(
            parameters::get_parameter(np, CGAL::internal_np::geom_traits))),
        options(fill_options_from(np)),
        visitor(np) {}
  Vpm vpm;
  GeomTraits traits;
  Fill_options options;
  Visitor_parameter<NamedParameters> visitor;
};

}  // namespace internal

/// Fills every selected hole of `pm` with the method `fill_method`, checking every patch with
/// exact predicates and rolling back the patches that fail. A hole whose region contains island
/// border cycles (a ring hole) is bridged to them and filled as one region.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph`, triangulated
/// \param pm the mesh; `CGAL::is_valid_polygon_mesh(pm)` holds after the call
/// \param patches (overload) receives, per hole of the result, the faces and vertices kept
/// \param np named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{fill_method}
///     \cgalParamDescription{the method (`Fill_method`); `self_validated` ranks the faired
///       methods per hole by how well each predicts the known rings around it (see
///       doc/fill_holes.md, "Self-validated choice"); `automatic` tries advancing front, then
///       CGAL's Liepa (faster, less faithful); both record the fallbacks}
///     \cgalParamDefault{`Fill_method::self_validated`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_hole_edges}
///     \cgalParamDescription{holes with more border edges (islands included) are left open}
///     \cgalParamType{std::size_t} \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_hole_size}
///     \cgalParamDescription{holes whose border's bounding-box diagonal exceeds this fraction of
///       the mesh's bounding-box diagonal are left open}
///     \cgalParamType{double} \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{sheet_border_ratio}
///     \cgalParamDescription{a border cycle whose vector area (the area of its flat filling)
///       exceeds this fraction of the area of the connected component it borders is the outline
///       of an open sheet (a terrain, a scanned face) rather than a hole, and is left open and
///       reported (`Hole_fill_report::sheet_border`); a hole of a sphere's half is at 0.5, a flat
///       sheet's outline at 1. Infinity fills every cycle}
///     \cgalParamType{double} \cgalParamDefault{0.9}
///   \cgalParamNEnd
///   \cgalParamNBegin{hole_filter}
///     \cgalParamDescription{predicate `bool(const Hole_description&)`; holes it rejects are
///       left open}
///     \cgalParamDefault{`Accept_every_hole()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{detect_ring_holes}
///     \cgalParamDescription{find island cycles inside holes and fill each such ring hole as one
///       region; when false every border cycle is a hole of its own}
///     \cgalParamType{bool} \cgalParamDefault{true}
///   \cgalParamNEnd
///   \cgalParamNBegin{check_self_intersections}
///     \cgalParamDescription{check every patch against itself, its ring and every face of
///       the mesh whose bounding box meets the patch's (earlier patches included) with CGAL's
///       exact `self_intersections`; only turn off for measurements}
///     \cgalParamType{bool} \cgalParamDefault{true}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads (TBB) computing the patches of independent holes, each on
///       a copy of its surroundings; the patches are then spliced and checked in hole order, so
///       the mesh is the same for any number of threads (see doc/automatic_repair.md). Methods
///       that fill all holes at once (`curvature_variation`) run on one thread}
///     \cgalParamType{int} \cgalParamDefault{0: TBB's default (all cores)}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress and cancellation, see `Default_visitor`; one step
///       "fill holes", cancellation takes effect between holes}
///     \cgalParamDefault{`Default_visitor()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits} \cgalParamDefault{deduced from the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{(method parameters)}
///     \cgalParamDescription{passed on to the method: see hole_filling/advancing_front.h,
///       hole_filling/liepa.h (`fairing_continuity`) and the other methods' headers}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns one report per hole (ring holes count once), in border-cycle order.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Fill_result fill_holes(PolygonMesh& pm, std::vector<Fill_patch<PolygonMesh>>& patches,
                       const NamedParameters& np = parameters::default_values()) {
  internal::Fill_parameters<PolygonMesh, NamedParameters> p(pm, np);
  return internal::fill_holes_with_options(pm, p.vpm, p.traits, p.options, p.visitor.get(),
                                           patches);
}

template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Fill_result fill_holes(PolygonMesh& pm, const NamedParameters& np = parameters::default_values()) {
  std::vector<Fill_patch<PolygonMesh>> patches;
  return fill_holes(pm, patches, np);
}

/// Fills the hole of the border halfedge `border_halfedge` (with its islands, when it is a ring
/// hole and `detect_ring_holes` is true) like `fill_holes`, ignoring the selection parameters.
/// `patch` (overload) receives the faces and vertices kept.
/// \pre `is_border(border_halfedge, pm)`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Hole_fill_report fill_hole(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const NamedParameters& np = parameters::default_values()) {
  CGAL_precondition(is_border(border_halfedge, pm));
  internal::Fill_parameters<PolygonMesh, NamedParameters> p(pm, np);
  return internal::fill_hole_with_options(pm, p.vpm, p.traits, border_halfedge, p.options,
                                          p.visitor.get(), patch);
}

template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Hole_fill_report fill_hole(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    const NamedParameters& np = parameters::default_values()) {
  Fill_patch<PolygonMesh> patch;
  return fill_hole(pm, border_halfedge, patch, np);
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_FILL_HOLES
extern
#endif
    template Fill_result
    fill_holes_with_options<Core_mesh, Core_vpm, Core_traits>(Core_mesh&, Core_vpm,
                                                              const Core_traits&,
                                                              const Fill_options&, Any_visitor,
                                                              std::vector<Fill_patch<Core_mesh>>&);
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_FILL_HOLES
extern
#endif
    template Hole_fill_report
    fill_hole_with_options<Core_mesh, Core_vpm, Core_traits>(Core_mesh&, Core_vpm,
                                                             const Core_traits&, Core_halfedge,
                                                             const Fill_options&, Any_visitor,
                                                             Fill_patch<Core_mesh>&);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_FILL_HOLES_H
