// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_REMEMBERED_TRIANGULATION_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_REMEMBERED_TRIANGULATION_H

// CGAL's minimum-weight triangulation of a hole (`triangulate_hole`) is the costly part of
// Liepa's method: on a border it cannot close in its Delaunay search space it runs the
// exhaustive search, O(n^3) weight evaluations (about 1 s at 400 edges). One hole asks for the
// same triangulation many times: Liepa C1 and C2, curvature variation's initial patch, the
// last-resort C0, each on its own attempt, and the later steps of `automatic_repair` try the
// same borders again. A rejected patch is rolled back, so the border, and with it everything
// CGAL's search reads, is unchanged.
//
// The search reads only the border's points from the halfedge it is given, the third point of
// the face beyond each border edge, the edges that already join non-consecutive border
// vertices, and whether the exhaustive search may run: the key below. Its result depends on
// the first halfedge (the polygon's closing edge is the root of its dynamic program), so the
// same hole entered at another halfedge is another key. This file keeps the results per thread
// within a memory budget; for a key seen before, the triangles are given to CGAL's own tracer as
// the split index of each range of the border, and it builds the very faces and halfedges
// CGAL's search would build again: the memory changes no output. A failure (no triangulation,
// or the exhaustive search refused by `Cubic_search_limit`) is given back as well.

#include <CGAL/Mesh_repair/internal/hole_filling/cubic_search_limit.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <iterator>
#include <list>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Borders with fewer edges are triangulated directly: their search costs less than the key.
constexpr std::size_t min_remembered_border_edges = 24;

/// Memory kept per thread and point type for the results (keys and triangles); the oldest is
/// forgotten first. A 400-edge hole takes about 45 kB: this holds the failed holes of a large
/// scene from one step of `automatic_repair` to the next.
constexpr std::size_t remembered_triangulation_bytes = std::size_t(64) << 20;

/// Everything CGAL's search for one hole reads (Triangulate_hole_polygon_mesh.h), in the order
/// of the border from the halfedge it is given.
template <class Point>
struct Hole_triangulation_key {
  std::vector<Point> border;                // target of each border halfedge
  std::vector<Point> beyond;                // third point of the face beyond each border edge
  std::vector<std::pair<int, int>> chords;  // existing edges between non-consecutive vertices
  bool exhaustive_search_allowed = true;
  bool operator==(const Hole_triangulation_key& o) const {
    return exhaustive_search_allowed == o.exhaustive_search_allowed && border == o.border &&
           beyond == o.beyond && chords == o.chords;
  }
};

/// CGAL's result for a key: its triangles (indices in the key's order), or a failure.
struct Remembered_hole_triangulation {
  enum class Outcome { triangulated, none_found, search_too_large } outcome;
  std::vector<std::array<int, 3>> triangles;
};

template <class Point>
struct Remembered_triangulations {
  using Entry = std::pair<Hole_triangulation_key<Point>, Remembered_hole_triangulation>;
  std::list<Entry> entries;  // oldest first
  std::unordered_multimap<std::size_t, typename std::list<Entry>::iterator> by_hash;
  std::size_t bytes = 0;

  static std::size_t hash(const Hole_triangulation_key<Point>& key) {
    std::size_t h = key.border.size();
    const auto mix = [&h](double v) {
      h ^= std::hash<double>()(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    };
    for (const Point& p : key.border) {
      mix(CGAL::to_double(p.x()));
      mix(CGAL::to_double(p.y()));
      mix(CGAL::to_double(p.z()));
    }
    return h;
  }
  static std::size_t size_of(const Entry& e) {
    return (e.first.border.size() + e.first.beyond.size()) * sizeof(Point) +
           e.first.chords.size() * sizeof(std::pair<int, int>) +
           e.second.triangles.size() * sizeof(std::array<int, 3>);
  }
  const Remembered_hole_triangulation* find(const Hole_triangulation_key<Point>& key) const {
    auto range = by_hash.equal_range(hash(key));
    for (auto it = range.first; it != range.second; ++it)
      if (it->second->first == key) return &it->second->second;
    return nullptr;
  }
  void add(Hole_triangulation_key<Point> key, Remembered_hole_triangulation result) {
    const std::size_t h = hash(key);
    entries.emplace_back(std::move(key), std::move(result));
    by_hash.emplace(h, std::prev(entries.end()));
    bytes += size_of(entries.back());
    while (bytes > remembered_triangulation_bytes && entries.size() > 1) forget_oldest();
  }
  void forget_oldest() {
    auto range = by_hash.equal_range(hash(entries.front().first));
    for (auto it = range.first; it != range.second; ++it)
      if (it->second == entries.begin()) {
        by_hash.erase(it);
        break;
      }
    bytes -= size_of(entries.front());
    entries.pop_front();
  }
};

/// One memory per thread and point type, whatever mesh and parameters ask (the key is all that
/// CGAL's search reads).
template <class Point>
Remembered_triangulations<Point>& remembered_triangulations_of_this_thread() {
  static thread_local Remembered_triangulations<Point> memory;
  return memory;
}

/// The split index of each range (i, k) of the border, for CGAL's tracer (`get`): a triangle
/// a < b < c of a polygon triangulation is the one on the range (a, c).
struct Triangulation_splits {
  std::map<std::pair<int, int>, int> split;
  int get(int i, int k) const {
    auto it = split.find({i, k});
    return it == split.end() ? -1 : it->second;
  }
};

/// The halfedges of the hole of `border`, from `border`, and its key; false when a vertex
/// repeats along the border (CGAL gives no triangulation then, and nothing is remembered).
template <class PolygonMesh, class VertexPointMap, class Point>
bool hole_triangulation_key(
    const PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border,
    VertexPointMap vpm, Hole_triangulation_key<Point>& key,
    std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& sides) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::map<vertex_descriptor, int> index;
  for (auto h : halfedges_around_face(border, pm)) {
    if (!index.emplace(target(h, pm), int(sides.size())).second) return false;
    sides.push_back(h);
    key.border.push_back(get(vpm, target(h, pm)));
    key.beyond.push_back(get(vpm, target(next(opposite(next(h, pm), pm), pm), pm)));
  }
  const int n = int(sides.size());
  for (const auto& vi : index) {
    for (auto h : halfedges_around_target(vi.first, pm)) {
      auto it = index.find(source(h, pm));
      if (it == index.end()) continue;
      const int a = vi.second, b = it->second;
      if (a < b && b != a + 1 && !(a == 0 && b == n - 1)) key.chords.emplace_back(a, b);
    }
  }
  std::sort(key.chords.begin(), key.chords.end());
  return true;
}

