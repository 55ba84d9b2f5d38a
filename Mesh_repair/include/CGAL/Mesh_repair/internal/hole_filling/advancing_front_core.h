// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_ADVANCING_FRONT_CORE_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_ADVANCING_FRONT_CORE_H

// The advancing front of thesis section 4.4 (and its customised form of section 5.9), on plain
// arrays so that every method can reuse it: `advance_front` triangulates the region bounded by a
// border cycle, placing new nodes from averaged neighbour normals (eq. 4.8-4.12) at a target
// edge length, merging nodes closer than half an edge length, and checking every new triangle
// against the front with exact 2D orientation tests in the node's tangent plane. Where a new
// node goes is finished by a caller-supplied projection (identity, a fitted quadric, the Bezier
// patches of shape prediction) and the edge length comes from a caller-supplied size function.
// See doc/advancing_front.md.

#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <initializer_list>
#include <queue>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// The region to triangulate: a border cycle of distinct points (a point may occur twice in the
/// cycle at a pinched border). The cycle runs counterclockwise around the region seen from the
/// side its normals point to (a mesh's border halfedges do).
struct Front_input {
  std::vector<Vec3> points;        ///< border points; new nodes are appended after them
  std::vector<Vec3> normals;       ///< per point: the sum of its faces' unit normals (eq. 4.8)
  std::vector<std::size_t> cycle;  ///< indices into `points`, in border order
  /// Edges that already exist between two border points (mesh edges, border edges included):
  /// the front must not create them again.
  std::vector<std::pair<std::size_t, std::size_t>> existing_edges;
  /// The mesh around the hole (a few rings of faces), which no new triangle may meet: each
  /// corner is a border point (index < points.size()) or `context_points[i - points.size()]`.
  std::vector<Vec3> context_points;
  std::vector<std::array<std::size_t, 3>> context_triangles;
  /// True when `context_triangles` holds every face of the mesh whose bounding box overlaps the
  /// box [`context_lo`, `context_hi`] and every face sharing a vertex with the border (all of
  /// them triangles): a patch inside that box, each of whose triangles passed the front's exact
  /// test, then meets no face of the mesh (see `Front_triangulation::exactly_checked`).
  bool context_complete = false;
  Vec3 context_lo{0, 0, 0}, context_hi{0, 0, 0};
};

struct Front_options {
  double small_angle_deg = 75;      ///< below: one triangle closes the corner (thesis 4.4 rule a)
  double large_angle_deg = 135;     ///< above: three triangles, two new nodes (rule c)
  double merge_factor = 0.5;        ///< a new node within this times the edge length is merged
  double max_triangles_factor = 4;  ///< give up beyond this times the expected triangle count
  int smoothing_iterations = 3;     ///< tangential relaxation of the new nodes after closing
  /// A new triangle may not have a 3D angle below this (degrees), except the angle at the node
  /// of a one-triangle rule, which the front's own corner imposes: no sliver, no node placed
  /// on a front edge (which the tangent-plane test, on rounded projections, cannot see).
  double min_angle_deg = 3;
  /// When the front is stuck, close each remaining loop (up to `max_remnant_edges` edges) with
  /// the minimum-area triangulation of the loop's points restricted to triangles that pass the
  /// same exact 3D test as the front's (see `close_remnant`).
  bool close_remnant = false;
  std::size_t max_remnant_edges = 200;
  /// The work (stored triangles visited) left to the closings of remnant loops, shared by every
  /// attempt on one hole (`fill_hole_advancing_front` tries up to 15 placements and sizes): a
  /// hole whose loops have no valid triangulation (another part of the mesh passes through it)
  /// spends the budget once, not once per attempt. Null: `remnant_visit_budget` per loop.
  std::size_t* remnant_visits_left = nullptr;
  /// The size function ignores its second argument (the mean adjacent front edge length), so
  /// the front computes it once per node.
  bool size_from_position_only = false;
  /// Leave out the 3D test of each fan against the triangles already there (the tangent-plane
  /// test against the front stays) and test the closed patch once, in its final positions, with
  /// `recheck_patch`: on a hole where no fan would have failed the 3D test the patch is the
  /// same, for half the exact tests. The patch is `exactly_checked` only when that final test
  /// passed; a caller reruns the front without this option when it did not (see
  /// `fill_hole_advancing_front`). Not with `close_remnant`, whose triangulation needs the 3D
  /// test: a stuck front simply fails.
  bool defer_3d_test = false;
  /// Replaces the tangential relaxation after closing (with `smoothing_iterations` passes):
  /// moves the new nodes (from index `first_new`) of the closed triangulation. The moved patch is
  /// tested again like the relaxed one.
  std::function<void(std::vector<Vec3>& points,
                     const std::vector<std::array<std::size_t, 3>>& triangles,
                     std::size_t first_new)>
      relaxation;
  /// When the moved patch fails that test, put the nodes back where the front created them
  /// (where each fan passed its own exact test) instead of leaving the patch unchecked.
  bool undo_failed_relaxation = false;
};

/// `points` starts with the input's border points; `triangles` index into it, in creation order
/// (each triangle touches the front of its time, so adding them to a mesh in this order keeps
/// every intermediate border a set of cycles).
struct Front_triangulation {
  std::vector<Vec3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::size_t border_points = 0;
  bool closed = false;
  std::string failure;
  /// When the front fails: its open loops (indices into `points`, each loop in front order,
  /// i.e. counterclockwise around the part of the region still uncovered), for a caller that
  /// closes them another way (see `close_front_remnant` in advancing_front.h).
  std::vector<std::vector<std::size_t>> remnant;
  /// Edges of the loops closed by `Front_options::close_remnant` (0 when the front closed).
  std::size_t remnant_edges = 0;
  /// True when the closed triangulation has been checked exactly, in its final positions, as
  /// the whole-mesh check `patch_intersections_with_mesh` would check it: every triangle was
  /// tested with exact predicates against every other triangle of the patch and every context
  /// triangle whose bounding box it overlaps (each new triangle when it was added, each moved
  /// one when the relaxation moved a node), the input's context is complete and every new point
  /// lies in its box. A caller may then skip its own check of the patch (see
  /// doc/advancing_front.md, "Exact checks").
  bool exactly_checked = false;
};

/// A list of at most N elements without allocation (the front's fans have at most 3 triangles).
template <class T, std::size_t N>
class Small_list {
 public:
  Small_list() = default;
  Small_list(std::initializer_list<T> items) {
    for (const T& item : items) push_back(item);
  }
  void push_back(const T& item) {
    CGAL_assertion(size_ < N);
    items_[size_++] = item;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  T& operator[](std::size_t i) { return items_[i]; }
  const T* begin() const { return items_.data(); }
  const T* end() const { return items_.data() + size_; }

 private:
  std::array<T, N> items_{};
  std::size_t size_ = 0;
};

/// Finishes the position of a new node (candidate, normal of the node it grows from).
using Front_projection = std::function<Vec3(const Vec3&, const Vec3&)>;
/// The edge length wanted at a point, given the mean length of the two front edges there.
using Front_size = std::function<double(const Vec3&, double)>;

/// The stored triangles that the closing of one remnant loop may visit in its eager stage
/// (`Advancing_front::close_remnant_with`).
constexpr std::size_t remnant_visit_budget = 60'000'000;

class Advancing_front {
  using Point_2 = Epick::Point_2;
  static constexpr int none = -1;

  struct Front_edge {
    std::size_t from, to;
    int prev, next;
    bool alive;
    int next_out;  // the next live front edge leaving `from` (list headed by first_out_[from])
  };

  /// A set of undirected edges (keys from `key`): open addressing, no allocation per edge.
  class Edge_set {
   public:
    void reserve(std::size_t n) {
      std::size_t capacity = 16;
      while (capacity < 2 * n) capacity *= 2;
      if (capacity > slots_.size()) rehash(capacity);
    }
    void insert(std::uint64_t k) {
      if (2 * (size_ + 1) > slots_.size()) rehash(std::max<std::size_t>(16, 2 * slots_.size()));
      std::size_t i = slot(k);
      while (slots_[i] != empty && slots_[i] != k) i = (i + 1) & (slots_.size() - 1);
      if (slots_[i] == empty) {
        slots_[i] = k;
        ++size_;
      }
    }
    bool count(std::uint64_t k) const {
      if (slots_.empty()) return false;
      std::size_t i = slot(k);
      while (slots_[i] != empty) {
        if (slots_[i] == k) return true;
        i = (i + 1) & (slots_.size() - 1);
      }
      return false;
    }

