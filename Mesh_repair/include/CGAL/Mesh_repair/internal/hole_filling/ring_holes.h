// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_RING_HOLES_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_RING_HOLES_H

// Ring holes (thesis 4.4, Figures 4.9 and 4.12): a hole whose region contains other border
// cycles, the borders of island patches floating in it. `group_ring_holes` finds which island
// cycles belong to which hole; `bridge_island` joins an island's cycle to its hole's cycle by a
// strip of triangles along the shortest valid bridge, so that any method then fills one simple
// hole. See doc/fill_holes.md.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// A hole to fill as one region: its outer border cycle and the island cycles inside it.
template <class halfedge_descriptor>
struct Hole_group {
  halfedge_descriptor outer;
  std::vector<halfedge_descriptor> islands;
};

/// An orthonormal frame whose third axis is `normal`: projects points onto the plane.
struct Plane_frame {
  Vec3 origin{0, 0, 0}, u{1, 0, 0}, v{0, 1, 0}, normal{0, 0, 1};

  Plane_frame() = default;
  Plane_frame(const Vec3& o, const Vec3& n) : origin(o), normal(normalized(n)) {
    tangent_frame(normal, u, v);
  }
  Epick::Point_2 project(const Vec3& p) const {
    const Vec3 d = sub(p, origin);
    return Epick::Point_2(dot(d, u), dot(d, v));
  }
  double height(const Vec3& p) const { return dot(sub(p, origin), normal); }
};

/// Winding number of `polygon` around `p`, decided with exact orientation tests (Sunday's
/// crossing rule); points on the polygon count as outside (winding number 0).
inline int winding_number(const std::vector<Epick::Point_2>& polygon, const Epick::Point_2& p) {
  int winding = 0;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Epick::Point_2& a = polygon[k];
    const Epick::Point_2& b = polygon[(k + 1) % n];
    const CGAL::Orientation o = CGAL::orientation(a, b, p);
    if (o == CGAL::COLLINEAR && std::min(a.x(), b.x()) <= p.x() &&
        p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
        p.y() <= std::max(a.y(), b.y()))
      return 0;
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && o == CGAL::LEFT_TURN) ++winding;
    } else if (b.y() <= p.y() && o == CGAL::RIGHT_TURN) {
      --winding;
    }
  }
  return winding;
}

template <class PolygonMesh, class VertexPointMap>
std::vector<Vec3> cycle_points(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                               const PolygonMesh& pm, VertexPointMap vpm) {
  std::vector<Vec3> points;
  for (auto c : halfedges_around_face(h, pm)) points.push_back(to_array(get(vpm, source(c, pm))));
  return points;
}

inline double cosine(const Vec3& a, const Vec3& b) {
  const double n = norm(a) * norm(b);
  return n > 0 ? dot(a, b) / n : 0.0;
}

/// For each island cycle, the hole cycles whose centroid lies within their diameter of the
/// island's centroid (in each coordinate: a superset of the distance test), in increasing index
/// order; empty for the other cycles. Box intersection: a mesh with thousands of holes and
/// islands (a soup of separate faces, each an island) is not tested pair by pair.
inline std::vector<std::vector<std::size_t>> holes_near_islands(
    const std::vector<Border_cycle_geometry>& geometry, const std::vector<bool>& is_hole,
    const std::vector<bool>& is_island) {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<Box> hole_boxes, island_boxes;
  for (std::size_t k = 0; k < geometry.size(); ++k) {
    const Vec3& c = geometry[k].centroid;
    // A hole's box is widened by a rounding margin: it must hold every island that the distance
    // test below accepts.
    const double magnitude = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
    const double r =
        is_hole[k] ? geometry[k].diameter + 1e-9 * (geometry[k].diameter + magnitude) : 0.0;
    double lo[3] = {c[0] - r, c[1] - r, c[2] - r}, hi[3] = {c[0] + r, c[1] + r, c[2] + r};
    if (is_hole[k]) hole_boxes.emplace_back(lo, hi, k);
    if (is_island[k]) island_boxes.emplace_back(lo, hi, k);
  }
  std::vector<std::vector<std::size_t>> candidates(geometry.size());
  CGAL::box_intersection_d(island_boxes.begin(), island_boxes.end(), hole_boxes.begin(),
                           hole_boxes.end(), [&](const Box& island, const Box& hole) {
                             candidates[island.info()].push_back(hole.info());
                           });
  for (std::vector<std::size_t>& holes : candidates) std::sort(holes.begin(), holes.end());
  return candidates;
}

