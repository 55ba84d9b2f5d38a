// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_REGION_H
#define CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_REGION_H

// Thesis 7.2.3: the group of triangles removed around a chosen element, as closed polygons
// ready for re-triangulation. Three shapes of region:
//  (a) the triangles around the removable interior nodes of an element (reduction, Fig. 7.3);
//  (b) the element and its three edge neighbours, a hexagon (quality, Fig. 7.4);
//  (c) the star of a removable edge-feature node, split along the chord joining its two feature
//      neighbours, so that the feature line survives as that chord.
// Polygons follow the halfedges that become border when the region is removed, which is the
// orientation the GA expects.

#include <CGAL/Mesh_repair/internal/optimize_mesh/feature_classification.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace optimize {

template <class PolygonMesh>
struct Region_polygon {
  using GT = boost::graph_traits<PolygonMesh>;
  std::vector<typename GT::vertex_descriptor> nodes;
  // Halfedge of polygon edge i (nodes[i] -> nodes[i+1], last one closing) in a face of the
  // region; null for a new edge (feature chord or new border edge).
  std::vector<typename GT::halfedge_descriptor> inner;
  std::vector<typename GT::face_descriptor> faces;  // removed faces on this polygon's side
};

template <class PolygonMesh>
struct Region {
  using GT = boost::graph_traits<PolygonMesh>;
  std::vector<typename GT::face_descriptor> faces;
  std::vector<typename GT::vertex_descriptor> removed;
  std::vector<Region_polygon<PolygonMesh>> polygons;
  bool contains(typename GT::face_descriptor f) const {
    return std::find(faces.begin(), faces.end(), f) != faces.end();
  }
};

template <class PolygonMesh>
void add_star(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm,
              std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& faces) {
  for (auto f : faces_around_target(halfedge(v, pm), pm))
    if (f != boost::graph_traits<PolygonMesh>::null_face() &&
        std::find(faces.begin(), faces.end(), f) == faces.end())
      faces.push_back(f);
}

// The single boundary cycle of `region.faces`; false when the region is not a disc bounded by a
// simple polygon with exactly the removed nodes inside, or when an edge inside it is a feature.
template <class PolygonMesh, class Classification>
bool close_region(Region<PolygonMesh>& region, const PolygonMesh& pm,
                  const Classification& classification) {
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  std::vector<halfedge_descriptor> boundary;
  for (auto f : region.faces) {
    for (halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm)) {
      const auto across = face(opposite(h, pm), pm);
      if (across != boost::graph_traits<PolygonMesh>::null_face() && region.contains(across)) {
        if (classification.is_feature(h)) return false;  // a feature edge would disappear
        continue;
      }
      boundary.push_back(h);
    }
  }
  const std::size_t n = boundary.size();
  if (n < 3 || region.faces.size() != n + 2 * region.removed.size() - 2) return false;
  Region_polygon<PolygonMesh> polygon;
  polygon.faces = region.faces;
  halfedge_descriptor h = boundary.front();
  for (std::size_t step = 0; step < n; ++step) {
    polygon.nodes.push_back(source(h, pm));
    polygon.inner.push_back(h);
    std::size_t found = 0;
    halfedge_descriptor following = h;
    for (halfedge_descriptor g : boundary)
      if (source(g, pm) == target(h, pm)) {
        following = g;
        ++found;
      }
    if (found != 1) return false;  // the boundary touches itself at target(h)
    h = following;
  }
  if (h != boundary.front()) return false;  // more than one cycle
  for (auto v : region.removed)
    if (std::find(polygon.nodes.begin(), polygon.nodes.end(), v) != polygon.nodes.end())
      return false;
  region.polygons.push_back(std::move(polygon));
  return true;
}

/// (a) The triangles around the removable interior nodes of `f`.
template <class PolygonMesh, class Classification>
bool node_region(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                 const PolygonMesh& pm, const Classification& classification,
                 Region<PolygonMesh>& region) {
  for (auto v : vertices_around_face(halfedge(f, pm), pm))
    if (classification.type(v) == Node_type::interior) region.removed.push_back(v);
  if (region.removed.empty()) return false;
  for (auto v : region.removed) add_star(v, pm, region.faces);
  return close_region(region, pm, classification);
}

