// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_REGION_REPLACEMENT_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_REGION_REPLACEMENT_H

// Replacing regions of faces by checked hole-filling patches, all or nothing per region: the
// faces are removed, every hole that the removal opened is filled, and a region whose holes are
// not all filled is put back as it was. Two steps of automatic_repair use it: holes whose
// patches were all rejected are grown by rings of faces and filled again (the folded and
// overlapping triangles of scanned borders go with the ring, Pernot's "uncertainty area"), and
// self-intersecting faces are removed with their ring and the holes refilled (MeshFix's idea,
// here with the exact patch checks of fill_holes).

#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/finite_distance_traits.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/hole_filling/patch_check.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <iomanip>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// What one region replacement did.
struct Region_replacement_report {
  std::size_t regions = 0;             ///< after merging the regions that share a vertex
  std::size_t regions_replaced = 0;    ///< every hole they opened was filled
  std::size_t faces_removed = 0;       ///< in the replaced regions
  std::size_t faces_added = 0;         ///< by their patches
  std::size_t faces_not_restored = 0;  ///< of failed regions, could not be put back (counted)
  std::size_t regions_too_far = 0;     ///< filled, but a patch was too far from the faces removed
  std::size_t regions_too_large =
      0;                       ///< left alone: too large a share of their part's faces and area
  std::vector<bool> replaced;  ///< per region given, in the caller's order
  /// Per region given, for the replaced ones: the faces and vertices of the patches of the holes
  /// its removal opened, and the faces removed, all of the merged regions it succeeded or failed
  /// with (`regions_merged` of them, itself included), so that a caller records them per region.
  std::vector<std::size_t> region_faces_added, region_vertices_added, region_faces_removed,
      regions_merged;
  std::vector<Fill_method> region_method;  ///< the method of the first patch of each region's holes
  /// Per region given: empty when replaced, else why its faces were left or put back.
  std::vector<std::string> region_failure;
};

/// The connected component (by edges) of every face.
template <class PolygonMesh>
std::unordered_map<typename boost::graph_traits<PolygonMesh>::face_descriptor, std::size_t>
face_components(const PolygonMesh& pm) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::unordered_map<face_descriptor, std::size_t> component;
  std::size_t next = 0;
  for (face_descriptor seed : faces(pm)) {
    if (component.count(seed)) continue;
    std::vector<face_descriptor> stack{seed};
    component.emplace(seed, next);
    while (!stack.empty()) {
      const face_descriptor f = stack.back();
      stack.pop_back();
      for (auto h : halfedges_around_face(halfedge(f, pm), pm)) {
        const auto g = face(opposite(h, pm), pm);
        if (g != boost::graph_traits<PolygonMesh>::null_face() && component.emplace(g, next).second)
          stack.push_back(g);
      }
    }
    ++next;
  }
  return component;
}

/// The parts (components of `component`) a face of which meets a face of another part (exact
/// predicates, bounded enumeration), the faces of `skipped` left out.
template <class PolygonMesh, class VertexPointMap, class GeomTraits, class FaceComponents,
          class FaceSet>
std::unordered_set<std::size_t> parts_in_contact(const PolygonMesh& pm, VertexPointMap vpm,
                                                 const GeomTraits& traits,
                                                 const FaceComponents& component,
                                                 const FaceSet& skipped) {
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> range;
  for (auto f : faces(pm))
    if (!skipped.count(f)) range.push_back(f);
  std::unordered_set<std::size_t> parts;
  const auto found =
      Bounded_face_intersections<PolygonMesh, VertexPointMap, GeomTraits>(pm, vpm, traits)
          .find(range, nullptr, default_pair_limit(range.size()));
  for (const auto& pair : found.pairs)
    if (component.at(pair.first) != component.at(pair.second)) {
      parts.insert(component.at(pair.first));
      parts.insert(component.at(pair.second));
    }
  return parts;
}

