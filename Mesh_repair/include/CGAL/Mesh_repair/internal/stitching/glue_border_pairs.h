// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_STITCHING_GLUE_BORDER_PAIRS_H
#define CGAL_MESH_REPAIR_INTERNAL_STITCHING_GLUE_BORDER_PAIRS_H

// Gluing of given pairs of border halfedges in linear time and memory.
//
// `glue_border_halfedge_pairs(pm, pairs)` does what CGAL 5.5's
// `Polygon_mesh_processing::stitch_borders(pm, pairs)` does (internal::filter_stitchable_pairs
// followed by internal::run_stitch_borders in CGAL/Polygon_mesh_processing/stitch_borders.h): the
// same pairs are refused, the same vertices are kept, the same connectivity is built. CGAL keeps
// its union-find handles in an `unordered_map` over vertices and detects the edges that would be
// duplicated by merging with an `unordered_map` keyed by vertex pairs, which dominated stitching
// a million border vertices. Here the vertices of the pairs get compact ids, the union-find is two
// arrays, and the duplicated-edge check groups the incident edges of each merged vertex in a
// small sorted list.
//
// What the check guarantees (as in CGAL): after gluing, no two edges join the same two vertices
// unless both were border edges (a pair scheduled for gluing, or a two-edge border loop); a pair
// touching a vertex where an interior edge would be duplicated is refused with all pairs sharing
// such a vertex. Each border halfedge takes part in at most one pair, so every merged vertex
// joins the fans of manifold border vertices side to side along glued edges, which cannot pinch a
// vertex: gluing manifold borders never creates a non-manifold vertex.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Union-find with the semantics of `CGAL::Union_find` (union by size; on equal sizes the set of
/// the first argument goes under the second), so the same representatives, hence the same kept
/// vertices, come out as in CGAL's stitching.
class Sized_union_find {
 public:
  explicit Sized_union_find(std::size_t n) : up_(n), size_(n, 1) { reset(); }
  void reset() {
    for (std::size_t i = 0; i < up_.size(); ++i) up_[i] = i, size_[i] = 1;
  }
  std::size_t find(std::size_t x) {
    std::size_t r = x;
    while (up_[r] != r) r = up_[r];
    while (up_[x] != r) {
      const std::size_t u = up_[x];
      up_[x] = r;
      x = u;
    }
    return r;
  }
  void unite(std::size_t p, std::size_t q) {
    p = find(p), q = find(q);
    if (p == q) return;
    if (size_[p] > size_[q]) std::swap(p, q);
    up_[p] = q;
    size_[q] += size_[p];
  }

 private:
  std::vector<std::size_t> up_, size_;
};

