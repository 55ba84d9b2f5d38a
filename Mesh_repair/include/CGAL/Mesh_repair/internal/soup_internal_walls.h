// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SOUP_INTERNAL_WALLS_H
#define CGAL_MESH_REPAIR_INTERNAL_SOUP_INTERNAL_WALLS_H

// Internal walls of a polygon soup: a sheet written once whose whole outline lies on edges of
// three polygons, inside the closed surface that the other polygons of its part form (a CAD
// solid of two cells sharing a face, a partition inside a box), or on it (a face given a second
// time with another triangulation). Kept, it makes every edge of
// its outline non-manifold, the soup's orientation splits them, and the repair sees three
// open surfaces that no patch can close; removed, the part is one closed surface.

#include <CGAL/Intersections_3/Ray_3_Segment_3.h>
#include <CGAL/Intersections_3/Ray_3_Triangle_3.h>
#include <CGAL/Kernel_traits.h>

#include <CGAL/Mesh_repair/internal/soup_edge.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// The candidate sheets examined at most per soup, and the points of each tested for being
/// inside (each test is linear in its part's size).
constexpr std::size_t max_internal_wall_candidates = 64;
constexpr std::size_t max_wall_samples = 32;

namespace soup_walls {

inline std::size_t find(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The polygons of each sheet: connected through edges of exactly two polygons.
inline std::vector<std::size_t> sheets(const std::vector<std::vector<std::size_t>>& polygons,
                                       const std::map<Soup_edge, std::vector<std::size_t>>& edges) {
  std::vector<std::size_t> parent(polygons.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  for (const auto& entry : edges)
    if (entry.second.size() == 2)
      parent[find(parent, entry.second[0])] = find(parent, entry.second[1]);
  for (std::size_t i = 0; i < polygons.size(); ++i) parent[i] = find(parent, i);
  return parent;
}

// 1 when the ray from `p` along `d` crosses an odd number of the triangles, 0 when even, -1 when
// it touches one of their edges (the parity would be meaningless): exact predicates only.
template <class Kernel>
int ray_parity(const std::vector<typename Kernel::Triangle_3>& triangles,
               const typename Kernel::Point_3& p, const typename Kernel::Vector_3& d) {
  const typename Kernel::Ray_3 ray(p, d);
  bool odd = false;
  for (const auto& t : triangles) {
    if (!CGAL::do_intersect(ray, t)) continue;
    for (int k = 0; k < 3; ++k)
      if (CGAL::do_intersect(ray, typename Kernel::Segment_3(t[k], t[(k + 1) % 3]))) return -1;
    odd = !odd;
  }
  return odd ? 1 : 0;
}

// Where `p` lies against the closed surface of `triangles`: on it (2), or strictly inside (1)
// or outside (0) by the parity along one of a few directions whose ray misses every edge (-1
// when none does).
template <class Kernel>
int side_of_closed_surface(const std::vector<typename Kernel::Triangle_3>& triangles,
                           const typename Kernel::Point_3& p) {
  using V = typename Kernel::Vector_3;
  const V directions[] = {V(0.5377, 0.8622, 0.1310), V(-0.3190, 0.2265, -0.9203),
                          V(0.7071, -0.5537, 0.4397), V(-0.8161, -0.3571, 0.4546)};
  for (const auto& t : triangles)
    if (t.has_on(p)) return 2;
  for (const V& d : directions) {
    const int parity = ray_parity<Kernel>(triangles, p, d);
    if (parity >= 0) return parity;
  }
  return -1;
}

// Every sampled triangle of `sheet` (up to `max_wall_samples`, spread evenly) has its centroid
// inside the closed surface of `others` or on it (a face written a second time with another
// triangulation): a sheet partly outside is no wall.
template <class Kernel>
bool inside_everywhere(const std::vector<typename Kernel::Triangle_3>& sheet,
                       const std::vector<typename Kernel::Triangle_3>& others) {
  const std::size_t step = std::max<std::size_t>(1, sheet.size() / max_wall_samples);
  for (std::size_t i = 0; i < sheet.size(); i += step) {
    const int side = side_of_closed_surface<Kernel>(others, CGAL::centroid(sheet[i]));
    if (side != 1 && side != 2) return false;
  }
  return true;
}

// True when an edge has three polygons or more: one sort of the edges, so that the common soup
// without any costs no map.
inline bool has_edge_of_three_polygons(const std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<Soup_edge> keys;
  for (const auto& p : polygons)
    for (std::size_t k = 0; k < p.size(); ++k)
      keys.push_back(soup_edge(p[k], p[(k + 1) % p.size()]));
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i + 2 < keys.size(); ++i)
    if (keys[i] == keys[i + 2]) return true;
  return false;
}

using Edge_map = std::map<Soup_edge, std::vector<std::size_t>>;

// The part of each polygon: polygons connected through any shared edge.
inline std::vector<std::size_t> parts_of(std::size_t count, const Edge_map& edges) {
  std::vector<std::size_t> part(count);
  std::iota(part.begin(), part.end(), std::size_t(0));
  for (const auto& entry : edges)
    for (std::size_t i : entry.second) part[find(part, i)] = find(part, entry.second[0]);
  for (std::size_t i = 0; i < count; ++i) part[i] = find(part, i);
  return part;
}

// Sheets without an edge of one polygon or of more than three.
inline std::vector<std::size_t> candidate_sheets(const Edge_map& edges,
                                                 const std::vector<std::size_t>& sheet) {
  std::map<std::size_t, bool> candidate;  // sheet -> still a candidate
  for (const auto& entry : edges) {
    const std::size_t n = entry.second.size();
    for (std::size_t i : entry.second) {
      auto it = candidate.emplace(sheet[i], true).first;
      if (n == 1 || n > 3) it->second = false;
    }
  }
  std::vector<std::size_t> sheets;
  for (const auto& [s, possible] : candidate)
    if (possible) sheets.push_back(s);
  return sheets;
}

// Whether `wall` has an edge of three polygons and its part, without it and the polygons
// already removed, is closed (each of the part's edges has two polygons left, or none).
inline bool closed_without(std::size_t wall, const std::vector<const Edge_map::value_type*>& edges,
                           const std::vector<std::size_t>& sheet,
                           const std::vector<bool>& removed) {
  bool on_non_manifold_edge = false;
  for (const auto* entry : edges) {
    std::size_t n = 0;
    bool used = false;
    for (std::size_t i : entry->second) {
      used = used || sheet[i] == wall;
      n += sheet[i] != wall && !removed[i] ? 1 : 0;
    }
    on_non_manifold_edge = on_non_manifold_edge || (used && entry->second.size() == 3);
    if (n != 0 && n != 2) return false;
  }
  return on_non_manifold_edge;
}

// Drops the polygons marked in `removed`, keeping the order of the others.
inline void erase_polygons(std::vector<std::vector<std::size_t>>& polygons,
                           const std::vector<bool>& removed) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (removed[i]) continue;
    if (kept != i) polygons[kept] = std::move(polygons[i]);
    ++kept;
  }
  polygons.resize(kept);
}

}  // namespace soup_walls

