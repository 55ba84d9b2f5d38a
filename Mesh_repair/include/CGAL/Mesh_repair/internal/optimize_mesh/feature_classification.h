// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_FEATURE_CLASSIFICATION_H
#define CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_FEATURE_CLASSIFICATION_H

// Thesis 7.2.1-7.2.2: edges are feature or non-feature (border, or dihedral angle below the
// tolerance); nodes are vertex, fixed / removable edge feature, fixed interior or interior. The
// fixed nodes form a maximal independent set of the node graph (and, along feature lines, of the
// feature-line graph), so removing only the other nodes keeps the grading of the mesh.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace optimize {

enum class Node_type : unsigned char {
  unclassified,
  interior,                // removable, on no feature edge
  fixed_interior,          // kept, on no feature edge (member of the independent set)
  removable_edge_feature,  // on exactly two nearly aligned feature edges, removable
  fixed_edge_feature,      // on a feature line, kept
  vertex                   // corner: one or more than two feature edges
};

inline bool is_removable(Node_type t) {
  return t == Node_type::interior || t == Node_type::removable_edge_feature;
}
inline bool is_fixed(Node_type t) {
  return t == Node_type::fixed_interior || t == Node_type::fixed_edge_feature ||
         t == Node_type::vertex;
}

template <class PolygonMesh, class VertexPointMap, class GeomTraits>
class Feature_classification {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using FT = typename GeomTraits::FT;

 public:
  /// `feature_angle_deg`: an edge is a feature when the interior (dihedral) angle between its two
  /// faces is below it (180 = flat); a node between two feature edges is fixed when the angle
  /// the two edges make is below it (180 = straight line).
  Feature_classification(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& gt,
                         double feature_angle_deg)
      : pm_(pm),
        vpm_(vpm),
        gt_(gt),
        cosine_(std::cos(feature_angle_deg * CGAL_PI / 180.0)),
        feature_(get(CGAL::dynamic_edge_property_t<char>(), pm)),
        type_(get(CGAL::dynamic_vertex_property_t<Node_type>(), pm)) {}

  /// Classifies every edge and node. `node_order` lists every node: those visited first join
  /// the independent set (are kept) when no neighbour is kept yet.
  template <class NodeOrder>
  void classify(const NodeOrder& node_order) {
    for (edge_descriptor e : edges(pm_)) put(feature_, e, is_feature_edge(halfedge(e, pm_)));
    std::vector<vertex_descriptor> feature_nodes;
    for (vertex_descriptor v : node_order) {
      put(type_, v, classify_by_feature_edges(v));
      if (get(type_, v) != Node_type::unclassified) feature_nodes.push_back(v);
    }
    independent_set_on_feature_lines(feature_nodes);
    independent_set_inside(node_order);
  }

  bool is_feature(edge_descriptor e) const { return get(feature_, e); }
  bool is_feature(halfedge_descriptor h) const { return get(feature_, edge(h, pm_)); }
  Node_type type(vertex_descriptor v) const { return get(type_, v); }

  /// The two feature neighbours of an edge-feature node (`false` if it has not exactly two).
  bool feature_neighbours(vertex_descriptor v, vertex_descriptor& a, vertex_descriptor& b) const {
    int count = 0;
    for (halfedge_descriptor h : halfedges_around_target(v, pm_)) {
      if (!is_feature(h)) continue;
      (count == 0 ? a : b) = source(h, pm_);
      ++count;
    }
    return count == 2;
  }

  std::size_t count(Node_type t) const {
    std::size_t n = 0;
    for (vertex_descriptor v : vertices(pm_)) n += (get(type_, v) == t);
    return n;
  }

  /// Exact: border edge, or dihedral angle strictly below the tolerance.
  bool is_feature_edge(halfedge_descriptor h) const {
    if (is_border_edge(h, pm_)) return true;
    const auto& a = get(vpm_, source(h, pm_));
    const auto& b = get(vpm_, target(h, pm_));
    const auto& c = get(vpm_, target(next(h, pm_), pm_));
    const auto& d = get(vpm_, target(next(opposite(h, pm_), pm_), pm_));
    return gt_.compare_dihedral_angle_3_object()(a, b, c, d, FT(cosine_)) == CGAL::SMALLER;
  }

 private:
  Node_type classify_by_feature_edges(vertex_descriptor v) const {
    int feature_edges = 0;
    for (halfedge_descriptor h : halfedges_around_target(v, pm_)) feature_edges += is_feature(h);
    if (feature_edges == 0) return Node_type::unclassified;
    if (feature_edges != 2) return Node_type::vertex;
    vertex_descriptor a, b;
    feature_neighbours(v, a, b);
    // The angle a-v-b against the tolerance (180 degrees = straight feature line). A threshold
    // on a measured angle, not a validity decision: computed in double (CGAL 5.5 has no
    // Compare_angle_3 predicate).
    const auto va = get(vpm_, a) - get(vpm_, v), vb = get(vpm_, b) - get(vpm_, v);
    const double lengths = std::sqrt(CGAL::to_double(va.squared_length() * vb.squared_length()));
    const bool sharp = CGAL::to_double(va * vb) > cosine_ * lengths;
    return sharp ? Node_type::fixed_edge_feature : Node_type::removable_edge_feature;
  }

  // Pseudo code of 7.2.2, "classify nodes on the feature edges": walking the feature nodes, one
  // next to a kept feature node becomes removable, otherwise it is kept.
  void independent_set_on_feature_lines(const std::vector<vertex_descriptor>& feature_nodes) {
    for (vertex_descriptor v : feature_nodes) {
      if (get(type_, v) != Node_type::removable_edge_feature) continue;
      bool next_to_fixed = false;
      for (halfedge_descriptor h : halfedges_around_target(v, pm_))
        if (is_feature(h) && is_fixed(get(type_, source(h, pm_)))) next_to_fixed = true;
      put(type_, v,
          next_to_fixed ? Node_type::removable_edge_feature : Node_type::fixed_edge_feature);
    }
  }

  // "Classify nodes which are not on the feature edges": one next to a kept node is removable.
  template <class NodeOrder>
  void independent_set_inside(const NodeOrder& order) {
    for (vertex_descriptor v : order) {
      if (get(type_, v) != Node_type::unclassified) continue;
      bool next_to_fixed = false;
      for (vertex_descriptor w : vertices_around_target(halfedge(v, pm_), pm_))
        if (is_fixed(get(type_, w))) {
          next_to_fixed = true;
          break;
        }
      put(type_, v, next_to_fixed ? Node_type::interior : Node_type::fixed_interior);
    }
  }

  const PolygonMesh& pm_;
  VertexPointMap vpm_;
  const GeomTraits& gt_;
  double cosine_;
  // char, not bool: OpenMesh stores a bool property in a std::vector<bool>, whose
  // elements its property map cannot return by reference (does not compile).
  typename boost::property_map<PolygonMesh, CGAL::dynamic_edge_property_t<char>>::type feature_;
  typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<Node_type>>::type type_;
};

}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif
