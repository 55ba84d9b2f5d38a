// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_COINCIDENT_ELEMENTS_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_COINCIDENT_ELEMENTS_H

// Defects that a halfedge mesh can only hold through vertices at the same position (what the
// polygon-soup stage leaves after splitting non-manifold elements, or a mesh built from a soup
// without merging points) or through pinched vertex umbrellas:
// - non-manifold vertices: a position whose faces, glued across edges carried by exactly two
//   face sides, fall into several fans (the definition of CGAL's orient_polygon_soup);
// - non-manifold edges: a segment carried by three or more face sides;
// - duplicated faces: faces on the same three positions;
// - inconsistent orientation: faces glued along a coincident edge that both run it the same way.
// Positions are compared exactly. Only positions with several vertices, or vertices CGAL finds
// non-manifold, are examined, so a clean mesh costs one sort of its vertices.

#include <CGAL/Mesh_repair/internal/detect_defects/mesh_access.h>

#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Union_find.h>

#include <algorithm>
#include <array>
#include <map>
#include <queue>
#include <set>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

/// Position ids: vertices at exactly the same point share one id.
template <class Access>
struct Positions {
  std::vector<std::size_t> id_of_vertex;  ///< by vertex index
  std::vector<bool> shared;               ///< by position id: carried by several vertices
  std::size_t count = 0;
};

template <class Access>
Positions<Access> position_ids(const Access& mesh) {
  using vertex_descriptor = typename Access::vertex_descriptor;
  std::vector<vertex_descriptor> sorted(vertices(mesh.pm).begin(), vertices(mesh.pm).end());
  auto less = mesh.gt.less_xyz_3_object();
  std::sort(sorted.begin(), sorted.end(), [&](vertex_descriptor a, vertex_descriptor b) {
    return less(mesh.point(a), mesh.point(b));
  });
  Positions<Access> positions;
  positions.id_of_vertex.assign(num_vertices(mesh.pm), 0);
  auto equal = mesh.gt.equal_3_object();
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const bool same = i > 0 && equal(mesh.point(sorted[i - 1]), mesh.point(sorted[i]));
    if (!same) {
      positions.shared.push_back(false);
      ++positions.count;
    } else {
      positions.shared.back() = true;
    }
    positions.id_of_vertex[mesh.index(sorted[i])] = positions.count - 1;
  }
  return positions;
}

/// A face side seen from one position: the face and the positions before and after it.
struct Corner {
  std::size_t face_index;
  std::size_t previous_position, next_position;
};

struct Coincidence_result {
  std::vector<Non_manifold_edge> non_manifold_edges;
  std::vector<Vertex_location> non_manifold_vertices;
  std::vector<std::pair<std::size_t, std::size_t>> duplicated_face_indices;
  /// Pairs of faces glued along a coincident edge: (face, face, same direction).
  std::vector<std::tuple<std::size_t, std::size_t, bool>> geometric_gluings;
};

template <class Access>
class Coincidence_finder {
 public:
  using vertex_descriptor = typename Access::vertex_descriptor;
  using halfedge_descriptor = typename Access::halfedge_descriptor;
  using face_descriptor = typename Access::face_descriptor;

  Coincidence_finder(const Access& mesh, const Positions<Access>& positions)
      : mesh_(mesh), positions_(positions) {}

  Coincidence_result run() {
    collect_candidates();
    for (auto& entry : corners_of_position_) examine_position(entry.first, entry.second);
    find_duplicated_faces();
    return std::move(result_);
  }

 private:
  std::size_t position(vertex_descriptor v) const {
    return positions_.id_of_vertex[mesh_.index(v)];
  }

