// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PATCH_CHECK_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PATCH_CHECK_H

// The exact self-intersection check of a fill patch and the rollback of a rejected patch. Every
// method's patch goes through these two functions in the dispatcher, so no method can leave a
// self-intersecting patch in the mesh.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <type_traits>
#include <unordered_map>
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

  /// The vertices whose position the method changed (kept patches only; after a rollback they
  /// are back where they were).
  std::vector<vertex_descriptor> moved_vertices() const {
    std::vector<vertex_descriptor> moved;
    for (const auto& saved : saved_)
      if (get(vpm_, saved.first) != saved.second) moved.push_back(saved.first);
    return moved;
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

/// Number of pairs of intersecting triangles of `range` (a degenerate face counts as a pair with
/// itself) that involve at least one face of `patch`, decided with the exact predicates of
/// `traits` by CGAL's test of two faces. Pairs of two other faces existed before the fill and
/// are not examined (internal/bounded_pairs.h). The enumeration stops at the pair limit of the
/// range: a patch that meets its surroundings that often counts as intersecting (at least one).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::size_t pairs_involving_patch(
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& range,
    const PolygonMesh& pm, const Fill_patch<PolygonMesh>& patch, VertexPointMap vpm,
    const GeomTraits& traits) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  const std::unordered_set<face_descriptor> in_patch(patch.faces.begin(), patch.faces.end());
  std::vector<face_descriptor> patch_faces, others;
  for (face_descriptor f : range) (in_patch.count(f) ? patch_faces : others).push_back(f);
  const auto found = bounded_intersections_involving(patch_faces, others, pm,
                                                     default_pair_limit(range.size()), vpm, traits);
  return found.truncated ? std::max<std::size_t>(found.pairs.size(), 1) : found.pairs.size();
}

/// Bounding boxes of the faces a new patch must not meet: every face of the mesh when the
/// filling starts, then the faces of each kept patch. A patch's ring check sees only the faces
/// around its border; two patches bulging into each other (two holes facing each other across a
/// thin gap, as in libcgal-demo's blobby_3cc) or a patch crossing a far part of the mesh are
/// found only by looking at every face near the patch. The boxes are computed once (one pass
/// over the mesh) so each patch costs one scan of boxes, not of geometry.
template <class PolygonMesh, class VertexPointMap>
class Face_box_cache {
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;

 public:
  /// With `other_parts_are_obstacles` false, a query returns only faces of the connected
  /// components of the faces it excludes (the hole's ring) and faces of kept patches: a patch may
  /// then meet the faces other parts had. The patches of other parts are returned apart when the
  /// caller asks (`other_parts_patches`): the check lets a patch cross them, not lie on them.
  Face_box_cache(const PolygonMesh& pm, VertexPointMap vpm, bool other_parts_are_obstacles = true)
      : pm_(pm), vpm_(vpm), other_parts_are_obstacles_(other_parts_are_obstacles) {}

  /// Takes the faces of the mesh as it is now. Call it before the first patch is added: a
  /// patch present at that time would stay in the cache after a rollback removed it.
  void build() {
    if (built_) return;
    built_ = true;
    faces_.reserve(num_faces(pm_));
    boxes_.reserve(num_faces(pm_));
    for (face_descriptor f : faces(pm_)) {
      faces_.push_back(f);
      boxes_.push_back(face_box(f));
    }
    build_grid();
    number_components();
  }

  /// The connected component (by edges, when the cache was built) of `f`; a kept patch belongs
  /// to the component of the faces around it. `no_component` for a face the cache never saw.
  std::size_t component_of(face_descriptor f) const {
    const auto found = component_.find(f);
    return found == component_.end() ? no_component : found->second;
  }
  static constexpr std::size_t no_component = std::size_t(-1);

  /// The faces (not in `exclude`) whose box overlaps `box`, in the order they entered the
  /// cache (the order a scan of every box gives); without `other_parts_are_obstacles`, only
  /// those of the components of the faces of `exclude` and those of kept patches, the patches of
  /// other components in `other_parts_patches` instead when it is given.
  template <class FaceSet>
  std::vector<face_descriptor> overlapping(
      const CGAL::Bbox_3& box, const FaceSet& exclude,
      std::vector<face_descriptor>* other_parts_patches = nullptr) const {
    CGAL_precondition(built_);
    std::unordered_set<std::size_t> parts;
    if (!other_parts_are_obstacles_)
      for (const auto& element : exclude) {
        const face_descriptor f = face_of(element);
        if (component_of(f) != no_component) parts.insert(component_of(f));
      }
    std::vector<std::size_t> candidates;
    const std::array<std::size_t, 6> range = cell_range(box);
    for (std::size_t x = range[0]; x <= range[3]; ++x)
      for (std::size_t y = range[1]; y <= range[4]; ++y)
        for (std::size_t z = range[2]; z <= range[5]; ++z) {
          const std::vector<std::size_t>& cell =
              cells_[(x * cells_per_axis_ + y) * cells_per_axis_ + z];
          candidates.insert(candidates.end(), cell.begin(), cell.end());
        }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::vector<face_descriptor> found;
    std::unordered_set<face_descriptor> seen;  // a moved face is in the cache twice
    for (std::size_t i : candidates) {
      const bool other_part = !parts.empty() && !parts.count(component_of(faces_[i]));
      if (other_part && !patch_faces_.count(faces_[i])) continue;
      if (CGAL::do_overlap(boxes_[i], box) && exclude.count(faces_[i]) == 0 &&
          seen.insert(faces_[i]).second)
        (other_part && other_parts_patches ? *other_parts_patches : found).push_back(faces_[i]);
    }
    return found;
  }