/// (a') The star of one removable interior node `v` (region (a) restricted to one node).
template <class PolygonMesh, class Classification>
bool star_region(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                 const PolygonMesh& pm, const Classification& classification,
                 Region<PolygonMesh>& region) {
  if (classification.type(v) != Node_type::interior) return false;
  region.removed.push_back(v);
  add_star(v, pm, region.faces);
  return close_region(region, pm, classification);
}

/// (b) The element and its edge neighbours; a neighbour across a feature edge is left out
/// (thesis: "the related triangular elements will not be involved").
template <class PolygonMesh, class Classification>
bool edge_region(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                 const PolygonMesh& pm, const Classification& classification,
                 Region<PolygonMesh>& region) {
  region.faces.push_back(f);
  for (auto h : halfedges_around_face(halfedge(f, pm), pm))
    if (!classification.is_feature(h)) region.faces.push_back(face(opposite(h, pm), pm));
  if (region.faces.size() < 2) return false;
  return close_region(region, pm, classification);
}

/// (c) The star of the removable edge-feature node `v`, split along the chord joining its two
/// feature neighbours (one polygon when `v` is on the border).
template <class PolygonMesh, class Classification>
bool feature_node_region(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                         const PolygonMesh& pm, const Classification& classification,
                         Region<PolygonMesh>& region) {
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  // Outgoing halfedges v -> link node, counterclockwise, starting after the border if any.
  halfedge_descriptor start = opposite(halfedge(v, pm), pm);
  for (halfedge_descriptor h : halfedges_around_source(v, pm))
    if (is_border(opposite(h, pm), pm)) start = h;
  std::vector<halfedge_descriptor> spokes;
  halfedge_descriptor h = start;
  do {
    spokes.push_back(h);
    if (is_border(h, pm)) break;
    h = opposite(prev(h, pm), pm);
  } while (h != start);
  const bool on_border = is_border(spokes.back(), pm);
  const std::size_t m = spokes.size();
  if (m < 3) return false;
  std::vector<std::size_t> feature_spokes;
  for (std::size_t i = 0; i < m; ++i)
    if (classification.is_feature(spokes[i]) && (!on_border || i == 0 || i + 1 == m))
      feature_spokes.push_back(i);
  if (feature_spokes.size() != 2) return false;
  region.removed.push_back(v);
  for (std::size_t i = 0; i < m; ++i)
    if (!is_border(spokes[i], pm)) region.faces.push_back(face(spokes[i], pm));
  // Sides: spokes [s0, s1] and, when interior, [s1, s0] cyclically.
  const std::size_t s0 = feature_spokes[0], s1 = feature_spokes[1];
  auto side = [&](std::size_t from, std::size_t to) {
    Region_polygon<PolygonMesh> polygon;
    for (std::size_t i = from;; i = (i + 1) % m) {
      polygon.nodes.push_back(target(spokes[i], pm));
      if (i == to) break;
      polygon.inner.push_back(next(spokes[i], pm));
      polygon.faces.push_back(face(spokes[i], pm));
    }
    polygon.inner.push_back(GT::null_halfedge());  // the new feature chord or border edge
    return polygon;
  };
  const auto a = target(spokes[s0], pm), b = target(spokes[s1], pm);
  region.polygons.push_back(side(s0, s1));
  if (!on_border) region.polygons.push_back(side(s1, s0));
  // The chord a-b must be new, unless a and b already bound a face of the star (that side then
  // has no triangle and the existing edge carries the feature line).
  bool adjacent_in_star = false;
  for (const auto& polygon : region.polygons) adjacent_in_star |= polygon.nodes.size() == 2;
  if (!adjacent_in_star && halfedge(a, b, pm).second) return false;
  if (on_border && adjacent_in_star) return false;
  return true;
}

}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif
