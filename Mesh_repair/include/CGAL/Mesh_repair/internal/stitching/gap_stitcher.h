// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_STITCHING_GAP_STITCHER_H
#define CGAL_MESH_REPAIR_INTERNAL_STITCHING_GAP_STITCHER_H

// The machinery of stitch_gaps() and repair_t_junctions() (thesis 4.2, 4.3, 4.3.1).
//
// The mesh stays a valid halfedge mesh throughout: nodes are never merged directly (that would
// create non-manifold vertices between two borders). Instead they are grouped in clusters, each
// cluster's members are moved to one merge point, T-junction nodes are inserted with Euler
// operations, and finally the border halfedges whose end clusters match in opposite directions
// are glued (glue_border_pairs.h: what CGAL's `stitch_borders(pm, pairs)` does, in linear time),
// which merges the vertices along them.
//
// Every pass is linear or O(n log n) in the number of border nodes: the node pairs come from a
// kd-tree (point_kd_tree.h), which also tells whether CGAL's search for exactly coincident
// borders can find anything (see run()); clusters are linked lists over node ids, matching pairs
// are bucketed by cluster, T-junctions found by box intersection.

#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/cubic_curves.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/stitching/glue_border_pairs.h>
#include <CGAL/Mesh_repair/internal/stitching/merge_point.h>
#include <CGAL/Mesh_repair/internal/stitching/point_kd_tree.h>
#include <CGAL/Mesh_repair/internal/vec3.h>
#include <CGAL/Mesh_repair/stitch_result.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

struct Stitch_settings {
  double merge_tolerance = -1;  ///< absolute; negative: derived from local edge lengths
  /// Derived tolerance of a border vertex, and the most it may move: this fraction of its
  /// shortest incident edge (border or not).
  double default_tolerance_fraction = 0.5;
  /// With a derived tolerance, no vertex moves farther than this fraction of the mesh's
  /// bounding-box diagonal either (0: no such bound). On a model of a few large faces half the
  /// shortest edge is a large share of the model: the crossed quads of a 16-face torch were
  /// folded onto each other, points moved by 31% of its diagonal. Moving within the tangent
  /// plane is no safer: that fold was within both planes.
  double max_derived_move_in_diagonals = 0;
  bool merge_nodes = true;  ///< node pairs within tolerance (4.2); false: exactly coincident only
  bool repair_t_junctions = true;  ///< node insertion into edges (thesis 4.3)
  bool use_cubic_curves = true;    ///< T-junction nodes on the boundary curve (4.3.1)
  int max_t_junction_passes = 8;
};

template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Visitor>
class Gap_stitcher {
  using Graph_traits = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;
  using Point = typename GeomTraits::Point_3;
  using Vector = typename GeomTraits::Vector_3;
  using Node_id_map =
      typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<std::size_t>>::type;
  // char, not bool: see t_junction_pass().
  using Frozen_map =
      typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<char>>::type;
  static constexpr std::size_t no_node = 0;  // node ids are stored +1 so 0 means "not a node"

 public:
  /// `frozen`: vertices that must neither move nor take a T-junction node on their edges (the
  /// automatic repair's stitching trial freezes those whose stitching made faces intersect).
  Gap_stitcher(PolygonMesh& pm, VertexPointMap vpm, const Stitch_settings& settings,
               Visitor& visitor, const std::vector<vertex_descriptor>& frozen = {})
      : pm_(pm),
        vpm_(vpm),
        settings_(settings),
        visitor_(visitor),
        node_of_(get(CGAL::dynamic_vertex_property_t<std::size_t>(), pm)),
        frozen_(get(CGAL::dynamic_vertex_property_t<char>(), pm)) {
    for (vertex_descriptor v : vertices(pm_)) put(frozen_, v, 0);
    for (vertex_descriptor v : frozen) put(frozen_, v, 1);
  }

  Stitch_result run() {
    result_.border_edges_before = count_border_edges();
    if (settings_.merge_tolerance < 0 && settings_.max_derived_move_in_diagonals > 0)
      max_derived_move_ = settings_.max_derived_move_in_diagonals * mesh_bbox_diagonal(pm_, vpm_);
    collect_border_nodes();
    if (!cancelled()) pair_nodes();
    // Exactly coincident borders are glued by CGAL's `stitch_borders`, as if first: it needs two
    // border nodes at one point (found by the pairing) or two edges joining the same border
    // nodes (found while collecting them). Without either, its O(n log n) search over all border
    // halfedges would glue nothing and is skipped; if it glues something, nodes and pairs are
    // collected again on the glued mesh.
    visitor_.start_step("stitch coincident borders");
    if (coincident_possible_)
      result_.coincident_edges_stitched = CGAL::Polygon_mesh_processing::stitch_borders(
          pm_, CGAL::parameters::vertex_point_map(vpm_));
    visitor_.end_step("stitch coincident borders");
    if (result_.coincident_edges_stitched > 0) {
      clear_nodes();
      collect_border_nodes();
      if (!cancelled()) pair_nodes();
    }
    if (!cancelled()) place_clusters(false);
    // Past the pair limit nothing is merged, and the T-junction search would meet as many
    // pairs: the stitcher stops there (result_.node_pairs_truncated says so).
    for (int pass = 0;
         settings_.repair_t_junctions && pass < settings_.max_t_junction_passes && !cancelled() &&
         !result_.node_pairs_truncated && !result_.t_junction_search_truncated;
         ++pass) {
      if (t_junction_pass() == 0) break;
      place_clusters(false);
    }
    if (!cancelled()) {
      place_clusters(true);
      stitch_clusters();
    }
    result_.border_edges_after = count_border_edges();
    result_.cancelled = cancelled();
    return result_;
  }

 private:
  // ---- nodes and clusters -------------------------------------------------------------------

  Vec3 position(vertex_descriptor v) const {
    const Point& p = get(vpm_, v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }

  std::size_t node(vertex_descriptor v) const { return get(node_of_, v); }

  /// `shortest_edge`: of the input vertex, for its move bound; infinite for a vertex created
  /// here (a T-junction node), which has no input position to keep.
  std::size_t add_node(vertex_descriptor v, const Vec3& normal, double tolerance,
                       double shortest_edge) {
    node_vertex_.push_back(v);
    node_original_.push_back(position(v));
    node_normal_.push_back(normal);
    node_tolerance_.push_back(tolerance);
    node_shortest_edge_.push_back(shortest_edge);
    parent_.push_back(node_vertex_.size() - 1);
    next_member_.push_back(no_member);
    last_member_.push_back(node_vertex_.size() - 1);
    cluster_size_.push_back(1);
    placed_.push_back(false);
    put(node_of_, v, node_vertex_.size());
    matching_pairs_valid_ = false;
    return node_vertex_.size() - 1;
  }

  std::size_t root(std::size_t id) {
    while (parent_[id] != id) id = parent_[id] = parent_[parent_[id]];
    return id;
  }

  /// Members of the cluster rooted at `r` into `out`, in the order they joined (a node alone is
  /// its own cluster).
  const std::vector<std::size_t>& members(std::size_t r, std::vector<std::size_t>& out) const {
    out.clear();
    for (std::size_t id = r; id != no_member; id = next_member_[id]) out.push_back(id);
    return out;
  }

  /// The members of `rb` join those of `ra` (a linked list per cluster: no allocation).
  void unite(std::size_t ra, std::size_t rb) {
    next_member_[last_member_[ra]] = rb;
    last_member_[ra] = last_member_[rb];
    cluster_size_[ra] += cluster_size_[rb];
    parent_[rb] = ra;
    placed_[ra] = false;
    matching_pairs_valid_ = false;
  }

  /// Roots of the clusters of two or more nodes.
  std::vector<std::size_t> cluster_roots() const {
    std::vector<std::size_t> roots;
    for (std::size_t id = 0; id < parent_.size(); ++id)
      if (parent_[id] == id && cluster_size_[id] > 1) roots.push_back(id);
    return roots;
  }

  bool share_face(vertex_descriptor x, vertex_descriptor y) const {
    if (x == y) return true;
    for (halfedge_descriptor h : halfedges_around_target(x, pm_)) {
      if (is_border(h, pm_)) continue;
      for (vertex_descriptor w : vertices_around_face(h, pm_))
        if (w == y) return true;
    }
    return false;
  }

  /// Whether `x` and `y` are the far corners of the two faces of one edge: a flap folded onto
  /// its neighbour (a folded scan border). Merged, the two faces would have the same corners, a
  /// duplicated face, which leaves a border when either copy is removed.
  bool opposite_across_an_edge(vertex_descriptor x, vertex_descriptor y) const {
    for (halfedge_descriptor h : halfedges_around_target(x, pm_)) {
      if (is_border(h, pm_)) continue;
      const halfedge_descriptor across = opposite(next(next(h, pm_), pm_), pm_);
      if (!is_border(across, pm_) && target(next(across, pm_), pm_) == y) return true;
    }
    return false;
  }

  double pair_tolerance(std::size_t a, std::size_t b) const {
    if (!settings_.merge_nodes) return 0.0;
    return std::min(node_tolerance_[a], node_tolerance_[b]);
  }

  /// Complete linkage: every pair of the joined cluster is within tolerance and of no common face.
  bool can_unite(std::size_t ra, std::size_t rb) {
    for (std::size_t x : members(ra, members_a_)) {
      for (std::size_t y : members(rb, members_b_)) {
        if (share_face(node_vertex_[x], node_vertex_[y])) {
          ++result_.rejected_same_face;
          return false;
        }
        if (opposite_across_an_edge(node_vertex_[x], node_vertex_[y])) {
          ++result_.rejected_folded_flap;
          return false;
        }
        const double d = norm(node_original_[x] - node_original_[y]);
        if (d > pair_tolerance(x, y)) {
          ++result_.rejected_too_far;
          return false;
        }
        if (along_one_border_side(x, y, d)) {
          ++result_.rejected_same_side;
          return false;
        }
      }
    }
    return true;
  }

  // ---- step 1: border nodes, normals (eq. 4.1) and local tolerances -----------------------

  Vec3 node_normal(vertex_descriptor v) {
    std::vector<std::pair<Vector, double>>& weighted = normal_scratch_;
    weighted.clear();
    for (halfedge_descriptor h : halfedges_around_target(v, pm_)) {
      if (is_border(h, pm_)) continue;
      const Point& p = get(vpm_, v);
      const Point& before = get(vpm_, source(h, pm_));
      const Point& after = get(vpm_, target(next(h, pm_), pm_));
      const Vector u = before - p, w = after - p;
      const Vector n = CGAL::cross_product(w, u);
      const double length = std::sqrt(CGAL::to_double(n.squared_length()));
      const double lu = std::sqrt(CGAL::to_double(u.squared_length()));
      const double lw = std::sqrt(CGAL::to_double(w.squared_length()));
      if (length == 0 || lu == 0 || lw == 0) continue;
      const double angle = std::atan2(length, CGAL::to_double(u * w));
      weighted.emplace_back(n / length, angle);
    }
    const Vector n = angle_weighted_normal<Vector>(weighted);
    return {CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())};
  }

  void clear_nodes() {
    node_of_ = get(CGAL::dynamic_vertex_property_t<std::size_t>(), pm_);
    for (auto* v : {&parent_, &next_member_, &last_member_, &cluster_size_}) v->clear();
    node_vertex_.clear();
    node_original_.clear();
    node_normal_.clear();
    node_tolerance_.clear();
    node_shortest_edge_.clear();
    placed_.clear();
    placed_on_planes_.clear();
    coincident_possible_ = false;
    matching_pairs_valid_ = false;
    result_.node_merges = result_.rejected_same_face = result_.rejected_too_far = 0;
    result_.rejected_same_side = result_.rejected_folded_flap = 0;
  }

  /// Whether `h` (border, from u to v) is a degenerate or a multiple edge, or v ends another
  /// border halfedge: configurations where CGAL's `stitch_borders` may glue without two border
  /// vertices at one point.
  bool unusual_border_halfedge(halfedge_descriptor h, std::vector<unsigned char>& ends_border) {
    const vertex_descriptor u = source(h, pm_), v = target(h, pm_);
    if (u == v || is_border(opposite(h, pm_), pm_)) return true;
    for (halfedge_descriptor g : halfedges_around_target(v, pm_))
      if (g != h && source(g, pm_) == u) return true;
    return ends_border[node(v) - 1]++ > 0;
  }

  void collect_border_nodes() {
    visitor_.start_step("border nodes");
    std::vector<unsigned char> ends_border;
    const bool derived = settings_.merge_tolerance < 0;
    for (halfedge_descriptor h : halfedges(pm_)) {
      if (!is_border(h, pm_)) continue;
      for (vertex_descriptor v : {source(h, pm_), target(h, pm_)}) {
        if (node(v) != no_node) continue;
        const double shortest = shortest_incident_edge(v);
        const double tolerance =
            derived ? settings_.default_tolerance_fraction * shortest : settings_.merge_tolerance;
        add_node(v, node_normal(v), get(frozen_, v) ? 0.0 : tolerance, shortest);
        ends_border.push_back(0);
      }
      if (!coincident_possible_ && unusual_border_halfedge(h, ends_border))
        coincident_possible_ = true;
    }
    result_.border_nodes = node_vertex_.size();
    result_.tolerance_derived = derived;
    locate_nodes_on_cycles();
    if (!node_tolerance_.empty()) {
      result_.merge_tolerance = *std::max_element(node_tolerance_.begin(), node_tolerance_.end());
      result_.min_local_tolerance =
          *std::min_element(node_tolerance_.begin(), node_tolerance_.end());
    } else {
      result_.merge_tolerance = result_.min_local_tolerance =
          std::max(0.0, settings_.merge_tolerance);
    }
    visitor_.end_step("border nodes");
  }

  /// Each node's border cycle and arc-length position along it (the node's first cycle where
  /// the border touches itself).
  void locate_nodes_on_cycles() {
    node_cycle_.assign(node_vertex_.size(), no_cycle);
    node_arc_.assign(node_vertex_.size(), 0.0);
    cycle_length_.clear();
    for (halfedge_descriptor start : border_cycles(pm_)) {
      double arc = 0;
      for (halfedge_descriptor h : cycle_halfedges(start, pm_)) {
        const std::size_t n = node(source(h, pm_));
        if (n != no_node && node_cycle_[n - 1] == no_cycle) {
          node_cycle_[n - 1] = cycle_length_.size();
          node_arc_[n - 1] = arc;
        }
        arc += norm(position(target(h, pm_)) - position(source(h, pm_)));
      }
      cycle_length_.push_back(arc);
    }
  }

  /// Whether nodes `i` and `j`, `d` apart, lie on one side of a gap: on one border cycle, with
  /// the shorter way along it less than twice as long as the straight line (the border runs from
  /// one to the other, so merging them would fold it). Across a gap, or at the tip of a slit
  /// (a V sharper than 60 degrees), the way along the border is much longer.
  bool along_one_border_side(std::size_t i, std::size_t j, double d) const {
    if (i >= node_cycle_.size() || j >= node_cycle_.size()) return false;  // T-junction nodes
    const std::size_t c = node_cycle_[i];
    if (c == no_cycle || c != node_cycle_[j] || d == 0) return false;
    const double along = std::abs(node_arc_[i] - node_arc_[j]);
    return std::min(along, cycle_length_[c] - along) < 2 * d;
  }

  // ---- step 2: node pairs within tolerance, greedily by distance (kd-tree) -----------------