/// The faces within `rings` vertex rings of `seeds` (the seeds included), ring by ring; with
/// `ring_of`, the ring of each (1: a face around a seed).
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> faces_within_rings(
    const PolygonMesh& pm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& seeds,
    int rings, std::vector<int>* ring_of = nullptr) {
  using GT = boost::graph_traits<PolygonMesh>;
  std::unordered_set<typename GT::vertex_descriptor> reached(seeds.begin(), seeds.end());
  std::vector<typename GT::vertex_descriptor> frontier(seeds.begin(), seeds.end());
  std::unordered_set<typename GT::face_descriptor> seen;
  std::vector<typename GT::face_descriptor> faces;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<typename GT::vertex_descriptor> next_frontier;
    for (auto v : frontier) {
      for (auto f : faces_around_target(halfedge(v, pm), pm)) {
        if (f == GT::null_face() || !seen.insert(f).second) continue;
        faces.push_back(f);
        if (ring_of) ring_of->push_back(ring + 1);
        for (auto w : vertices_around_face(halfedge(f, pm), pm))
          if (reached.insert(w).second) next_frontier.push_back(w);
      }
    }
    frontier.swap(next_frontier);
  }
  return faces;
}

/// Removes regions of faces and fills the holes they open; see the file comment.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
class Region_replacer {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Group = Hole_group<halfedge_descriptor>;

 public:
  Region_replacer(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                  const Fill_options& options, Any_visitor visitor)
      : pm_(pm), vpm_(vpm), traits_(traits), options_(options), visitor_(visitor) {}

