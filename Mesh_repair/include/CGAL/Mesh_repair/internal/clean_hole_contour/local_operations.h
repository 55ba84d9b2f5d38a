// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CLEAN_HOLE_CONTOUR_LOCAL_OPERATIONS_H
#define CGAL_MESH_REPAIR_INTERNAL_CLEAN_HOLE_CONTOUR_LOCAL_OPERATIONS_H

// The guarded local operations of the contour cleaning (Pernot 4): each checks, before touching
// the mesh, that it keeps it manifold (link condition, no pinched border vertex, no duplicated
// edge) and creates no fold. A fold is decided exactly: the sign of n_old . n_new for every
// triangle whose shape changes, in rational arithmetic on the (double) coordinates.

#include <CGAL/Exact_rational.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace clean_hole_contour {

using Exact = CGAL::Exact_rational;
using Exact_point = std::array<Exact, 3>;

template <class Point>
Exact_point exact(const Point& p) {
  return {Exact(CGAL::to_double(p.x())), Exact(CGAL::to_double(p.y())),
          Exact(CGAL::to_double(p.z()))};
}

inline std::array<Exact, 3> exact_normal(const Exact_point& a, const Exact_point& b,
                                         const Exact_point& c) {
  std::array<Exact, 3> u, v;
  for (int k = 0; k < 3; ++k) {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
  }
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

/// True when triangle (a2, b2, c2) keeps the orientation of (a1, b1, c1) and is not degenerate:
/// exact sign of the dot product of their normals.
inline bool same_side(const std::array<Exact_point, 3>& before,
                      const std::array<Exact_point, 3>& after) {
  const auto n1 = exact_normal(before[0], before[1], before[2]);
  const auto n2 = exact_normal(after[0], after[1], after[2]);
  return CGAL::sign(n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2]) == CGAL::POSITIVE;
}

template <class PolygonMesh>
bool is_border_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                      const PolygonMesh& pm) {
  for (auto h : CGAL::halfedges_around_target(v, pm))
    if (is_border(h, pm)) return true;
  return false;
}

template <class PolygonMesh>
std::size_t cycle_length(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border,
                         const PolygonMesh& pm) {
  std::size_t n = 0;
  for (auto h : CGAL::halfedges_around_face(border, pm)) {
    (void)h;
    ++n;
  }
  return n;
}

/// A border halfedge around v, or null.
template <class PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge_at(
    typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm) {
  for (auto h : CGAL::halfedges_around_target(v, pm))
    if (is_border(h, pm)) return h;
  return boost::graph_traits<PolygonMesh>::null_halfedge();
}

/// Collapses the edge of h, the surviving vertex placed at `position`, if the result is
/// manifold and no remaining triangle around the two vertices folds. Returns the surviving
/// vertex, or null when refused (mesh unchanged).
template <class PolygonMesh, class VertexPointMap, class Point>
typename boost::graph_traits<PolygonMesh>::vertex_descriptor guarded_collapse(
    PolygonMesh& pm, VertexPointMap vpm,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const Point& position) {
  using GT = boost::graph_traits<PolygonMesh>;
  const auto u = source(h, pm), w = target(h, pm);
  if (!CGAL::Euler::does_satisfy_link_condition(edge(h, pm), pm)) return GT::null_vertex();
  const bool border_edge = is_border(h, pm) || is_border(opposite(h, pm), pm);
  if (!border_edge && is_border_vertex(u, pm) && is_border_vertex(w, pm))
    return GT::null_vertex();  // would pinch two border points into a non-manifold vertex
  const Exact_point moved = exact(position);
  for (auto v : {u, w}) {
    for (auto g : CGAL::halfedges_around_target(v, pm)) {
      if (is_border(g, pm)) continue;
      std::array<typename GT::vertex_descriptor, 3> t{source(g, pm), target(g, pm),
                                                      target(next(g, pm), pm)};
      const bool on_edge =
          (t[0] == u || t[1] == u || t[2] == u) && (t[0] == w || t[1] == w || t[2] == w);
      if (on_edge) continue;  // removed by the collapse
      std::array<Exact_point, 3> before, after;
      for (int k = 0; k < 3; ++k) {
        before[k] = exact(get(vpm, t[k]));
        after[k] = (t[k] == u || t[k] == w) ? moved : before[k];
      }
      if (!same_side(before, after)) return GT::null_vertex();
    }
  }
  const auto kept = CGAL::Euler::collapse_edge(edge(h, pm), pm);
  put(vpm, kept, position);
  return kept;
}

/// Flips the interior edge of h if both new triangles face the side of the old pair (the sum of
/// the two old normals, so that a flat old triangle does not block its own repair) and the new
/// edge does not exist yet (no duplicated edge).
template <class PolygonMesh, class VertexPointMap>
bool guarded_flip(PolygonMesh& pm, VertexPointMap vpm,
                  typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h) {
  const auto o = opposite(h, pm);
  if (is_border(h, pm) || is_border(o, pm)) return false;
  const auto a = source(h, pm), b = target(h, pm);
  const auto c = target(next(h, pm), pm), d = target(next(o, pm), pm);
  if (c == d || halfedge(c, d, pm).second) return false;
  const Exact_point pa = exact(get(vpm, a)), pb = exact(get(vpm, b)), pc = exact(get(vpm, c)),
                    pd = exact(get(vpm, d));
  const auto n1 = exact_normal(pa, pb, pc), n2 = exact_normal(pb, pa, pd);
  for (const auto& n : {exact_normal(pa, pd, pc), exact_normal(pd, pb, pc)}) {
    Exact dot = 0;
    for (int k = 0; k < 3; ++k) dot += n[k] * (n1[k] + n2[k]);
    if (CGAL::sign(dot) != CGAL::POSITIVE) return false;
  }
  CGAL::Euler::flip_edge(h, pm);
  return true;
}

}  // namespace clean_hole_contour
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CLEAN_HOLE_CONTOUR_LOCAL_OPERATIONS_H
