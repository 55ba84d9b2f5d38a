// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PATCH_CHECK_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PATCH_CHECK_H

// The exact self-intersection check of a fill patch and the rollback of a rejected patch. Every
// method's patch goes through these two functions in the dispatcher, so no method can leave a
// self-intersecting patch in the mesh.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <iterator>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Remembers what a hole filling may change so that it can be undone: the positions of the
/// hole's border vertices and of their neighbours (methods that smooth the contour move those),
/// and, through the method's `Fill_patch`, the faces and vertices it added.
template <class PolygonMesh, class VertexPointMap>
class Patch_transaction {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

 public:
  Patch_transaction(PolygonMesh& pm, VertexPointMap vpm,
                    const std::vector<halfedge_descriptor>& border_cycles)
      : pm_(pm), vpm_(vpm) {
    std::unordered_set<vertex_descriptor> seen;
    for (halfedge_descriptor cycle : border_cycles) {
      for (halfedge_descriptor h : halfedges_around_face(cycle, pm_)) {
        for (halfedge_descriptor around : halfedges_around_target(target(h, pm_), pm_)) {
          for (vertex_descriptor v : {target(around, pm_), source(around, pm_)}) {
            if (seen.insert(v).second) saved_.emplace_back(v, get(vpm_, v));
          }
        }
      }
    }
  }

  /// Removes the faces and vertices of `patch` (last added first, so each removal undoes one
  /// addition), restores the saved positions and clears `patch`. The border cycles are back.
  void rollback(Fill_patch<PolygonMesh>& patch) {
    std::vector<vertex_descriptor> isolated;
    for (vertex_descriptor v : patch.vertices) {
      if (halfedge(v, pm_) == GT::null_halfedge()) isolated.push_back(v);
    }
    for (auto it = patch.faces.rbegin(); it != patch.faces.rend(); ++it) {
      CGAL::Euler::remove_face(halfedge(*it, pm_), pm_);
    }
    for (vertex_descriptor v : isolated) remove_vertex(v, pm_);
    for (const auto& saved : saved_) put(vpm_, saved.first, saved.second);
    patch.faces.clear();
    patch.vertices.clear();
  }

 private:
  PolygonMesh& pm_;
  VertexPointMap vpm_;
  std::vector<std::pair<vertex_descriptor, Point>> saved_;
};

/// The faces of `patch` plus the faces sharing a vertex with them (the ring): the range that
/// the self-intersection check examines.
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> patch_with_ring(
    const PolygonMesh& pm, const Fill_patch<PolygonMesh>& patch) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::unordered_set<face_descriptor> in_range(patch.faces.begin(), patch.faces.end());
  std::vector<face_descriptor> range(patch.faces.begin(), patch.faces.end());
  for (face_descriptor f : patch.faces) {
    for (auto h : halfedges_around_face(halfedge(f, pm), pm)) {
      for (face_descriptor g : faces_around_target(h, pm)) {
        if (g != boost::graph_traits<PolygonMesh>::null_face() && in_range.insert(g).second)
          range.push_back(g);
      }
    }
  }
  return range;
}

/// Number of pairs of intersecting triangles (a degenerate patch face counts as a pair with
/// itself) among the patch and its ring that involve at least one patch face, decided with the
/// exact predicates of `traits` by CGAL's `self_intersections`. Intersections between two ring
/// faces existed before the fill and are not counted.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::size_t patch_intersections(const PolygonMesh& pm, const Fill_patch<PolygonMesh>& patch,
                                VertexPointMap vpm, const GeomTraits& traits) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  const auto range = patch_with_ring(pm, patch);
  std::vector<std::pair<face_descriptor, face_descriptor>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(
      range, pm, std::back_inserter(pairs),
      CGAL::parameters::vertex_point_map(vpm).geom_traits(traits));
  const std::unordered_set<face_descriptor> in_patch(patch.faces.begin(), patch.faces.end());
  return std::size_t(std::count_if(pairs.begin(), pairs.end(), [&](const auto& pair) {
    return in_patch.count(pair.first) > 0 || in_patch.count(pair.second) > 0;
  }));
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PATCH_CHECK_H