  /// Replaces each of `regions` (face sets; regions sharing a vertex are merged and succeed or
  /// fail together). The holes are filled with `apply_selection` false: they are the caller's.
  Region_replacement_report replace(const std::vector<std::vector<face_descriptor>>& regions) {
    Region_replacement_report report;
    std::vector<std::size_t> unit_of;
    std::vector<std::vector<face_descriptor>> unit_faces = units_of(regions, unit_of);
    const std::size_t units = unit_faces.size();
    report.regions = units;
    std::vector<Removed> removed(units);
    for (std::size_t u = 0; u < units; ++u) {
      removed[u].faces = std::move(unit_faces[u]);
      removed[u].skipped = pinches(removed[u].faces) > 0;
      if (removed[u].skipped) removed[u].failure = "its removal would pinch a vertex";
      if (!removed[u].skipped) record(removed[u]);
      // A region with no kept face along it is a whole component: removing it opens no hole
      // and would lose it.
      if (removed[u].rim.empty() && !removed[u].skipped) {
        removed[u].skipped = true;
        removed[u].failure = "it is a whole part";
      }
    }
    if (max_part_share < 1) skip_large_shares_of_parts(removed, report);
    // The opposite of every rim halfedge is a border halfedge of the unit's holes once the
    // faces are gone: it finds the holes each unit opened.
    std::unordered_map<halfedge_descriptor, std::size_t> unit_of_border;
    for (std::size_t u = 0; u < units; ++u)
      for (halfedge_descriptor h : removed[u].rim) unit_of_border.emplace(opposite(h, pm_), u);
    for (Removed& unit : removed)
      if (!unit.skipped) remove_faces(unit);

    std::vector<Group> groups;
    std::vector<std::vector<std::size_t>> units_of_group;
    for (const Group& group : hole_groups(pm_, vpm_, options_.detect_ring_holes)) {
      std::vector<std::size_t> touched = units_touched(group, unit_of_border);
      if (touched.empty()) continue;
      groups.push_back(group);
      units_of_group.push_back(std::move(touched));
    }
    // A hole opened by two units ties them: both succeed or both fail.
    std::vector<std::size_t> tie(units);
    std::iota(tie.begin(), tie.end(), std::size_t(0));
    for (const auto& touched : units_of_group)
      for (std::size_t u : touched) join(tie, touched.front(), u);

    std::vector<std::vector<halfedge_descriptor>> cycles_of_tie(units);
    for (std::size_t k = 0; k < groups.size(); ++k) {
      auto& cycles = cycles_of_tie[find(tie, units_of_group[k].front())];
      cycles.push_back(groups[k].outer);
      cycles.insert(cycles.end(), groups[k].islands.begin(), groups[k].islands.end());
    }
    std::vector<Patch_transaction<PolygonMesh, VertexPointMap>> transactions;
    std::vector<std::size_t> transaction_of_tie(units, std::size_t(-1));
    for (std::size_t t = 0; t < units; ++t) {
      if (cycles_of_tie[t].empty()) continue;
      transaction_of_tie[t] = transactions.size();
      transactions.emplace_back(pm_, vpm_, cycles_of_tie[t]);
    }

    std::vector<double> edge_length(units, 0.0), edges(units, 0.0);  // of the holes, per tie
    for (std::size_t k = 0; k < groups.size(); ++k) {
      const std::size_t t = find(tie, units_of_group[k].front());
      add_border_edges(groups[k], edge_length[t], edges[t]);
    }
    std::vector<Fill_patch<PolygonMesh>> patches;
    const Fill_result filled =
        fill_hole_groups(pm_, vpm_, traits_, groups, patches, options_, visitor_, false);
    fill_results.push_back(filled);
    // A tie succeeds when it opened holes and every one of them was filled (and, with a
    // deviation bound, its patches stay near the faces it removed).
    std::vector<bool> tie_ok(units, false);
    std::vector<std::string> tie_failure(units, "its removal opened no hole");
    for (std::size_t k = 0; k < groups.size(); ++k) {
      tie_ok[find(tie, units_of_group[k].front())] = true;
      tie_failure[find(tie, units_of_group[k].front())].clear();
    }
    for (std::size_t k = 0; k < groups.size(); ++k) {
      const std::size_t t = find(tie, units_of_group[k].front());
      if (filled.holes[k].filled || !tie_ok[t]) continue;
      tie_ok[t] = false;
      tie_failure[t] = "the patch of the hole it opened (" +
                       std::to_string(filled.holes[k].border_edges) +
                       " edges) was rejected: " + filled.holes[k].failure;
    }
    std::vector<Triangle> surface;
    std::unique_ptr<Triangle_tree> tree;
    for (std::size_t t = 0; t < units; ++t) {
      const double bound =
          (std::min)(max_deviation, max_deviation_in_border_edges > 0
                                        ? max_deviation_in_border_edges * edge_length[t] / edges[t]
                                        : max_deviation);
      if (!tie_ok[t] || !std::isfinite(bound)) continue;
      if (!tree) {
        surface = surface_triangles();
        tree = std::make_unique<Triangle_tree>(surface.begin(), surface.end());
      }
      const double farthest = farthest_removed_corner(t, tie, removed, *tree);
      if (farthest > bound) {
        tie_ok[t] = false;
        ++report.regions_too_far;
        tie_failure[t] = "its faces reach " + short_text(farthest) +
                         " from the filled surface, over the bound " + short_text(bound);
      }
    }
    for (std::size_t k = 0; k < groups.size(); ++k) {
      const std::size_t t = find(tie, units_of_group[k].front());
      if (tie_ok[t]) {
        report.faces_added += patches[k].faces.size();
      } else if (transaction_of_tie[t] != std::size_t(-1)) {
        transactions[transaction_of_tie[t]].rollback(patches[k]);
      }
    }
    std::vector<bool> unit_ok(units);
    for (std::size_t u = 0; u < units; ++u) {
      unit_ok[u] = !removed[u].skipped && tie_ok[find(tie, u)];
      if (removed[u].skipped) continue;
      if (unit_ok[u]) {
        ++report.regions_replaced;
        report.faces_removed += removed[u].faces.size();
      } else {
        report.faces_not_restored += restore(removed[u]);
      }
    }
    for (std::size_t r = 0; r < regions.size(); ++r) {
      const std::size_t u = unit_of[r];
      report.replaced.push_back(unit_ok[u]);
      report.region_failure.push_back(unit_ok[u]           ? std::string()
                                      : removed[u].skipped ? removed[u].failure
                                                           : tie_failure[find(tie, u)]);
    }
    record_per_region(unit_of, tie, removed, units_of_group, patches, filled, unit_ok, report);
    return report;
  }

