// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_GENETIC_GA_TRIANGULATION_H
#define CGAL_MESH_REPAIR_INTERNAL_GENETIC_GA_TRIANGULATION_H

/// \file ga_triangulation.h
/// Genetic-algorithm triangulation of a closed polygon of n 3D points (thesis 5.4, Table 5.2,
/// eq. 5.8-5.13; the same GA re-triangulates the empty regions of chapter 7, Table 7.1,
/// eq. 7.5-7.9). Shared by `shape_prediction` and `optimize_mesh`.
///
/// Interface (everything in `CGAL::Mesh_repair::internal::genetic`):
///
/// 1. `Chord_table table = valid_chords<Kernel>(points, vertex_normals);`
///    The polygon `points[0..n-1]` is closed (edge n-1 -> 0) and oriented counterclockwise seen
///    from its outside (for a hole: the order of its border halfedges). A chord (i,j), i<j, is a
///    segment between two non-adjacent nodes (Table 5.2 order: by i, then j). It is valid when it
///    lies inside the polygon: decided with exact `Orientation_2` / `Do_intersect_2` after
///    projection onto the Newell (best-fitting) plane when that projection is a simple polygon;
///    otherwise (strongly non-planar holes) with a projection-free test: exact `Orientation_3`
///    cone tests at both ends around the node normals `vertex_normals` (may be empty: then the
///    Newell normal is used). `table.planar` says which test was used.
/// 2. `auto seed = min_dihedral_triangulation<Kernel>(points, outside_normals, table);`
///    O(n^3) dynamic program minimising the sum of (1 - cos) of the dihedral angles between
///    adjacent new triangles and between new triangles and the existing faces across the polygon
///    edges. `outside_normals[i]` is the unit normal of the existing face across edge (i, i+1)
///    (empty vector, or a null vector for an edge with no face: no boundary term).
///    Returns std::nullopt when no triangulation with valid chords exists.
/// 3. `Ga_result r = ga_triangulate<Kernel>(points, outside_normals, table, fitness, options);`
///    Chromosome = the valid chords (bit b set when chord b of `table.chords` is used, eq. 5.8).
///    Population seeded with the dynamic-programming triangulation and flips of it; multi-point
///    crossover on the chromosome followed by a combinatorial repair (a chord is kept only if its
///    end indices do not interleave with those of an accepted chord: an exact crossing test for
///    chords inside the polygon); mutation = edge flip (only to a valid chord); elitism, so the
///    result is never worse than the seed. Stops after `options.max_generations` (500) or when
///    the best fitness reaches `options.target_fitness` (0.7), or (our addition) after
///    `options.stall_generations` (60) generations without improvement. Reproducible for
///    `options.random_seed`.
///
/// Fitness is pluggable: any callable `double(const Triangulation_statistics&)`, larger is
/// better. The GA computes the statistics (angles between normals of adjacent triangles, alpha_i;
/// between new and existing triangles, beta_i; triangle shape terms, eq. 7.6) with every
/// triangle's normal and shape term cached for the whole run, so one evaluation is O(n) array
/// work and holes of hundreds of nodes run in a fraction of a second.
/// Two fitness functors are provided: `Smoothness_fitness` (eq. 5.9-5.13, shape prediction)
/// and `Shape_smoothness_fitness` (eq. 7.6-7.9, mesh optimisation).
/// Output triangles are (i, j, k) with i < j < k, which is the polygon's orientation.

#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/Random.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace genetic {

using Chord = std::pair<int, int>;    // (i, j) with i < j
using Triangle = std::array<int, 3>;  // (i, j, k) with i < j < k
constexpr double ga_pi = 3.14159265358979323846;

/// The valid chords of a polygon, in the order of Table 5.2.
struct Chord_table {
  int n = 0;
  std::vector<Chord> chords;  // valid chords, sorted by (i, j)
  std::vector<int> index;     // index[i*n+j] = position in `chords`, -1 when invalid
  bool planar = true;         // validity decided in the projection (else projection-free)
  bool is_valid(int i, int j) const {
    if (i > j) std::swap(i, j);
    if (j == i + 1 || (i == 0 && j == n - 1)) return true;  // polygon edge
    return index[std::size_t(i) * n + j] >= 0;
  }
};

/// What the GA measures on a triangulation; the fitness functor combines it.
struct Triangulation_statistics {
  int n = 0;                   // polygon nodes
  int interior_count = 0;      // chords (n - 3)
  double sum_interior_sq = 0;  // sum (pi - alpha_i)^2, alpha_i angle between adjacent normals
  double min_alpha = 0, max_alpha = 0;
  int boundary_count = 0;      // polygon edges with an existing face across them
  double sum_boundary_sq = 0;  // sum (pi - beta_i)^2
  double min_beta = 0, max_beta = 0;
  int triangle_count = 0;  // n - 2
  double sum_shape = 0;    // sum over triangles of 2/3 pi^2 - sum_j (theta_j - pi/3)^2
};

/// Eq. 5.9-5.13 (thesis 5.4.2): w_a f_internal + w_b f_boundary + w_c (d_alpha + d_beta)/2.
struct Smoothness_fitness {
  double w_internal = 1.0 / 3, w_boundary = 1.0 / 3, w_deviation = 1.0 / 3;
  double operator()(const Triangulation_statistics& s) const {
    const double pi2 = ga_pi * ga_pi;
    const double f_internal =
        s.interior_count > 0 ? s.sum_interior_sq / (s.interior_count * pi2) : 1.0;
    const double f_boundary =
        s.boundary_count > 0 ? s.sum_boundary_sq / (s.boundary_count * pi2) : 1.0;
    const double d_alpha = s.interior_count > 0 ? 1 - (s.max_alpha - s.min_alpha) / ga_pi : 1.0;
    const double d_beta = s.boundary_count > 0 ? 1 - (s.max_beta - s.min_beta) / ga_pi : 1.0;
    return w_internal * f_internal + w_boundary * f_boundary +
           w_deviation * 0.5 * (d_alpha + d_beta);
  }
};

/// Eq. 7.6-7.9 (thesis 7.x), each factor normalised to [0,1]: w_a f_a + w_b f_b + w_c f_c.
struct Shape_smoothness_fitness {
  double w_shape = 1.0 / 3, w_internal = 1.0 / 3, w_boundary = 1.0 / 3;
  double operator()(const Triangulation_statistics& s) const {
    const double pi2 = ga_pi * ga_pi;
    const double f_a = s.triangle_count > 0 ? s.sum_shape / (s.triangle_count * 2.0 / 3 * pi2) : 1;
    const double f_b = s.interior_count > 0 ? s.sum_interior_sq / (s.interior_count * pi2) : 1;
    const double f_c = s.boundary_count > 0 ? s.sum_boundary_sq / (s.boundary_count * pi2) : 1;
    return w_shape * f_a + w_internal * f_b + w_boundary * f_c;
  }
};

struct Ga_options {
  int population_size = 30;
  int max_generations = 500;
  double target_fitness = 0.7;
  unsigned int random_seed = 0;
  int crossover_points = 3;  // multi-point crossover (thesis 5.4.2)
  double crossover_rate = 0.8;
  double mutation_rate = 0.3;  // probability that a child gets 1..3 edge flips
  /// Also stop after this many generations without improvement of the best fitness (0: never).
  /// Not in the thesis: on holes whose seed is far below the target the GA otherwise runs all
  /// 500 generations for a gain of a few thousandths (see doc/shape_prediction.md).
  int stall_generations = 60;
  /// An improvement of the best fitness by less than this does not restart the stall count
  /// (0: every improvement does). On folded holes the best fitness creeps up by thousandths
  /// for dozens of generations; see doc/shape_prediction.md, "GA stall".
  double stall_improvement = 0;
};

struct Ga_result {
  bool found = false;  // false: no triangulation with valid chords exists
  std::vector<Triangle> triangles;
  double fitness = 0;       // of `triangles`
  double seed_fitness = 0;  // of the dynamic-programming seed
  int generations = 0;      // generations run
  Triangulation_statistics statistics;
};

namespace detail {

template <class Kernel>
typename Kernel::Vector_3 newell_normal(const std::vector<typename Kernel::Point_3>& p) {
  double x = 0, y = 0, z = 0;
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % n];
    x += (a.y() - b.y()) * (a.z() + b.z());
    y += (a.z() - b.z()) * (a.x() + b.x());
    z += (a.x() - b.x()) * (a.y() + b.y());
  }
  const double len = std::sqrt(x * x + y * y + z * z);
  if (len == 0) return typename Kernel::Vector_3(0, 0, 1);
  return typename Kernel::Vector_3(x / len, y / len, z / len);
}

template <class Kernel>
typename Kernel::Vector_3 triangle_unit_normal(const typename Kernel::Point_3& a,
                                               const typename Kernel::Point_3& b,
                                               const typename Kernel::Point_3& c) {
  auto v = CGAL::cross_product(b - a, c - a);
  const double len = std::sqrt(CGAL::to_double(v.squared_length()));
  return len > 0 ? v / len : typename Kernel::Vector_3(0, 0, 0);
}

inline double angle_between(double cx, double cy, double cz, double dx, double dy, double dz) {
  const double c = std::max(-1.0, std::min(1.0, cx * dx + cy * dy + cz * dz));
  return std::acos(c);
}

}  // namespace detail

/// Valid chords of the closed polygon `points` (see the header comment).
template <class Kernel>
Chord_table valid_chords(const std::vector<typename Kernel::Point_3>& points,
                         const std::vector<typename Kernel::Vector_3>& vertex_normals = {}) {
  using Point_2 = typename Kernel::Point_2;
  using Point_3 = typename Kernel::Point_3;
  using Segment_2 = typename Kernel::Segment_2;
  using Vector_3 = typename Kernel::Vector_3;
  Kernel kernel;
  const int n = int(points.size());
  Chord_table table;
  table.n = n;
  table.index.assign(std::size_t(n) * n, -1);
  if (n < 4) return table;

  // Projection onto the Newell plane; the polygon is counterclockwise there.
  const Vector_3 normal = detail::newell_normal<Kernel>(points);  // unit
  Vec3 u, v;
  tangent_frame(to_array(normal), u, v, 0.9);
  std::vector<Point_2> q;
  q.reserve(n);
  for (const Point_3& p : points) {
    const Vec3 d = to_array(p - points[0]);
    q.emplace_back(dot(d, u), dot(d, v));
  }
  auto orientation_2 = kernel.orientation_2_object();
  auto do_intersect_2 = kernel.do_intersect_2_object();

  bool simple = true;
  for (int i = 0; i < n && simple; ++i) {
    const Segment_2 ei(q[i], q[(i + 1) % n]);
    if (ei.is_degenerate()) simple = false;
    for (int j = i + 2; j < n && simple; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (do_intersect_2(ei, Segment_2(q[j], q[(j + 1) % n]))) simple = false;
    }
    // Adjacent edges folding back onto each other.
    const Point_2& a = q[i];
    const Point_2& b = q[(i + 1) % n];
    const Point_2& c = q[(i + 2) % n];
    if (simple && orientation_2(a, b, c) == CGAL::COLLINEAR && (b - a) * (c - b) < 0)
      simple = false;
  }
  table.planar = simple;

  auto left_2 = [&](int a, int b, int c) {
    return orientation_2(q[a], q[b], q[c]) == CGAL::LEFT_TURN;
  };
  // Projection-free test: "left" in the tangent plane of the node at which the cone is tested.
  auto orientation_3 = kernel.orientation_3_object();
  std::vector<Point_3> lifted(n);
  for (int i = 0; i < n; ++i) {
    const Vector_3 ni =
        (std::size_t(i) < vertex_normals.size() && vertex_normals[i].squared_length() > 0)
            ? vertex_normals[i]
            : normal;
    lifted[i] = points[i] + ni;
  }
  // O'Rourke's InCone (Computational Geometry in C): is the chord a->b inside the polygon's
  // angle at a? `left(p, q, r)`: r strictly left of p->q; "left or on" is !left(q, p, r).
  auto in_cone = [&](int a, int b, const auto& left) {
    const int prev = (a + n - 1) % n, next = (a + 1) % n;
    const bool convex = !left(next, a, prev);
    if (convex) return left(a, b, prev) && left(b, a, next);
    return !(!left(b, a, next) && !left(a, b, prev));
  };

  for (int i = 0; i < n; ++i) {
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      bool valid;
      if (simple) {
        valid = in_cone(i, j, left_2) && in_cone(j, i, left_2);
        if (valid) {
          const Segment_2 chord(q[i], q[j]);
          for (int k = 0; k < n && valid; ++k) {
            const int k1 = (k + 1) % n;
            if (k == i || k == j || k1 == i || k1 == j) continue;
            if (do_intersect_2(chord, Segment_2(q[k], q[k1]))) valid = false;
          }
        }
      } else {
        auto left_at = [&](int apex) {
          return [&, apex](int a, int b, int c) {
            // c strictly left of a->b seen from the normal at `apex`.
            return orientation_3(points[a], points[b], points[b] + (lifted[apex] - points[apex]),
                                 points[c]) == CGAL::NEGATIVE;
          };
        };
        valid = in_cone(i, j, left_at(i)) && in_cone(j, i, left_at(j));
      }
      if (valid) {
        table.index[std::size_t(i) * n + j] = int(table.chords.size());
        table.chords.emplace_back(i, j);
      }
    }
  }
  return table;
}

namespace detail {

// Caches every triangle's normal and shape term for a whole GA run.
template <class Kernel>
class Triangle_cache {
 public:
  using Point_3 = typename Kernel::Point_3;
  struct Entry {
    double nx, ny, nz, shape;
  };
  explicit Triangle_cache(const std::vector<Point_3>& points) : points_(points) {}
  const Entry& operator()(const Triangle& t) {
    const std::int64_t n = std::int64_t(points_.size());
    const std::int64_t key = (std::int64_t(t[0]) * n + t[1]) * n + t[2];
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    return cache_.emplace(key, compute(t)).first->second;
  }