/// `PMP::triangulate_hole(pm, border, faces, np)` (no vertex added), remembering its result per
/// thread (see the file comment). `vpm` must be the point map of `np`, which must hold
/// `Cubic_search_limit` as its visitor, and `exhaustive_search_allowed` must be the negation of
/// its `do_not_use_cubic_algorithm`; throws `Cubic_search_too_large` as the visitor does.
template <class PolygonMesh, class VertexPointMap, class NamedParameters>
void triangulate_hole_remembered(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border,
    VertexPointMap vpm, bool exhaustive_search_allowed,
    std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& faces,
    const NamedParameters& np) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Remembered = Remembered_hole_triangulation;
  std::size_t border_edges = 0;
  for (auto h : halfedges_around_face(border, pm)) {
    static_cast<void>(h);
    ++border_edges;
  }
  Hole_triangulation_key<Point> key;
  key.exhaustive_search_allowed = exhaustive_search_allowed;
  std::vector<halfedge_descriptor> sides;
  if (border_edges < min_remembered_border_edges ||
      !hole_triangulation_key(pm, border, vpm, key, sides)) {
    PMP::triangulate_hole(pm, border, std::back_inserter(faces), np);
    return;
  }
  const int n = int(sides.size());
  Remembered_triangulations<Point>& memory = remembered_triangulations_of_this_thread<Point>();
  if (const Remembered* known = memory.find(key)) {
    if (known->outcome == Remembered::Outcome::search_too_large) throw Cubic_search_too_large();
    if (known->outcome == Remembered::Outcome::none_found) return;
    Triangulation_splits splits;
    for (const std::array<int, 3>& t : known->triangles) splits.split[{t[0], t[2]}] = t[1];
    using Out = std::back_insert_iterator<std::vector<face_descriptor>>;
    PMP::internal::Tracer_polyhedron<PolygonMesh, Out> tracer(std::back_inserter(faces), pm, sides);
    tracer(splits, 0, n - 1);
    return;
  }
  const std::size_t created_from = faces.size();
  try {
    PMP::triangulate_hole(pm, border, std::back_inserter(faces), np);
  } catch (const Cubic_search_too_large&) {
    memory.add(std::move(key), Remembered{Remembered::Outcome::search_too_large, {}});
    throw;
  }
  Remembered result{faces.size() == created_from ? Remembered::Outcome::none_found
                                                 : Remembered::Outcome::triangulated,
                    {}};
  std::map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, int> index;
  for (int i = 0; i < n; ++i) index[target(sides[std::size_t(i)], pm)] = i;
  for (std::size_t f = created_from; f < faces.size(); ++f) {
    std::array<int, 3> t{};
    std::size_t k = 0;
    for (auto v : vertices_around_face(halfedge(faces[f], pm), pm)) {
      auto it = index.find(v);
      if (k == 3 || it == index.end()) return;  // not a triangle of border vertices
      t[k++] = it->second;
    }
    if (k != 3) return;
    std::sort(t.begin(), t.end());
    result.triangles.push_back(t);
  }
  if (result.outcome == Remembered::Outcome::triangulated &&
      result.triangles.size() + 2 != std::size_t(n))
    return;
  memory.add(std::move(key), std::move(result));
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_REMEMBERED_TRIANGULATION_H