   private:
    static constexpr std::uint64_t empty = ~std::uint64_t(0);
    std::size_t slot(std::uint64_t k) const {
      k ^= k >> 33;
      k *= 0xff51afd7ed558ccdULL;
      k ^= k >> 33;
      return std::size_t(k) & (slots_.size() - 1);
    }
    void rehash(std::size_t capacity) {
      std::vector<std::uint64_t> old(capacity, empty);
      old.swap(slots_);
      size_ = 0;
      for (std::uint64_t k : old)
        if (k != empty) insert(k);
    }
    std::vector<std::uint64_t> slots_;
    std::size_t size_ = 0;
  };
  struct Corner {  // the corner at the target of edge `in`, between `in` and its next
    double angle;
    int in;
    std::uint32_t stamp;
    // Ties broken by edge, so that the order does not depend on the heap's history.
    bool operator>(const Corner& other) const {
      return angle > other.angle || (angle == other.angle && in > other.in);
    }
  };

 public:
  Advancing_front(const Front_input& input, Front_projection project, Front_size size,
                  const Front_options& options)
      : project_(std::move(project)), size_(std::move(size)), options_(options) {
    points_ = input.points;
    normal_sums_ = input.normals;
    first_out_.assign(points_.size(), none);
    double perimeter = 0;
    Vec3 vector_area{0, 0, 0};
    const std::size_t n = input.cycle.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& p = points_[input.cycle[k]];
      const Vec3& q = points_[input.cycle[(k + 1) % n]];
      perimeter += norm(sub(q, p));
      vector_area = add(vector_area, scale(cross(p, q), 0.5));
    }
    hole_normal_ = normalized(vector_area);
    border_length_ = perimeter;
    mean_length_ = n > 0 ? perimeter / double(n) : 1.0;
    if (!(mean_length_ > 0)) mean_length_ = 1.0;
    cell_ = 2.0 * mean_length_;
    // Triangles are filed by box in cells of 3 border edges: of 1, 1.5, 2 and 3, the fastest
    // on the 200- and 500-edge holes of bench_fill (fewer cells per query outweigh the longer
    // cell lists).
    triangle_cell_ = 3.0 * mean_length_;
    const double expected = std::max(norm(vector_area), perimeter * mean_length_) /
                            (0.433 * mean_length_ * mean_length_);
    // Clamped before the conversion: on degenerate borders `expected` can be huge or NaN.
    const double allowed = options_.max_triangles_factor * expected;
    max_triangles_ = std::size_t(allowed >= 0 && allowed < 1e8 ? allowed : 1e8) + 4 * n + 16;
    {
      const std::size_t guess = std::min<std::size_t>(std::size_t(expected) + 2 * n, 1u << 22);
      edges_.reserve(2 * guess + input.existing_edges.size());
      grid_.reserve(guess / 2 + n);
      triangle_grid_.reserve(guess + input.context_triangles.size());
      stored_.reserve(guess + input.context_triangles.size());
      visit_stamp_.reserve(guess + input.context_triangles.size());
      triangles_.reserve(guess);
      points_.reserve(guess / 2 + points_.size());
      normal_sums_.reserve(guess / 2 + points_.size());
      first_out_.reserve(guess / 2 + points_.size());
      front_.reserve(3 * guess);
      stamps_.reserve(3 * guess);
      loop_of_.reserve(3 * guess);
    }
    for (const auto& e : input.existing_edges) edges_.insert(key(e.first, e.second));
    context_complete_ = input.context_complete;
    context_lo_ = input.context_lo;
    context_hi_ = input.context_hi;
    const std::size_t border = input.points.size();
    for (const auto& t : input.context_triangles) {
      std::array<std::size_t, 3> ids;
      std::array<Vec3, 3> corners;
      for (int k = 0; k < 3; ++k) {
        ids[k] = t[k] < border ? t[k] : std::size_t(-1) - (t[k] - border);
        corners[k] = t[k] < border ? input.points[t[k]] : input.context_points[t[k] - border];
      }
      store_triangle(ids, corners);
    }
    for (std::size_t k = 0; k < n; ++k) add_front_edge(input.cycle[k], input.cycle[(k + 1) % n]);
    for (std::size_t k = 0; k < n; ++k) {
      front_[k].next = int((k + 1) % n);
      front_[k].prev = int((k + n - 1) % n);
    }
    for (std::size_t k = 0; k < n; ++k) push_corner(int(k));
  }

  Front_triangulation run() {
    Front_triangulation result;
    result.border_points = border_count_ = points_.size();
    while (alive_ > 0) {
      if (triangles_.size() > max_triangles_) {
        result.failure = "the front does not close (too many triangles)";
        break;
      }
      // Every corner that could succeed is in the queue: a blocked one comes back only when the
      // front changes within its reach, so an empty queue means no rule applies anywhere.
      if (queue_.empty()) {
        result.failure = "the front is stuck: no valid triangle at any node";
        break;
      }
      const Corner corner = queue_.top();
      queue_.pop();
      if (!front_[corner.in].alive || stamps_[corner.in] != corner.stamp) continue;
      touched_.clear();
      reach_center_ = points_[front_[corner.in].to];
      reach_ = 0;
      if (advance(corner.in, corner.angle)) {
        wake_blocked_corners();
      } else {
        blocked_.push_back({corner.in, stamps_[corner.in], reach_});
      }
    }
    result.closed = alive_ == 0;
    if (result.closed) smooth();
    if (!result.closed) result.remnant = open_loops();
    if (!result.closed && options_.close_remnant && !options_.defer_3d_test) {
      result.remnant_edges = 0;
      double remnant_length = 0;
      for (const auto& loop : result.remnant) {
        result.remnant_edges += loop.size();
        for (std::size_t k = 0; k < loop.size(); ++k)
          remnant_length += norm(sub(points_[loop[(k + 1) % loop.size()]], points_[loop[k]]));
      }
      // A front that placed triangles and is left longer than the hole's border went around
      // something in the hole (another piece of the surface across it): the least-area closing
      // of such loops spans past the hole, a bag around the piece (libcgal-demo's
      // blobby_3cc.off: a 130-edge remnant of a 71-edge hole closed by 2,831 faces enclosing the
      // whole model). A front stuck at once is the border itself, which may be closed.
      const bool grew = !triangles_.empty() && remnant_length > border_length_;
      if (grew) result.failure += "; its remnant is longer than the hole's border (not closed)";
      bool all = !grew;
      for (const auto& loop : result.remnant) all = all && close_remnant(loop);
      if (all) {
        result.closed = true;
        result.failure.clear();
        result.remnant.clear();
      }
    }
    result.exactly_checked = result.closed && context_complete_ && !unchecked_;
    for (std::size_t p = border_count_; p < points_.size() && result.exactly_checked; ++p) {
      for (int d = 0; d < 3; ++d) {
        if (!(context_lo_[d] <= points_[p][d] && points_[p][d] <= context_hi_[d]))
          result.exactly_checked = false;
      }
    }
    result.points = std::move(points_);
    result.triangles = std::move(triangles_);
    result.border_points = border_count_;
    return result;
  }

 private:
  /// After a rule changed the front, the blocked corners whose outcome may have changed go back
  /// to the queue: those whose node or front neighbours the rule touched (their normals,
  /// angles and edges changed), and those whose tests (front points, stored triangles) reached
  /// the box of the touched points. The others would fail again as they did: waking every
  /// blocked corner after each success made a stalled 1,200-edge front quadratic.
  void wake_blocked_corners() {
    if (touched_.empty()) return;
    CGAL::Bbox_3 box;
    for (std::size_t p : touched_) box += point_3(points_[p]).bbox();
    std::sort(touched_.begin(), touched_.end());
    const auto is_touched = [&](std::size_t p) {
      return std::binary_search(touched_.begin(), touched_.end(), p);
    };
    std::size_t kept = 0;
    for (const Blocked_corner& corner : blocked_) {
      if (!front_[corner.in].alive || stamps_[corner.in] != corner.stamp) continue;
      const Front_edge& in = front_[corner.in];
      const std::size_t v = in.to;
      const bool woken = is_touched(in.from) || is_touched(v) || is_touched(front_[in.next].to) ||
                         distance_to_box(points_[v], box) <= corner.reach * (1 + 1e-6);
      if (woken) {
        push_corner(corner.in);
      } else {
        blocked_[kept++] = corner;
      }
    }
    blocked_.resize(kept);
  }
  static double distance_to_box(const Vec3& p, const CGAL::Bbox_3& box) {
    Vec3 d{0, 0, 0};
    for (int k = 0; k < 3; ++k) d[k] = std::max({box.min(k) - p[k], p[k] - box.max(k), 0.0});
    return norm(d);
  }
  /// Widens the reach of the corner under test to a query ball (center, radius).
  void note_reach(const Vec3& center, double radius) const {
    reach_ = std::max(reach_, norm(sub(center, reach_center_)) + radius);
  }
  void note_reach(const CGAL::Bbox_3& box) const {
    Vec3 far{0, 0, 0};
    for (int k = 0; k < 3; ++k)
      far[k] = std::max(std::abs(box.min(k) - reach_center_[k]),
                        std::abs(box.max(k) - reach_center_[k]));
    reach_ = std::max(reach_, norm(far));
  }