 private:
  Entry compute(const Triangle& t) const {
    const auto nrm =
        detail::triangle_unit_normal<Kernel>(points_[t[0]], points_[t[1]], points_[t[2]]);
    Entry e{CGAL::to_double(nrm.x()), CGAL::to_double(nrm.y()), CGAL::to_double(nrm.z()), 0};
    double penalty = 0;
    for (int c = 0; c < 3; ++c) {
      const auto a = points_[t[(c + 1) % 3]] - points_[t[c]];
      const auto b = points_[t[(c + 2) % 3]] - points_[t[c]];
      const double la = std::sqrt(CGAL::to_double(a.squared_length()));
      const double lb = std::sqrt(CGAL::to_double(b.squared_length()));
      double theta = 0;  // a degenerate corner
      if (la > 0 && lb > 0)
        theta = std::acos(std::max(-1.0, std::min(1.0, CGAL::to_double(a * b) / (la * lb))));
      penalty += (theta - ga_pi / 3) * (theta - ga_pi / 3);
    }
    e.shape = std::max(0.0, 2.0 / 3 * ga_pi * ga_pi - penalty);
    return e;
  }
  const std::vector<Point_3>& points_;
  std::unordered_map<std::int64_t, Entry> cache_;
};

/// Scratch buffers of `triangles_of`, reused across the calls of a GA run.
struct Triangles_of_scratch {
  std::vector<int> start, fill, neighbours;
};

inline void triangles_of(int n, const std::vector<Chord>& chords, Triangles_of_scratch& scratch,
                         std::vector<Triangle>& triangles) {
  // Adjacency of the outerplanar graph in one array: node v's neighbours are
  // neighbours[start[v] .. start[v + 1]), its two polygon neighbours first.
  std::vector<int>& start = scratch.start;
  std::vector<int>& fill = scratch.fill;
  std::vector<int>& neighbours = scratch.neighbours;
  start.assign(std::size_t(n) + 1, 0);
  for (int i = 0; i < n; ++i) start[i + 1] = 2;
  for (const Chord& c : chords) {
    ++start[c.first + 1];
    ++start[c.second + 1];
  }
  for (int i = 0; i < n; ++i) start[i + 1] += start[i];
  neighbours.resize(std::size_t(start[n]));
  fill.assign(start.begin(), start.end() - 1);
  for (int i = 0; i < n; ++i) {
    neighbours[fill[i]++] = (i + 1) % n;
    neighbours[fill[i]++] = (i + n - 1) % n;
  }
  for (const Chord& c : chords) {
    neighbours[fill[c.first]++] = c.second;
    neighbours[fill[c.second]++] = c.first;
  }
  triangles.clear();
  triangles.reserve(std::size_t(std::max(n - 2, 0)));
  for (int v = 0; v < n; ++v) {
    int* begin = neighbours.data() + start[v];
    int* end = neighbours.data() + start[v + 1];
    std::sort(begin, end, [v, n](int a, int b) { return (a - v + n) % n < (b - v + n) % n; });
    for (int* k = begin; k + 1 < end; ++k) {
      Triangle t{v, k[0], k[1]};
      std::sort(t.begin(), t.end());
      if (t[0] == v) triangles.push_back(t);
    }
  }
}

// Triangles of a complete set of n-3 non-crossing chords of an n-gon (outerplanar graph):
// consecutive neighbours of each node, in polygon order, close a triangle.
inline std::vector<Triangle> triangles_of(int n, const std::vector<Chord>& chords) {
  Triangles_of_scratch scratch;
  std::vector<Triangle> triangles;
  triangles_of(n, chords, scratch, triangles);
  return triangles;
}

// Do chords (a,b) and (c,d) cross? Exact for chords inside a simple polygon: their end indices
// interleave along the boundary.
inline bool interleave(const Chord& x, const Chord& y) {
  const int a = x.first, b = x.second, c = y.first, d = y.second;
  return (a < c && c < b && b < d) || (c < a && a < d && d < b);
}

// Accepts chords one by one unless they cross an accepted one. A chord (a,b) is crossed by an
// accepted chord iff a node k strictly between a and b has a partner beyond b or before a
// (chords never wrap: their ends are sorted), i.e. iff the largest partner over (a,b) exceeds b
// or the smallest is below a: two range queries on segment trees, O(log n) per chord instead of
// a walk over one side of the chord (the GA's crossover adds up to 2(n-3) chords per child).
class Chord_set_builder {
 public:
  explicit Chord_set_builder(int n) : n_(n), partners_(n) {
    while (leaves_ < n_) leaves_ *= 2;
    largest_.assign(2 * std::size_t(leaves_), -1);
    smallest_.assign(2 * std::size_t(leaves_), n_);
  }
  /// Empties the set (keeps the buffers).
  void clear() {
    for (const Chord& c : chords_) {
      for (int k : {c.first, c.second}) {
        partners_[k].clear();
        for (std::size_t i = std::size_t(k) + leaves_; i > 0; i /= 2) {
          largest_[i] = -1;
          smallest_[i] = n_;
        }
      }
    }
    chords_.clear();
  }
  /// A triangulation of the polygon has n - 3 chords: every further chord crosses one.
  bool full() const { return int(chords_.size()) >= n_ - 3; }
  bool try_add(const Chord& c) {
    const int a = c.first, b = c.second;
    for (int w : partners_[a])
      if (w == b) return false;
    if (b - a >= 2 && (range(a + 1, b, true) > b || range(a + 1, b, false) < a)) return false;
    partners_[a].push_back(b);
    partners_[b].push_back(a);
    record(a, b);
    record(b, a);
    chords_.push_back(c);
    return true;
  }
  const std::vector<Chord>& chords() const { return chords_; }

