// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PINCHES_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PINCHES_H

// Pinched holes: two holes touching at a vertex make a non-manifold vertex, which reading a
// mesh splits into two vertices at the same place; the two holes then form one border cycle
// shaped like a figure eight through those two vertices. No triangulation of that cycle is
// valid (any triangle across the waist is degenerate). Welding the two vertices back and
// splitting the cycle at the weld gives two simple holes that every method can fill; once both
// are filled the welded vertex is manifold again. The weld is undone when the fill is rolled back.

#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// One weld: the border halfedges entering the two coincident vertices, the vertex removed
/// (kept isolated until committed) and the halfedges whose target it was.
template <class PolygonMesh>
struct Pinch_weld {
  using GT = boost::graph_traits<PolygonMesh>;
  typename GT::halfedge_descriptor kept_in, removed_in;
  typename GT::vertex_descriptor kept, removed;
  typename GT::halfedge_descriptor kept_halfedge, removed_halfedge;
  std::vector<typename GT::halfedge_descriptor> retargeted;
};

template <class PolygonMesh>
bool in_same_cycle(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor a,
                   typename boost::graph_traits<PolygonMesh>::halfedge_descriptor b,
                   const PolygonMesh& pm) {
  for (auto h : halfedges_around_face(a, pm)) {
    if (h == b) return true;
  }
  return false;
}

/// Welds the coincident vertices of the border cycle of `h` and splits it at each weld
/// (exact equality of points). Returns one border halfedge per resulting cycle; `welds`
/// receives what `unweld_pinches` needs.
template <class PolygonMesh, class VertexPointMap>
std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> weld_pinches(
    PolygonMesh& pm, VertexPointMap vpm,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
    std::vector<Pinch_weld<PolygonMesh>>& welds) {
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  std::map<std::array<double, 3>, halfedge_descriptor> entering;
  std::vector<halfedge_descriptor> cycle = cycle_halfedges(h, pm);
  for (halfedge_descriptor in : cycle) {
    const auto key = to_array(get(vpm, target(in, pm)));
    auto found = entering.emplace(key, in);
    if (found.second) continue;
    const halfedge_descriptor first = found.first->second;
    if (!in_same_cycle(first, in, pm)) continue;
    Pinch_weld<PolygonMesh> weld;
    weld.kept_in = first;
    weld.removed_in = in;
    weld.kept = target(first, pm);
    weld.removed = target(in, pm);
    weld.kept_halfedge = halfedge(weld.kept, pm);
    weld.removed_halfedge = halfedge(weld.removed, pm);
    if (weld.kept != weld.removed) {
      for (halfedge_descriptor around : halfedges_around_target(in, pm))
        weld.retargeted.push_back(around);
      for (halfedge_descriptor around : weld.retargeted) set_target(around, weld.kept, pm);
      set_halfedge(weld.removed, boost::graph_traits<PolygonMesh>::null_halfedge(), pm);
    }
    const halfedge_descriptor first_next = next(first, pm), in_next = next(in, pm);
    set_next(first, in_next, pm);
    set_next(in, first_next, pm);
    set_halfedge(weld.kept, first, pm);
    welds.push_back(weld);
  }
  std::vector<halfedge_descriptor> cycles;
  std::unordered_set<halfedge_descriptor> seen;
  for (halfedge_descriptor c : cycle) {
    if (seen.count(c)) continue;
    cycles.push_back(c);
    for (halfedge_descriptor d : halfedges_around_face(c, pm)) seen.insert(d);
  }
  return cycles;
}

/// Undoes `weld_pinches` (after the fill's faces were removed), last weld first.
template <class PolygonMesh>
void unweld_pinches(PolygonMesh& pm, std::vector<Pinch_weld<PolygonMesh>>& welds) {
  for (auto it = welds.rbegin(); it != welds.rend(); ++it) {
    const auto kept_next = next(it->kept_in, pm), removed_next = next(it->removed_in, pm);
    set_next(it->kept_in, removed_next, pm);
    set_next(it->removed_in, kept_next, pm);
    for (auto h : it->retargeted) set_target(h, it->removed, pm);
    set_halfedge(it->kept, it->kept_halfedge, pm);
    set_halfedge(it->removed, it->removed_halfedge, pm);
  }
  welds.clear();
}

/// Makes the welds permanent: removes the welded-away vertices.
template <class PolygonMesh>
void commit_pinches(PolygonMesh& pm, std::vector<Pinch_weld<PolygonMesh>>& welds) {
  for (const auto& weld : welds) {
    if (weld.kept != weld.removed) remove_vertex(weld.removed, pm);
  }
  welds.clear();
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PINCHES_H