/// Glues each pair `(h1, h2)` of border halfedges of `pm` (opposite directions; `h2` and its
/// opposite are removed, the vertices of `h2` merged into those of `h1`), like CGAL's
/// `stitch_borders(pm, pairs)`; returns the number of pairs glued.
template <class PolygonMesh, class HalfedgePairs>
std::size_t glue_border_halfedge_pairs(PolygonMesh& pm, const HalfedgePairs& pairs) {
  using Graph_traits = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using Pair = std::pair<halfedge_descriptor, halfedge_descriptor>;
  if (pairs.empty()) return 0;

  // Compact ids of the vertices of the pairs, +1 so 0 means "not in a pair".
  // (Dynamic property maps start value-initialised, as the node ids of Gap_stitcher rely on.)
  auto id_of = get(CGAL::dynamic_vertex_property_t<std::size_t>(), pm);
  std::vector<vertex_descriptor> vertex_of;
  auto id = [&](vertex_descriptor v) {
    std::size_t i = get(id_of, v);
    if (i == 0) {
      vertex_of.push_back(v);
      i = vertex_of.size();
      put(id_of, v, i);
    }
    return i - 1;
  };
  for (const Pair& p : pairs) {
    id(target(p.first, pm)), id(source(p.second, pm));
    id(source(p.first, pm)), id(target(p.second, pm));
  }
  const std::size_t n = vertex_of.size();
  Sized_union_find uf(n);
  auto join_pairs = [&](const std::vector<Pair>& range) {
    for (const Pair& p : range) {
      uf.unite(get(id_of, target(p.first, pm)) - 1, get(id_of, source(p.second, pm)) - 1);
      uf.unite(get(id_of, source(p.first, pm)) - 1, get(id_of, target(p.second, pm)) - 1);
    }
  };
  std::vector<Pair> to_stitch(pairs.begin(), pairs.end());
  join_pairs(to_stitch);

  // Vertices where an edge would be present more than once after merging (CGAL's
  // filter_stitchable_pairs). Per merged vertex r, list the other end of every incident edge (as
  // merged); an edge within r is listed once, an edge between merged vertices r and s once in r's
  // list and once in s's, so the multiplicity of each end in r's list is the number of edges CGAL
  // finds for that vertex pair.
  std::vector<std::size_t> group_start(n + 1, 0), group_members(n);
  for (std::size_t i = 0; i < n; ++i) ++group_start[uf.find(i) + 1];
  for (std::size_t i = 0; i < n; ++i) group_start[i + 1] += group_start[i];
  {
    std::vector<std::size_t> fill(group_start.begin(), group_start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) group_members[fill[uf.find(i)]++] = i;
  }
  std::vector<char> unstitchable(n, 0);
  bool any_unstitchable = false;
  auto mark = [&](vertex_descriptor v) {
    const std::size_t i = get(id_of, v);
    if (i != 0) unstitchable[i - 1] = 1, any_unstitchable = true;
  };
  std::vector<std::pair<vertex_descriptor, halfedge_descriptor>> ends;
  for (std::size_t r = 0; r < n; ++r) {
    if (group_start[r] == group_start[r + 1]) continue;
    ends.clear();
    for (std::size_t k = group_start[r]; k < group_start[r + 1]; ++k) {
      const std::size_t member = group_members[k];
      for (halfedge_descriptor h : halfedges_around_target(vertex_of[member], pm)) {
        const vertex_descriptor other = source(h, pm);
        const std::size_t other_id = get(id_of, other);
        if (other_id == 0) {
          ends.emplace_back(other, h);
          continue;
        }
        const std::size_t s = uf.find(other_id - 1);
        if (s == r && other_id - 1 < member) continue;  // an edge within r: list it once
        ends.emplace_back(vertex_of[s], h);
      }
    }
    if (ends.size() < 2) continue;
    std::sort(ends.begin(), ends.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t begin = 0; begin < ends.size();) {
      std::size_t end = begin + 1;
      while (end < ends.size() && !(ends[begin].first < ends[end].first)) ++end;
      const std::size_t count = end - begin;
      // Two border edges: most likely a pair to glue, or a two-edge border loop (as CGAL).
      const bool refused =
          count > 2 || (count == 2 && !(is_border_edge(ends[begin].second, pm) &&
                                        is_border_edge(ends[begin + 1].second, pm)));
      if (refused)
        for (std::size_t k = begin; k < end; ++k)
          mark(source(ends[k].second, pm)), mark(target(ends[k].second, pm));
      begin = end;
    }
  }
  if (any_unstitchable) {
    auto ok = [&](halfedge_descriptor h) {
      return !unstitchable[get(id_of, source(h, pm)) - 1] &&
             !unstitchable[get(id_of, target(h, pm)) - 1];
    };
    std::vector<Pair> filtered;
    for (const Pair& p : to_stitch)
      if (ok(p.first) && ok(p.second)) filtered.push_back(p);
    to_stitch.swap(filtered);
    uf.reset();  // redone: a refused vertex may have been the representative
    join_pairs(to_stitch);
  }

  // CGAL's run_stitch_borders: retarget the halfedges of the merged vertices to the kept one...
  auto kept = [&](vertex_descriptor v) { return vertex_of[uf.find(get(id_of, v) - 1)]; };
  auto retarget = [&](halfedge_descriptor h, vertex_descriptor v) {
    const halfedge_descriptor start = h;
    do {
      set_target(h, v, pm);
      h = opposite(next(h, pm), pm);
    } while (h != start);
  };
  std::vector<vertex_descriptor> to_delete;
  for (const Pair& p : to_stitch) {
    const halfedge_descriptor h1 = p.first, h2 = p.second;
    const vertex_descriptor h1_tgt = target(h1, pm), h2_src = source(h2, pm);
    vertex_descriptor keep = kept(h1_tgt);
    if (keep != h1_tgt) to_delete.push_back(h1_tgt), retarget(h1, keep);
    if (keep != h2_src && h1_tgt != h2_src)
      to_delete.push_back(h2_src), retarget(opposite(h2, pm), keep);
    set_halfedge(keep, h1, pm);
    const vertex_descriptor h1_src = source(h1, pm), h2_tgt = target(h2, pm);
    keep = kept(h2_tgt);
    if (keep != h2_tgt) to_delete.push_back(h2_tgt), retarget(h2, keep);
    if (keep != h1_src && h1_src != h2_tgt)
      to_delete.push_back(h1_src), retarget(opposite(h1, pm), keep);
    set_halfedge(keep, opposite(h1, pm), pm);
  }
  // ...link the border neighbours across each glued pair...
  for (const Pair& p : to_stitch) {
    const halfedge_descriptor h1 = p.first, h2 = p.second;
    set_next(prev(h2, pm), next(h1, pm), pm);
    set_next(prev(h1, pm), next(h2, pm), pm);
  }
  // ...and let h1 take the place of opposite(h2) in its face; h2's edge goes.
  for (const Pair& p : to_stitch) {
    const halfedge_descriptor h1 = p.first, h2 = p.second, o2 = opposite(h2, pm);
    set_face(h1, face(o2, pm), pm);
    set_halfedge(face(h1, pm), h1, pm);
    set_next(prev(o2, pm), h1, pm);
    set_next(h1, next(o2, pm), pm);
    remove_edge(edge(h2, pm), pm);
  }
  for (vertex_descriptor v : to_delete) remove_vertex(v, pm);
  return to_stitch.size();
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_STITCHING_GLUE_BORDER_PAIRS_H