/// The one ring-hole test (thesis 4.4), shared by `detect_defects` (which reports islands) and
/// `fill_holes` (which bridges them): for each cycle of `cycles`, the index in `cycles` of the
/// hole it is an island of, or -1.
///
/// Border halfedges run counter-clockwise around a hole seen from the side the surface faces,
/// and clockwise around the outer border of a patch (an island lies to the left of its border
/// halfedges). So a cycle is a hole when its vector area points along the normals of the faces
/// along it (cosine above 0.5) and the border of an island when it points against them (cosine
/// below -0.5). An island belongs to a hole when it faces the same way as the surface around
/// the hole (the normals along both cycles make an acute angle: an island turned over cannot be
/// joined to its hole by a strip without a fold; that is an orientation defect, not a ring
/// hole) and every island vertex lies strictly inside the hole's cycle projected onto the hole's
/// plane (centroid, vector area; exact orientation tests), within the slab of half-width the
/// hole's diameter. Among several such holes the smallest (vector area) is kept.
template <class PolygonMesh, class VertexPointMap>
std::vector<long> ring_hole_owners(
    const PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& cycles) {
  std::vector<long> owner(cycles.size(), -1);
  if (cycles.size() < 2) return owner;
  std::vector<Border_cycle_geometry> geometry;
  std::vector<bool> is_hole(cycles.size(), false), is_island(cycles.size(), false);
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    geometry.push_back(cycle_geometry(cycles[k], pm, vpm));
    const double turn = cosine(geometry[k].vector_area, geometry[k].ring_normal);
    is_hole[k] = turn > 0.5;
    is_island[k] = turn < -0.5;
  }
  const std::vector<std::vector<std::size_t>> candidates =
      holes_near_islands(geometry, is_hole, is_island);
  for (std::size_t island = 0; island < cycles.size(); ++island) {
    if (candidates[island].empty()) continue;
    const std::vector<Vec3> island_points = cycle_points(cycles[island], pm, vpm);
    double best_area = std::numeric_limits<double>::max();
    for (std::size_t hole : candidates[island]) {
      const Border_cycle_geometry& g = geometry[hole];
      const double area = norm(g.vector_area);
      if (area == 0 || area >= best_area) continue;
      if (dot(geometry[island].ring_normal, g.ring_normal) <= 0) continue;
      if (norm(sub(geometry[island].centroid, g.centroid)) > g.diameter) continue;
      const Plane_frame frame(g.centroid, g.vector_area);
      std::vector<Epick::Point_2> polygon;
      for (const Vec3& p : cycle_points(cycles[hole], pm, vpm)) polygon.push_back(frame.project(p));
      const bool inside =
          std::all_of(island_points.begin(), island_points.end(), [&](const Vec3& p) {
            return std::abs(frame.height(p)) <= g.diameter &&
                   winding_number(polygon, frame.project(p)) != 0;
          });
      if (inside) {
        best_area = area;
        owner[island] = long(hole);
      }
    }
  }
  return owner;
}

/// Groups border cycles into holes: each island cycle of `ring_hole_owners` goes with its hole;
/// islands in no hole, and every cycle when `detect` is false, stay holes of their own.
template <class PolygonMesh, class VertexPointMap>
std::vector<Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>>
group_ring_holes(
    const PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& cycles,
    bool detect) {
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  std::vector<Hole_group<halfedge_descriptor>> groups;
  const std::vector<long> owner =
      detect ? ring_hole_owners(pm, vpm, cycles) : std::vector<long>(cycles.size(), -1);
  std::vector<long> group_of(cycles.size(), -1);
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    if (owner[k] >= 0) continue;
    group_of[k] = long(groups.size());
    groups.push_back({cycles[k], {}});
  }
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    if (owner[k] >= 0)
      groups[std::size_t(group_of[std::size_t(owner[k])])].islands.push_back(cycles[k]);
  }
  return groups;
}

/// True when the open segments p-q and r-s cross or touch in the plane (exact).
inline bool segments_meet(const Epick::Point_2& p, const Epick::Point_2& q, const Epick::Point_2& r,
                          const Epick::Point_2& s) {
  return CGAL::do_intersect(Epick::Segment_2(p, q), Epick::Segment_2(r, s));
}