/// Removes the internal walls of `polygons` (see above): each sheet whose every outline edge is
/// shared by exactly three polygons, whose part without it is closed (every edge of two
/// polygons), and which lies strictly inside that closed surface or on it (the centroids of its
/// triangles, by exact ray parity). Returns the walls and the polygons removed.
template <class Point>
std::pair<std::size_t, std::size_t> remove_internal_walls(
    const std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons) {
  using namespace soup_walls;
  using Triangle = typename CGAL::Kernel_traits<Point>::Kernel::Triangle_3;
  if (!has_edge_of_three_polygons(polygons)) return {0, 0};
  Edge_map edges;
  for (std::size_t i = 0; i < polygons.size(); ++i)
    for (std::size_t k = 0; k < polygons[i].size(); ++k)
      edges[soup_edge(polygons[i][k], polygons[i][(k + 1) % polygons[i].size()])].push_back(i);
  if (std::none_of(edges.begin(), edges.end(), [](const auto& e) { return e.second.size() == 3; }))
    return {0, 0};  // only edges of four polygons or more
  const std::vector<std::size_t> sheet = sheets(polygons, edges);
  const std::vector<std::size_t> part = parts_of(polygons.size(), edges);
  // Each part's edges and polygons, listed once for all its candidates.
  std::map<std::size_t, std::vector<const Edge_map::value_type*>> part_edges;
  for (const auto& entry : edges) part_edges[part[entry.second[0]]].push_back(&entry);
  std::map<std::size_t, std::vector<std::size_t>> part_polygons;
  for (std::size_t i = 0; i < polygons.size(); ++i) part_polygons[part[i]].push_back(i);
  std::vector<bool> removed(polygons.size(), false);
  std::size_t walls = 0, polygons_removed = 0, examined = 0;
  for (std::size_t wall : candidate_sheets(edges, sheet)) {
    if (++examined > max_internal_wall_candidates) break;
    if (!closed_without(wall, part_edges[part[wall]], sheet, removed)) continue;
    std::vector<Triangle> others, own;
    for (std::size_t i : part_polygons[part[wall]]) {
      if (removed[i]) continue;
      const auto& q = polygons[i];
      for (std::size_t k = 1; k + 1 < q.size(); ++k) {
        const Triangle t(points[q[0]], points[q[k]], points[q[k + 1]]);
        if (!t.is_degenerate()) (sheet[i] == wall ? own : others).push_back(t);
      }
    }
    if (own.empty() || !inside_everywhere<typename CGAL::Kernel_traits<Point>::Kernel>(own, others))
      continue;
    ++walls;
    for (std::size_t i : part_polygons[part[wall]])
      if (sheet[i] == wall) removed[i] = true, ++polygons_removed;
  }
  if (walls > 0) erase_polygons(polygons, removed);
  return {walls, polygons_removed};
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SOUP_INTERNAL_WALLS_H
