// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_THROUGH_HOLES_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_THROUGH_HOLES_H

// Through-holes whose wall is missing. CAD models often give a plate with an opening (a
// calendar's binding holes, a drain in a sink) as the plate's two faces, each with the opening cut
// out, and nothing between them. The two border cycles are translated copies of each other, run
// in opposite directions and bound one part. What the surface misses is the tube between them:
// two caps would close an opening the model shows, and where a rod passes through it (the
// calendar's rings) every cap meets the rod. The tube joins matching vertices quad by quad and is
// kept only when none of its faces meets a face of the mesh or of another tube (CGAL's exact test
// of two faces, as for every fill patch).

#include <CGAL/Mesh_repair/internal/automatic_repair/region_replacement.h>
#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// What the bridging of through-holes did.
struct Through_hole_report {
  std::size_t pairs = 0;        ///< pairs of border cycles that match as the two ends of a tube
  std::size_t bridged = 0;      ///< tubes kept
  std::size_t rejected = 0;     ///< tubes removed again: a face met the mesh or another tube
  std::size_t faces_added = 0;  ///< by the tubes kept
};

/// The match. The two cycles have the same number of edges (at most `max_through_hole_edges`),
/// every vertex of one lies within `through_hole_shape_tolerance` radii of its partner moved by
/// one common translation, and that translation is at most `max_through_hole_depth` radii long
/// and within 60 degrees of the cycle's axis (cosine `min_through_hole_axis_cosine`). The radius
/// is the largest distance of a cycle vertex from the cycle's centroid.
constexpr std::size_t max_through_hole_edges = 1024;
constexpr double through_hole_shape_tolerance = 0.02;
constexpr double max_through_hole_depth = 2.0;
constexpr double min_through_hole_axis_cosine = 0.5;
/// Each cycle is compared with at most this many others (the next ones of its edge count by the x
/// of their centroids): a mesh with thousands of alike holes in a row stays linear.
constexpr std::size_t max_through_hole_candidates = 256;
/// The faces along each end may lean toward the other end by at most 30 degrees (sine).
constexpr double max_through_hole_ring_slope = 0.5;

template <class PolygonMesh>
struct Through_hole_cycle {
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vertices;
  std::vector<Vec3> points;
  std::vector<Vec3> ring_points;  ///< per edge, the third corner of the face along it
  Vec3 centroid;
  Vec3 axis;  ///< unit vector area
  double radius = 0;
  typename boost::graph_traits<PolygonMesh>::face_descriptor face;  ///< a face along the cycle
};

/// The border cycles that may end a tube: simple, of at most `max_through_hole_edges` edges, with
/// a non-zero vector area; sorted by edge count, then by the x of the centroid.
template <class PolygonMesh, class VertexPointMap>
std::vector<Through_hole_cycle<PolygonMesh>> through_hole_cycles(const PolygonMesh& pm,
                                                                 VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::vector<Through_hole_cycle<PolygonMesh>> cycles;
  for (auto h : border_cycles(pm)) {
    Through_hole_cycle<PolygonMesh> cycle;
    std::unordered_set<vertex_descriptor> seen;
    bool simple = true;
    for (auto c : halfedges_around_face(h, pm)) {
      simple = simple && seen.insert(source(c, pm)).second;
      cycle.vertices.push_back(source(c, pm));
      cycle.points.push_back(to_array(get(vpm, source(c, pm))));
      cycle.ring_points.push_back(to_array(get(vpm, target(next(opposite(c, pm), pm), pm))));
      if (cycle.vertices.size() > max_through_hole_edges) break;
    }
    const std::size_t n = cycle.vertices.size();
    if (!simple || n < 3 || n > max_through_hole_edges) continue;
    Vec3 area{0, 0, 0};
    for (std::size_t t = 0; t < n; ++t) {
      cycle.centroid = cycle.centroid + cycle.points[t];
      area = area + cross(cycle.points[t], cycle.points[(t + 1) % n]);
    }
    cycle.centroid = cycle.centroid * (1.0 / double(n));
    for (const Vec3& p : cycle.points)
      cycle.radius = (std::max)(cycle.radius, norm(p - cycle.centroid));
    if (!(norm(area) > 0) || !(cycle.radius > 0)) continue;
    cycle.axis = normalized(area);
    cycle.face = face(opposite(h, pm), pm);
    cycles.push_back(std::move(cycle));
  }
  std::sort(cycles.begin(), cycles.end(), [](const auto& a, const auto& b) {
    return std::make_tuple(a.points.size(), a.centroid[0]) <
           std::make_tuple(b.points.size(), b.centroid[0]);
  });
  return cycles;
}

/// Whether a face along `cycle` leans toward `direction` by more than 30 degrees from the plane
/// normal to it. Around a through-hole the faces along each end lie in the plate's face, or slope
/// away (a chamfer); the faces of an open sleeve run from one end toward the other, and a tube
/// joining its ends would line it from inside.
template <class PolygonMesh>
bool reaches_toward(const Through_hole_cycle<PolygonMesh>& cycle, const Vec3& direction) {
  const Vec3 unit = normalized(direction);
  for (std::size_t t = 0; t < cycle.points.size(); ++t) {
    const Vec3 edge = cycle.ring_points[t] - cycle.points[t];
    if (dot(edge, unit) > max_through_hole_ring_slope * norm(edge)) return true;
  }
  return false;
}

/// The shift s such that vertex t of `a` pairs with vertex s - t of `b` (the two cycles run in
/// opposite directions), or `n` when the cycles are not translated copies of each other that a
/// tube may join.
template <class PolygonMesh>
std::size_t through_hole_shift(const Through_hole_cycle<PolygonMesh>& a,
                               const Through_hole_cycle<PolygonMesh>& b) {
  const std::size_t n = a.points.size();
  const double tolerance = through_hole_shape_tolerance * a.radius;
  if (b.points.size() != n || std::abs(a.radius - b.radius) > 2 * tolerance) return n;
  const Vec3 translation = b.centroid - a.centroid;
  const double depth = norm(translation);
  if (!(depth > 0) || depth > max_through_hole_depth * a.radius ||
      std::abs(dot(translation, a.axis)) < min_through_hole_axis_cosine * depth)
    return n;
  if (reaches_toward(a, translation) || reaches_toward(b, -translation)) return n;
  for (std::size_t s = 0; s < n; ++s) {
    bool match = true;
    for (std::size_t t = 0; t < n && match; ++t)
      match = norm(b.points[(s + n - t) % n] - a.points[t] - translation) <= tolerance;
    if (match) return s;
  }
  return n;
}

/// Adds the tube between `a` and `b` (shift `s`), each quad split along its shorter diagonal;
/// returns its faces, or nothing (and the faces it added removed) when the cycles share a vertex
/// or CGAL cannot add a face.
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> add_tube(
    const Through_hole_cycle<PolygonMesh>& a, const Through_hole_cycle<PolygonMesh>& b,
    std::size_t s, PolygonMesh& pm) {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  std::vector<typename GT::face_descriptor> faces;
  const std::size_t n = a.points.size();
  // Cycles that share a vertex (pinched at it) would make the tube pass through that vertex twice.
  const std::unordered_set<vertex_descriptor> in_a(a.vertices.begin(), a.vertices.end());
  for (vertex_descriptor v : b.vertices)
    if (in_a.count(v)) return faces;
  auto add = [&](vertex_descriptor u, vertex_descriptor v, vertex_descriptor w) {
    const auto f = CGAL::Euler::add_face(std::array<vertex_descriptor, 3>{{u, v, w}}, pm);
    if (f != GT::null_face()) faces.push_back(f);
    return f != GT::null_face();
  };
  for (std::size_t t = 0; t < n; ++t) {
    // The quad a0 a1 b1 b0: a0 -> a1 and b1 -> b0 are the border edges it closes.
    const std::size_t i0 = (s + n - t) % n, i1 = (s + 2 * n - t - 1) % n;
    const vertex_descriptor a0 = a.vertices[t], a1 = a.vertices[(t + 1) % n];
    const vertex_descriptor b0 = b.vertices[i0], b1 = b.vertices[i1];
    const bool split_at_a0 =
        norm(b.points[i1] - a.points[t]) <= norm(b.points[i0] - a.points[(t + 1) % n]);
    const bool added =
        split_at_a0 ? add(a0, a1, b1) && add(a0, b1, b0) : add(a0, a1, b0) && add(a1, b1, b0);
    if (added) continue;
    for (auto it = faces.rbegin(); it != faces.rend(); ++it)
      CGAL::Euler::remove_face(halfedge(*it, pm), pm);
    return {};
  }
  return faces;
}

/// Finds the pairs of border cycles of one part that end a missing tube, adds the tubes, and
/// removes again every tube a face of which meets another face (of the mesh, of its own tube or
/// of another tube) or is degenerate. As for the caps of step 10c, a tube may meet the faces of
/// other parts when its own part already met another part (the rings of a calendar touch the
/// edges of the holes they pass through); that contact is kept like the others.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Through_hole_report bridge_through_holes(PolygonMesh& pm, VertexPointMap vpm,
                                         const GeomTraits& traits) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  Through_hole_report report;
  const auto cycles = through_hole_cycles(pm, vpm);
  std::vector<bool> used(cycles.size(), false);
  std::vector<std::vector<face_descriptor>> tubes;
  std::unordered_map<face_descriptor, std::size_t> part;  // computed at the first match
  auto one_part = [&](const auto& a, const auto& b) {
    if (part.empty()) part = face_components(pm);
    return part.at(a.face) == part.at(b.face);
  };
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    const std::size_t n = cycles[i].points.size();
    const double reach = max_through_hole_depth * cycles[i].radius;
    for (std::size_t j = i + 1;
         !used[i] && j < cycles.size() && j <= i + max_through_hole_candidates; ++j) {
      if (cycles[j].points.size() != n || cycles[j].centroid[0] - cycles[i].centroid[0] > reach)
        break;
      if (used[j]) continue;
      const std::size_t s = through_hole_shift(cycles[i], cycles[j]);
      if (s == n || !one_part(cycles[i], cycles[j])) continue;
      used[i] = used[j] = true;
      ++report.pairs;
      auto tube = add_tube(cycles[i], cycles[j], s, pm);
      if (tube.empty())
        ++report.rejected;
      else
        tubes.push_back(std::move(tube));
    }
  }
  if (tubes.empty()) return report;
  std::unordered_map<face_descriptor, std::size_t> tube_of;
  std::vector<face_descriptor> tube_faces, others;
  for (std::size_t k = 0; k < tubes.size(); ++k)
    for (face_descriptor f : tubes[k]) {
      tube_of.emplace(f, k);
      tube_faces.push_back(f);
    }
  for (face_descriptor f : faces(pm))
    if (!tube_of.count(f)) others.push_back(f);
  const auto found = bounded_intersections_involving(
      tube_faces, others, pm, default_pair_limit(num_faces(pm)), vpm, traits);
  const auto component = face_components(pm);
  std::unordered_set<std::size_t> in_contact;
  bool contacts_known = false;
  std::vector<bool> rejected(tubes.size(), found.truncated);
  for (const auto& pair : found.pairs) {
    const bool across = component.at(pair.first) != component.at(pair.second) &&
                        !tube_of.count(pair.first) != !tube_of.count(pair.second);
    if (across && !contacts_known) {
      in_contact = parts_in_contact(pm, vpm, traits, component, tube_of);
      contacts_known = true;
    }
    for (face_descriptor f : {pair.first, pair.second}) {
      const auto tube = tube_of.find(f);
      if (tube != tube_of.end() && !(across && in_contact.count(component.at(f))))
        rejected[tube->second] = true;
    }
  }
  for (std::size_t k = 0; k < tubes.size(); ++k) {
    if (!rejected[k]) {
      ++report.bridged;
      report.faces_added += tubes[k].size();
      continue;
    }
    ++report.rejected;
    for (auto it = tubes[k].rbegin(); it != tubes[k].rend(); ++it)
      CGAL::Euler::remove_face(halfedge(*it, pm), pm);
  }
  return report;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_THROUGH_HOLES_H