  /// Records a kept patch: its faces join the cache, and the faces around the vertices it moved
  /// join again with their new boxes (the stale box only adds a candidate, never hides one).
  template <class Patch>
  void keep(const Patch& patch, const std::vector<vertex_descriptor>& moved) {
    CGAL_precondition(built_);
    std::size_t component = no_component;
    for (face_descriptor f : patch_with_ring(pm_, patch))
      if (component == no_component) component = component_of(f);
    for (face_descriptor f : patch.faces) {
      add(f);
      component_[f] = component;
      patch_faces_.insert(f);
    }
    for (vertex_descriptor v : moved) {
      if (halfedge(v, pm_) == GT::null_halfedge()) continue;
      for (face_descriptor f : faces_around_target(halfedge(v, pm_), pm_))
        if (f != GT::null_face()) add(f);
    }
  }

  CGAL::Bbox_3 face_box(face_descriptor f) const {
    CGAL::Bbox_3 box;
    for (auto h : halfedges_around_face(halfedge(f, pm_), pm_))
      box += get(vpm_, target(h, pm_)).bbox();
    return box;
  }

 private:
  /// The face of an element of an `exclude` set or map.
  template <class Element>
  static face_descriptor face_of(const Element& element) {
    if constexpr (std::is_same_v<Element, face_descriptor>)
      return element;
    else
      return element.first;
  }

  void number_components() {
    std::size_t next = 0;
    for (face_descriptor seed : faces_) {
      if (!component_.emplace(seed, next).second) continue;
      std::vector<face_descriptor> stack{seed};
      while (!stack.empty()) {
        const face_descriptor f = stack.back();
        stack.pop_back();
        for (auto h : halfedges_around_face(halfedge(f, pm_), pm_)) {
          const face_descriptor g = face(opposite(h, pm_), pm_);
          if (g != GT::null_face() && component_.emplace(g, next).second) stack.push_back(g);
        }
      }
      ++next;
    }
  }

  void add(face_descriptor f) {
    faces_.push_back(f);
    boxes_.push_back(face_box(f));
    insert_in_grid(faces_.size() - 1);
  }

  /// A uniform grid over the mesh's box, so that a query looks at the faces near it instead of
  /// every face (a patch in a million-face mesh). Boxes outside the grid are clamped into its
  /// border cells; cell indices grow with the coordinate, so every overlap is kept.
  void build_grid() {
    for (const CGAL::Bbox_3& box : boxes_) extent_ += box;
    cells_per_axis_ = std::size_t(std::clamp(std::cbrt(double(boxes_.size())) / 1.5, 1.0, 96.0));
    cells_.assign(cells_per_axis_ * cells_per_axis_ * cells_per_axis_, {});
    for (std::size_t i = 0; i < boxes_.size(); ++i) insert_in_grid(i);
  }

  void insert_in_grid(std::size_t i) {
    const std::array<std::size_t, 6> range = cell_range(boxes_[i]);
    for (std::size_t x = range[0]; x <= range[3]; ++x)
      for (std::size_t y = range[1]; y <= range[4]; ++y)
        for (std::size_t z = range[2]; z <= range[5]; ++z)
          cells_[(x * cells_per_axis_ + y) * cells_per_axis_ + z].push_back(i);
  }

  /// First and last cell per axis (x, y, z, then x, y, z) of the cells `box` meets.
  std::array<std::size_t, 6> cell_range(const CGAL::Bbox_3& box) const {
    std::array<std::size_t, 6> range{};
    for (int d = 0; d < 3; ++d) {
      const double length = extent_.max(d) - extent_.min(d);
      const auto cell = [&](double t) {
        const double u = (t - extent_.min(d)) / length * double(cells_per_axis_);
        if (!(length > 0) || !(u > 0)) return std::size_t(0);
        return std::size_t(std::min(u, double(cells_per_axis_ - 1)));
      };
      range[std::size_t(d)] = cell(box.min(d));
      range[std::size_t(d) + 3] = cell(box.max(d));
    }
    return range;
  }

  const PolygonMesh& pm_;
  VertexPointMap vpm_;
  bool other_parts_are_obstacles_ = true;
  bool built_ = false;
  std::vector<face_descriptor> faces_;
  std::vector<CGAL::Bbox_3> boxes_;
  CGAL::Bbox_3 extent_;
  std::size_t cells_per_axis_ = 1;
  std::vector<std::vector<std::size_t>> cells_;  ///< indices into faces_/boxes_
  std::unordered_map<face_descriptor, std::size_t> component_;
  std::unordered_set<face_descriptor> patch_faces_;  ///< of kept patches
};

/// Pairs of a face of `patch` and a face of `others` (no shared vertex) that lie in one plane
/// and overlap, by exact predicates: two parts' patches on one plane would be duplicated faces.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::size_t coplanar_overlaps(
    const PolygonMesh& pm, const Fill_patch<PolygonMesh>& patch,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& others,
    VertexPointMap vpm, const GeomTraits& traits) {
  using Triangle = typename GeomTraits::Triangle_3;
  const auto triangle = [&](auto f) {
    const auto h = halfedge(f, pm);
    return Triangle(get(vpm, source(h, pm)), get(vpm, target(h, pm)),
                    get(vpm, target(next(h, pm), pm)));
  };
  const auto coplanar = traits.coplanar_3_object();
  const auto do_intersect = traits.do_intersect_3_object();
  std::size_t pairs = 0;
  for (auto g : others) {
    const Triangle b = triangle(g);
    for (auto f : patch.faces) {
      const Triangle a = triangle(f);
      if (!CGAL::do_overlap(a.bbox(), b.bbox())) continue;
      if (coplanar(a[0], a[1], a[2], b[0]) && coplanar(a[0], a[1], a[2], b[1]) &&
          coplanar(a[0], a[1], a[2], b[2]) && do_intersect(a, b))
        ++pairs;
    }
  }
  return pairs;
}

/// Pairs of intersecting faces with at least one patch face, among the patch, its ring and
/// every other face of the mesh near the patch (`cache`), by CGAL's exact `self_intersections`.
/// Without `other_parts_are_obstacles` the patches of other parts count only where the patch
/// lies on them.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::size_t patch_intersections_with_mesh(const PolygonMesh& pm,
                                          const Fill_patch<PolygonMesh>& patch, VertexPointMap vpm,
                                          const GeomTraits& traits,
                                          Face_box_cache<PolygonMesh, VertexPointMap>& cache) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::vector<face_descriptor> range = patch_with_ring(pm, patch);
  std::unordered_set<face_descriptor> in_range(range.begin(), range.end());
  CGAL::Bbox_3 box;
  for (face_descriptor f : patch.faces) box += cache.face_box(f);
  std::vector<face_descriptor> other_parts_patches;
  const std::vector<face_descriptor> near = cache.overlapping(box, in_range, &other_parts_patches);
  range.insert(range.end(), near.begin(), near.end());
  return pairs_involving_patch(range, pm, patch, vpm, traits) +
         coplanar_overlaps(pm, patch, other_parts_patches, vpm, traits);
}

/// How far the patch's new vertices reach from its border, in border radii: the largest distance
/// of a new vertex to the centroid of the border's vertices (the vertices of patch faces that
/// the patch did not create), over the largest distance of a border vertex to it. A cap on a
/// round border reaches 1; 0 for a patch without new vertices or a border of one point.
template <class PolygonMesh, class VertexPointMap>
double patch_reach_in_border_radii(const PolygonMesh& pm, const Fill_patch<PolygonMesh>& patch,
                                   VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  const std::unordered_set<vertex_descriptor> created(patch.vertices.begin(), patch.vertices.end());
  std::unordered_set<vertex_descriptor> border;
  for (auto f : patch.faces)
    for (vertex_descriptor v : vertices_around_face(halfedge(f, pm), pm))
      if (!created.count(v)) border.insert(v);
  if (created.empty() || border.empty()) return 0;
  const auto at = [&](vertex_descriptor v) { return to_array(get(vpm, v)); };
  Vec3 centre;
  for (vertex_descriptor v : border) centre += at(v);
  centre = centre * (1.0 / double(border.size()));
  double radius = 0, reach = 0;
  for (vertex_descriptor v : border) radius = std::max(radius, norm(at(v) - centre));
  for (vertex_descriptor v : created) reach = std::max(reach, norm(at(v) - centre));
  return radius > 0 ? reach / radius : 0;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_PATCH_CHECK_H