/// Joins the island cycle of `island` to the cycle of `outer` by a ladder of triangles along the
/// shortest bridge between their vertices whose two rails cross no border edge of either cycle
/// in the outer cycle's plane (thesis Figure 4.12(a-b)). The ladder has one rung per
/// `edge_length` of bridge. Created faces and vertices are appended to `patch`. Returns a border
/// halfedge of the merged cycle, or the null halfedge when no valid bridge exists (the mesh is
/// then unchanged).
template <class PolygonMesh, class VertexPointMap>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor bridge_island(
    PolygonMesh& pm, VertexPointMap vpm,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor outer,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor island, double edge_length,
    Fill_patch<PolygonMesh>& patch) {
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

  const std::vector<halfedge_descriptor> outer_cycle = cycle_halfedges(outer, pm);
  const std::vector<halfedge_descriptor> island_cycle = cycle_halfedges(island, pm);
  const Border_cycle_geometry g = cycle_geometry(outer, pm, vpm);
  const Plane_frame frame(g.centroid, g.vector_area);
  auto point_of = [&](vertex_descriptor v) { return to_array(get(vpm, v)); };
  auto flat = [&](vertex_descriptor v) { return frame.project(point_of(v)); };

  std::vector<std::pair<Epick::Point_2, Epick::Point_2>> border_segments;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> border_ends;
  for (const auto* cycle : {&outer_cycle, &island_cycle}) {
    for (halfedge_descriptor h : *cycle) {
      border_segments.emplace_back(flat(source(h, pm)), flat(target(h, pm)));
      border_ends.emplace_back(source(h, pm), target(h, pm));
    }
  }
  // A rail from a to b may touch only border edges incident to a or b.
  auto rail_is_free = [&](vertex_descriptor a, vertex_descriptor b) {
    const Epick::Point_2 pa = flat(a), pb = flat(b);
    if (pa == pb) return false;
    for (std::size_t k = 0; k < border_segments.size(); ++k) {
      const auto& ends = border_ends[k];
      if (ends.first == a || ends.second == a || ends.first == b || ends.second == b) continue;
      if (segments_meet(pa, pb, border_segments[k].first, border_segments[k].second)) return false;
    }
    return true;
  };

  // Candidate bridges o -> i_n between the source of an outer halfedge and the target of an
  // island halfedge, shortest first.
  // Large cycles keep only each vertex's nearest partner, to bound memory.
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> candidates;
  const bool all_pairs = outer_cycle.size() * island_cycle.size() <= 1000000;
  std::vector<std::pair<double, std::size_t>> nearest_island(
      outer_cycle.size(), {std::numeric_limits<double>::max(), 0});
  std::vector<std::pair<double, std::size_t>> nearest_outer(
      island_cycle.size(), {std::numeric_limits<double>::max(), 0});
  for (std::size_t a = 0; a < outer_cycle.size(); ++a) {
    for (std::size_t b = 0; b < island_cycle.size(); ++b) {
      const double d =
          norm(sub(point_of(source(outer_cycle[a], pm)), point_of(target(island_cycle[b], pm))));
      if (all_pairs) candidates.push_back({d, {a, b}});
      nearest_island[a] = std::min(nearest_island[a], {d, b});
      nearest_outer[b] = std::min(nearest_outer[b], {d, a});
    }
  }
  if (!all_pairs) {
    for (std::size_t a = 0; a < outer_cycle.size(); ++a)
      candidates.push_back({nearest_island[a].first, {a, nearest_island[a].second}});
    for (std::size_t b = 0; b < island_cycle.size(); ++b)
      candidates.push_back({nearest_outer[b].first, {nearest_outer[b].second, b}});
  }
  std::sort(candidates.begin(), candidates.end());
  const std::size_t tries = std::min<std::size_t>(candidates.size(), 2000);
  for (std::size_t t = 0; t < tries; ++t) {
    const halfedge_descriptor ho = outer_cycle[candidates[t].second.first];
    const halfedge_descriptor hi = island_cycle[candidates[t].second.second];
    const vertex_descriptor o = source(ho, pm), o_next = target(ho, pm);
    const vertex_descriptor i = source(hi, pm), i_next = target(hi, pm);
    if (!rail_is_free(o, i_next) || !rail_is_free(o_next, i)) continue;
    if (segments_meet(flat(o), flat(i_next), flat(o_next), flat(i))) continue;
    const halfedge_descriptor keep = prev(ho, pm);
    const double length = candidates[t].first;
    const int rungs = std::max(1, int(std::lround(length / std::max(edge_length, 1e-300))));
    // Rails A (o to i_next) and B (o_next to i); quad j is (A_j, B_j, B_j+1, A_j+1).
    std::vector<vertex_descriptor> rail_a{o}, rail_b{o_next};
    for (int j = 1; j < rungs; ++j) {
      const double s = double(j) / rungs;
      for (auto* rail : {&rail_a, &rail_b}) {
        const Vec3 from = point_of(rail == &rail_a ? o : o_next);
        const Vec3 to = point_of(rail == &rail_a ? i_next : i);
        const Vec3 p = add(scale(from, 1 - s), scale(to, s));
        vertex_descriptor v = add_vertex(pm);
        put(vpm, v, Point(p[0], p[1], p[2]));
        patch.vertices.push_back(v);
        rail->push_back(v);
      }
    }
    rail_a.push_back(i_next);
    rail_b.push_back(i);
    for (int j = 0; j < rungs; ++j) {
      for (const std::array<vertex_descriptor, 3>& triangle :
           {std::array<vertex_descriptor, 3>{rail_a[j], rail_b[j], rail_b[j + 1]},
            std::array<vertex_descriptor, 3>{rail_a[j], rail_b[j + 1], rail_a[j + 1]}}) {
        const auto f = CGAL::Euler::add_face(triangle, pm);
        if (f == GT::null_face()) return GT::null_halfedge();  // caller rolls back `patch`
        patch.faces.push_back(f);
      }
    }
    return keep;
  }
  return GT::null_halfedge();
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_RING_HOLES_H
