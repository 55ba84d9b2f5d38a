// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_FACE_TRIANGULATION_H
#define CGAL_MESH_REPAIR_INTERNAL_FACE_TRIANGULATION_H

// CGAL's triangulation of a polygonal face (Polygon_mesh_processing::triangulate_face: the
// constrained Delaunay triangulation of the face projected along its normal), built into the
// mesh in an order that depends on the face alone. CGAL 5.5 creates the new edges in the order
// of its triangulation's edge iterator, which reports each edge from the one of its two faces
// that lies at the lower memory address: from run to run, the same triangles get other halfedge
// indices. Everything that then walks the mesh in index order (border cycles, hole groups, the
// rings grown around a hole) meets the holes in another order and may decide otherwise: a Debian
// furniture model came out of `repair` with 747 or with 758 intersecting pairs, one run in three.
// Here the triangles are sorted, and the halfedges are created in that order.

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Collects the faces `triangulate_face` creates (the visitor is copied: it holds a pointer).
template <class PolygonMesh>
struct Subface_collector {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::vector<face_descriptor>* faces;
  void before_subface_creations(face_descriptor) {}
  void after_subface_created(face_descriptor f) { faces->push_back(f); }
  void after_subface_creations() {}
};

using Corner_triangle = std::array<std::size_t, 3>;