  void pair_nodes() {
    visitor_.start_step("pair border nodes");
    const Point_kd_tree tree(node_original_);
    struct Candidate {
      double distance;
      std::size_t i, j;
      bool same_face;  // the two nodes share a face (computed here, in spatial order)
      bool folded;     // opposite_across_an_edge
    };
    // Nodes within tolerance of each other can be O(n^2) pairs (a self-overlapping star polygon
    // whose long edges give a large derived tolerance: 1.77 M pairs on 5000 nodes), and joining
    // clusters checks every pair of their members. Past the pair limit (internal/
    // bounded_pairs.h) the pairing is not done at all: the greedy order needs every candidate.
    Bounded_pairs<Candidate> found;
    Bounded_collector<Candidate> collector(found, default_pair_limit(node_original_.size()));
    Progress_reporter<Visitor> report(visitor_, node_original_.size());
    std::size_t done = 0;
    bool stopped = false;
    collector.run([&](auto&) {
      // Queries in tree order, so consecutive queries visit the same tree nodes and mesh regions.
      for (const Point_kd_tree::Item& item : tree.items()) {
        if (!report(done++)) {
          stopped = true;
          return;
        }
        const std::size_t i = item.id;
        const double radius = settings_.merge_nodes ? node_tolerance_[i] : 0.0;
        tree.for_each_within(item.point, radius, [&](std::size_t j, double) {
          if (j <= i) return;
          const double d = norm(node_original_[i] - node_original_[j]);
          if (d == 0) coincident_possible_ = true;  // two border nodes at one point
          if (d > pair_tolerance(i, j)) return;
          if (along_one_border_side(i, j, d))
            ++result_.rejected_same_side;
          else
            collector.add({d, i, j, share_face(node_vertex_[i], node_vertex_[j]),
                           opposite_across_an_edge(node_vertex_[i], node_vertex_[j])});
        });
      }
    });
    if (stopped) {
      visitor_.end_step("pair border nodes");  // balanced on cancellation too
      return;
    }
    if (found.truncated) {
      result_.node_pairs_truncated = true;
      result_.node_pairs_within_tolerance = found.pairs.size();
      visitor_.end_step("pair border nodes");
      return;
    }
    std::vector<Candidate>& candidates = found.pairs;
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
      return std::tie(x.distance, x.i, x.j) < std::tie(y.distance, y.i, y.j);
    });
    for (const Candidate& c : candidates) {
      const std::size_t ri = root(c.i), rj = root(c.j);
      if (ri == rj) continue;
      if (cluster_size_[ri] == 1 && cluster_size_[rj] == 1) {
        // can_unite() of two single nodes within tolerance: only the face tests are left.
        if (c.same_face) {
          ++result_.rejected_same_face;
          continue;
        }
        if (c.folded) {
          ++result_.rejected_folded_flap;
          continue;
        }
      } else if (!can_unite(ri, rj)) {
        continue;
      }
      unite(ri, rj);
      ++result_.node_merges;
    }
    visitor_.end_step("pair border nodes");
  }

  // ---- step 3: every cluster moves to its merge point (thesis 4.2, Figure 4.2) ----------------

  void place_clusters(bool final_placement) {
    placed_on_planes_.resize(node_vertex_.size());
    for (std::size_t r : cluster_roots()) {
      // A cluster unchanged since its last placement stays there (its nodes' original positions
      // and normals are fixed): only the final count is needed.
      if (!placed_[r]) {
        std::vector<Merge_node>& merge_nodes = merge_scratch_;
        merge_nodes.clear();
        double tolerance = std::numeric_limits<double>::infinity();
        for (std::size_t id = r; id != no_member; id = next_member_[id]) {
          merge_nodes.push_back({node_original_[id], node_normal_[id]});
          tolerance = std::min(tolerance, node_tolerance_[id]);
        }
        bool used_planes = false;
        Vec3 target = merge_point(merge_nodes, tolerance, &used_planes);
        if (used_planes && !within_move_limits(r, target)) {
          target = merge_point(merge_nodes, 0.0, nullptr);  // the centroid
          used_planes = false;
        }
        if (!within_move_limits(r, target)) {
          dissolve(r);
          ++result_.merges_undone_by_move_limit;
          continue;
        }
        for (std::size_t id = r; id != no_member; id = next_member_[id])
          put(vpm_, node_vertex_[id], Point(target[0], target[1], target[2]));
        placed_[r] = true;
        placed_on_planes_[r] = used_planes;
      }
      if (final_placement)
        ++(placed_on_planes_[r] ? result_.tangent_plane_merges : result_.midpoint_merges);
    }
  }

  // ---- step 4: T-junctions (thesis 4.3, Figures 4.4-4.6) --------------------------------------

  struct Edge_hit {
    double distance;
    std::size_t edge;  // index into the border halfedges of the pass
    double t;          // parameter of the projection along the edge
    Vec3 point;        // where the new node goes (chord projection or boundary curve)
  };

  /// Unit tangent of the border at `v` between `before` and `after`, or the chord direction
  /// when the border turns sharply there (a corner must not bend the curve).
  Vector nodal_tangent(const Vec3& before, const Vec3& at, const Vec3& after,
                       const Vector& chord) const {
    const Vec3 in = at - before, out = after - at;
    const double lin = std::sqrt(dot(in, in)), lout = std::sqrt(dot(out, out));
    if (lin == 0 || lout == 0 || dot(in, out) < std::cos(CGAL_PI / 6) * lin * lout) return chord;
    const Vector t(after[0] - before[0], after[1] - before[1], after[2] - before[2]);
    return t / std::sqrt(CGAL::to_double(t.squared_length()));
  }

  /// Where the node for `v` goes on the border halfedge `h` at chord parameter `t`: on the cubic
  /// boundary curve (eq. 4.2-4.7) through the ends' normals when enabled, else on the chord.
  Vec3 edge_point(halfedge_descriptor h, double t, const Vec3& v) const {
    const Vec3 a = position(source(h, pm_)), b = position(target(h, pm_));
    const Vec3 on_chord = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
                           a[2] + t * (b[2] - a[2])};
    const std::size_t na = node(source(h, pm_)), nb = node(target(h, pm_));
    if (!settings_.use_cubic_curves || na == no_node || nb == no_node) return on_chord;
    const Vec3& normal_a = node_normal_[na - 1];
    const Vec3& normal_b = node_normal_[nb - 1];
    if (dot(normal_a, normal_a) == 0 || dot(normal_b, normal_b) == 0) return on_chord;
    const double length = norm(a - b);
    const Vector chord((b[0] - a[0]) / length, (b[1] - a[1]) / length, (b[2] - a[2]) / length);
    const Vector ta = nodal_tangent(position(source(prev(h, pm_), pm_)), a, b, chord);
    const Vector tb = nodal_tangent(a, b, position(target(next(h, pm_), pm_)), chord);
    const auto curve = make_cubic_boundary_curve(
        Point(a[0], a[1], a[2]), Vector(normal_a[0], normal_a[1], normal_a[2]), ta,
        Point(b[0], b[1], b[2]), Vector(normal_b[0], normal_b[1], normal_b[2]), tb);
    const Point query(v[0], v[1], v[2]);
    const double s = closest_curve_parameter(curve, query, t);
    if (s <= 0 || s >= 1) return on_chord;
    const Point p = curve(s);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }

  /// The border halfedge nearest to each border node whose interior it projects into, within
  /// tolerance (box intersection, so no quadratic pass).
  std::vector<std::pair<std::size_t, Edge_hit>> find_t_junctions(
      const std::vector<halfedge_descriptor>& border, const std::vector<bool>& node_needed) {
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
    std::vector<Box> node_boxes, edge_boxes;
    for (std::size_t id = 0; id < node_vertex_.size(); ++id) {
      if (!node_needed[id]) continue;
      const Vec3 p = position(node_vertex_[id]);
      const double r = node_tolerance_[id];
      double lo[3] = {p[0] - r, p[1] - r, p[2] - r}, hi[3] = {p[0] + r, p[1] + r, p[2] + r};
      node_boxes.emplace_back(lo, hi, id);
    }
    for (std::size_t k = 0; k < border.size(); ++k) {
      const Vec3 a = position(source(border[k], pm_)), b = position(target(border[k], pm_));
      double lo[3], hi[3];
      for (int i = 0; i < 3; ++i) lo[i] = std::min(a[i], b[i]), hi[i] = std::max(a[i], b[i]);
      edge_boxes.emplace_back(lo, hi, k);
    }
    std::vector<Edge_hit> best(node_vertex_.size(),
                               Edge_hit{std::numeric_limits<double>::infinity(), 0, 0, {}});
    // Long border edges across a self-overlapping border overlap the boxes of most nodes: the
    // box pairs, not the hits, are quadratic there. Past the candidate budget the search stops
    // and the pass splits nothing (t_junction_search_truncated).
    Pair_budget budget(candidate_limit(node_boxes.size() + edge_boxes.size()));
    auto consider = [&](const Box& node_box, const Box& edge_box) {
      budget.spend();
      const std::size_t id = node_box.info();
      const halfedge_descriptor h = border[edge_box.info()];
      const vertex_descriptor v = node_vertex_[id];
      const vertex_descriptor a = source(h, pm_), b = target(h, pm_);
      if (v == a || v == b || get(frozen_, a) || get(frozen_, b)) return;
      const Vec3 pa = position(a), pb = position(b), pv = position(v);
      const Vec3 ab = pb - pa;
      const double length2 = dot(ab, ab);
      if (length2 == 0) return;
      const double t = dot(pv - pa, ab) / length2;
      if (!(t > 0 && t < 1)) return;
      const Vec3 projection = {pa[0] + t * ab[0], pa[1] + t * ab[1], pa[2] + t * ab[2]};
      if (projection == pa || projection == pb) return;
      double tolerance = node_tolerance_[id];
      if (result_.tolerance_derived)
        tolerance = std::min(tolerance, settings_.default_tolerance_fraction * std::sqrt(length2));
      const double d = norm(pv - projection);
      if (d > tolerance || d >= best[id].distance) return;
      const std::size_t na = node(a), nb = node(b);
      if ((na != no_node && along_one_border_side(id, na - 1, d)) ||
          (nb != no_node && along_one_border_side(id, nb - 1, d)))
        return;
      best[id] = Edge_hit{d, edge_box.info(), t, projection};
    };
    budget.run([&] {
      CGAL::box_intersection_d(node_boxes.begin(), node_boxes.end(), edge_boxes.begin(),
                               edge_boxes.end(), consider);
    });
    std::vector<std::pair<std::size_t, Edge_hit>> hits;
    if (budget.exhausted()) {
      result_.t_junction_search_truncated = true;
      return hits;
    }
    for (std::size_t id = 0; id < best.size(); ++id)
      if (best[id].distance < std::numeric_limits<double>::infinity())
        hits.emplace_back(id, best[id]);
    return hits;
  }

  /// Whether node `id` may be merged with a new node inside border halfedge `h`: no node of its
  /// cluster may share a face with the edge's ends (it would merge two nodes of one face).
  bool may_join_edge(std::size_t id, halfedge_descriptor h) {
    const std::size_t r = root(id);
    for (vertex_descriptor end : {source(h, pm_), target(h, pm_)}) {
      const std::size_t end_node = node(end);
      if (end_node != no_node && root(end_node - 1) == r) return false;
      for (std::size_t member : members(r, members_a_))
        if (share_face(node_vertex_[member], end)) return false;
    }
    return true;
  }

  std::size_t t_junction_pass() {
    visitor_.start_step("T-junctions");
    // Border edges already matched by a partner form conforming seams: only the others (and
    // their nodes) can take part in a T-junction, so the search scales with the defects.
    // char, not bool: OpenMesh stores a bool property in a std::vector<bool>, whose
    // elements its property map cannot return by reference (does not compile).
    auto matched = get(CGAL::dynamic_halfedge_property_t<char>(), pm_);
    for (halfedge_descriptor h : halfedges(pm_)) put(matched, h, false);
    for (const auto& [h1, h2] : matching_border_pairs_cached()) {
      put(matched, h1, true);
      put(matched, h2, true);
    }
    std::vector<halfedge_descriptor> border;
    std::vector<bool> node_needed(node_vertex_.size(), false);
    for (halfedge_descriptor h : halfedges(pm_)) {
      if (!is_border(h, pm_) || get(matched, h)) continue;
      border.push_back(h);
      for (vertex_descriptor v : {source(h, pm_), target(h, pm_)})
        if (node(v) != no_node) node_needed[node(v) - 1] = true;
    }
    auto hits = find_t_junctions(border, node_needed);
    // Group by edge, nodes in decreasing t (Figure 4.6: several nodes on one edge).
    std::sort(hits.begin(), hits.end(), [](const auto& x, const auto& y) {
      return std::make_pair(x.second.edge, -x.second.t) <
             std::make_pair(y.second.edge, -y.second.t);
    });
    std::size_t splits = 0;
    for (std::size_t begin = 0; begin < hits.size();) {
      std::size_t end = begin;
      while (end < hits.size() && hits[end].second.edge == hits[begin].second.edge) ++end;
      splits += split_border_edge(border[hits[begin].second.edge], hits.begin() + begin,
                                  hits.begin() + end);
      begin = end;
      if (cancelled()) break;
    }
    result_.t_junctions_split += splits;
    visitor_.end_step("T-junctions");
    return splits;
  }

  /// Inserts one node per hit into border halfedge `h` (hits sorted by decreasing t), splits the
  /// incident triangle accordingly and puts each new node in the cluster of its hitting node.
  template <class Iterator>
  std::size_t split_border_edge(halfedge_descriptor h, Iterator first, Iterator last) {
    std::vector<std::pair<std::size_t, Vec3>> accepted;  // node, point on the edge
    std::vector<std::size_t> roots_used;
    for (Iterator it = first; it != last; ++it) {
      const std::size_t r = root(it->first);
      if (std::find(roots_used.begin(), roots_used.end(), r) != roots_used.end()) continue;
      if (!may_join_edge(it->first, h)) continue;
      roots_used.push_back(r);
      accepted.emplace_back(it->first,
                            edge_point(h, it->second.t, position(node_vertex_[it->first])));
    }
    if (accepted.empty()) return 0;
    halfedge_descriptor inner = opposite(h, pm_);  // in the triangle (a, b, c) along b -> a
    if (is_border(inner, pm_)) return 0;
    const Vec3 face_normal = triangle_normal(inner);
    for (const auto& [id, point] : accepted) {
      // inner runs from the remaining far end towards a; t decreases, so the new node lies on it.
      const halfedge_descriptor to_new = CGAL::Euler::split_edge(inner, pm_);
      const vertex_descriptor created = target(to_new, pm_);
      put(vpm_, created, Point(point[0], point[1], point[2]));
      CGAL::Euler::split_face(to_new, next(inner, pm_), pm_);
      const std::size_t new_id = add_node(created, face_normal, node_tolerance_[id],
                                          std::numeric_limits<double>::infinity());
      unite(root(id), new_id);
    }
    return accepted.size();
  }

  Vec3 triangle_normal(halfedge_descriptor h) const {
    const Vec3 a = position(source(h, pm_)), b = position(target(h, pm_)),
               c = position(target(next(h, pm_), pm_));
    const Vec3 u = b - a, w = c - a;
    Vec3 n = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double length = std::sqrt(dot(n, n));
    if (length == 0) return {0, 0, 0};
    return {n[0] / length, n[1] / length, n[2] / length};
  }

  // ---- step 5: glue the border halfedges whose end clusters match -------------------------------

  using Halfedge_pairs = std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>>;

  /// Border halfedges whose end clusters match exactly one border halfedge the other way, in
  /// increasing order of (lower, higher) end cluster root.
  Halfedge_pairs matching_border_pairs() {
    struct Entry {
      std::size_t high;
      bool forward;
      halfedge_descriptor h;
    };
    // Bucketed by the lower root (counting sort over node ids), each bucket sorted by the higher.
    std::vector<std::size_t> bucket_start(node_vertex_.size() + 1, 0);
    std::vector<std::pair<std::size_t, Entry>> unsorted;
    for (halfedge_descriptor h : halfedges(pm_)) {
      if (!is_border(h, pm_)) continue;
      const std::size_t na = node(source(h, pm_)), nb = node(target(h, pm_));
      if (na == no_node || nb == no_node) continue;
      const std::size_t ra = root(na - 1), rb = root(nb - 1);
      if (ra == rb) continue;
      unsorted.push_back({std::min(ra, rb), Entry{std::max(ra, rb), ra < rb, h}});
      ++bucket_start[std::min(ra, rb) + 1];
    }
    for (std::size_t k = 0; k + 1 < bucket_start.size(); ++k)
      bucket_start[k + 1] += bucket_start[k];
    std::vector<Entry> entries(unsorted.size());
    {
      std::vector<std::size_t> fill(bucket_start.begin(), bucket_start.end() - 1);
      for (const auto& [low, entry] : unsorted) entries[fill[low]++] = entry;
    }
    std::vector<std::pair<std::size_t, Entry>>().swap(unsorted);
    Halfedge_pairs pairs;
    for (std::size_t low = 0; low + 1 < bucket_start.size(); ++low) {
      const auto first = entries.begin() + bucket_start[low],
                 last = entries.begin() + bucket_start[low + 1];
      if (last - first < 2) continue;
      std::sort(first, last, [](const Entry& x, const Entry& y) {
        return std::tie(x.high, x.forward) < std::tie(y.high, y.forward);
      });
      for (auto begin = first; begin != last;) {
        auto end = begin;
        while (end != last && end->high == begin->high) ++end;
        // Exactly one halfedge each way: gluing more would create a non-manifold edge.
        if (end - begin == 2 && begin->forward != (begin + 1)->forward)
          pairs.emplace_back(begin->h, (begin + 1)->h);
        begin = end;
      }
    }
    return pairs;
  }

  /// matching_border_pairs(), reused while no cluster or border halfedge changed.
  const Halfedge_pairs& matching_border_pairs_cached() {
    if (!matching_pairs_valid_) {
      matching_pairs_ = matching_border_pairs();
      matching_pairs_valid_ = true;
    }
    return matching_pairs_;
  }

  void stitch_clusters() {
    visitor_.start_step("stitch merged nodes");
    Halfedge_pairs to_stitch = matching_border_pairs_cached();
    // Removing an unglued T-junction node joins its halfedges into its neighbours': the pairs
    // are found again on the mesh as it is now (gluing the earlier list there was seen to give
    // an invalid mesh).
    if (restore_unglued_nodes(to_stitch)) to_stitch = matching_border_pairs();
    measure_moves();
    result_.edges_stitched = glue_border_halfedge_pairs(pm_, to_stitch);
    visitor_.end_step("stitch merged nodes");
  }

  /// A clustered node that no glued edge joins to another stays a separate vertex: left at
  /// the merge point it would sit on another vertex without being one (a new gap, and a
  /// coincident pair any point-merging reader would see), so it goes back to where it was, and
  /// a T-junction node glued to nothing is removed again. Its cluster is counted as
  /// unstitched: a touching point, not a seam.
  /// Returns whether a T-junction node was removed.
  bool restore_unglued_nodes(const Halfedge_pairs& to_stitch) {
    std::vector<std::size_t> glued(node_vertex_.size());
    for (std::size_t id = 0; id < glued.size(); ++id) glued[id] = id;
    auto find = [&](std::size_t id) {
      while (glued[id] != id) id = glued[id] = glued[glued[id]];
      return id;
    };
    auto join = [&](vertex_descriptor x, vertex_descriptor y) {
      glued[find(node(x) - 1)] = find(node(y) - 1);
    };
    for (const auto& [h1, h2] : to_stitch) {
      join(source(h1, pm_), target(h2, pm_));
      join(target(h1, pm_), source(h2, pm_));
    }
    std::vector<std::size_t> group_size(glued.size(), 0);
    for (std::size_t id = 0; id < glued.size(); ++id) ++group_size[find(id)];
    for (std::size_t r : cluster_roots()) {
      bool unstitched = false;
      for (std::size_t id = r; id != no_member; id = next_member_[id]) {
        unstitched = unstitched || find(id) != find(r);
        if (group_size[find(id)] > 1 || position(node_vertex_[id]) == node_original_[id]) continue;
        const Vec3& p = node_original_[id];
        put(vpm_, node_vertex_[id], Point(p[0], p[1], p[2]));
        ++result_.unglued_nodes_restored;
      }
      if (unstitched) ++result_.unstitched_clusters;
    }
    // Latest first: a later split may sit on an edge of an earlier one.
    bool removed = false;
    for (std::size_t id = node_vertex_.size(); id-- > 0;) {
      if (!created_node(id) || group_size[find(id)] > 1) continue;
      if (!undo_t_junction_split(node_vertex_[id])) continue;
      node_vertex_[id] = boost::graph_traits<PolygonMesh>::null_vertex();
      --result_.t_junctions_split;
      ++result_.t_junction_splits_undone;
      removed = true;
    }
    return removed;
  }

  bool created_node(std::size_t id) const {
    return node_shortest_edge_[id] == std::numeric_limits<double>::infinity();
  }

  /// Undoes split_border_edge for node `c` (an edge split, then a face split): joins the two
  /// faces at its interior edge, then joins it into an end of the split edge.
  bool undo_t_junction_split(vertex_descriptor c) {
    halfedge_descriptor interior = boost::graph_traits<PolygonMesh>::null_halfedge();
    halfedge_descriptor to_end = interior;
    std::size_t degree = 0;
    for (halfedge_descriptor h : halfedges_around_target(c, pm_)) {
      ++degree;
      if (!CGAL::is_border_edge(h, pm_))
        interior = h;
      else
        to_end = opposite(h, pm_);
    }
    if (degree != 3 || interior == boost::graph_traits<PolygonMesh>::null_halfedge() ||
        to_end == boost::graph_traits<PolygonMesh>::null_halfedge())
      return false;
    // join_vertex needs both sides of the joined edge larger than triangles: a border cycle of
    // three edges would become a two-edge loop.
    const halfedge_descriptor border = is_border(to_end, pm_) ? to_end : opposite(to_end, pm_);
    std::size_t border_size = 0;
    for (halfedge_descriptor h : halfedges_around_face(border, pm_)) {
      (void)h;
      if (++border_size > 3) break;
    }
    if (border_size <= 3) return false;
    CGAL::Euler::join_face(interior, pm_);
    CGAL::Euler::join_vertex(to_end, pm_);
    return true;
  }

  /// The largest move of a vertex, absolute and relative to its shortest incident edge.
  void measure_moves() {
    for (std::size_t id = 0; id < node_vertex_.size(); ++id) {
      if (node_vertex_[id] == boost::graph_traits<PolygonMesh>::null_vertex()) continue;
      const double move = norm(position(node_vertex_[id]) - node_original_[id]);
      result_.max_displacement = std::max(result_.max_displacement, move);
      if (move > 0 && node_shortest_edge_[id] < std::numeric_limits<double>::infinity())
        result_.max_move_to_shortest_edge =
            std::max(result_.max_move_to_shortest_edge, move / node_shortest_edge_[id]);
    }
  }

  double shortest_incident_edge(vertex_descriptor v) const {
    double shortest = std::numeric_limits<double>::infinity();
    const Vec3 p = position(v);
    for (halfedge_descriptor h : halfedges_around_target(v, pm_))
      shortest = std::min(shortest, norm(position(source(h, pm_)) - p));
    return shortest;
  }

  /// With a derived tolerance no input vertex moves farther than the tolerance fraction of its
  /// shortest incident edge, nor than `max_derived_move_` (a given tolerance is the user's bound).
  bool within_move_limits(std::size_t r, const Vec3& target) const {
    if (settings_.merge_tolerance >= 0) return true;
    for (std::size_t id = r; id != no_member; id = next_member_[id]) {
      const double move = norm(target - node_original_[id]);
      if (move > settings_.default_tolerance_fraction * node_shortest_edge_[id] ||
          move > max_derived_move_)
        return false;
    }
    return true;
  }

  /// The nodes of cluster `r` become single nodes again, back at their original positions.
  void dissolve(std::size_t r) {
    for (std::size_t id = r, next; id != no_member; id = next) {
      next = next_member_[id];
      const Vec3& p = node_original_[id];
      put(vpm_, node_vertex_[id], Point(p[0], p[1], p[2]));
      parent_[id] = last_member_[id] = id;
      next_member_[id] = no_member;
      cluster_size_[id] = 1;
      placed_[id] = false;
    }
    matching_pairs_valid_ = false;
  }

  std::size_t count_border_edges() const {
    std::size_t count = 0;
    for (halfedge_descriptor h : halfedges(pm_))
      if (is_border(h, pm_)) ++count;
    return count;
  }

  bool cancelled() {
    if (!cancelled_) cancelled_ = !visitor_.progress(1.0);
    return cancelled_;
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  Stitch_settings settings_;
  double max_derived_move_ = std::numeric_limits<double>::infinity();  ///< see Stitch_settings
  Visitor& visitor_;
  Node_id_map node_of_;
  Frozen_map frozen_;
  std::vector<vertex_descriptor> node_vertex_;
  std::vector<Vec3> node_original_, node_normal_;
  std::vector<double> node_tolerance_;
  std::vector<double> node_shortest_edge_;  // at collection; infinite for created nodes
  static constexpr std::size_t no_cycle = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> node_cycle_;  // at collection (locate_nodes_on_cycles)
  std::vector<double> node_arc_, cycle_length_;
  static constexpr std::size_t no_member = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> parent_;
  std::vector<std::size_t> next_member_;  // the cluster of a root, as a list from the root
  std::vector<std::size_t> last_member_, cluster_size_;  // at roots
  // At roots: whether the cluster is unchanged since its last placement, and how it was placed.
  std::vector<bool> placed_;
  std::vector<bool> placed_on_planes_;
  std::vector<std::size_t> members_a_, members_b_;
  std::vector<std::pair<Vector, double>> normal_scratch_;
  std::vector<Merge_node> merge_scratch_;
  bool coincident_possible_ = false;  // see run()
  Halfedge_pairs matching_pairs_;
  bool matching_pairs_valid_ = false;
  bool cancelled_ = false;
  Stitch_result result_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_STITCHING_GAP_STITCHER_H
