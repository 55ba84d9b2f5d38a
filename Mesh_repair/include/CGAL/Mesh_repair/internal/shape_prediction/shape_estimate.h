// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_SHAPE_ESTIMATE_H
#define CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_SHAPE_ESTIMATE_H

// The shape estimate of a hole (thesis 5.3-5.5), independent of any mesh type: boundary
// smoothing (eq. 5.1), rough-set simplification (5.3.2, Table 5.1, eq. 5.6-5.7), GA initial
// triangulation of the essential nodes (5.4), reinsertion of the removed nodes, and the network
// of quartic Bezier patches over the resulting triangulation (5.5).

#include <CGAL/Mesh_repair/internal/genetic/ga_triangulation.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/bezier_patches.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace shape_prediction {

/// A hole's border polygon, in the order of its border halfedges.
template <class Kernel>
struct Hole_polygon {
  std::vector<typename Kernel::Point_3> points;
  std::vector<typename Kernel::Vector_3> normals;       ///< at each node (unit), for the patches
  std::vector<typename Kernel::Vector_3> face_normals;  ///< eq. 5.30 at each node (unit), for
                                                        ///< the chord validity of the GA
  std::vector<typename Kernel::Vector_3> outside;       ///< unit normal of the face across edge
                                                        ///< (i, i+1); null vector when none
};

struct Shape_estimate_options {
  int smoothing_iterations = 1;            ///< eq. 5.1 passes; positions drive the GA only
  bool simplify = true;                    ///< rough-set simplification (5.3.2)
  double simplification_tolerance = 0.05;  ///< max removed-node distance / essential chord
  genetic::Ga_options ga;
  genetic::Smoothness_fitness fitness;
};

template <class Kernel>
struct Shape_estimate {
  bool ok = false;
  std::string failure;
  std::vector<int> essential;                ///< nodes that entered the GA
  genetic::Ga_result ga;                     ///< over the essential nodes
  std::vector<genetic::Triangle> triangles;  ///< over all nodes (removed ones reinserted)
  std::optional<Bezier_patch_network<Kernel>> patches;
};

/// Eq. 5.1, `iterations` synchronous passes: B' = ((A + C)/2 + B)/2.
template <class Kernel>
std::vector<typename Kernel::Point_3> smooth_boundary(
    const std::vector<typename Kernel::Point_3>& points, int iterations) {
  std::vector<typename Kernel::Point_3> current = points, next = points;
  const std::size_t n = points.size();
  for (int it = 0; it < iterations && n >= 3; ++it) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto& a = current[(i + n - 1) % n];
      const auto& c = current[(i + 1) % n];
      next[i] = CGAL::midpoint(CGAL::midpoint(a, c), current[i]);
    }
    current.swap(next);
  }
  return current;
}

/// Table 5.1 sub-range of the principal angle alpha (degrees): 1 = very large ... 5 = very small.
inline int alpha_class(double alpha) {
  if (alpha > 165) return 1;
  if (alpha > 120) return 2;
  if (alpha > 90) return 3;
  if (alpha > 45) return 4;
  return 5;
}

/// Table 5.1 sub-range of the normal deviation beta (degrees): 5 = very small ... 1 = very large.
inline int beta_class(double beta) {
  if (beta < 15) return 5;
  if (beta < 30) return 4;
  if (beta < 60) return 3;
  if (beta < 90) return 2;
  return 1;
}

/// Eq. 5.6: is (alpha_a, beta_b) in D_Remove? Every other pair is in D_Preserve (eq. 5.7).
inline bool in_d_remove(int a, int b) {
  static const int remove[][2] = {{1, 5}, {1, 4}, {1, 3}, {1, 2}, {2, 5}, {3, 2}, {3, 1},
                                  {4, 2}, {4, 1}, {5, 5}, {5, 4}, {5, 2}, {5, 1}};
  for (const auto& r : remove)
    if (r[0] == a && r[1] == b) return true;
  return false;
}

namespace detail {

template <class Vector_3>
double angle_degrees(const Vector_3& a, const Vector_3& b) {
  const double la = std::sqrt(CGAL::to_double(a.squared_length()));
  const double lb = std::sqrt(CGAL::to_double(b.squared_length()));
  if (la == 0 || lb == 0) return 0;
  const double c = std::clamp(CGAL::to_double(a * b) / (la * lb), -1.0, 1.0);
  return std::acos(c) * 180.0 / genetic::ga_pi;
}

// Squared distance from p to the segment [a, b].
template <class Point_3>
double distance_to_chord(const Point_3& p, const Point_3& a, const Point_3& b) {
  const auto ab = b - a;
  const double l2 = CGAL::to_double(ab.squared_length());
  double t = l2 > 0 ? CGAL::to_double((p - a) * ab) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, a + t * ab)));
}

}  // namespace detail

/// Rough-set classification (5.3.2): true for the nodes to preserve. alpha is the angle between
/// the two border edges at the node, beta the angle between the normals of the two border
/// faces at it.
template <class Kernel>
std::vector<bool> rough_set_preserved(const Hole_polygon<Kernel>& hole,
                                      const std::vector<typename Kernel::Point_3>& points) {
  const std::size_t n = points.size();
  std::vector<bool> preserve(n, true);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
    const double alpha = detail::angle_degrees(points[prev] - points[i], points[next] - points[i]);
    const auto& fa = hole.outside[prev];
    const auto& fb = hole.outside[i];
    const bool both = fa.squared_length() > 0 && fb.squared_length() > 0;
    const double beta = both ? detail::angle_degrees(fa, fb) : 0;
    preserve[i] = !in_d_remove(alpha_class(alpha), beta_class(beta));
  }
  return preserve;
}

/// The essential nodes: the rough-set preserved ones, plus (our guard, see
/// doc/shape_prediction.md) the farthest removed node of any run that strays more than
/// `tolerance` times its chord from the chord between its essential ends, recursively, and at
/// least three nodes spread along the border.
template <class Kernel>
std::vector<int> essential_nodes(const std::vector<typename Kernel::Point_3>& points,
                                 std::vector<bool> preserve, double tolerance) {
  const int n = int(points.size());
  int kept = int(std::count(preserve.begin(), preserve.end(), true));
  if (kept < 3) {
    for (int k = 0; k < 3; ++k) preserve[(k * n) / 3] = true;
  }
  bool changed = true;
  while (changed) {
    changed = false;
    std::vector<int> ess;
    for (int i = 0; i < n; ++i)
      if (preserve[i]) ess.push_back(i);
    for (std::size_t k = 0; k < ess.size(); ++k) {
      const int a = ess[k], b = ess[(k + 1) % ess.size()];
      const double chord = std::sqrt(CGAL::to_double(CGAL::squared_distance(points[a], points[b])));
      int worst = -1;
      double worst_distance = tolerance * chord;
      for (int i = (a + 1) % n; i != b; i = (i + 1) % n) {
        const double d = detail::distance_to_chord(points[i], points[a], points[b]);
        if (d > worst_distance) {
          worst_distance = d;
          worst = i;
        }
      }
      if (worst >= 0) {
        preserve[worst] = true;
        changed = true;
      }
    }
  }
  std::vector<int> ess;
  for (int i = 0; i < n; ++i)
    if (preserve[i]) ess.push_back(i);
  return ess;
}

namespace detail {

// The GA triangle over essential nodes (a, b, c), with the removed nodes of its border edges
// put back, triangulated by the minimum-dihedral dynamic program (a fan when that fails).
template <class Kernel>
void reinsert_removed(const Hole_polygon<Kernel>& hole, const std::vector<int>& essential,
                      const genetic::Triangle& t, std::vector<genetic::Triangle>& out) {
  using Vector_3 = typename Kernel::Vector_3;
  const int n = int(hole.points.size()), m = int(essential.size());
  std::vector<int> polygon;
  std::vector<Vector_3> outside;
  auto append_edge = [&](int from, int to) {  // essential indices, polygon edge or chord
    const bool border = to == (from + 1) % m;
    const int a = essential[from], b = essential[to];
    if (!border) {
      polygon.push_back(a);
      outside.push_back(Vector_3(0, 0, 0));
      return;
    }
    for (int i = a; i != b; i = (i + 1) % n) {
      polygon.push_back(i);
      outside.push_back(hole.outside[i]);
    }
  };
  // Triangles of the GA are (i < j < k), counterclockwise along the polygon order.
  append_edge(t[0], t[1]);
  append_edge(t[1], t[2]);
  append_edge(t[2], t[0]);
  if (polygon.size() == 3) {
    out.push_back({polygon[0], polygon[1], polygon[2]});
    return;
  }
  std::vector<typename Kernel::Point_3> points;
  for (int i : polygon) points.push_back(hole.points[i]);
  const auto table = genetic::valid_chords<Kernel>(points);
  const auto local = genetic::min_dihedral_triangulation<Kernel>(points, outside, table);
  if (local) {
    for (const auto& lt : *local) out.push_back({polygon[lt[0]], polygon[lt[1]], polygon[lt[2]]});
    return;
  }
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
    out.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

}  // namespace detail

/// Builds the shape estimate of `hole` (thesis 5.3-5.5).
template <class Kernel>
Shape_estimate<Kernel> estimate_shape(const Hole_polygon<Kernel>& hole,
                                      const Shape_estimate_options& options) {
  using Point_3 = typename Kernel::Point_3;
  using Vector_3 = typename Kernel::Vector_3;
  Shape_estimate<Kernel> estimate;
  const int n = int(hole.points.size());
  if (n < 3) {
    estimate.failure = "border cycle with fewer than 3 nodes";
    return estimate;
  }
  const std::vector<Point_3> smoothed =
      smooth_boundary<Kernel>(hole.points, options.smoothing_iterations);
  std::vector<bool> preserve(n, true);
  if (options.simplify) preserve = rough_set_preserved(hole, smoothed);
  estimate.essential =
      essential_nodes<Kernel>(smoothed, preserve, options.simplification_tolerance);

  auto run_ga = [&](const std::vector<int>& essential) {
    std::vector<Point_3> points;
    std::vector<Vector_3> normals, outside;
    const int m = int(essential.size());
    for (int k = 0; k < m; ++k) {
      points.push_back(smoothed[essential[k]]);
      normals.push_back(hole.face_normals.empty() ? hole.normals[essential[k]]
                                                  : hole.face_normals[essential[k]]);
      // The existing faces across a run of removed edges: their mean normal.
      Vector_3 sum(0, 0, 0);
      for (int i = essential[k]; i != essential[(k + 1) % m]; i = (i + 1) % n)
        sum = sum + hole.outside[i];
      const double l = std::sqrt(CGAL::to_double(sum.squared_length()));
      outside.push_back(l > 0 ? sum / l : sum);
    }
    const auto table = genetic::valid_chords<Kernel>(points, normals);
    return genetic::ga_triangulate<Kernel>(points, outside, table, options.fitness, options.ga);
  };
  estimate.ga = run_ga(estimate.essential);
  if (!estimate.ga.found && int(estimate.essential.size()) < n) {
    // The simplified polygon may self-overlap where the full one does not.
    estimate.essential.resize(n);
    for (int i = 0; i < n; ++i) estimate.essential[i] = i;
    estimate.ga = run_ga(estimate.essential);
  }
  if (!estimate.ga.found) {
    estimate.failure = "no triangulation of the border polygon with valid chords";
    return estimate;
  }
  for (const auto& t : estimate.ga.triangles)
    detail::reinsert_removed(hole, estimate.essential, t, estimate.triangles);
  estimate.patches.emplace(hole.points, hole.normals, estimate.triangles);
  estimate.ok = true;
  return estimate;
}

}  // namespace shape_prediction
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_SHAPE_ESTIMATE_H
