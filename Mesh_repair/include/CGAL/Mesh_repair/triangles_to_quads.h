// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_TRIANGLES_TO_QUADS_H
#define CGAL_MESH_REPAIR_TRIANGLES_TO_QUADS_H

/// \file triangles_to_quads.h
/// Topological operators of Chen, Hsu, Lin 2.1: the conversion of a triangle mesh into a quad
/// mesh by merging adjacent triangle pairs (best pairs first), the quad clean-up operators
/// (element collapse, node elimination and edge swap) applied where they raise quality, and quality
/// edge flips that clean a primary triangulation. See doc/mga_smooth.md.

#include <CGAL/Mesh_repair/internal/vec3.h>
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
  std::size_t collapsed_elements = 0;   ///< poor quads collapsed along a diagonal
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

  // Element collapse (Chen et al. 2.1, after Canann et al.): a poor quad (a, b, c, d) with a short
  // diagonal a-c is removed by merging a and c into one node m; the edges a-b and c-b
  // become one edge, as do a-d and c-d. Done only when every element around a and c keeps its
  // orientation and stays convex (exact orientation tests), no element or edge would be doubled
  // (a and c share no neighbour but b and d and no element but the quad), and the worst quality of
  // the elements around a and c rises. m is the diagonal's midpoint, a or c, whichever is best.
  std::size_t collapse_poor_quads(double max_beta) {
    std::vector<std::pair<double, face_descriptor>> candidates;
    for (face_descriptor f : faces(pm_)) {
      if (degree(f, pm_) != 4) continue;
      const double beta = quality(ring(halfedge(f, pm_)));
      if (beta < max_beta) candidates.emplace_back(beta, f);
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    // A collapse removes its quad and two triangles of its own split; the faces around keep
    // their descriptors (CGAL's join_face keeps the neighbour), so later candidates stay valid.
    std::size_t collapsed = 0;
    for (const auto& candidate : candidates) {
      const face_descriptor f = candidate.second;
      if (degree(f, pm_) != 4) continue;  // an earlier collapse changed it
      // The two diagonals: h_a = halfedge of f whose target is a, its diagonal partner c is the
      // target of next(next(h_a)).
      Plan best;
      halfedge_descriptor h = halfedge(f, pm_);
      for (int diagonal = 0; diagonal < 2; ++diagonal, h = next(h, pm_)) {
        const Plan plan = plan_collapse(h);
        if (plan.gain > best.gain) best = plan;
      }
      if (!(best.gain > 0)) continue;
      // Remove the quad: split it along a-c, then collapse the new edge (CGAL's collapse_edge
      // joins each of the two triangles with its neighbour across a-b and a-d and merges a
      // into c).
      const halfedge_descriptor ac = CGAL::Euler::split_face(best.to_a, best.to_c, pm_);
      const vertex_descriptor kept = CGAL::Euler::collapse_edge(edge(ac, pm_), pm_);
      put(vpm_, kept, best.position);
      ++collapsed;
    }
    return collapsed;
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

  struct Plan {
    double gain = 0;  // worst quality after minus before
    halfedge_descriptor to_a, to_c;
    Point position;
  };

  // Checks and scores the collapse of the diagonal from a = target(h) to c = target(next(next(h)))
  // of the quad of h.
  Plan plan_collapse(halfedge_descriptor h) const {
    Plan plan;
    const halfedge_descriptor to_b = next(h, pm_), to_c = next(to_b, pm_), to_d = next(to_c, pm_);
    const vertex_descriptor a = target(h, pm_), b = target(to_b, pm_), c = target(to_c, pm_),
                            d = target(to_d, pm_);
    // Only a short diagonal is collapsed (at most 0.4 of the other): collapsing a diagonal of a
    // long thin quad would move its ends far.
    if (!(norm(point(a) - point(c)) <= 0.4 * norm(point(b) - point(d)))) return plan;
    // Interior quad, b and d keep at least three edges, a and c on no feature or border edge.
    for (halfedge_descriptor k : {h, to_b, to_c, to_d})
      if (is_border(opposite(k, pm_), pm_)) return plan;
    if (is_border(a, pm_) || is_border(c, pm_) || is_border(b, pm_) || is_border(d, pm_))
      return plan;
    if (degree(b, pm_) < 4 || degree(d, pm_) < 4) return plan;
    for (vertex_descriptor v : {a, c})
      for (halfedge_descriptor k : halfedges_around_target(v, pm_))
        if (is_feature(k)) return plan;
    // The faces across a-b and b-c (and across c-d and d-a) must differ, or b (d) would end in a
    // doubled edge.
    if (face(opposite(to_b, pm_), pm_) == face(opposite(to_c, pm_), pm_) ||
        face(opposite(to_d, pm_), pm_) == face(opposite(h, pm_), pm_))
      return plan;
    // a and c: no edge, no common element but the quad, no common neighbour but b and d.
    const face_descriptor quad = face(h, pm_);
    std::vector<vertex_descriptor> neighbours_of_a;
    for (vertex_descriptor n : vertices_around_target(a, pm_)) neighbours_of_a.push_back(n);
    for (vertex_descriptor n : vertices_around_target(c, pm_)) {
      if (n == a) return plan;
      if (n != b && n != d &&
          std::find(neighbours_of_a.begin(), neighbours_of_a.end(), n) != neighbours_of_a.end())
        return plan;
    }
    std::vector<face_descriptor> around;  // the elements around a and c, but the quad
    for (vertex_descriptor v : {a, c})
      for (face_descriptor g : faces_around_target(halfedge(v, pm_), pm_))
        if (g != quad) {
          if (std::find(around.begin(), around.end(), g) != around.end()) return plan;
          around.push_back(g);
        }
    // Worst quality before (the quad included), and each element's reference normal.
    double before = quality(ring(h));
    std::vector<std::vector<vertex_descriptor>> rings;
    std::vector<Vec3> normals;
    for (face_descriptor g : around) {
      rings.push_back(ring(halfedge(g, pm_)));
      normals.push_back(face_normal(halfedge(g, pm_)));
      before = std::min(before, quality(rings.back()));
    }
    const Vec3 pa = point(a), pc = point(c);
    const Vec3 options[3] = {0.5 * (pa + pc), pa, pc};
    for (const Vec3& option : options) {
      const Point m(option[0], option[1], option[2]);
      double after = 1;
      bool valid = true;
      for (std::size_t i = 0; i < rings.size() && valid; ++i) {
        std::vector<Point> corners;
        for (vertex_descriptor v : rings[i]) corners.push_back(v == a || v == c ? m : get(vpm_, v));
        valid = oriented_like(corners, normals[i]);
        if (valid) after = std::min(after, quality_of(corners));
      }
      if (valid && after - before > plan.gain) {
        plan.gain = after - before;
        plan.to_a = h, plan.to_c = to_c;
        plan.position = m;
      }
    }
    return plan;
  }

  static double quality_of(const std::vector<Point>& c) {
    if (c.size() == 3) return alpha(c[0], c[1], c[2]);
    if (c.size() == 4) return quad_beta(c[0], c[1], c[2], c[3]);
    return 0;
  }

  // Exact test on explicit corner positions: every corner triangle is oriented like `normal`.
  static bool oriented_like(const std::vector<Point>& r, const Vec3& normal) {
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point &a = r[i], &b = r[(i + 1) % n], &c = r[(i + n - 1) % n];
      const Point tip(CGAL::to_double(a.x()) + normal[0], CGAL::to_double(a.y()) + normal[1],
                      CGAL::to_double(a.z()) + normal[2]);
      if (GT().orientation_3_object()(a, b, c, tip) != CGAL::POSITIVE) return false;
      if (n == 3) break;
    }
    return true;
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
/// element collapse (a quad of beta < 0.3 with a short diagonal, at most 0.4 of the other, loses
/// that diagonal: its two ends merge, when no element folds or turns non-convex (exact orientation
/// tests), no edge or element would be doubled, and the worst quality around rises), node
/// elimination (interior nodes of two quads) and edge swap (best split of the hexagon of two
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
  const double feature_angle_deg = choose_parameter(
      get_parameter(np, internal_np::feature_angle_deg_t()), default_smoothing_feature_angle_deg);
  internal::Topology_cleaner<PolygonMesh, decltype(vpm)> cleaner(pm, vpm, feature_angle_deg);
  Quad_conversion_result result;
  result.merged_pairs = cleaner.merge_pairs(0.05);
  result.collapsed_elements = cleaner.collapse_poor_quads(0.3);
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
  const double feature_angle_deg = choose_parameter(
      get_parameter(np, internal_np::feature_angle_deg_t()), default_smoothing_feature_angle_deg);
  internal::Topology_cleaner<PolygonMesh, decltype(vpm)> cleaner(pm, vpm, feature_angle_deg);
  Edge_flip_result result;
  std::tie(result.flips, result.rejected_folds) = cleaner.flip_for_quality(std::cos(CGAL_PI / 18));
  return result;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_TRIANGLES_TO_QUADS_H