  std::vector<Fill_result> fill_results;  ///< of every call, for the reports
  /// A region is replaced only if every corner of its removed faces lies within this many mean
  /// border edges of its holes from their patches (when positive), and within `max_deviation`:
  /// the patch stands for the faces it replaces instead of rebuilding the surface.
  double max_deviation_in_border_edges = 0;
  double max_deviation = std::numeric_limits<double>::infinity();
  /// A region holding more than this share of both the faces and the area of the parts
  /// (connected components) it lies in is left alone: replacing it would rebuild the part instead
  /// of repairing it (a coarse part is within a few rings of one defect everywhere). Both, since
  /// either alone misjudges: the long faces of a spike are a large area but a few faces, the
  /// small faces of a fillet many faces but a small area.
  double max_part_share = 1;

 private:
  /// A region as removed: its faces (corner vertices and positions), the halfedges of the kept
  /// faces along it (rim), and the corners that leave the mesh with it (no face outside it).
  struct Removed {
    std::vector<face_descriptor> faces;
    std::vector<std::array<vertex_descriptor, 3>> corners;
    std::vector<std::array<Point, 3>> positions;
    std::vector<halfedge_descriptor> rim;
    std::unordered_set<vertex_descriptor> leaving;
    bool skipped = false;  ///< would pinch a vertex or remove a whole component: left alone
    std::string failure;   ///< why it was skipped
  };

  /// Faces around a vertex in circulation order, and whether each stays (not removed, not a
  /// border gap). Removing a region must leave every kept vertex one fan of faces: a vertex
  /// with two fans would be pinched, which no patch can make manifold again.
  std::size_t fans_left(vertex_descriptor v, const std::unordered_set<face_descriptor>& doomed) {
    std::vector<bool> kept;
    for (halfedge_descriptor h : halfedges_around_target(halfedge(v, pm_), pm_)) {
      const face_descriptor f = face(h, pm_);
      kept.push_back(f != GT::null_face() && !doomed.count(f));
    }
    std::size_t fans = 0;
    for (std::size_t i = 0; i < kept.size(); ++i)
      if (kept[i] && !kept[(i + kept.size() - 1) % kept.size()]) ++fans;
    return fans;
  }

  /// The corners of `faces` that would be pinched by their removal.
  std::vector<vertex_descriptor> pinched_corners(const std::vector<face_descriptor>& faces) {
    const std::unordered_set<face_descriptor> doomed(faces.begin(), faces.end());
    std::unordered_set<vertex_descriptor> seen;
    std::vector<vertex_descriptor> pinched;
    for (face_descriptor f : faces)
      for (vertex_descriptor v : vertices_around_face(halfedge(f, pm_), pm_))
        if (seen.insert(v).second && fans_left(v, doomed) > 1) pinched.push_back(v);
    return pinched;
  }

  std::size_t pinches(const std::vector<face_descriptor>& faces) {
    return pinched_corners(faces).size();
  }

  /// Adds the faces around the vertices that `faces` would pinch; false when none.
  bool close_over_pinches(std::vector<face_descriptor>& faces) {
    const std::vector<vertex_descriptor> pinched = pinched_corners(faces);
    std::unordered_set<face_descriptor> in(faces.begin(), faces.end());
    for (vertex_descriptor v : pinched)
      for (face_descriptor f : faces_around_target(halfedge(v, pm_), pm_))
        if (f != GT::null_face() && in.insert(f).second) faces.push_back(f);
    return !pinched.empty();
  }

  /// Merges the units that share a vertex; false when none did.
  bool join_units(std::vector<std::vector<face_descriptor>>& units,
                  std::vector<std::size_t>& unit_of) {
    const std::vector<std::size_t> merged = merge_regions(units);
    const std::size_t count = count_units(merged);
    if (count == units.size()) return false;
    std::vector<std::vector<face_descriptor>> joined(count);
    for (std::size_t u = 0; u < units.size(); ++u)
      joined[merged[u]].insert(joined[merged[u]].end(), units[u].begin(), units[u].end());
    for (auto& unit : joined) {
      std::unordered_set<face_descriptor> seen;
      std::vector<face_descriptor> unique;
      for (face_descriptor f : unit)
        if (seen.insert(f).second) unique.push_back(f);
      unit.swap(unique);
    }
    for (std::size_t& u : unit_of) u = merged[u];
    units.swap(joined);
    return true;
  }

