// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_TRIANGLES_TO_QUADS_H
#define CGAL_MESH_REPAIR_TRIANGLES_TO_QUADS_H

/// \file triangles_to_quads.h
/// Topological operators of Chen, Hsu, Lin 2.1: the conversion of a triangle mesh into a quad
/// mesh by merging adjacent triangle pairs (best pairs first), the quad clean-up operators (node
/// elimination and edge swap) applied where they raise quality, and quality edge
/// flips that clean a primary triangulation. See doc/mga_smooth.md.

#include <CGAL/Mesh_repair/internal/c1_surface/vec3.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `triangles_to_quads` did.
struct Quad_conversion_result {
  std::size_t merged_pairs = 0;         ///< triangle pairs merged into quads
  std::size_t remaining_triangles = 0;  ///< triangles left without a partner
  std::size_t quads = 0;                ///< quads in the final mesh
  std::size_t eliminated_nodes = 0;     ///< interior nodes of valence 2 removed
  std::size_t swapped_edges = 0;        ///< quad-quad edges swapped to a better hexagon split
};

/// What `flip_edges_for_quality` did.
struct Edge_flip_result {
  std::size_t flips = 0;
  std::size_t rejected_folds = 0;  ///< flips refused by the exact orientation test
};

namespace internal {

template <class PolygonMesh, class VertexPointMap>
class Topology_cleaner {
 public:
  using GT =
      typename Kernel_traits<typename boost::property_traits<VertexPointMap>::value_type>::Kernel;
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

  Topology_cleaner(PolygonMesh& pm, VertexPointMap vpm, double feature_angle_deg)
      : pm_(pm), vpm_(vpm), cos_feature_(std::cos(CGAL_PI - feature_angle_deg * CGAL_PI / 180.0)) {}

  Vec3 point(vertex_descriptor v) const {
    const Point& p = get(vpm_, v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }

  std::vector<vertex_descriptor> ring(halfedge_descriptor h) const {
    std::vector<vertex_descriptor> r;
    for (vertex_descriptor v : vertices_around_face(h, pm_)) r.push_back(v);
    return r;
  }

  Vec3 face_normal(halfedge_descriptor h) const {
    Vec3 n;
    const auto r = ring(h);
    for (std::size_t i = 0; i < r.size(); ++i)
      n += cross(point(r[i]), point(r[(i + 1) % r.size()]));
    return n;
  }

  double quality(const std::vector<vertex_descriptor>& r) const {
    if (r.size() == 3) return alpha(point(r[0]), point(r[1]), point(r[2]));
    if (r.size() == 4) return quad_beta(point(r[0]), point(r[1]), point(r[2]), point(r[3]));
    return 0;
  }

  bool is_feature(halfedge_descriptor h) const {
    if (is_border_edge(h, pm_)) return true;
    const Vec3 a = normalized(face_normal(h)), b = normalized(face_normal(opposite(h, pm_)));
    return dot(a, b) < cos_feature_;
  }

  // Exact test: every corner triangle of polygon `r` is oriented like `normal`.
  bool oriented_like(const std::vector<vertex_descriptor>& r, const Vec3& normal) const {
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point &a = get(vpm_, r[i]), &b = get(vpm_, r[(i + 1) % n]),
                  &c = get(vpm_, r[(i + n - 1) % n]);
      const Vec3 pa = point(r[i]);
      const Point tip(pa[0] + normal[0], pa[1] + normal[1], pa[2] + normal[2]);
      if (GT().orientation_3_object()(a, b, c, tip) != CGAL::POSITIVE) return false;
      if (n == 3) break;
    }
    return true;
  }

  // The quad formed by the two triangles of `h`, starting at source(h): a, d, b, c.
  std::vector<vertex_descriptor> merged_ring(halfedge_descriptor h) const {
    return {source(h, pm_), target(next(opposite(h, pm_), pm_), pm_), target(h, pm_),
            target(next(h, pm_), pm_)};
  }

  bool is_triangle(halfedge_descriptor h) const {
    return !is_border(h, pm_) && degree(face(h, pm_), pm_) == 3;
  }