  // ---- bookkeeping --------------------------------------------------------------------------
  static std::uint64_t key(std::size_t a, std::size_t b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t(a) << 32) | std::uint64_t(b);
  }
  /// The live front edge from a to b, or `none`.
  int front_edge_between(std::size_t a, std::size_t b) const {
    if (a >= first_out_.size()) return none;
    for (int e = first_out_[a]; e != none; e = front_[e].next_out)
      if (front_[e].to == b) return e;
    return none;
  }
  bool on_front(std::size_t p) const { return first_out_[p] != none; }
  /// floor(x / cell) as an integer, clamped to +-2^52 (NaN to 0) so that the conversion is
  /// defined for any coordinate range: a file with coordinates from 1e-12 to 1e33 gives huge
  /// quotients, whose conversion to int64 was undefined.
  static std::int64_t cell_index(double x, double cell) {
    const double q = std::floor(x / cell);
    constexpr double limit = 4503599627370496.0;  // 2^52
    if (!(q == q)) return 0;
    return std::int64_t(std::max(-limit, std::min(limit, q)));
  }
  std::uint64_t cell_key(const Vec3& p) const {
    auto c = [&](double x) { return std::uint64_t(cell_index(x, cell_) & 0x1fffff); };
    return (c(p[0]) << 42) | (c(p[1]) << 21) | c(p[2]);
  }
  // The grid holds the front's points only: a point joins it with its first outgoing front edge
  // and leaves it with its last, so proximity searches never scan the patch's interior.
  void insert_in_grid(std::size_t p) { grid_[cell_key(points_[p])].push_back(p); }
  void remove_from_grid(std::size_t p) {
    auto& cell = grid_[cell_key(points_[p])];
    const auto it = std::find(cell.begin(), cell.end(), p);
    CGAL_assertion(it != cell.end());
    *it = cell.back();
    cell.pop_back();
  }

  int add_front_edge(std::size_t from, std::size_t to) {
    const int e = int(front_.size());
    front_.push_back({from, to, none, none, true, first_out_[from]});
    stamps_.push_back(0);
    loop_of_.push_back(0);  // set by `link`; the hole's cycle is loop 0
    edges_.insert(key(from, to));
    touched_.push_back(from);
    touched_.push_back(to);
    if (first_out_[from] == none) insert_in_grid(from);
    first_out_[from] = e;
    ++alive_;
    return e;
  }
  void kill(int e) {
    Front_edge& edge = front_[e];
    edge.alive = false;
    touched_.push_back(edge.from);
    touched_.push_back(edge.to);
    int* link = &first_out_[edge.from];
    while (*link != e) link = &front_[*link].next_out;
    *link = edge.next_out;
    if (first_out_[edge.from] == none) remove_from_grid(edge.from);
    --alive_;
  }
  /// Makes b follow a; b joins a's loop (each rule links its new edges from a live one).
  void link(int a, int b) {
    front_[a].next = b;
    front_[b].prev = a;
    loop_of_[b] = loop_of_[a];
  }
  /// After a rule split a loop in two (edges a and b now on different loops), the shorter
  /// gets a fresh id: the walk is as long as the shorter loop, O(n log n) over a run, where
  /// walking the front to tell two loops apart cost O(n) per merge attempt (a 984-edge hole:
  /// a third of two minutes).
  void relabel_shorter_loop(int a, int b) {
    const int fresh = loop_count_++;
    for (int x = a, y = b;;) {
      x = front_[x].next;
      y = front_[y].next;
      if (x == a || y == b) {
        const int start = x == a ? a : b;
        int e = start;
        do {
          loop_of_[e] = fresh;
          e = front_[e].next;
        } while (e != start);
        return;
      }
    }
  }

  Vec3 normal(std::size_t p) const {
    const Vec3 n = normalized(normal_sums_[p]);
    return norm(n) > 0 ? n : hole_normal_;
  }
  std::size_t new_point(const Vec3& p) {
    points_.push_back(p);
    normal_sums_.push_back({0, 0, 0});
    first_out_.push_back(none);
    return points_.size() - 1;
  }
  void add_triangle(std::size_t a, std::size_t b, std::size_t c) {
    triangles_.push_back({a, b, c});
    touched_.insert(touched_.end(), {a, b, c});
    triangle_stored_.push_back(store_triangle({a, b, c}, {points_[a], points_[b], points_[c]}));
    edges_.insert(key(a, b));
    edges_.insert(key(b, c));
    edges_.insert(key(c, a));
    // Eq. 4.8: a node's normal is the mean of its elements' unit normals.
    const Vec3 n = normalized(cross(sub(points_[b], points_[a]), sub(points_[c], points_[a])));
    for (std::size_t p : {a, b, c}) normal_sums_[p] = add(normal_sums_[p], n);
  }

  /// Interior angle (radians, in [0, 2pi)) at the target of `in`, in the node's tangent plane.
  double angle_at(int in) const {
    const Front_edge& e = front_[in];
    const std::size_t a = e.from, v = e.to, b = front_[e.next].to;
    const Vec3 n = normal(v);
    Vec3 u = sub(points_[a], points_[v]), w = sub(points_[b], points_[v]);
    u = sub(u, scale(n, dot(u, n)));
    w = sub(w, scale(n, dot(w, n)));
    double theta = std::atan2(dot(n, cross(w, u)), dot(w, u));
    if (theta < 0) theta += 2 * CGAL_PI;
    return theta;
  }
  void push_corner(int in) {
    if (!front_[in].alive) return;
    ++stamps_[in];
    queue_.push({angle_at(in), in, stamps_[in]});
  }

  // ---- geometry checks ----------------------------------------------------------------------
  /// The tangent frame at a node: exact 2D tests run on points projected onto it.
  struct Tangent_frame {
    Vec3 origin, u, v, n;
    Point_2 operator()(const Vec3& p) const {
      const Vec3 d = sub(p, origin);
      return Point_2(dot(d, u), dot(d, v));
    }
    double height(const Vec3& p) const { return dot(sub(p, origin), n); }
  };
  Tangent_frame frame_at(std::size_t v) const {
    Tangent_frame f;
    f.origin = points_[v];
    f.n = normal(v);
    tangent_frame(f.n, f.u, f.v);
    return f;
  }

  /// Front points within `radius` of `center` and not far off the tangent plane (in a buffer
  /// that the next call overwrites).
  const std::vector<std::size_t>& nearby_front_points(const Tangent_frame& frame,
                                                      double radius) const {
    std::vector<std::size_t>& found = near_points_;
    found.clear();
    note_reach(frame.origin, radius);
    const Vec3& c = frame.origin;
    const auto base = [&](double x) { return cell_index(x, cell_); };
    std::array<std::int64_t, 3> lo, hi;
    for (int d = 0; d < 3; ++d) {
      lo[d] = base(c[d] - radius);
      hi[d] = base(c[d] + radius);
      if (hi[d] - lo[d] > 64) {  // absurd radius: every front point is a candidate
        for (std::size_t p = 0; p < points_.size(); ++p) {
          const Vec3 v = sub(points_[p], c);
          if (on_front(p) && dot(v, v) <= radius * radius &&
              std::abs(frame.height(points_[p])) <= 0.5 * radius)
            found.push_back(p);
        }
        return found;
      }
    }
    const auto consider = [&](const std::vector<std::size_t>& cell) {
      for (std::size_t p : cell) {
        const Vec3 d = sub(points_[p], c);
        if (dot(d, d) <= radius * radius && std::abs(frame.height(points_[p])) <= 0.5 * radius)
          found.push_back(p);
      }
    };
    const std::int64_t cells = (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
    if (cells > std::int64_t(grid_.size())) {
      // Fewer occupied cells than cells in the box (a large radius over a sparse front: up to
      // 65^3 look-ups per query): the occupied cells of the box, in the order of the loops below.
      for (const auto& cell : cells_in_box(lo, hi)) consider(*cell.second);
      return found;
    }
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j) {
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
          const auto it = grid_.find(point_cell_key({i, j, k}));
          if (it != grid_.end()) consider(it->second);
        }
      }
    }
    return found;
  }
  static std::uint64_t point_cell_key(const std::array<std::int64_t, 3>& c) {
    return (std::uint64_t(c[0] & 0x1fffff) << 42) | (std::uint64_t(c[1] & 0x1fffff) << 21) |
           std::uint64_t(c[2] & 0x1fffff);
  }
  /// The occupied cells of the front's grid whose key the cells lo..hi (at most 65 per axis)
  /// have, each with those cell indices, sorted as the loops over lo..hi visit them.
  std::vector<std::pair<std::array<std::int64_t, 3>, const std::vector<std::size_t>*>> cells_in_box(
      const std::array<std::int64_t, 3>& lo, const std::array<std::int64_t, 3>& hi) const {
    std::vector<std::pair<std::array<std::int64_t, 3>, const std::vector<std::size_t>*>> in_box;
    for (const auto& cell : grid_) {
      std::array<std::int64_t, 3> index;
      bool inside = true;
      for (int d = 0; d < 3 && inside; ++d) {
        const std::int64_t masked = std::int64_t((cell.first >> (42 - 21 * d)) & 0x1fffff);
        index[d] = lo[d] + ((masked - lo[d]) & 0x1fffff);  // the one index of lo..hi so masked
        inside = index[d] <= hi[d];
      }
      if (inside) in_box.emplace_back(index, &cell.second);
    }
    std::sort(in_box.begin(), in_box.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    return in_box;
  }

  /// A candidate fan: triangles to add, each listed (a, b, c) counterclockwise.
  struct Fan {
    Small_list<std::array<std::size_t, 3>, 3> triangles;
    Small_list<Vec3, 2> new_points;  // positions of the fan's new nodes, from points_.size()
  };
  const Vec3& position(const Fan& fan, std::size_t p) const {
    return p < points_.size() ? points_[p] : fan.new_points[p - points_.size()];
  }

  /// Exact checks of a fan at node v in its tangent plane: every triangle counterclockwise, no
  /// front point inside or on a triangle, no new edge meeting a front edge away from its ends;
  /// and no new edge that already exists in the mesh or the patch.
  bool fan_is_valid(std::size_t v, const Fan& fan, std::initializer_list<int> consumed,
                    bool check_shape = true) const {
    if (check_shape && !fan_is_well_shaped(fan)) return false;
    const Tangent_frame frame = frame_at(v);
    double radius = 0;
    Small_list<std::pair<std::size_t, std::size_t>, 9> new_edges;
    Small_list<Epick::Segment_2, 9> new_segments;     // the new edges in the tangent plane
    Small_list<std::array<Point_2, 3>, 3> projected;  // the fan's triangles in the tangent plane
    for (const auto& t : fan.triangles) {
      for (int k = 0; k < 3; ++k) {
        radius = std::max(radius, norm(sub(position(fan, t[k]), points_[v])));
        const std::size_t s = t[k], e = t[(k + 1) % 3];
        const int front_edge = front_edge_between(s, e);
        if (front_edge != none) {  // the fan may only consume the edges it replaces
          if (std::find(consumed.begin(), consumed.end(), front_edge) == consumed.end())
            return false;
          continue;
        }
        if (s < points_.size() && e < points_.size() && edges_.count(key(s, e))) return false;
        new_edges.push_back({s, e});
        new_segments.push_back(Epick::Segment_2(frame(position(fan, s)), frame(position(fan, e))));
      }
      const Point_2 p0 = frame(position(fan, t[0])), p1 = frame(position(fan, t[1])),
                    p2 = frame(position(fan, t[2]));
      if (CGAL::orientation(p0, p1, p2) != CGAL::LEFT_TURN) return false;
      projected.push_back({p0, p1, p2});
    }
    for (std::size_t x : nearby_front_points(frame, 1.5 * radius + 1e-300)) {
      const Point_2 px = frame(points_[x]);
      for (std::size_t i = 0; i < fan.triangles.size(); ++i) {
        const auto& t = fan.triangles[i];
        if (x == t[0] || x == t[1] || x == t[2]) continue;
        const Point_2 &p0 = projected[i][0], &p1 = projected[i][1], &p2 = projected[i][2];
        if (CGAL::orientation(p0, p1, px) != CGAL::RIGHT_TURN &&
            CGAL::orientation(p1, p2, px) != CGAL::RIGHT_TURN &&
            CGAL::orientation(p2, p0, px) != CGAL::RIGHT_TURN)
          return false;
      }
      for (int e = first_out_[x]; e != none; e = front_[e].next_out) {
        const std::size_t y = front_[e].to;
        const Point_2 py = frame(points_[y]);
        for (std::size_t i = 0; i < new_edges.size(); ++i) {
          const auto& edge = new_edges[i];
          if (edge.first == x || edge.first == y || edge.second == x || edge.second == y) continue;
          if (CGAL::do_intersect(new_segments[i], Epick::Segment_2(px, py))) return false;
        }
      }
    }
    if (options_.defer_3d_test) return true;
    // 3D: the fan's triangles against each other and against the triangles already there.
    Small_list<Stored_triangle, 3> candidates;
    for (const auto& t : fan.triangles) {
      candidates.push_back(
          make_stored(t, {position(fan, t[0]), position(fan, t[1]), position(fan, t[2])}));
      if (CGAL::collinear(candidates[candidates.size() - 1].corners[0],
                          candidates[candidates.size() - 1].corners[1],
                          candidates[candidates.size() - 1].corners[2]))
        return false;
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      for (std::size_t j = i + 1; j < candidates.size(); ++j) {
        if (triangles_meet(candidates[i].ids, candidates[i].corners, candidates[j])) return false;
      }
    }
    return !meets_stored_triangles(candidates.begin(), candidates.end());
  }

  // ---- exact 3D test against the triangles already there --------------------------------------
  using Point_3 = Epick::Point_3;
  struct Stored_triangle {
    std::array<std::size_t, 3> ids;
    std::array<Point_3, 3> corners;
    CGAL::Bbox_3 box;
  };
  static Point_3 point_3(const Vec3& p) { return Point_3(p[0], p[1], p[2]); }
  static Stored_triangle make_stored(const std::array<std::size_t, 3>& ids,
                                     const std::array<Vec3, 3>& corners) {
    Stored_triangle stored{
        ids, {point_3(corners[0]), point_3(corners[1]), point_3(corners[2])}, CGAL::Bbox_3()};
    stored.box = stored.corners[0].bbox() + stored.corners[1].bbox() + stored.corners[2].bbox();
    return stored;
  }

  /// Calls f on the cells of the triangle grid overlapped by `box`; false (and no call) when the
  /// box spans more than 64 cells along an axis or more than 512 cells in all: such triangles
  /// are kept in `large_` and such queries scan every stored triangle (the same exact tests, so
  /// the same result). The bound on the count keeps the grid's memory proportional to the
  /// number of triangles whatever their shape (a long thin triangle across 64 x 64 x 64 cells
  /// filed 274,625 entries).
  template <class F>
  bool for_cells(const CGAL::Bbox_3& box, F f) const {
    std::array<std::int64_t, 3> lo, hi;
    std::int64_t cells = 1;
    for (int d = 0; d < 3; ++d) {
      lo[d] = cell_index(box.min(d), triangle_cell_);
      hi[d] = cell_index(box.max(d), triangle_cell_);
      if (!(hi[d] - lo[d] <= 64)) return false;
      cells *= hi[d] - lo[d] + 1;
    }
    if (cells > 512) return false;
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k) f(triangle_cell_key({i, j, k}));
    return true;
  }
  static std::uint64_t triangle_cell_key(const std::array<std::int64_t, 3>& c) {
    return (std::uint64_t(c[0] & 0x1fffff) << 42) | (std::uint64_t(c[1] & 0x1fffff) << 21) |
           std::uint64_t(c[2] & 0x1fffff);
  }

  static constexpr std::size_t not_stored = std::size_t(-1);
  /// Stores a triangle for the exact tests; its index, or `not_stored` for a degenerate one.
  std::size_t store_triangle(const std::array<std::size_t, 3>& ids,
                             const std::array<Vec3, 3>& corners) {
    const Stored_triangle stored = make_stored(ids, corners);
    if (CGAL::collinear(stored.corners[0], stored.corners[1], stored.corners[2])) return not_stored;
    const std::size_t index = stored_.size();
    stored_.push_back(stored);
    visit_stamp_.push_back(0);
    // Deferred: nothing queries the grid before `recheck_patch`, which files every triangle.
    if (!options_.defer_3d_test) register_in_cells(index);
    return index;
  }
  /// A grid entry: a stored triangle and its box rounded outwards to floats, so that a scan of
  /// a cell reads one contiguous array and rejects most candidates without touching them.
  struct Cell_entry {
    std::array<float, 6> box;
    std::uint32_t index;
  };
  static std::array<float, 6> float_box(const CGAL::Bbox_3& box) {
    // Widened by 1e-6 relative (and 1e-30 absolute) before rounding to float (relative error
    // below 6e-8), so the float box contains the double one.
    std::array<float, 6> rounded;
    for (int d = 0; d < 3; ++d) {
      const double lo = box.min(d), hi = box.max(d);
      rounded[d] = float(lo - std::abs(lo) * 1e-6 - 1e-30);
      rounded[d + 3] = float(hi + std::abs(hi) * 1e-6 + 1e-30);
    }
    return rounded;
  }
  static bool float_boxes_overlap(const std::array<float, 6>& a, const std::array<float, 6>& b) {
    return a[0] <= b[3] && b[0] <= a[3] && a[1] <= b[4] && b[1] <= a[4] && a[2] <= b[5] &&
           b[2] <= a[5];
  }
  void register_in_cells(std::size_t index) {
    const Cell_entry entry{float_box(stored_[index].box), std::uint32_t(index)};
    if (!for_cells(stored_[index].box,
                   [&](std::uint64_t cell) { triangle_grid_[cell].push_back(entry); }))
      large_.push_back(index);
  }

  /// Calls `test(index)` on every stored triangle whose box may overlap `box`, once per visit
  /// (stored triangles whose stamp is already `visit_` are skipped); stops when it returns true.
  template <class Test>
  bool any_stored_near(const CGAL::Bbox_3& box, Test test) const {
    note_reach(box);
    bool found = false;
    const auto visit = [&](std::size_t index) {
      ++visits_;
      if (visit_stamp_[index] == visit_) return;
      visit_stamp_[index] = visit_;
      found = test(index);
    };
    for (std::size_t index : large_) {
      visit(index);
      if (found) return true;
    }
    const std::array<float, 6> rounded = float_box(box);
    const bool gridded = for_cells(box, [&](std::uint64_t cell) {
      if (found) return;
      const auto it = triangle_grid_.find(cell);
      if (it == triangle_grid_.end()) return;
      for (const Cell_entry& entry : it->second) {
        if (!float_boxes_overlap(entry.box, rounded)) continue;  // conservative: boxes rounded out
        visit(entry.index);
        if (found) return;
      }
    });
    if (!gridded) {
      for (std::size_t index = 0; index < stored_.size() && !found; ++index) visit(index);
    }
    return found;
  }

  /// Exact test (Epick's filtered predicates) of a new triangle against the stored triangles
  /// whose boxes it overlaps. Triangles sharing an edge meet when they fold onto each other
  /// (coplanar, same side); sharing a vertex, when the edge opposite it in one meets the other.
  bool meets_stored_triangle(const std::array<std::size_t, 3>& ids,
                             const std::array<Vec3, 3>& corners) const {
    const Stored_triangle t = make_stored(ids, corners);
    if (CGAL::collinear(t.corners[0], t.corners[1], t.corners[2])) return true;
    return meets_stored_triangles(&t, &t + 1);
  }

  /// `meets_stored_triangle` for several triangles at once (a fan): one pass over the cells.
  bool meets_stored_triangles(const Stored_triangle* first, const Stored_triangle* last) const {
    CGAL::Bbox_3 box;
    for (const Stored_triangle* t = first; t != last; ++t) box += t->box;
    ++visit_;
    return any_stored_near(box, [&](std::size_t index) {
      const Stored_triangle& stored = stored_[index];
      for (const Stored_triangle* t = first; t != last; ++t) {
        if (CGAL::do_overlap(t->box, stored.box) && triangles_meet(t->ids, t->corners, stored))
          return true;
      }
      return false;
    });
  }

  static bool triangles_meet(const std::array<std::size_t, 3>& ids, const std::array<Point_3, 3>& t,
                             const Stored_triangle& s) {
    int shared = 0, ia = -1, ib = -1, ja = -1, jb = -1;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (ids[i] != s.ids[j]) continue;
        ++shared;
        if (ia < 0) {
          ia = i;
          ja = j;
        } else {
          ib = i;
          jb = j;
        }
      }
    }
    if (shared >= 3) return true;  // the same triangle twice
    if (shared == 2) {
      const Point_3& r = t[3 - ia - ib];
      const Point_3& q = s.corners[3 - ja - jb];
      return CGAL::orientation(t[ia], t[ib], r, q) == CGAL::COPLANAR &&
             CGAL::coplanar_orientation(t[ia], t[ib], r, q) == CGAL::POSITIVE;
    }
    if (shared == 1) {
      // Quick exact exits: the two other corners of one triangle strictly on one side of the
      // other's plane, so the triangles meet at the shared corner only.
      const Point_3 &t1 = t[(ia + 1) % 3], &t2 = t[(ia + 2) % 3];
      const CGAL::Orientation o1 = CGAL::orientation(s.corners[0], s.corners[1], s.corners[2], t1);
      if (o1 != CGAL::COPLANAR &&
          o1 == CGAL::orientation(s.corners[0], s.corners[1], s.corners[2], t2))
        return false;
      const Point_3 &s1 = s.corners[(ja + 1) % 3], &s2 = s.corners[(ja + 2) % 3];
      const CGAL::Orientation o2 = CGAL::orientation(t[0], t[1], t[2], s1);
      if (o2 != CGAL::COPLANAR && o2 == CGAL::orientation(t[0], t[1], t[2], s2)) return false;
      const Epick::Segment_3 opposite_t(t[(ia + 1) % 3], t[(ia + 2) % 3]);
      const Epick::Segment_3 opposite_s(s.corners[(ja + 1) % 3], s.corners[(ja + 2) % 3]);
      return CGAL::do_intersect(opposite_t,
                                Epick::Triangle_3(s.corners[0], s.corners[1], s.corners[2])) ||
             CGAL::do_intersect(opposite_s, Epick::Triangle_3(t[0], t[1], t[2]));
    }
    return CGAL::do_intersect(Epick::Triangle_3(t[0], t[1], t[2]),
                              Epick::Triangle_3(s.corners[0], s.corners[1], s.corners[2]));
  }

  /// 3D angles of the fan's triangles (a, v, b): none below `min_angle_deg`, except the angle at
  /// v (index 1) of a single triangle, which is the front's corner itself.
  bool fan_is_well_shaped(const Fan& fan) const {
    const double limit = std::cos(options_.min_angle_deg * CGAL_PI / 180.0);
    for (const auto& t : fan.triangles) {
      for (int k = 0; k < 3; ++k) {
        if (k == 1 && fan.triangles.size() == 1) continue;
        const Vec3& o = position(fan, t[k]);
        const Vec3 u = sub(position(fan, t[(k + 1) % 3]), o);
        const Vec3 w = sub(position(fan, t[(k + 2) % 3]), o);
        const double nu = norm(u), nw = norm(w);
        if (!(nu > 0) || !(nw > 0)) return false;
        if (dot(u, w) > limit * nu * nw) return false;  // angle below the limit
      }
    }
    return true;
  }

  // ---- the rules ----------------------------------------------------------------------------
  /// The edge length wanted at node v between front neighbours a and b.
  double size_at(std::size_t v, std::size_t a, std::size_t b) {
    if (options_.size_from_position_only) {
      if (size_cache_.size() < points_.size()) size_cache_.resize(points_.size(), -1.0);
      if (size_cache_[v] < 0) size_cache_[v] = size_(points_[v], 0.0);
      return size_cache_[v];
    }
    return size_(points_[v],
                 0.5 * (norm(sub(points_[a], points_[v])) + norm(sub(points_[b], points_[v]))));
  }

  /// Direction at v rotated by phi from the tangent direction of `toward` about `n`
  /// (counterclockwise for positive phi).
  Vec3 rotated(std::size_t v, std::size_t toward, const Vec3& n, double phi) const {
    Vec3 w = sub(points_[toward], points_[v]);
    w = normalized(sub(w, scale(n, dot(w, n))));
    const Vec3 left = cross(n, w);
    return add(scale(w, std::cos(phi)), scale(left, std::sin(phi)));
  }

  bool advance(int in, double theta) {
    const Front_edge& e_in = front_[in];
    const int out = e_in.next;
    const std::size_t a = e_in.from, v = e_in.to, b = front_[out].to;
    if (front_[out].next == in) {  // two edges a->v->a: a zero-width channel, glue it
      kill(in);
      kill(out);
      return true;
    }
    if (front_[front_[out].next].next == in) return close_triangle(in);
    const double deg = theta * 180.0 / CGAL_PI;
    if (deg < options_.small_angle_deg) return ear(in);
    const double length = size_at(v, a, b);
    // Eq. 4.9-4.12: the new elements' normals average the node's with its neighbours'.
    const Vec3 n = normal(v);
    const Vec3 n1 = normalized(add(n, normal(a))), n2 = normalized(add(n, normal(b)));
    if (deg <= options_.large_angle_deg) {
      return bisect(in, theta, length, n, n1, n2) || ear(in);
    }
    return trisect(in, theta, length, n, n1, n2) || bisect(in, theta, length, n, n1, n2) ||
           (deg < 180 && ear(in));
  }

  bool close_triangle(int in) {
    const int out = front_[in].next, last = front_[out].next;
    const std::size_t a = front_[in].from, v = front_[in].to, b = front_[out].to;
    Fan fan{{{a, v, b}}, {}};
    if (!fan_is_valid(v, fan, {in, out, last}, false)) return false;  // forced: the loop's last
    kill(in);
    kill(out);
    kill(last);
    add_triangle(a, v, b);
    return true;
  }

  /// Rule a: the triangle (a, v, b); the front edge a->b replaces a->v->b.
  bool ear(int in) {
    const int out = front_[in].next;
    const std::size_t a = front_[in].from, v = front_[in].to, b = front_[out].to;
    if (a == b) return false;
    Fan fan{{{a, v, b}}, {}};
    if (!fan_is_valid(v, fan, {in, out})) return false;
    const int before = front_[in].prev, after = front_[out].next;
    kill(in);
    kill(out);
    add_triangle(a, v, b);
    const int e = add_front_edge(a, b);
    link(before, e);
    link(e, after);
    push_corner(before);
    push_corner(e);
    return true;
  }

  /// Nearest front point within `radius` of p, other than v; or `none`.
  long nearest_front_point(const Vec3& p, std::size_t v, double radius) const {
    Tangent_frame frame;
    frame.origin = p;
    frame.n = normal(v);
    long best = none;
    double best_distance = radius;
    for (std::size_t x : nearby_front_points(frame, radius)) {
      const double d = norm(sub(points_[x], p));
      if (x != v && d <= best_distance) {
        best = long(x);
        best_distance = d;
      }
    }
    return best;
  }

  /// Projects the position `p` of a new node (normal `n`); false, and no projection, when `p`,
  /// `n` or the projection is not finite: the directions of rules b and c are 0/0 at corners of
  /// denormal coordinates, and neither the guide surface's tree nor the exact tests may see a
  /// NaN (`is_finite`; a fuzzed STL of four such triangles stopped the tool with SIGFPE).
  bool placed(Vec3& p, const Vec3& n) const {
    if (!is_finite(p) || !is_finite(n)) return false;
    p = project_(p, n);
    return is_finite(p);
  }

  /// Rule b: one new node from the two equilateral apexes on edges A and B in the planes of
  /// normals n1 and n2 (thesis Figure 4.11), averaged; merged with a front node closer than half
  /// an edge length.
  bool bisect(int in, double theta, double length, const Vec3& n, const Vec3& n1, const Vec3& n2) {
    const int out = front_[in].next;
    const std::size_t a = front_[in].from, v = front_[in].to, b = front_[out].to;
    const double sixty = CGAL_PI / 3;
    const Vec3 apex_b = add(points_[v], scale(rotated(v, b, n2, sixty), length));
    const Vec3 apex_a = add(points_[v], scale(rotated(v, a, n1, -sixty), length));
    Vec3 p = scale(add(apex_a, apex_b), 0.5);
    if (norm(sub(p, points_[v])) < 0.5 * length)
      p = add(points_[v], scale(rotated(v, b, n, 0.5 * theta), length));
    if (!placed(p, n)) return false;
    const long q = nearest_front_point(p, v, options_.merge_factor * length);
    if (q != none && (std::size_t(q) == a || std::size_t(q) == b)) return false;  // ear instead
    if (q != none && merge_fan(in, std::size_t(q))) return true;
    return fresh_fan(in, {p});
  }

  /// Rule c: two new nodes at a third and two thirds of the angle (thesis eq. 5.33), tilted by
  /// n2 and n1; not merged (a close front node sends the corner to rule b).
  bool trisect(int in, double theta, double length, const Vec3& n, const Vec3& n1, const Vec3& n2) {
    (void)n;
    const int out = front_[in].next;
    const std::size_t a = front_[in].from, v = front_[in].to, b = front_[out].to;
    Vec3 pb = add(points_[v], scale(rotated(v, b, n2, theta / 3), length));
    Vec3 pa = add(points_[v], scale(rotated(v, a, n1, -theta / 3), length));
    if (!placed(pb, n2) || !placed(pa, n1)) return false;
    const double merge = options_.merge_factor * length;
    if (nearest_front_point(pa, v, merge) != none || nearest_front_point(pb, v, merge) != none)
      return false;
    return fresh_fan(in, {pa, pb});
  }

  /// Fan a, p_1, ..., p_k, b around v with new nodes.
  bool fresh_fan(int in, const Small_list<Vec3, 2>& nodes) {
    const int out = front_[in].next;
    const std::size_t a = front_[in].from, v = front_[in].to, b = front_[out].to;
    Fan fan;
    fan.new_points = nodes;
    Small_list<std::size_t, 4> chain{a};
    for (std::size_t k = 0; k < nodes.size(); ++k) chain.push_back(points_.size() + k);
    chain.push_back(b);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k)
      fan.triangles.push_back({chain[k], v, chain[k + 1]});
    if (!fan_is_valid(v, fan, {in, out})) return false;
    const int before = front_[in].prev, after = front_[out].next;
    for (const Vec3& p : nodes) new_point(p);
    kill(in);
    kill(out);
    for (const auto& t : fan.triangles) add_triangle(t[0], t[1], t[2]);
    int previous = before;
    Small_list<int, 3> created;
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      const int e = add_front_edge(chain[k], chain[k + 1]);
      link(previous, e);
      created.push_back(e);
      previous = e;
    }
    link(previous, after);
    push_corner(before);
    for (int e : created) push_corner(e);
    return true;
  }

  /// Rule b with the new node merged into the front node q: triangles (a, v, q), (q, v, b),
  /// which split the front loop in two (or consume q's edges when q neighbours a or b).
  bool merge_fan(int in, std::size_t q) {
    if (first_out_[q] == none || front_[first_out_[q]].next_out != none) return false;
    const int out = front_[in].next;
    const std::size_t a = front_[in].from, v = front_[in].to, b = front_[out].to;
    const int q_out = first_out_[q], q_in = front_[q_out].prev;
    if (loop_of_[out] != loop_of_[q_out]) return false;
    Fan fan{{{a, v, q}, {q, v, b}}, {}};
    if (edges_.count(key(v, q))) return false;
    const bool consumes_a = q_out == front_[in].prev;  // front edge q->a
    const bool consumes_b = q_in == front_[out].next;  // front edge b->q
    if (!fan_is_valid(v, fan, {in, out, consumes_a ? q_out : in, consumes_b ? q_in : in}))
      return false;
    const int before = front_[in].prev, after = front_[out].next;
    kill(in);
    kill(out);
    add_triangle(a, v, q);
    add_triangle(q, v, b);
    if (consumes_a && consumes_b) {
      kill(q_out);
      kill(q_in);
      return true;
    }
    if (consumes_a) {
      kill(q_out);
      const int e = add_front_edge(q, b);
      link(q_in, e);
      link(e, after);
      push_corner(q_in);
      push_corner(e);
      return true;
    }
    if (consumes_b) {
      kill(q_in);
      const int e = add_front_edge(a, q);
      link(before, e);
      link(e, q_out);
      push_corner(before);
      push_corner(e);
      return true;
    }
    const int to_q = add_front_edge(a, q), from_q = add_front_edge(q, b);
    link(before, to_q);
    link(to_q, q_out);
    link(q_in, from_q);
    link(from_q, after);
    relabel_shorter_loop(to_q, from_q);
    for (int e : {before, to_q, q_in, from_q}) push_corner(e);
    return true;
  }

  /// Closes one loop of the stuck front: the triangulation of its polygon (no new point) of
  /// least total area among those whose every triangle passes the exact 3D test against the
  /// triangles already there and creates no existing edge; well-shaped triangles first, any
  /// non-degenerate ones if that fails.
  bool close_remnant(const std::vector<std::size_t>& loop) {
    const std::size_t n = loop.size();
    if (n < 3 || n > options_.max_remnant_edges) return false;
    for (bool shaped : {true, false}) {
      if (close_remnant_with(loop, shaped)) return true;
    }
    return false;
  }

  /// The least-area triangulation whose triangles all pass the exact 3D test, found in two
  /// bounded stages. Lazy: the dynamic program over the polygon (O(n^3) arithmetic) runs with the
  /// cheap tests only, the exact test runs on the triangles of its optimum alone, those that fail
  /// are excluded and the program runs again; each round's optimum is over a superset of the
  /// valid triangulations, so the first whose triangles all pass is the answer, found with a few
  /// hundred exact tests where testing every candidate took minutes (a 126-edge loop spanning
  /// its mesh: each of the O(n^3) candidates scanned every stored triangle). Eager, when
  /// `remnant_lazy_rounds` rounds did not settle it (loops with no valid triangulation, or many
  /// failing candidates): the program tests each candidate that would improve on the best so
  /// far, reusing every answer, until done or `remnant_visit_budget` stored triangles were
  /// visited; the loop is then left open. With `Front_options::remnant_visits_left`, the
  /// eager stage stops when the hole's shared budget is spent.
  static constexpr int remnant_lazy_rounds = 64, remnant_free_rounds = 8;
  /// A program step (one apex tried) is a few multiplications, a visit an exact triangle test.
  static constexpr std::size_t remnant_steps_per_visit = 8;
  bool close_remnant_with(const std::vector<std::size_t>& loop, bool shaped) {
    const std::size_t n = loop.size();
    enum : char { unknown, cheap_ok, passes, fails };
    std::vector<char> state(n * n * n, unknown);  // at most 8 MB (200-edge loops)
    const auto exact_test = [&](std::size_t i, std::size_t k, std::size_t j) {
      const std::size_t a = loop[i], b = loop[k], c = loop[j];
      return !meets_stored_triangle({a, b, c}, {points_[a], points_[b], points_[c]});
    };
    bool eager = false;
    const std::size_t visits_at_start = visits_, steps_at_start = steps_;
    std::size_t* shared = options_.remnant_visits_left;
    const std::size_t budget =
        shared != nullptr ? std::min(remnant_visit_budget, *shared) : remnant_visit_budget;
    // The programs' steps count too: on loops crossed by other parts they outnumbered the exact
    // tests' visits tenfold and the budget never saw them (doc/fuzzing.md).
    const auto used = [&] {
      return visits_ - visits_at_start + (steps_ - steps_at_start) / remnant_steps_per_visit;
    };
    const auto spend = [&](bool closed) {
      if (shared != nullptr) *shared -= std::min(*shared, used());
      return closed;
    };
    const auto allowed = [&](std::size_t i, std::size_t k, std::size_t j) {
      char& s = state[(i * n + k) * n + j];
      if (s == unknown) s = cheap_test(loop, i, k, j, shaped) ? cheap_ok : fails;
      if (s == cheap_ok && eager && used() <= budget) s = exact_test(i, k, j) ? passes : fails;
      return s == passes || (s == cheap_ok && !eager);
    };
    Least_area_table table;  // kept from round to round: each round only excludes triangles
    for (int round = 0; round < remnant_lazy_rounds; ++round) {
      // Past `remnant_free_rounds`, the rounds stop once the hole's budget is spent: a loop with
      // no valid triangulation repeated all 64 on every attempt (15 per hole), about 2 s per
      // failing hole on a furniture model. The free rounds keep closing the loops that settle
      // in a few rounds after an earlier attempt spent it (a femur hole needs them).
      if (round >= remnant_free_rounds && used() > budget) return spend(false);
      const std::vector<std::array<std::size_t, 3>> triangles =
          least_area_triangulation(loop, allowed, &table);
      if (triangles.empty()) return spend(false);
      bool all_pass = true;
      for (const auto& t : triangles) {
        char& s = state[(t[0] * n + t[1]) * n + t[2]];
        if (s == cheap_ok) s = exact_test(t[0], t[1], t[2]) ? passes : fails;
        all_pass = all_pass && s == passes;
      }
      if (all_pass) return spend(add_remnant_triangles(loop, triangles));
    }
    eager = true;
    const std::vector<std::array<std::size_t, 3>> triangles =
        least_area_triangulation(loop, allowed);
    if (triangles.empty() || used() > budget) return spend(false);
    return spend(add_remnant_triangles(loop, triangles));
  }

  /// The tests of a remnant triangle (positions i < k < j in `loop`) that need no search: three
  /// distinct points, no chord that is already an edge, and, when `shaped`, no small angle.
  bool cheap_test(const std::vector<std::size_t>& loop, std::size_t i, std::size_t k, std::size_t j,
                  bool shaped) const {
    const std::size_t n = loop.size(), a = loop[i], b = loop[k], c = loop[j];
    if (a == b || b == c || a == c) return false;
    for (const auto& chord : {std::make_pair(i, k), std::make_pair(k, j), std::make_pair(i, j)}) {
      if (chord.second == chord.first + 1 || (chord.first == 0 && chord.second == n - 1))
        continue;  // a loop edge
      if (edges_.count(key(loop[chord.first], loop[chord.second]))) return false;
    }
    return !shaped || fan_is_well_shaped(Fan{{{a, b, c}}, {}});
  }

  bool add_remnant_triangles(const std::vector<std::size_t>& loop,
                             const std::vector<std::array<std::size_t, 3>>& triangles) {
    for (const auto& t : triangles) {
      const std::size_t a = loop[t[0]], b = loop[t[1]], c = loop[t[2]];
      // Each triangle passed the test against what was there before the loop's
      // triangulation, not against the loop's other triangles: test it against them too.
      if (meets_stored_triangle({a, b, c}, {points_[a], points_[b], points_[c]})) unchecked_ = true;
      add_triangle(a, b, c);
    }
    return true;
  }

  /// The dynamic program's table of `least_area_triangulation`: for each span (i, j) of the loop,
  /// the least area of a triangulation of the polygon i..j and the apex of its triangle on (i, j).
  struct Least_area_table {
    std::vector<double> weight;
    std::vector<int> apex;
  };

  /// The triangulation of the polygon `loop` of least total area whose triangles (i, k, j), as
  /// positions in the loop with i < k < j, satisfy `allowed` (empty when there is none). The
  /// triangles come in an order where each is attached to the border of its time. With a
  /// `table` filled by an earlier call on the same loop, whose `allowed` admitted every triangle
  /// this one admits (the lazy rounds only exclude), only the spans whose optimum lost a
  /// triangle are computed again: the others keep their optimum, whose alternatives can only
  /// have grown, and the result is the one a fresh program would give (ties to the first apex).
  template <class Allowed>
  std::vector<std::array<std::size_t, 3>> least_area_triangulation(
      const std::vector<std::size_t>& loop, const Allowed& allowed,
      Least_area_table* table = nullptr) const {
    const std::size_t n = loop.size();
    const double infinite = std::numeric_limits<double>::infinity();
    Least_area_table local;
    Least_area_table& t = table != nullptr ? *table : local;
    const bool fresh = t.weight.size() != n * n;
    if (fresh) {
      t.weight.assign(n * n, infinite);
      t.apex.assign(n * n, -1);
      for (std::size_t i = 0; i + 1 < n; ++i) t.weight[i * n + i + 1] = 0;
    }
    std::vector<double>& weight = t.weight;
    std::vector<int>& apex = t.apex;
    std::vector<char> changed(fresh ? 0 : n * n, 0);  // spans whose least area grew
    for (std::size_t gap = 2; gap < n; ++gap) {
      for (std::size_t i = 0; i + gap < n; ++i) {
        const std::size_t j = i + gap;
        double before = infinite;
        if (!fresh) {
          const int k = apex[i * n + j];
          if (k < 0) continue;  // no triangulation before, none with fewer triangles allowed
          if (allowed(i, std::size_t(k), j) && !changed[i * n + k] && !changed[k * n + j]) continue;
          before = weight[i * n + j];
          weight[i * n + j] = infinite;
          apex[i * n + j] = -1;
        }
        steps_ += gap - 1;
        for (std::size_t k = i + 1; k < j; ++k) {
          const double w = weight[i * n + k] + weight[k * n + j];
          if (!(w < weight[i * n + j]) || !allowed(i, k, j)) continue;
          const Vec3 area = cross(sub(points_[loop[k]], points_[loop[i]]),
                                  sub(points_[loop[j]], points_[loop[i]]));
          const double total = w + 0.5 * norm(area);
          if (total < weight[i * n + j]) {
            weight[i * n + j] = total;
            apex[i * n + j] = int(k);
          }
        }
        if (!fresh && weight[i * n + j] != before) changed[i * n + j] = 1;
      }
    }
    std::vector<std::array<std::size_t, 3>> triangles;
    if (apex[n - 1] < 0) return triangles;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, n - 1}};
    while (!stack.empty()) {
      const auto [i, j] = stack.back();
      stack.pop_back();
      if (j < i + 2) continue;
      const std::size_t k = std::size_t(apex[i * n + j]);
      triangles.push_back({i, k, j});
      stack.emplace_back(k, j);
      stack.emplace_back(i, k);
    }
    return triangles;
  }

  /// The loops of the live front edges.
  std::vector<std::vector<std::size_t>> open_loops() const {
    std::vector<std::vector<std::size_t>> loops;
    std::vector<char> seen(front_.size(), 0);
    for (std::size_t start = 0; start < front_.size(); ++start) {
      if (!front_[start].alive || seen[start]) continue;
      std::vector<std::size_t> loop;
      int e = int(start);
      while (!seen[e] && front_[e].alive) {
        seen[e] = 1;
        loop.push_back(front_[e].from);
        e = front_[e].next;
      }
      loops.push_back(std::move(loop));
    }
    return loops;
  }

  // ---- after closing --------------------------------------------------------------------------
  /// Tangential relaxation of the new nodes towards their neighbours' centroid, each move
  /// finished by the projection: evens out the triangles without shrinking the patch. The moved
  /// triangles are then tested again (`recheck_patch`), so the patch stays exactly checked.
  void smooth() {
    const bool relax = options_.smoothing_iterations > 0 && points_.size() > border_count_;
    std::vector<Vec3> created;
    if (relax && options_.undo_failed_relaxation) created = points_;
    if (relax && options_.relaxation)
      options_.relaxation(points_, triangles_, border_count_);
    else if (relax)
      relax_new_nodes();
    // The fans' 3D test saw the nodes where they were created, or was deferred to here.
    if (!(relax || options_.defer_3d_test) || recheck_patch()) return;
    if (relax && options_.undo_failed_relaxation && !options_.defer_3d_test) {
      points_ = std::move(created);
      if (recheck_patch()) return;
    }
    unchecked_ = true;
  }

  void relax_new_nodes() {
    const std::size_t count = points_.size();
    // Each new node's neighbours, in one array (a node's triangle corners, each neighbour met
    // twice around an interior node: the duplicates weigh every neighbour equally).
    std::vector<std::size_t> first(count - border_count_ + 1, 0);
    for (const auto& t : triangles_)
      for (std::size_t p : t)
        if (p >= border_count_) first[p - border_count_ + 1] += 2;
    for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
    std::vector<std::size_t> neighbours(first.back());
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (const auto& t : triangles_) {
      for (int k = 0; k < 3; ++k) {
        if (t[k] < border_count_) continue;
        std::size_t& at = fill[t[k] - border_count_];
        neighbours[at++] = t[(k + 1) % 3];
        neighbours[at++] = t[(k + 2) % 3];
      }
    }
    for (int iteration = 0; iteration < options_.smoothing_iterations; ++iteration) {
      for (std::size_t p = border_count_; p < count; ++p) {
        const std::size_t begin = first[p - border_count_], end = first[p - border_count_ + 1];
        if (begin == end) continue;
        Vec3 centroid{0, 0, 0};
        for (std::size_t k = begin; k < end; ++k) centroid = add(centroid, points_[neighbours[k]]);
        centroid = scale(centroid, 1.0 / double(end - begin));
        const Vec3 n = normal(p);
        Vec3 move = sub(centroid, points_[p]);
        move = sub(move, scale(n, dot(move, n)));
        Vec3 moved = add(points_[p], move);
        if (placed(moved, n)) points_[p] = moved;
      }
    }
  }

  /// After the relaxation moved the new nodes: every triangle of the patch, at its final
  /// position, is tested exactly against every other one and every context triangle whose box
  /// it overlaps (each pair once). True when none meets (nor is degenerate).
  bool recheck_patch() {
    if (triangles_.empty()) return true;
    std::size_t first_patch = stored_.size();
    for (std::size_t index = 0; index < triangles_.size(); ++index) {
      const std::size_t stored = triangle_stored_[index];
      if (stored == not_stored) return false;
      first_patch = std::min(first_patch, stored);
      const auto& t = triangles_[index];
      stored_[stored] = make_stored(t, {points_[t[0]], points_[t[1]], points_[t[2]]});
      const Stored_triangle& moved = stored_[stored];
      if (CGAL::collinear(moved.corners[0], moved.corners[1], moved.corners[2])) return false;
    }
    for (auto& cell : triangle_grid_) cell.second.clear();
    large_.clear();
    for (std::size_t index = 0; index < stored_.size(); ++index) register_in_cells(index);
    // A pair of triangles (not both of the context) is tested when their boxes overlap; both are
    // filed in the cell holding the lowest corner of the boxes' intersection, and the pair is
    // tested there only, so once. One pass over each cell's list instead of a query per triangle.
    // Each list is in index order (filed above in that order), the context's triangles first.
    const auto meets = [&](std::size_t i, std::size_t j) {
      if (i < first_patch && j < first_patch) return false;
      const Stored_triangle &a = stored_[i], &b = stored_[j];
      return CGAL::do_overlap(a.box, b.box) && triangles_meet(a.ids, a.corners, b);
    };
    for (const auto& [cell, entries] : triangle_grid_) {
      const auto patch_begin = std::partition_point(
          entries.begin(), entries.end(),
          [first_patch](const Cell_entry& e) { return e.index < first_patch; });
      for (auto i = patch_begin; i != entries.end(); ++i) {
        for (auto j = entries.begin(); j != i; ++j) {
          if (!float_boxes_overlap(i->box, j->box)) continue;
          const CGAL::Bbox_3 &a = stored_[i->index].box, &b = stored_[j->index].box;
          std::array<std::int64_t, 3> lowest;
          for (int d = 0; d < 3; ++d)
            lowest[d] = cell_index(std::max(a.min(d), b.min(d)), triangle_cell_);
          if (triangle_cell_key(lowest) != cell) continue;
          if (meets(i->index, j->index)) return false;
        }
      }
    }
    // Triangles too large for the grid, against every other (two large ones: once).
    std::vector<bool> large(stored_.size(), false);
    for (std::size_t index : large_) large[index] = true;
    for (std::size_t l : large_) {
      for (std::size_t index = 0; index < stored_.size(); ++index) {
        if (index == l || (large[index] && index < l)) continue;
        if (meets(l, index)) return false;
      }
    }
    return true;
  }

  Front_projection project_;
  Front_size size_;
  Front_options options_;
  std::vector<Vec3> points_, normal_sums_;
  std::vector<int> first_out_;  // per point: its first live outgoing front edge, or `none`
  std::vector<Front_edge> front_;
  std::vector<std::uint32_t> stamps_;
  Edge_set edges_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid_;
  std::priority_queue<Corner, std::vector<Corner>, std::greater<Corner>> queue_;
  /// A corner no rule applies to, and how far from its node its tests looked.
  struct Blocked_corner {
    int in;
    std::uint32_t stamp;
    double reach;
  };
  std::vector<Blocked_corner> blocked_;
  std::vector<std::size_t> touched_;  ///< points whose front or triangles the last rule changed
  mutable Vec3 reach_center_{0, 0, 0};
  mutable double reach_ = 0;
  std::vector<std::array<std::size_t, 3>> triangles_;
  std::vector<std::size_t> triangle_stored_;  // per triangle: its index in stored_
  std::vector<Stored_triangle> stored_;
  std::vector<std::size_t> large_;  // stored triangles spanning too many cells for the grid
  std::vector<double> size_cache_;  // per point, with `size_from_position_only` (-1: not yet)
  mutable std::vector<std::size_t> near_points_;
  bool context_complete_ = false, unchecked_ = false;
  Vec3 context_lo_{0, 0, 0}, context_hi_{0, 0, 0};
  std::unordered_map<std::uint64_t, std::vector<Cell_entry>> triangle_grid_;
  mutable std::vector<std::uint32_t> visit_stamp_;
  mutable std::uint32_t visit_ = 0;
  std::vector<int> loop_of_;  ///< the loop of each front edge (ids from `relabel_shorter_loop`)
  int loop_count_ = 1;
  mutable std::size_t visits_ = 0;  ///< stored triangles visited, the unit of a search's work
  mutable std::size_t steps_ = 0;   ///< apexes tried by `least_area_triangulation`
  std::size_t alive_ = 0, border_count_ = 0, max_triangles_ = 0;
  double mean_length_ = 1, cell_ = 1, triangle_cell_ = 1;
  double border_length_ = 0;  ///< the hole's perimeter
  Vec3 hole_normal_{0, 0, 1};
};