  // Candidate positions: shared ones and those of vertices with pinched umbrellas. One pass
  // over the halfedges gathers their corners, whatever umbrella they belong to.
  void collect_candidates() {
    std::vector<bool> candidate(positions_.count, false);
    bool any = false;
    for (std::size_t p = 0; p < positions_.count; ++p)
      if (positions_.shared[p]) candidate[p] = any = true;
    std::vector<halfedge_descriptor> umbrellas;
    CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh_.pm, std::back_inserter(umbrellas));
    for (halfedge_descriptor h : umbrellas) candidate[position(target(h, mesh_.pm))] = any = true;
    if (!any) return;
    for (halfedge_descriptor h : halfedges(mesh_.pm)) {
      if (is_border(h, mesh_.pm)) continue;
      const std::size_t p = position(target(h, mesh_.pm));
      if (!candidate[p]) continue;
      const face_descriptor f = face(h, mesh_.pm);
      corners_of_position_[p].push_back({mesh_.index(f), position(source(h, mesh_.pm)),
                                         position(target(next(h, mesh_.pm), mesh_.pm))});
      if (!face_seen_.count(mesh_.index(f))) face_seen_[mesh_.index(f)] = f;
      representative_[p] = target(h, mesh_.pm);
    }
  }

  void examine_position(std::size_t p, const std::vector<Corner>& corners) {
    // Face sides along each segment (p, q), with the direction the face runs it.
    std::map<std::size_t, std::vector<std::pair<std::size_t, bool>>> sides;  // q -> (corner, p->q)
    for (std::size_t c = 0; c < corners.size(); ++c) {
      sides[corners[c].next_position].push_back({c, true});
      sides[corners[c].previous_position].push_back({c, false});
    }
    CGAL::Union_find<std::size_t> fans;
    std::vector<typename CGAL::Union_find<std::size_t>::handle> handles;
    for (std::size_t c = 0; c < corners.size(); ++c) handles.push_back(fans.make_set(c));
    for (const auto& entry : sides) {
      const auto& along = entry.second;
      if (along.size() > 2) {
        record_non_manifold_edge(p, entry.first, along.size(), corners[along.front().first]);
      } else if (along.size() == 2) {
        fans.unify_sets(handles[along[0].first], handles[along[1].first]);
        record_gluing(corners[along[0].first].face_index, corners[along[1].first].face_index,
                      along[0].second == along[1].second);
      }
    }
    if (fans.number_of_sets() > 1) {
      const vertex_descriptor v = representative_[p];
      result_.non_manifold_vertices.push_back({mesh_.index(v), mesh_.coordinates(v), false});
    }
  }

  void record_non_manifold_edge(std::size_t p, std::size_t q, std::size_t face_sides,
                                const Corner& corner) {
    if (!edges_seen_.insert({std::min(p, q), std::max(p, q)}).second) return;
    const face_descriptor f = face_seen_.at(corner.face_index);
    Non_manifold_edge edge;
    for (halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh_.pm), mesh_.pm)) {
      if (position(source(h, mesh_.pm)) == p && position(target(h, mesh_.pm)) == q) {
        edge.source = mesh_.index(source(h, mesh_.pm));
        edge.target = mesh_.index(target(h, mesh_.pm));
        edge.source_point = mesh_.coordinates(source(h, mesh_.pm));
        edge.target_point = mesh_.coordinates(target(h, mesh_.pm));
      } else if (position(source(h, mesh_.pm)) == q && position(target(h, mesh_.pm)) == p) {
        edge.source = mesh_.index(target(h, mesh_.pm));
        edge.target = mesh_.index(source(h, mesh_.pm));
        edge.source_point = mesh_.coordinates(target(h, mesh_.pm));
        edge.target_point = mesh_.coordinates(source(h, mesh_.pm));
      }
    }
    edge.face_sides = face_sides;
    result_.non_manifold_edges.push_back(edge);
  }

  // Faces sharing a mesh edge are consistently oriented by construction; only faces glued
  // across coincident but distinct edges can disagree.
  void record_gluing(std::size_t f, std::size_t g, bool same_direction) {
    if (f == g) return;
    if (!gluings_seen_.insert({std::min(f, g), std::max(f, g)}).second) return;
    result_.geometric_gluings.emplace_back(f, g, same_direction);
  }

  void find_duplicated_faces() {
    std::map<std::array<std::size_t, 3>, std::size_t> faces_by_positions;
    for (const auto& entry : face_seen_) {
      const face_descriptor f = entry.second;
      if (!mesh_.is_triangle_face(f)) continue;
      std::array<std::size_t, 3> key;
      int k = 0;
      for (vertex_descriptor v : vertices_around_face(halfedge(f, mesh_.pm), mesh_.pm))
        key[k++] = position(v);
      std::sort(key.begin(), key.end());
      auto inserted = faces_by_positions.insert({key, entry.first});
      if (!inserted.second)
        result_.duplicated_face_indices.emplace_back(inserted.first->second, entry.first);
    }
  }

  const Access& mesh_;
  const Positions<Access>& positions_;
  std::map<std::size_t, std::vector<Corner>> corners_of_position_;
  std::map<std::size_t, vertex_descriptor> representative_;
  std::unordered_map<std::size_t, face_descriptor> face_seen_;
  std::set<std::pair<std::size_t, std::size_t>> edges_seen_, gluings_seen_;
  Coincidence_result result_;
};

