// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CLEAN_HOLE_CONTOUR_OFFENDING_FACES_H
#define CGAL_MESH_REPAIR_INTERNAL_CLEAN_HOLE_CONTOUR_OFFENDING_FACES_H

// The faces along a hole's contour that a patch cannot be joined to (Pernot, Moraru and Veron,
// section 4, as a choice of faces rather than edits): badly oriented triangles with two border
// edges (4.1, removed recursively), degenerate triangles (4.2, here exactly: collinear corners),
// and the faces a scanned border folds onto its neighbours (a sharp fold, or two faces crossing).
// automatic_repair removes them, with what the removal pinches, and fills the hole again
// (step_grow_failed_holes); a patch that would have to meet them is rejected on every method.

#include <CGAL/Mesh_repair/internal/bounded_pairs.h>

#include <boost/graph/graph_traits.hpp>

#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Two faces across an edge are folded when the dihedral angle between them is below this
/// (a flat surface has 180 degrees); the cosine of 30 degrees.
constexpr double folded_dihedral_cosine = 0.8660254037844386;

/// The faces of `range` (a hole's surroundings; `ring_of` gives the vertex ring of each, 1 for
/// the faces around the border) that are degenerate, or of two faces that cross or are folded
/// onto each other the one nearer the border (both when equally near: the fold's face, not the
/// surface it lies on), then, repeated while some are found, the faces left with two open edges
/// once those are gone (ears). The yes/no questions are the traits' exact predicates. In the
/// order of `range`; empty when the contour is clean.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> offending_contour_faces(
    const PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& range,
    const std::vector<int>& ring_of) {
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  std::unordered_map<face_descriptor, int> ring;
  std::unordered_map<face_descriptor, std::size_t> position;  // in `range`: each edge once
  for (std::size_t i = 0; i < range.size(); ++i) {
    position[range[i]] = i;
    if (i < ring_of.size()) ring[range[i]] = ring_of[i];
  }
  std::unordered_set<face_descriptor> offending, degenerate;
  auto offends = [&](face_descriptor f, face_descriptor g) {
    if (ring[f] <= ring[g]) offending.insert(f);
    if (ring[g] <= ring[f]) offending.insert(g);
  };
  const auto found =
      Bounded_face_intersections<PolygonMesh, VertexPointMap, GeomTraits>(pm, vpm, traits)
          .find(range, nullptr, default_pair_limit(range.size()));
  for (const auto& pair : found.pairs) {
    offends(pair.first, pair.second);
    if (pair.first == pair.second) degenerate.insert(pair.first);
  }
  const auto dihedral = traits.compare_dihedral_angle_3_object();
  for (face_descriptor f : range) {
    if (degenerate.count(f)) continue;  // the angle of a degenerate face is not defined
    for (auto h : halfedges_around_face(halfedge(f, pm), pm)) {
      const face_descriptor g = face(opposite(h, pm), pm);
      const auto other = position.find(g);
      if (other == position.end() || other->second < position[f] || degenerate.count(g)) continue;
      const auto p = get(vpm, source(h, pm)), q = get(vpm, target(h, pm));
      const auto r = get(vpm, target(next(h, pm), pm));
      const auto s = get(vpm, target(next(opposite(h, pm), pm), pm));
      if (dihedral(p, q, r, s, typename GeomTraits::FT(folded_dihedral_cosine)) == CGAL::SMALLER)
        offends(f, g);
    }
  }
  // Ears of the border as it is once the faces found are gone (and those of the border itself).
  auto open_edges = [&](face_descriptor f) {
    int open = 0;
    for (auto h : halfedges_around_face(halfedge(f, pm), pm)) {
      const face_descriptor g = face(opposite(h, pm), pm);
      if (g == GT::null_face() || offending.count(g)) ++open;
    }
    return open;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (face_descriptor f : range)
      if (!offending.count(f) && open_edges(f) >= 2) {
        offending.insert(f);
        changed = true;
      }
  }
  std::vector<face_descriptor> faces;
  for (face_descriptor f : range)
    if (offending.count(f)) faces.push_back(f);
  return faces;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CLEAN_HOLE_CONTOUR_OFFENDING_FACES_H