  std::size_t merge_pairs(double min_beta) {
    std::vector<std::tuple<double, std::size_t, halfedge_descriptor>> candidates;
    std::size_t order = 0;
    for (auto e : edges(pm_)) {
      const halfedge_descriptor h = halfedge(e, pm_);
      ++order;
      if (!is_triangle(h) || !is_triangle(opposite(h, pm_)) || is_feature(h)) continue;
      const auto quad = merged_ring(h);
      if (quad[1] == quad[3]) continue;
      const double beta = quality(quad);
      if (beta > min_beta && oriented_like(quad, face_normal(h) + face_normal(opposite(h, pm_))))
        candidates.emplace_back(beta, order, h);
    }
    std::sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
      return std::get<0>(x) > std::get<0>(y) ||
             (std::get<0>(x) == std::get<0>(y) && std::get<1>(x) < std::get<1>(y));
    });
    std::size_t merged = 0;
    for (const auto& candidate : candidates) {
      const halfedge_descriptor h = std::get<2>(candidate);
      if (!is_triangle(h) || !is_triangle(opposite(h, pm_))) continue;
      CGAL::Euler::join_face(h, pm_);
      ++merged;
    }
    return merged;
  }

  // Node elimination: an interior node shared by exactly two quads is removed, the two quads
  // becoming one (Canann et al.), when the result is a valid, better quad.
  std::size_t eliminate_valence_two_nodes() {
    std::size_t removed = 0;
    std::vector<vertex_descriptor> candidates;
    for (vertex_descriptor v : vertices(pm_))
      if (!is_border(v, pm_) && degree(v, pm_) == 2) candidates.push_back(v);
    for (vertex_descriptor v : candidates) {
      if (degree(v, pm_) != 2) continue;  // an earlier elimination changed its star
      const halfedge_descriptor h = halfedge(v, pm_);
      const halfedge_descriptor g = opposite(next(h, pm_), pm_);
      if (degree(face(h, pm_), pm_) != 4 || degree(face(g, pm_), pm_) != 4) continue;
      const Vec3 normal = face_normal(h) + face_normal(g);
      std::vector<vertex_descriptor> quad = {
          target(next(h, pm_), pm_), target(next(next(h, pm_), pm_), pm_),
          target(next(next(next(h, pm_), pm_), pm_), pm_), target(next(next(g, pm_), pm_), pm_)};
      const bool distinct = std::set<vertex_descriptor>(quad.begin(), quad.end()).size() == 4;
      if (!distinct || !oriented_like(quad, normal)) continue;
      if (quality(quad) <= std::min(quality(ring(h)), quality(ring(g)))) continue;
      CGAL::Euler::remove_center_vertex(h, pm_);
      ++removed;
    }
    return removed;
  }

  // Edge swap (Canann et al., Kinney): two quads sharing an edge form a hexagon, which has three
  // splits into two quads; the one with the best worst beta is kept.
  std::size_t swap_quad_edges() {
    std::size_t swapped = 0;
    std::vector<halfedge_descriptor> candidates;
    for (auto e : edges(pm_)) candidates.push_back(halfedge(e, pm_));
    for (halfedge_descriptor h : candidates) {
      if (is_border_edge(h, pm_) || degree(face(h, pm_), pm_) != 4 ||
          degree(face(opposite(h, pm_), pm_), pm_) != 4 || is_feature(h))
        continue;
      if (degree(source(h, pm_), pm_) < 3 || degree(target(h, pm_), pm_) < 3) continue;
      // Hexagon from target(h): h0 = next(h) ... around both faces.
      std::vector<halfedge_descriptor> hexagon;
      for (halfedge_descriptor k = next(h, pm_); k != h; k = next(k, pm_)) hexagon.push_back(k);
      const halfedge_descriptor o = opposite(h, pm_);
      for (halfedge_descriptor k = next(o, pm_); k != o; k = next(k, pm_)) hexagon.push_back(k);
      std::vector<vertex_descriptor> corners;
      for (halfedge_descriptor k : hexagon) corners.push_back(source(k, pm_));
      if (std::set<vertex_descriptor>(corners.begin(), corners.end()).size() != 6) continue;
      const Vec3 normal = face_normal(h) + face_normal(o);
      // Split s joins corners s and s+3; the current split is s = 0 (h joins corners 0 and 3).
      auto split_quads = [&](int s) {
        std::vector<vertex_descriptor> q1, q2;
        for (int i = 0; i < 4; ++i) q1.push_back(corners[(s + i) % 6]);
        for (int i = 0; i < 4; ++i) q2.push_back(corners[(s + 3 + i) % 6]);
        return std::make_pair(q1, q2);
      };
      auto score = [&](int s) {
        const auto q = split_quads(s);
        if (!oriented_like(q.first, normal) || !oriented_like(q.second, normal)) return -1.0;
        return std::min(quality(q.first), quality(q.second));
      };
      const double current = score(0);
      int best = 0;
      double best_score = current;
      for (int s = 1; s < 3; ++s) {
        const auto q = split_quads(s);
        if (halfedge(q.first[0], q.second[0], pm_).second) continue;  // diagonal already an edge
        const double value = score(s);
        if (value > best_score + 1e-9) best = s, best_score = value;
      }
      if (best == 0) continue;
      const halfedge_descriptor joined = CGAL::Euler::join_face(h, pm_);
      halfedge_descriptor from = joined, to = joined;
      for (halfedge_descriptor k : halfedges_around_face(joined, pm_)) {
        if (target(k, pm_) == corners[best]) from = k;
        if (target(k, pm_) == corners[best + 3]) to = k;
      }
      CGAL::Euler::split_face(from, to, pm_);
      ++swapped;
    }
    return swapped;
  }

  std::pair<std::size_t, std::size_t> flip_for_quality(double cos_flat) {
    std::size_t flips = 0, rejected = 0;
    std::vector<halfedge_descriptor> candidates;
    for (auto e : edges(pm_)) candidates.push_back(halfedge(e, pm_));
    for (halfedge_descriptor h : candidates) {
      if (!is_triangle(h) || !is_triangle(opposite(h, pm_))) continue;
      const Vec3 n1 = normalized(face_normal(h)), n2 = normalized(face_normal(opposite(h, pm_)));
      if (dot(n1, n2) < cos_flat) continue;  // flipping a curved pair would change the shape
      const auto quad = merged_ring(h);      // a, d, b, c
      if (quad[1] == quad[3] || halfedge(quad[1], quad[3], pm_).second) continue;
      const double before = std::min(quality(ring(h)), quality(ring(opposite(h, pm_))));
      const std::vector<vertex_descriptor> t1 = {quad[0], quad[1], quad[3]},
                                           t2 = {quad[1], quad[2], quad[3]};
      const double after = std::min(quality(t1), quality(t2));
      if (after <= before + 1e-6) continue;
      if (!oriented_like(t1, n1 + n2) || !oriented_like(t2, n1 + n2)) {
        ++rejected;
        continue;
      }
      CGAL::Euler::flip_edge(h, pm_);
      ++flips;
    }
    return {flips, rejected};
  }

 private:
  PolygonMesh& pm_;
  VertexPointMap vpm_;
  double cos_feature_;
};

}  // namespace internal

/// Converts a triangle mesh into a quad-dominant mesh (Chen et al. 2.1): adjacent triangle pairs
/// are merged greedily, the pair whose quad has the best beta (eq. 7) first; edges whose dihedral
/// angle is below `feature_angle_deg`, and pairs whose quad would be non-convex or fold (exact
/// orientation test), are never merged. Then the clean-up operators run where they raise quality:
/// node elimination (interior nodes of two quads) and edge swap (best split of the hexagon of two
/// quads). Triangles without a partner
/// stay. The mesh stays valid.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph`
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{feature_angle_deg} \cgalParamDescription{edges with a dihedral angle below
///     it are not merged} \cgalParamType{double} \cgalParamDefault{120} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Quad_conversion_result triangles_to_quads(
    PolygonMesh& pm, const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, pm));
  const double feature_angle_deg =
      choose_parameter(get_parameter(np, internal_np::feature_angle_deg_t()), 120.0);
  internal::Topology_cleaner<PolygonMesh, decltype(vpm)> cleaner(pm, vpm, feature_angle_deg);
  Quad_conversion_result result;
  result.merged_pairs = cleaner.merge_pairs(0.05);
  result.eliminated_nodes = cleaner.eliminate_valence_two_nodes();
  result.swapped_edges = cleaner.swap_quad_edges();
  for (auto f : faces(pm)) {
    const auto d = degree(f, pm);
    result.remaining_triangles += d == 3;
    result.quads += d == 4;
  }
  return result;
}

/// Flips edges between two nearly coplanar triangles (normals within `feature_angle_deg`'s
/// complement, and at most 10 degrees apart) when the flip raises the smaller alpha of the pair
/// and folds nothing (exact test): the clean-up of a primary triangulation (Chen et al. 2.1).
/// Same named parameters as `triangles_to_quads`.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Edge_flip_result flip_edges_for_quality(PolygonMesh& pm,
                                        const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, pm));
  const double feature_angle_deg =
      choose_parameter(get_parameter(np, internal_np::feature_angle_deg_t()), 120.0);
  internal::Topology_cleaner<PolygonMesh, decltype(vpm)> cleaner(pm, vpm, feature_angle_deg);
  Edge_flip_result result;
  std::tie(result.flips, result.rejected_folds) = cleaner.flip_for_quality(std::cos(CGAL_PI / 18));
  return result;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_TRIANGLES_TO_QUADS_H
