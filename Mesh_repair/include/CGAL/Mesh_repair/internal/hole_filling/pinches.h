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
// A loop of two edges between coincident vertices becomes, once welded, two edges joining the
// same two vertices: a slit with no area that no method can triangulate, and that
// `is_valid_polygon_mesh` rejects. It is not filled but zipped into one edge when the welds are
// committed.

#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
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

/// Whether the border cycle of `h` is two edges between the same two vertices.
template <class PolygonMesh>
bool is_two_edge_slit(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                      const PolygonMesh& pm) {
  return is_border(h, pm) && next(next(h, pm), pm) == h;
}

/// Whether welding the target of `in` into the target of `first` (border halfedges of one cycle)
/// would join two edges that are not a two-edge loop of the cycle (a vertex adjacent to both
/// would then be joined to the weld by two edges, which a file shows as one edge with more than
/// two faces), or put the weld twice in one face (a face holding both vertices).
template <class PolygonMesh>
bool weld_doubles_an_edge(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor first,
                          typename boost::graph_traits<PolygonMesh>::halfedge_descriptor in,
                          const PolygonMesh& pm) {
  using GT = boost::graph_traits<PolygonMesh>;
  const auto kept = target(first, pm), removed = target(in, pm);
  if (kept == removed) return false;
  std::set<typename GT::vertex_descriptor> neighbours;
  std::set<typename GT::face_descriptor> faces;
  for (auto around : halfedges_around_target(first, pm)) {
    neighbours.insert(source(around, pm));
    if (!is_border(around, pm)) faces.insert(face(around, pm));
  }
  for (auto around : halfedges_around_target(in, pm)) {
    if (!is_border(around, pm) && faces.count(face(around, pm))) return true;
    const auto y = source(around, pm);
    if (!neighbours.count(y)) continue;
    const bool loop_after_first =
        next(next(first, pm), pm) == in && target(next(first, pm), pm) == y;
    const bool loop_after_in = next(next(in, pm), pm) == first && target(next(in, pm), pm) == y;
    if (!loop_after_first && !loop_after_in) return true;
  }
  return false;
}

/// Welds the coincident vertices of the border cycle of `h` and splits it at each weld
/// (exact equality of points). Returns one border halfedge per resulting cycle of three edges
/// or more (two-edge slits are zipped by `commit_pinches`); `welds` receives what
/// `unweld_pinches` needs.
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
    if (!in_same_cycle(first, in, pm) || weld_doubles_an_edge(first, in, pm)) continue;
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
    if (!is_two_edge_slit(c, pm)) cycles.push_back(c);
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

/// Zips the slit of `h` (`is_two_edge_slit`) into one edge: `h` takes the place of the
/// opposite of the other border halfedge, whose edge is removed. CGAL's
/// `stitch_boundary_cycle` refuses, as the two edges already join the same vertices. Returns
/// false, changing nothing, when one face lies on both sides (`weld_pinches` makes no such slit:
/// that face would hold both welded vertices).
template <class PolygonMesh>
bool zip_two_edge_slit(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                       PolygonMesh& pm) {
  const auto g = next(h, pm), og = opposite(g, pm);
  const auto face_kept = face(og, pm);
  if (face_kept == face(opposite(h, pm), pm)) return false;
  const auto before = prev(og, pm), after = next(og, pm);
  set_next(before, h, pm);
  set_next(h, after, pm);
  set_face(h, face_kept, pm);
  if (halfedge(face_kept, pm) == og) set_halfedge(face_kept, h, pm);
  set_halfedge(target(h, pm), h, pm);
  set_halfedge(source(h, pm), opposite(h, pm), pm);
  remove_edge(edge(g, pm), pm);
  // A vertex on a border keeps a border halfedge, as the halfedge graph requires.
  for (auto v : {target(h, pm), source(h, pm)})
    for (auto around : halfedges_around_target(v, pm))
      if (is_border(around, pm)) {
        set_halfedge(v, around, pm);
        break;
      }
  return true;
}

/// Makes the welds permanent: removes the welded-away vertices and zips the two-edge slits
/// the welds made. Returns the number of slits zipped.
template <class PolygonMesh>
std::size_t commit_pinches(PolygonMesh& pm, std::vector<Pinch_weld<PolygonMesh>>& welds) {
  for (const auto& weld : welds) {
    if (weld.kept != weld.removed) remove_vertex(weld.removed, pm);
  }
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> slits;
  for (const auto& weld : welds)
    for (auto h : halfedges_around_target(weld.kept, pm))
      if (is_two_edge_slit(h, pm) && std::find(slits.begin(), slits.end(), h) == slits.end() &&
          std::find(slits.begin(), slits.end(), next(h, pm)) == slits.end())
        slits.push_back(h);
  std::size_t zipped = 0;
  for (auto h : slits)
    if (is_two_edge_slit(h, pm) && zip_two_edge_slit(h, pm)) ++zipped;
  welds.clear();
  return zipped;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PINCHES_H