/// The edge length wanted inside the hole: an inverse-square-distance blend of the border's
/// edge lengths, times `factor` (the front's layers compress: see `front_spacing_factor` in
/// advancing_front.h), so the patch's density matches its surroundings everywhere (thesis 4.4)
/// without the drift of taking each node's two adjacent front edges, which shrink layer after
/// layer (see doc/advancing_front.md). The border is summarised by at most 64 runs of edges.
inline Front_size border_density(const Front_input& input, double factor) {
  const std::size_t n = input.cycle.size();
  const std::size_t runs = std::min<std::size_t>(n, 64);
  auto samples = std::make_shared<std::vector<std::pair<Vec3, double>>>();
  for (std::size_t r = 0; r < runs; ++r) {
    const std::size_t begin = r * n / runs, end = (r + 1) * n / runs;
    Vec3 middle{0, 0, 0};
    double length = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3& p = input.points[input.cycle[k]];
      const Vec3& q = input.points[input.cycle[(k + 1) % n]];
      length += norm(sub(q, p));
      middle = add(middle, scale(add(p, q), 0.5));
    }
    const double count = double(end - begin);
    samples->emplace_back(scale(middle, 1.0 / count), length / count);
  }
  return [samples, factor](const Vec3& at, double adjacent) {
    double weights = 0, blend = 0;
    for (const auto& sample : *samples) {
      const double d2 = dot(sub(at, sample.first), sub(at, sample.first));
      if (d2 == 0) return factor * sample.second;
      const double weight = 1.0 / d2;
      weights += weight;
      blend += sample.second * weight;
    }
    return factor * (weights > 0 ? blend / weights : adjacent);
  };
}

/// Triangulates the region bounded by `input.cycle` with the advancing front.
inline Front_triangulation advance_front(const Front_input& input, Front_projection project,
                                         Front_size size, const Front_options& options = {}) {
  Advancing_front front(input, std::move(project), std::move(size), options);
  return front.run();
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_ADVANCING_FRONT_CORE_H
