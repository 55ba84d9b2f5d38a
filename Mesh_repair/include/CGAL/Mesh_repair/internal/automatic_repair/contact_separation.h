// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_CONTACT_SEPARATION_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_CONTACT_SEPARATION_H

// Contacts moved apart (step "coincident elements"): where parts touch one another, or a surface
// touches itself, at a point or along an edge (CAD solids meeting edge to edge or corner to
// corner), the mesh keeps one vertex per fan of faces at one position. A file stores positions,
// and a reader that merges coincident points sees a non-manifold vertex or edge there, and
// CGAL's self-intersection test sees the faces of the two fans meet. Each such vertex is moved a
// little (about 1e-6 of the diagonal) into its own fan, towards the centre of its neighbours, so
// that the file shows what the mesh is; a move that makes faces meet that did not is undone.

#include <CGAL/Mesh_repair/internal/bounded_pairs.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// What `separate_contacts` did.
struct Contact_separation {
  std::size_t vertices_moved = 0;  ///< vertices at a shared position moved into their own fan
  std::size_t moves_undone = 0;    ///< moves that made faces meet, undone (the contact stays)
  bool skipped = false;            ///< too many intersecting pairs to check: nothing moved
};

/// Moves apart the vertices that share a position; see the file comment.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
class Contact_separator {
 public:
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Vector = typename GeomTraits::Vector_3;
  using Face_pair = std::pair<face_descriptor, face_descriptor>;
  using Index_pair = std::pair<std::size_t, std::size_t>;

  /// Rounds of undoing: each undoes the moves of the faces that meet a face they did not meet.
  static constexpr int max_rounds = 4;

  Contact_separator(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits)
      : pm_(pm), vpm_(vpm), traits_(traits), fim_(CGAL::get_initialized_face_index_map(pm)) {}

  Contact_separation separate(double distance) {
    Contact_separation report;
    const std::vector<vertex_descriptor> shared = vertices_at_shared_positions();
    if (shared.empty() || !(distance > 0) || !std::isfinite(distance)) return report;
    const std::vector<face_descriptor> moved_faces = faces_around(shared);
    const auto before = meeting_pairs(moved_faces);
    if (before.truncated) {
      report.skipped = true;
      return report;
    }
    std::set<Index_pair> met;
    for (const Face_pair& pair : before.pairs) met.insert(indices(pair));
    std::unordered_map<vertex_descriptor, Point> old;
    for (vertex_descriptor v : shared) {
      const Point p = get(vpm_, v);
      const Vector direction = into_own_fan(v);
      if (direction == CGAL::NULL_VECTOR) continue;
      const Point moved = p + direction * distance;
      if (!std::isfinite(CGAL::to_double(moved.x())) ||
          !std::isfinite(CGAL::to_double(moved.y())) || !std::isfinite(CGAL::to_double(moved.z())))
        continue;
      old.emplace(v, p);
      put(vpm_, v, moved);
    }
    for (int round = 0; round < max_rounds && !old.empty(); ++round)
      if (undo_new_contacts(moved_faces, met, old, report) == 0) return finish(old, report);
    // Still new contacts after the last round: every move undone.
    report.moves_undone += old.size();
    for (const auto& [v, p] : old) put(vpm_, v, p);
    old.clear();
    return finish(old, report);
  }

 private:
  std::vector<vertex_descriptor> vertices_at_shared_positions() const {
    std::map<Point, std::vector<vertex_descriptor>> at;
    for (vertex_descriptor v : vertices(pm_))
      if (halfedge(v, pm_) != boost::graph_traits<PolygonMesh>::null_halfedge())
        at[get(vpm_, v)].push_back(v);
    std::vector<vertex_descriptor> shared;
    for (const auto& entry : at)
      if (entry.second.size() > 1)
        shared.insert(shared.end(), entry.second.begin(), entry.second.end());
    return shared;
  }

  std::vector<face_descriptor> faces_around(const std::vector<vertex_descriptor>& shared) const {
    std::unordered_set<face_descriptor> seen;
    std::vector<face_descriptor> around;
    for (vertex_descriptor v : shared)
      for (face_descriptor f : faces_around_target(halfedge(v, pm_), pm_))
        if (f != boost::graph_traits<PolygonMesh>::null_face() && seen.insert(f).second)
          around.push_back(f);
    return around;
  }

  /// The pairs of faces that meet, one of them in `involved`.
  Bounded_pairs<Face_pair> meeting_pairs(const std::vector<face_descriptor>& involved) const {
    std::unordered_set<face_descriptor> in(involved.begin(), involved.end());
    std::vector<face_descriptor> others;
    for (face_descriptor f : faces(pm_))
      if (!in.count(f)) others.push_back(f);
    return bounded_intersections_involving(involved, others, pm_, pair_limit(0, num_faces(pm_)),
                                           vpm_, traits_);
  }

  /// The indices of the two faces, the smaller first.
  Index_pair indices(const Face_pair& pair) const {
    const std::size_t a = get(fim_, pair.first), b = get(fim_, pair.second);
    return {std::min(a, b), std::max(a, b)};
  }

  /// Towards the centre of the vertex's neighbours; where they surround it evenly, against the
  /// normal of its fan. Unit length, or null.
  Vector into_own_fan(vertex_descriptor v) const {
    const Point p = get(vpm_, v);
    Vector towards = CGAL::NULL_VECTOR, normal = CGAL::NULL_VECTOR;
    for (auto h : halfedges_around_target(halfedge(v, pm_), pm_)) {
      towards = towards + (get(vpm_, source(h, pm_)) - p);
      if (!is_border(h, pm_))
        normal = normal + CGAL::cross_product(get(vpm_, source(h, pm_)) - p,
                                              get(vpm_, target(next(h, pm_), pm_)) - p);
    }
    const Vector direction = towards.squared_length() > 0 ? towards : -normal;
    const double length = std::sqrt(CGAL::to_double(direction.squared_length()));
    return length > 0 && std::isfinite(length) ? direction / length : CGAL::NULL_VECTOR;
  }

  /// Undoes the moves of the vertices of faces that meet a face they did not meet; returns how
  /// many were undone.
  std::size_t undo_new_contacts(const std::vector<face_descriptor>& moved_faces,
                                const std::set<Index_pair>& met,
                                std::unordered_map<vertex_descriptor, Point>& old,
                                Contact_separation& report) {
    const auto now = meeting_pairs(moved_faces);
    std::size_t undone = 0;
    const auto undo = [&](face_descriptor f) {
      for (vertex_descriptor v : vertices_around_face(halfedge(f, pm_), pm_)) {
        const auto it = old.find(v);
        if (it == old.end()) continue;
        put(vpm_, v, it->second);
        old.erase(it);
        ++undone;
      }
    };
    for (const Face_pair& pair : now.pairs)
      if (now.truncated || !met.count(indices(pair))) {
        undo(pair.first);
        undo(pair.second);
      }
    report.moves_undone += undone;
    return undone;
  }

  Contact_separation finish(const std::unordered_map<vertex_descriptor, Point>& old,
                            Contact_separation& report) const {
    report.vertices_moved = old.size();
    return report;
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  const GeomTraits& traits_;
  typename CGAL::GetInitializedFaceIndexMap<PolygonMesh>::type fim_;
};

/// Moves apart by `distance` the vertices of `pm` that share a position (`Contact_separator`).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Contact_separation separate_contacts(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                                     double distance) {
  return Contact_separator<PolygonMesh, VertexPointMap, GeomTraits>(pm, vpm, traits)
      .separate(distance);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_CONTACT_SEPARATION_H