 private:
  void record(int k, int partner) {
    for (std::size_t i = std::size_t(k) + leaves_; i > 0; i /= 2) {
      largest_[i] = std::max(largest_[i], partner);
      smallest_[i] = std::min(smallest_[i], partner);
    }
  }
  /// Largest (or smallest) partner of the nodes in [lo, hi).
  int range(int lo, int hi, bool largest) const {
    const std::vector<int>& tree = largest ? largest_ : smallest_;
    int result = largest ? -1 : n_;
    const auto take = [&](std::size_t i) {
      result = largest ? std::max(result, tree[i]) : std::min(result, tree[i]);
    };
    for (std::size_t l = std::size_t(lo) + leaves_, r = std::size_t(hi) + leaves_; l < r;
         l /= 2, r /= 2) {
      if (l & 1) take(l++);
      if (r & 1) take(--r);
    }
    return result;
  }

  int n_;
  int leaves_ = 1;
  std::vector<std::vector<int>> partners_;
  std::vector<int> largest_, smallest_;  // segment trees over the nodes' partners
  std::vector<Chord> chords_;
};

}  // namespace detail

/// Minimum-dihedral triangulation by dynamic programming, O(n^3) (see the header comment).
template <class Kernel>
std::optional<std::vector<Triangle>> min_dihedral_triangulation(
    const std::vector<typename Kernel::Point_3>& points,
    const std::vector<typename Kernel::Vector_3>& outside_normals, const Chord_table& table) {
  using Vector_3 = typename Kernel::Vector_3;
  const int n = int(points.size());
  if (n < 3) return std::nullopt;
  if (n == 3) return std::vector<Triangle>{Triangle{0, 1, 2}};
  const double infinity = std::numeric_limits<double>::infinity();
  const std::size_t nn = std::size_t(n) * n;
  std::vector<double> cost(nn, infinity);
  std::vector<int> best(nn, -1);
  std::vector<std::array<double, 3>> normal(nn, {0, 0, 0});
  auto at = [n](int i, int k) { return std::size_t(i) * n + k; };
  auto outside = [&](int edge) -> std::array<double, 3> {
    if (std::size_t(edge) >= outside_normals.size()) return {0, 0, 0};
    const Vector_3& v = outside_normals[edge];
    return {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
  };
  // 1 - cos of the angle between two unit normals; no term when one is missing.
  auto bend = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    const double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    const double bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    if (aa == 0 || bb == 0) return 0.0;
    return 1.0 - (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  };
  for (int i = 0; i + 1 < n; ++i) {
    cost[at(i, i + 1)] = 0;
    normal[at(i, i + 1)] = outside(i);
  }
  for (int gap = 2; gap < n; ++gap) {
    for (int i = 0; i + gap < n; ++i) {
      const int k = i + gap;
      if (!table.is_valid(i, k)) continue;
      for (int m = i + 1; m < k; ++m) {
        const double sub = cost[at(i, m)] + cost[at(m, k)];
        if (!(sub < cost[at(i, k)])) continue;
        const auto t = detail::triangle_unit_normal<Kernel>(points[i], points[m], points[k]);
        const std::array<double, 3> tn{CGAL::to_double(t.x()), CGAL::to_double(t.y()),
                                       CGAL::to_double(t.z())};
        // A degenerate triangle bends as much as a fold.
        const bool degenerate = tn[0] == 0 && tn[1] == 0 && tn[2] == 0;
        double c =
            sub + (degenerate ? 4.0 : bend(tn, normal[at(i, m)]) + bend(tn, normal[at(m, k)]));
        if (k - i == n - 1 && !degenerate) c += bend(tn, outside(n - 1));
        if (c < cost[at(i, k)]) {
          cost[at(i, k)] = c;
          best[at(i, k)] = m;
          normal[at(i, k)] = tn;
        }
      }
    }
  }
  if (best[at(0, n - 1)] < 0) return std::nullopt;
  std::vector<Triangle> triangles;
  std::vector<std::pair<int, int>> stack{{0, n - 1}};
  while (!stack.empty()) {
    const auto [i, k] = stack.back();
    stack.pop_back();
    if (k - i < 2) continue;
    const int m = best[at(i, k)];
    triangles.push_back(Triangle{i, m, k});
    stack.emplace_back(i, m);
    stack.emplace_back(m, k);
  }
  return triangles;
}

namespace detail {

template <class Kernel, class Fitness>
class Ga_engine {
 public:
  using Point_3 = typename Kernel::Point_3;
  using Vector_3 = typename Kernel::Vector_3;
  struct Individual {
    std::vector<Chord> chords;  // sorted
    std::vector<Triangle> triangles;
    Triangulation_statistics statistics;
    double fitness = 0;
  };

  Ga_engine(const std::vector<Point_3>& points, const std::vector<Vector_3>& outside_normals,
            const Chord_table& table, const Fitness& fitness, const Ga_options& options)
      : points_(points),
        table_(table),
        fitness_(fitness),
        options_(options),
        n_(int(points.size())),
        cache_(points),
        random_(options.random_seed),
        owner_(std::size_t(n_) * n_, -1),
        builder_(n_) {
    outside_.resize(n_, {0, 0, 0});
    for (int i = 0; i < n_ && std::size_t(i) < outside_normals.size(); ++i)
      outside_[i] = {CGAL::to_double(outside_normals[i].x()),
                     CGAL::to_double(outside_normals[i].y()),
                     CGAL::to_double(outside_normals[i].z())};
  }

  Individual make(std::vector<Triangle> triangles) {
    Individual ind;
    for (Triangle& t : triangles) {
      std::sort(t.begin(), t.end());
      for (int c = 0; c < 3; ++c) {
        const int a = t[c], b = t[(c + 1) % 3];
        Chord ch(std::min(a, b), std::max(a, b));
        if (!is_polygon_edge(ch)) ind.chords.push_back(ch);
      }
    }
    std::sort(ind.chords.begin(), ind.chords.end());
    ind.chords.erase(std::unique(ind.chords.begin(), ind.chords.end()), ind.chords.end());
    ind.triangles = std::move(triangles);
    evaluate(ind);
    return ind;
  }

  Ga_result run(const Individual& seed) {
    Ga_result result;
    result.found = true;
    result.seed_fitness = seed.fitness;
    std::vector<Individual> population{seed};
    const int size = std::max(2, options_.population_size);
    while (int(population.size()) < size) {
      Individual ind = seed;
      const int flips = 1 + random_.get_int(0, std::max(1, n_ / 4));
      for (int f = 0; f < flips; ++f) flip(ind);
      evaluate(ind);
      population.push_back(std::move(ind));
    }
    Individual best = best_of(population);
    int generation = 0, last_improvement = 0;
    double stall_reference = best.fitness;  // the best fitness when the stall count restarted
    while (generation < options_.max_generations && best.fitness < options_.target_fitness &&
           !table_.chords.empty() &&
           (options_.stall_generations <= 0 ||
            generation - last_improvement < options_.stall_generations)) {
      std::vector<Individual> next{best};  // elitism: never worse than the seed
      while (int(next.size()) < size) {
        const Individual& a = tournament(population);
        const Individual& b = tournament(population);
        Individual child = random_.get_double() < options_.crossover_rate ? crossover(a, b) : a;
        if (random_.get_double() < options_.mutation_rate) {
          const int flips = 1 + random_.get_int(0, 3);
          for (int f = 0; f < flips; ++f) flip(child);
        }
        evaluate(child);
        next.push_back(std::move(child));
      }
      population.swap(next);
      const Individual& candidate = best_of(population);
      ++generation;
      if (candidate.fitness > best.fitness) {
        best = candidate;
        if (best.fitness > stall_reference + options_.stall_improvement) {
          last_improvement = generation;
          stall_reference = best.fitness;
        }
      }
    }
    result.triangles = best.triangles;
    result.fitness = best.fitness;
    result.statistics = best.statistics;
    result.generations = generation;
    return result;
  }

 private:
  bool is_polygon_edge(const Chord& c) const {
    return c.second == c.first + 1 || (c.first == 0 && c.second == n_ - 1);
  }

  const Individual& best_of(const std::vector<Individual>& population) const {
    std::size_t b = 0;
    for (std::size_t i = 1; i < population.size(); ++i)
      if (population[i].fitness > population[b].fitness) b = i;
    return population[b];
  }

  const Individual& tournament(const std::vector<Individual>& population) {
    const Individual& a = population[random_.get_int(0, int(population.size()))];
    const Individual& b = population[random_.get_int(0, int(population.size()))];
    return a.fitness >= b.fitness ? a : b;
  }

  // Multi-point crossover on the chromosome of Table 5.2 (bit = valid chord), then a
  // combinatorial repair: chords inherited in random order are kept if they cross no kept chord,
  // the set is completed from both parents; an incomplete child is discarded (thesis: unfit).
  Individual crossover(const Individual& a, const Individual& b) {
    const int length = int(table_.chords.size());
    std::vector<int>& cuts = cuts_;
    cuts.clear();
    for (int c = 0; c < options_.crossover_points; ++c) cuts.push_back(random_.get_int(0, length));
    std::sort(cuts.begin(), cuts.end());
    auto from_a = [&](const Chord& ch) {
      const int bit = table_.index[std::size_t(ch.first) * n_ + ch.second];
      const int segment = int(std::upper_bound(cuts.begin(), cuts.end(), bit) - cuts.begin());
      return segment % 2 == 0;
    };
    std::vector<Chord>& inherited = inherited_;
    std::vector<Chord>& rest = rest_;
    inherited.clear();
    rest.clear();
    for (const Chord& ch : a.chords) (from_a(ch) ? inherited : rest).push_back(ch);
    for (const Chord& ch : b.chords) (!from_a(ch) ? inherited : rest).push_back(ch);
    shuffle(inherited);
    shuffle(rest);
    Chord_set_builder& builder = builder_;
    builder.clear();
    for (const Chord& ch : inherited) {
      if (builder.full()) break;
      builder.try_add(ch);
    }
    for (const Chord& ch : rest) {
      if (builder.full()) break;
      builder.try_add(ch);
    }
    if (int(builder.chords().size()) != n_ - 3) return a;
    Individual child;
    child.chords = builder.chords();
    std::sort(child.chords.begin(), child.chords.end());
    triangles_of(n_, child.chords, triangles_scratch_, child.triangles);
    return child;
  }

  void shuffle(std::vector<Chord>& chords) {
    for (int i = int(chords.size()) - 1; i > 0; --i)
      std::swap(chords[i], chords[random_.get_int(0, i + 1)]);
  }

  // Mutation = edge flip of a random chord, kept only when the new chord is valid.
  void flip(Individual& ind) {
    if (ind.chords.empty()) return;
    const int pick = random_.get_int(0, int(ind.chords.size()));
    const Chord ab = ind.chords[pick];
    int opposite[2], found = 0, slots[2];
    for (int t = 0; t < int(ind.triangles.size()) && found < 2; ++t) {
      const Triangle& tri = ind.triangles[t];
      const bool has_a = tri[0] == ab.first || tri[1] == ab.first || tri[2] == ab.first;
      const bool has_b = tri[0] == ab.second || tri[1] == ab.second || tri[2] == ab.second;
      if (!has_a || !has_b) continue;
      opposite[found] = tri[0] + tri[1] + tri[2] - ab.first - ab.second;
      slots[found++] = t;
    }
    if (found != 2) return;
    const Chord cd(std::min(opposite[0], opposite[1]), std::max(opposite[0], opposite[1]));
    if (is_polygon_edge(cd) || !table_.is_valid(cd.first, cd.second)) return;
    ind.chords[pick] = cd;
    std::sort(ind.chords.begin(), ind.chords.end());
    Triangle t0{cd.first, cd.second, ab.first}, t1{cd.first, cd.second, ab.second};
    std::sort(t0.begin(), t0.end());
    std::sort(t1.begin(), t1.end());
    ind.triangles[slots[0]] = t0;
    ind.triangles[slots[1]] = t1;
  }

  void evaluate(Individual& ind) {
    Triangulation_statistics s;
    s.n = n_;
    s.triangle_count = int(ind.triangles.size());
    s.min_alpha = s.min_beta = ga_pi;
    s.max_alpha = s.max_beta = 0;
    touched_.clear();
    for (int t = 0; t < int(ind.triangles.size()); ++t) {
      const Triangle& tri = ind.triangles[t];
      const auto& e = cache_(tri);
      s.sum_shape += e.shape;
      const int edges[3][2] = {{tri[0], tri[1]}, {tri[1], tri[2]}, {tri[0], tri[2]}};
      for (const auto& edge : edges) {
        const Chord ch(edge[0], edge[1]);
        if (is_polygon_edge(ch)) {
          const int index = ch.second == ch.first + 1 ? ch.first : n_ - 1;
          const auto& o = outside_[index];
          if (o[0] == 0 && o[1] == 0 && o[2] == 0) continue;
          const double beta = angle_between(e.nx, e.ny, e.nz, o[0], o[1], o[2]);
          add(beta, s.boundary_count, s.sum_boundary_sq, s.min_beta, s.max_beta);
          continue;
        }
        const std::size_t key = std::size_t(ch.first) * n_ + ch.second;
        if (owner_[key] < 0) {
          owner_[key] = t;
          touched_.push_back(key);
          continue;
        }
        const auto& f = cache_(ind.triangles[owner_[key]]);
        const double alpha = angle_between(e.nx, e.ny, e.nz, f.nx, f.ny, f.nz);
        add(alpha, s.interior_count, s.sum_interior_sq, s.min_alpha, s.max_alpha);
      }
    }
    for (std::size_t key : touched_) owner_[key] = -1;
    if (s.interior_count == 0) s.min_alpha = 0;
    if (s.boundary_count == 0) s.min_beta = 0;
    ind.statistics = s;
    ind.fitness = fitness_(s);
  }

  static void add(double angle, int& count, double& sum_sq, double& lo, double& hi) {
    ++count;
    sum_sq += (ga_pi - angle) * (ga_pi - angle);
    lo = std::min(lo, angle);
    hi = std::max(hi, angle);
  }

  const std::vector<Point_3>& points_;
  const Chord_table& table_;
  const Fitness& fitness_;
  Ga_options options_;
  int n_;
  Triangle_cache<Kernel> cache_;
  CGAL::Random random_;
  std::vector<std::array<double, 3>> outside_;
  std::vector<int> owner_;
  std::vector<std::size_t> touched_;
  // Buffers of `crossover`, reused across children.
  detail::Chord_set_builder builder_;
  detail::Triangles_of_scratch triangles_scratch_;
  std::vector<Chord> inherited_, rest_;
  std::vector<int> cuts_;
};

}  // namespace detail

/// Evaluates `fitness` on a given triangulation (for comparisons and tests).
template <class Kernel, class Fitness>
double evaluate_triangulation(const std::vector<typename Kernel::Point_3>& points,
                              const std::vector<typename Kernel::Vector_3>& outside_normals,
                              const Chord_table& table, const std::vector<Triangle>& triangles,
                              const Fitness& fitness) {
  detail::Ga_engine<Kernel, Fitness> engine(points, outside_normals, table, fitness, Ga_options());
  return engine.make(triangles).fitness;
}

/// The GA of thesis 5.4 (see the header comment). `result.found` is false when the polygon has
/// no triangulation with valid chords.
template <class Kernel, class Fitness>
Ga_result ga_triangulate(const std::vector<typename Kernel::Point_3>& points,
                         const std::vector<typename Kernel::Vector_3>& outside_normals,
                         const Chord_table& table, const Fitness& fitness,
                         const Ga_options& options = Ga_options()) {
  auto seed = min_dihedral_triangulation<Kernel>(points, outside_normals, table);
  if (!seed) return Ga_result();
  detail::Ga_engine<Kernel, Fitness> engine(points, outside_normals, table, fitness, options);
  return engine.run(engine.make(std::move(*seed)));
}

/// Every triangulation with valid chords of a small polygon, best `fitness` first (our
/// addition, used by `optimize_mesh` for regions of at most a handful of nodes). An n-gon has
/// Catalan(n - 2) triangulations (2, 5, 14, 42 for n = 4..7): for such polygons enumerating them
/// all costs fewer fitness evaluations than one GA run, and its first entry is the optimum the
/// GA converges to (the GA searches the same space of valid chord sets with the same fitness).
/// Empty when no triangulation with valid chords exists. Does not change `ga_triangulate`.
template <class Kernel, class Fitness>
std::vector<std::pair<double, std::vector<Triangle>>> all_triangulations_by_fitness(
    const std::vector<typename Kernel::Point_3>& points,
    const std::vector<typename Kernel::Vector_3>& outside_normals, const Chord_table& table,
    const Fitness& fitness) {
  std::vector<std::pair<double, std::vector<Triangle>>> result;
  const int n = int(points.size());
  if (n < 3) return result;
  // Triangulations of the sub-polygon i..k closed by the (valid) chord or edge (i, k).
  auto enumerate = [&](auto&& self, int i, int k) -> std::vector<std::vector<Triangle>> {
    if (k - i < 2) return {std::vector<Triangle>()};
    std::vector<std::vector<Triangle>> all;
    for (int m = i + 1; m < k; ++m) {
      if (!table.is_valid(i, m) || !table.is_valid(m, k)) continue;
      const auto left = self(self, i, m);
      if (left.empty()) continue;
      const auto right = self(self, m, k);
      for (const auto& l : left)
        for (const auto& r : right) {
          std::vector<Triangle> t = l;
          t.insert(t.end(), r.begin(), r.end());
          t.push_back(Triangle{i, m, k});
          all.push_back(std::move(t));
        }
    }
    return all;
  };
  std::vector<std::vector<Triangle>> all = enumerate(enumerate, 0, n - 1);
  if (all.empty()) return result;
  detail::Ga_engine<Kernel, Fitness> engine(points, outside_normals, table, fitness, Ga_options());
  for (auto& triangles : all) {
    const double f = engine.make(triangles).fitness;
    result.emplace_back(f, std::move(triangles));
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  return result;
}

}  // namespace genetic
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_GENETIC_GA_TRIANGULATION_H