  /// The regions closed over their pinches and merged where they share a vertex, a few passes
  /// (closing can join regions, joining can pinch); `unit_of` maps each region to its unit.
  std::vector<std::vector<face_descriptor>> units_of(
      const std::vector<std::vector<face_descriptor>>& regions, std::vector<std::size_t>& unit_of) {
    std::vector<std::vector<face_descriptor>> units = regions;
    unit_of.resize(regions.size());
    std::iota(unit_of.begin(), unit_of.end(), std::size_t(0));
    for (int pass = 0; pass < 8; ++pass) {
      bool grown = false;
      for (auto& unit : units) grown = close_over_pinches(unit) || grown;
      if (!join_units(units, unit_of) && !grown) return units;
    }
    join_units(units, unit_of);  // a unit still pinched after the passes is skipped (replace)
    return units;
  }

  std::vector<std::size_t> merge_regions(const std::vector<std::vector<face_descriptor>>& regions) {
    std::vector<std::size_t> parent(regions.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::unordered_map<vertex_descriptor, std::size_t> owner;
    std::unordered_map<face_descriptor, std::size_t> face_owner;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      for (face_descriptor f : regions[r]) {
        auto inserted = face_owner.emplace(f, r);
        if (!inserted.second) join(parent, inserted.first->second, r);
        for (vertex_descriptor v : vertices_around_face(halfedge(f, pm_), pm_)) {
          auto at = owner.emplace(v, r);
          if (!at.second) join(parent, at.first->second, r);
        }
      }
    }
    std::map<std::size_t, std::size_t> dense;
    std::vector<std::size_t> unit(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r)
      unit[r] = dense.emplace(find(parent, r), dense.size()).first->second;
    return unit;
  }

  static std::size_t count_units(const std::vector<std::size_t>& unit_of) {
    std::size_t n = 0;
    for (std::size_t u : unit_of) n = std::max(n, u + 1);
    return n;
  }