/// Two triangles on the same three vertices (necessarily glued to each other, with opposite
/// orientations, in a halfedge mesh): a closed two-face component.
template <class Access>
void find_faces_on_same_vertices(const Access& mesh,
                                 std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  for (auto f : faces(mesh.pm)) {
    if (!mesh.is_triangle_face(f)) continue;
    const auto h = halfedge(f, mesh.pm);
    const auto g = face(opposite(h, mesh.pm), mesh.pm);
    if (g == boost::graph_traits<typename Access::Mesh>::null_face() ||
        mesh.index(g) <= mesh.index(f) || !mesh.is_triangle_face(g))
      continue;
    if (face(opposite(next(h, mesh.pm), mesh.pm), mesh.pm) == g &&
        face(opposite(prev(h, mesh.pm), mesh.pm), mesh.pm) == g)
      pairs.emplace_back(mesh.index(f), mesh.index(g));
  }
}

/// Faces to reverse so that all gluings agree: a breadth-first walk with parity over mesh
/// edges and coincident-edge gluings; per glued component the smaller side is reported.
/// Returns false when some component cannot be oriented.
template <class Access>
bool inconsistently_oriented_faces(
    const Access& mesh, const std::vector<std::tuple<std::size_t, std::size_t, bool>>& gluings,
    std::vector<std::size_t>& flipped) {
  bool any_disagreement = false;
  for (const auto& g : gluings) any_disagreement |= std::get<2>(g);
  if (!any_disagreement) return true;
  std::vector<typename Access::face_descriptor> face_of(num_faces(mesh.pm));
  for (auto f : faces(mesh.pm)) face_of[mesh.index(f)] = f;
  std::unordered_map<std::size_t, std::vector<std::pair<std::size_t, bool>>> extra;
  for (const auto& g : gluings) {
    extra[std::get<0>(g)].push_back({std::get<1>(g), std::get<2>(g)});
    extra[std::get<1>(g)].push_back({std::get<0>(g), std::get<2>(g)});
  }
  std::vector<int> parity(face_of.size(), -1);
  bool orientable = true;
  for (std::size_t seed = 0; seed < face_of.size(); ++seed) {
    if (parity[seed] >= 0 || !extra.count(seed)) continue;
    std::vector<std::size_t> component{seed};
    parity[seed] = 0;
    std::queue<std::size_t> queue;
    queue.push(seed);
    auto visit = [&](std::size_t from, std::size_t to, bool flip) {
      const int wanted = parity[from] ^ (flip ? 1 : 0);
      if (parity[to] < 0) {
        parity[to] = wanted;
        component.push_back(to);
        queue.push(to);
      } else if (parity[to] != wanted) {
        orientable = false;
      }
    };
    while (!queue.empty()) {
      const std::size_t f = queue.front();
      queue.pop();
      for (auto h : halfedges_around_face(halfedge(face_of[f], mesh.pm), mesh.pm)) {
        const auto g = face(opposite(h, mesh.pm), mesh.pm);
        if (g != boost::graph_traits<typename Access::Mesh>::null_face())
          visit(f, mesh.index(g), false);
      }
      auto it = extra.find(f);
      if (it != extra.end())
        for (const auto& e : it->second) visit(f, e.first, e.second);
    }
    std::vector<std::size_t> side[2];
    for (std::size_t f : component) side[parity[f]].push_back(f);
    const auto& smaller = side[0].size() <= side[1].size() ? side[0] : side[1];
    flipped.insert(flipped.end(), smaller.begin(), smaller.end());
  }
  std::sort(flipped.begin(), flipped.end());
  return orientable;
}

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_COINCIDENT_ELEMENTS_H