/// The triangles of the constrained Delaunay triangulation of `corners` (a closed polygon)
/// projected along `normal`, as corner indices in the polygon's orientation, each starting at
/// its smallest index, sorted. Empty when the projection does not triangulate the polygon as it
/// is: coincident corners, crossing sides, a corner on another side (CGAL would then split that
/// side, and the triangles would not close the face's own border).
template <class GeomTraits>
std::vector<Corner_triangle> projected_polygon_triangles(
    const std::vector<typename GeomTraits::Point_3>& corners,
    const typename GeomTraits::Vector_3& normal) {
  using P_traits = CGAL::Projection_traits_3<GeomTraits>;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, P_traits>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<
      P_traits, CGAL::Triangulation_face_base_with_info_2<bool, P_traits>>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<
      P_traits, CGAL::Triangulation_data_structure_2<Vb, Fb>, CGAL::Exact_intersections_tag>;
  const std::size_t n = corners.size();
  CDT cdt{P_traits(normal)};
  std::vector<typename CDT::Vertex_handle> handles;
  for (std::size_t i = 0; i < n; ++i) {
    handles.push_back(cdt.insert(corners[i]));
    handles.back()->info() = i;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (handles[i] != handles[(i + 1) % n]) cdt.insert_constraint(handles[i], handles[(i + 1) % n]);
  if (cdt.dimension() != 2 || cdt.number_of_vertices() != n) return {};
  // Outside: reached from the infinite face without crossing a constraint.
  for (auto fh : cdt.all_face_handles()) fh->info() = false;
  std::queue<typename CDT::Face_handle> queue;
  queue.push(cdt.infinite_face());
  while (!queue.empty()) {
    const auto fh = queue.front();
    queue.pop();
    if (fh->info()) continue;
    fh->info() = true;
    for (int i = 0; i < 3; ++i)
      if (!cdt.is_constrained(typename CDT::Edge(fh, i))) queue.push(fh->neighbor(i));
  }
  std::vector<Corner_triangle> triangles;
  for (auto fh : cdt.finite_face_handles()) {
    if (fh->info()) continue;
    Corner_triangle t{fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  // Every side once, in its direction, and every other edge twice, once each way.
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for (const Corner_triangle& t : triangles)
    for (int k = 0; k < 3; ++k) ++uses[{t[k], t[(k + 1) % 3]}];
  for (std::size_t i = 0; i < n; ++i)
    if (uses[{i, (i + 1) % n}] != 1 || uses.count({(i + 1) % n, i})) return {};
  for (const auto& use : uses) {
    const bool side = use.first.second == (use.first.first + 1) % n;
    if (use.second != 1 || (!side && !uses.count({use.first.second, use.first.first}))) return {};
  }
  if (triangles.size() + 2 != n) return {};
  return triangles;
}

/// Replaces the face `f` by the triangles `triangles` of its corners (the corners in the order of
/// the face's halfedges from `halfedge(f)`): `f` becomes the first, and the edges are created in
/// the order of the triangles (CGAL's construction in `triangulate_face_with_hole_filling`).
template <class PolygonMesh>
void build_corner_triangles(
    typename boost::graph_traits<PolygonMesh>::face_descriptor f, PolygonMesh& pm,
    const std::vector<Corner_triangle>& triangles,
    std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& created) {
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  std::vector<halfedge_descriptor> sides;
  std::vector<typename GT::vertex_descriptor> corners;
  for (halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm)) {
    sides.push_back(h);
    corners.push_back(source(h, pm));
  }
  const std::size_t n = sides.size();
  std::map<std::pair<std::size_t, std::size_t>, halfedge_descriptor> halfedge_of;
  for (std::size_t i = 0; i < n; ++i) halfedge_of[{i, (i + 1) % n}] = sides[i];
  bool first = true;
  for (const Corner_triangle& t : triangles) {
    const auto g = first ? f : add_face(pm);
    first = false;
    std::array<halfedge_descriptor, 3> h;
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      auto it = halfedge_of.find({a, b});
      if (it == halfedge_of.end()) {
        const halfedge_descriptor created_h = halfedge(add_edge(pm), pm);
        set_target(created_h, corners[b], pm);
        set_target(opposite(created_h, pm), corners[a], pm);
        halfedge_of[{b, a}] = opposite(created_h, pm);
        it = halfedge_of.emplace(std::make_pair(a, b), created_h).first;
      }
      h[k] = it->second;
    }
    for (int k = 0; k < 3; ++k) {
      set_next(h[k], h[(k + 1) % 3], pm);
      set_face(h[k], g, pm);
    }
    set_halfedge(g, h[0], pm);
    created.push_back(g);
  }
}

/// Triangulates the face `f` as CGAL's `triangulate_face` does (a quadrangle along its better
/// diagonal, a larger polygon by the constrained Delaunay triangulation of its projection along
/// its normal), in an order fixed by the face (see the file comment). Appends the triangles to
/// `created` (`f` itself when it is a triangle); false, the mesh unchanged, when the projection
/// does not triangulate the face.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
bool triangulate_face_in_fixed_order(
    typename boost::graph_traits<PolygonMesh>::face_descriptor f, PolygonMesh& pm,
    VertexPointMap vpm, const GeomTraits& traits,
    std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& created) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<typename GeomTraits::Point_3> corners;
  for (auto h : halfedges_around_face(halfedge(f, pm), pm))
    corners.push_back(get(vpm, source(h, pm)));
  const auto np = CGAL::parameters::vertex_point_map(vpm).geom_traits(traits);
  if (corners.size() == 3) {
    created.push_back(f);
    return true;
  }
  if (corners.size() == 4)  // split_face along one diagonal: no order to fix
    return PMP::triangulate_face(f, pm, np.visitor(Subface_collector<PolygonMesh>{&created}));
  const auto normal = PMP::compute_face_normal(f, pm, np);
  if (normal == typename GeomTraits::Vector_3(CGAL::NULL_VECTOR)) return false;
  const std::vector<Corner_triangle> triangles =
      projected_polygon_triangles<GeomTraits>(corners, normal);
  if (triangles.empty()) return false;
  build_corner_triangles(f, pm, triangles, created);
  return true;
}

/// `triangulate_face_in_fixed_order` on every face of `pm` with more than three sides, in index
/// order; false when one of them could not be triangulated (that face is left as it was).
template <class PolygonMesh>
bool triangulate_faces_in_fixed_order(PolygonMesh& pm) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  const auto vpm = get(CGAL::vertex_point, pm);
  using Point = typename boost::property_traits<decltype(vpm)>::value_type;
  std::vector<face_descriptor> polygons;
  for (face_descriptor f : faces(pm))
    if (degree(f, pm) > 3) polygons.push_back(f);
  bool all = true;
  std::vector<face_descriptor> created;
  for (face_descriptor f : polygons)
    all = triangulate_face_in_fixed_order(f, pm, vpm, typename Kernel_traits<Point>::Kernel(),
                                          created) &&
          all;
  return all;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_FACE_TRIANGULATION_H