  static std::size_t find(std::vector<std::size_t>& parent, std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  static void join(std::vector<std::size_t>& parent, std::size_t a, std::size_t b) {
    parent[find(parent, a)] = find(parent, b);
  }

  /// Fills the per-region counts of `report` (see Region_replacement_report): what each tie of
  /// merged regions removed and added, given to every region in it.
  void record_per_region(const std::vector<std::size_t>& unit_of, std::vector<std::size_t>& tie,
                         const std::vector<Removed>& removed,
                         const std::vector<std::vector<std::size_t>>& units_of_group,
                         const std::vector<Fill_patch<PolygonMesh>>& patches,
                         const Fill_result& filled, const std::vector<bool>& unit_ok,
                         Region_replacement_report& report) {
    const std::size_t units = removed.size();
    std::vector<std::size_t> added(units, 0), vertices(units, 0), gone(units, 0), members(units, 0);
    std::vector<Fill_method> method(units, options_.method);
    std::vector<bool> has_method(units, false);
    for (std::size_t k = 0; k < units_of_group.size(); ++k) {
      const std::size_t t = find(tie, units_of_group[k].front());
      added[t] += patches[k].faces.size();
      vertices[t] += patches[k].vertices.size();
      if (!has_method[t]) method[t] = filled.holes[k].used;
      has_method[t] = true;
    }
    for (std::size_t u = 0; u < units; ++u)
      if (unit_ok[u]) gone[find(tie, u)] += removed[u].faces.size();
    for (std::size_t u : unit_of) ++members[find(tie, u)];
    for (std::size_t u : unit_of) {
      const std::size_t t = find(tie, u);
      const bool ok = unit_ok[u];
      report.region_faces_added.push_back(ok ? added[t] : 0);
      report.region_vertices_added.push_back(ok ? vertices[t] : 0);
      report.region_faces_removed.push_back(ok ? gone[t] : 0);
      report.regions_merged.push_back(members[t]);
      report.region_method.push_back(method[t]);
    }
  }

  void record(Removed& unit) {
    std::unordered_set<face_descriptor> in_unit;
    std::vector<face_descriptor> unique;
    for (face_descriptor f : unit.faces)
      if (in_unit.insert(f).second) unique.push_back(f);
    unit.faces.swap(unique);
    for (face_descriptor f : unit.faces) {
      std::array<vertex_descriptor, 3> corners;
      std::array<Point, 3> positions;
      std::size_t i = 0;
      for (halfedge_descriptor h : halfedges_around_face(halfedge(f, pm_), pm_)) {
        if (i < 3) {
          corners[i] = target(h, pm_);
          positions[i] = get(vpm_, target(h, pm_));
        }
        ++i;
        const halfedge_descriptor o = opposite(h, pm_);
        if (!is_border(o, pm_) && !in_unit.count(face(o, pm_))) unit.rim.push_back(o);
      }
      unit.corners.push_back(corners);
      unit.positions.push_back(positions);
    }
    for (const auto& corners : unit.corners) {
      for (vertex_descriptor v : corners) {
        bool kept = false;
        for (face_descriptor g : faces_around_target(halfedge(v, pm_), pm_))
          kept = kept || (g != GT::null_face() && !in_unit.count(g));
        if (!kept) unit.leaving.insert(v);
      }
    }
  }

  /// Adds the lengths and the count of the border edges of `group`.
  void add_border_edges(const Group& group, double& length, double& count) const {
    const auto add = [&](halfedge_descriptor cycle) {
      for (halfedge_descriptor h : halfedges_around_face(cycle, pm_)) {
        length += std::sqrt(CGAL::to_double(
            CGAL::squared_distance(get(vpm_, source(h, pm_)), get(vpm_, target(h, pm_)))));
        count += 1;
      }
    };
    add(group.outer);
    for (halfedge_descriptor island : group.islands) add(island);
  }

  using Triangle = typename GeomTraits::Triangle_3;
  using Triangle_tree = Distance_tree<
      GeomTraits,
      CGAL::AABB_triangle_primitive<GeomTraits, typename std::vector<Triangle>::const_iterator>>;

  /// The triangles of the surface as it is once the holes are filled (the patches of ties that
  /// fail later included: a slight advantage to the others), for `near_surface`.
  std::vector<Triangle> surface_triangles() const {
    std::vector<Triangle> triangles;
    for (face_descriptor f : faces(pm_)) {
      const halfedge_descriptor h = halfedge(f, pm_);
      const Point& p = get(vpm_, source(h, pm_));
      for (halfedge_descriptor g = next(h, pm_); target(g, pm_) != source(h, pm_); g = next(g, pm_))
        triangles.emplace_back(p, get(vpm_, source(g, pm_)), get(vpm_, target(g, pm_)));
    }
    return triangles;
  }

  /// The largest distance from a corner of the faces the units of tie `t` removed to the
  /// surface (`tree`): what a reader of the output measures as the geometry kept.
  double farthest_removed_corner(std::size_t t, std::vector<std::size_t>& tie,
                                 const std::vector<Removed>& removed, const Triangle_tree& tree) {
    double farthest = 0;
    for (std::size_t u = 0; u < removed.size(); ++u) {
      if (removed[u].skipped || find(tie, u) != t) continue;
      for (const auto& corners : removed[u].positions)
        for (const Point& p : corners)
          farthest = (std::max)(farthest, CGAL::to_double(tree.squared_distance(p)));
    }
    return std::sqrt(farthest);
  }

  static std::string short_text(double value) {
    std::ostringstream out;
    out << std::setprecision(3) << value;
    return out.str();
  }

  double face_area(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    const Point& p = get(vpm_, source(h, pm_));
    double area = 0;
    for (halfedge_descriptor g = next(h, pm_); target(g, pm_) != source(h, pm_); g = next(g, pm_))
      area += std::sqrt(CGAL::to_double(traits_.compute_squared_area_3_object()(
          p, get(vpm_, source(g, pm_)), get(vpm_, target(g, pm_)))));
    return area;
  }

  /// Marks skipped (`max_part_share`) the units that hold too large a share of both the faces
  /// and the area of the parts they lie in; parts are labelled once, linear in the mesh.
  void skip_large_shares_of_parts(std::vector<Removed>& removed,
                                  Region_replacement_report& report) {
    const auto part = face_components(pm_);
    std::vector<double> part_area, part_faces;
    for (face_descriptor f : faces(pm_)) {
      const std::size_t p = part.at(f);
      if (p >= part_area.size()) {
        part_area.resize(p + 1, 0.0);
        part_faces.resize(p + 1, 0.0);
      }
      part_area[p] += face_area(f);
      part_faces[p] += 1;
    }
    for (Removed& unit : removed) {
      if (unit.skipped) continue;
      std::unordered_set<std::size_t> parts;
      double area = 0, whole_area = 0, whole_faces = 0;
      for (face_descriptor f : unit.faces) {
        area += face_area(f);
        const std::size_t p = part.at(f);
        if (parts.insert(p).second) {
          whole_area += part_area[p];
          whole_faces += part_faces[p];
        }
      }
      if (area > max_part_share * whole_area &&
          double(unit.faces.size()) > max_part_share * whole_faces) {
        unit.skipped = true;
        unit.failure = "it holds too large a share of its part";
        ++report.regions_too_large;
      }
    }
  }

  void remove_faces(Removed& unit) {
    for (face_descriptor f : unit.faces) CGAL::Euler::remove_face(halfedge(f, pm_), pm_);
  }

  std::vector<std::size_t> units_touched(
      const Group& group,
      const std::unordered_map<halfedge_descriptor, std::size_t>& unit_of_border) {
    std::vector<std::size_t> touched;
    auto visit = [&](halfedge_descriptor cycle) {
      for (halfedge_descriptor h : halfedges_around_face(cycle, pm_)) {
        auto it = unit_of_border.find(h);
        if (it != unit_of_border.end() &&
            std::find(touched.begin(), touched.end(), it->second) == touched.end())
          touched.push_back(it->second);
      }
    };
    visit(group.outer);
    for (halfedge_descriptor island : group.islands) visit(island);
    return touched;
  }

  /// Puts the faces of `unit` back on their corners (vertices that left with them are created
  /// again at their positions); returns how many faces could not be attached.
  std::size_t restore(const Removed& unit) {
    std::unordered_map<vertex_descriptor, vertex_descriptor> now;
    auto current = [&](vertex_descriptor v, const Point& p) {
      auto it = now.find(v);
      if (it != now.end()) return it->second;
      vertex_descriptor w = v;
      if (unit.leaving.count(v)) {
        w = add_vertex(pm_);
        put(vpm_, w, p);
      }
      now.emplace(v, w);
      return w;
    };
    std::vector<std::array<vertex_descriptor, 3>> pending;
    for (std::size_t i = 0; i < unit.corners.size(); ++i) {
      std::array<vertex_descriptor, 3> face;
      for (int c = 0; c < 3; ++c) face[c] = current(unit.corners[i][c], unit.positions[i][c]);
      pending.push_back(face);
    }
    // A face whose corners' fans are not joined yet cannot be attached: retried after others.
    bool progress = true;
    while (!pending.empty() && progress) {
      progress = false;
      std::vector<std::array<vertex_descriptor, 3>> later;
      for (const auto& face : pending) {
        if (CGAL::Euler::can_add_face(face, pm_) &&
            CGAL::Euler::add_face(face, pm_) != GT::null_face())
          progress = true;
        else
          later.push_back(face);
      }
      pending.swap(later);
    }
    return pending.size();
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  const GeomTraits& traits_;
  const Fill_options& options_;
  Any_visitor visitor_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_REGION_REPLACEMENT_H
