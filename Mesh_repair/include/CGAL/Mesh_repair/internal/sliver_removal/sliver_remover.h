// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SLIVER_REMOVAL_SLIVER_REMOVER_H
#define CGAL_MESH_REPAIR_INTERNAL_SLIVER_REMOVAL_SLIVER_REMOVER_H

// Element reconstruction of thesis 4.5: slivers (shape factor f below the threshold, eq. 4.13-4.14)
// with an edge shorter than the tolerance edge length are removed by merging the nodes of that
// edge (Figure 4.13), the others by swapping their longest edge (Figure 4.14). Feature edges
// (dihedral angle below the feature angle) and border edges are kept. Every change is checked
// exactly before it is made (local_checks.h), so a refused change leaves the mesh untouched.

#include <CGAL/Mesh_repair/sliver_result.h>
#include <CGAL/Mesh_repair/internal/sliver_removal/local_checks.h>
#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

struct Sliver_settings {
  double shape_factor_threshold = 0.7;
  double tolerance_edge_length = -1;  ///< negative: a quarter of the mean edge length
  double feature_angle_deg = 135;
  int max_passes = 5;
};

template <class TriangleMesh, class VertexPointMap, class GeomTraits, class Visitor>
class Sliver_remover {
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;
  using Point = typename GeomTraits::Point_3;
  using Vector = typename GeomTraits::Vector_3;
  using Triangle = Labelled_triangle<vertex_descriptor, Point>;

 public:
  Sliver_remover(TriangleMesh& tm, VertexPointMap vpm, const GeomTraits& gt,
                 const Sliver_settings& settings, Visitor& visitor)
      : tm_(tm), vpm_(vpm), gt_(gt), settings_(settings), visitor_(visitor) {}

  Sliver_result run() {
    result_.shape_factor_threshold = settings_.shape_factor_threshold;
    result_.feature_angle_deg = settings_.feature_angle_deg;
    result_.tolerance_edge_length = settings_.tolerance_edge_length >= 0
                                        ? settings_.tolerance_edge_length
                                        : 0.25 * mean_edge_length();
    result_.slivers_before = count_slivers(&result_.min_shape_factor_before);
    visitor_.start_step("slivers");
    for (int pass = 0; pass < settings_.max_passes; ++pass) {
      if (!visitor_.progress(double(pass) / settings_.max_passes)) {
        result_.cancelled = true;
        break;
      }
      if (reconstruction_pass() == 0) break;
    }
    visitor_.end_step("slivers");
    result_.slivers_after = count_slivers(&result_.min_shape_factor_after);
    return result_;
  }

 private:
  // ---- measures ---------------------------------------------------------------------------------

  // The map's own reference type: a point map that converts (OpenMesh's stores OpenMesh::Vec3d)
  // returns a Point by value, and `const Point&` would dangle.
  typename boost::property_traits<VertexPointMap>::reference point(vertex_descriptor v) const {
    return get(vpm_, v);
  }

  double length(halfedge_descriptor h) const {
    return std::sqrt(
        CGAL::to_double(CGAL::squared_distance(point(source(h, tm_)), point(target(h, tm_)))));
  }

  double mean_edge_length() const {
    double sum = 0;
    std::size_t count = 0;
    for (auto e : edges(tm_)) {
      sum += length(halfedge(e, tm_));
      ++count;
    }
    return count ? sum / double(count) : 0.0;
  }

  double face_shape_factor(halfedge_descriptor h) const {
    return shape_factor(point(source(h, tm_)), point(target(h, tm_)),
                        point(target(next(h, tm_), tm_)));
  }

  bool is_sliver(face_descriptor f) const {
    return face_shape_factor(halfedge(f, tm_)) < settings_.shape_factor_threshold;
  }

  std::size_t count_slivers(double* min_shape_factor) const {
    std::size_t count = 0;
    *min_shape_factor = 1;
    for (face_descriptor f : faces(tm_)) {
      const double value = face_shape_factor(halfedge(f, tm_));
      *min_shape_factor = std::min(*min_shape_factor, value);
      if (value < settings_.shape_factor_threshold) ++count;
    }
    return count;
  }

  Vector face_normal(halfedge_descriptor h) const {
    return CGAL::cross_product(point(target(h, tm_)) - point(source(h, tm_)),
                               point(target(next(h, tm_), tm_)) - point(source(h, tm_)));
  }

  /// Feature edge (thesis 4.5): a border edge, or the angle between its two faces, measured
  /// through the material (180 degrees when flat), below the feature angle.
  bool is_feature(halfedge_descriptor h) const {
    if (is_border_edge(h, tm_)) return true;
    const Vector n1 = face_normal(h), n2 = face_normal(opposite(h, tm_));
    const double l1 = std::sqrt(CGAL::to_double(n1.squared_length()));
    const double l2 = std::sqrt(CGAL::to_double(n2.squared_length()));
    if (l1 == 0 || l2 == 0) return false;  // a degenerate face has no meaningful angle
    const double cosine = std::clamp(CGAL::to_double(n1 * n2) / (l1 * l2), -1.0, 1.0);
    const double face_angle_deg = 180.0 - std::acos(cosine) * 180.0 / CGAL_PI;
    return face_angle_deg < settings_.feature_angle_deg;
  }

  /// Number of feature edges at `v`, not counting the edge of `except`.
  int feature_degree(vertex_descriptor v, halfedge_descriptor except) const {
    int count = 0;
    for (halfedge_descriptor h : halfedges_around_target(v, tm_))
      if (edge(h, tm_) != edge(except, tm_) && is_feature(h)) ++count;
    return count;
  }

  // ---- one pass over the slivers, worst first -------------------------------------------------

  std::size_t reconstruction_pass() {
    std::vector<std::pair<double, face_descriptor>> slivers;
    for (face_descriptor f : faces(tm_)) {
      const double value = face_shape_factor(halfedge(f, tm_));
      if (value < settings_.shape_factor_threshold) slivers.emplace_back(value, f);
    }
    std::sort(slivers.begin(), slivers.end());
    std::set<face_descriptor> touched;  // changed or gone in this pass
    std::size_t changes = 0;
    for (const auto& [value, f] : slivers) {
      if (touched.count(f) || !is_sliver(f)) continue;
      if (reconstruct(f, touched)) ++changes;
    }
    return changes;
  }

  /// Figure 4.13 when the shortest edge is below the tolerance, Figure 4.14 otherwise.
  bool reconstruct(face_descriptor f, std::set<face_descriptor>& touched) {
    std::array<halfedge_descriptor, 3> h = {halfedge(f, tm_), next(halfedge(f, tm_), tm_),
                                            prev(halfedge(f, tm_), tm_)};
    std::sort(h.begin(), h.end(),
              [&](halfedge_descriptor x, halfedge_descriptor y) { return length(x) < length(y); });
    if (length(h[0]) < result_.tolerance_edge_length) return collapse_short_edge(h[0], touched);
    const halfedge_descriptor longest = h[2];
    if (!is_feature(longest)) return flip(longest, touched);
    // Figure 4.14(c): the long edge is kept; the apex goes onto one of its ends instead.
    for (halfedge_descriptor side : {h[0], h[1]})
      if (!is_feature(side) && collapse_onto_long_edge(side, longest, touched)) return true;
    ++result_.kept_for_features;
    return false;
  }

  /// Collapses `side` (an edge from the apex to an end of the kept edge `kept`) moving the apex
  /// onto that end.
  bool collapse_onto_long_edge(halfedge_descriptor side, halfedge_descriptor kept,
                               std::set<face_descriptor>& touched) {
    const vertex_descriptor end_on_kept =
        (source(side, tm_) == source(kept, tm_) || source(side, tm_) == target(kept, tm_))
            ? source(side, tm_)
            : target(side, tm_);
    return try_collapse(side, point(end_on_kept), touched);
  }

  /// Figure 4.13: the two nodes of the short edge merge; a node on a feature line (or the
  /// border) keeps its position, otherwise they meet at the midpoint.
  bool collapse_short_edge(halfedge_descriptor h, std::set<face_descriptor>& touched) {
    const vertex_descriptor p = source(h, tm_), q = target(h, tm_);
    const int features_p = feature_degree(p, h), features_q = feature_degree(q, h);
    Point target_point = CGAL::midpoint(point(p), point(q));
    if (features_p > 0 && features_q > 0) {
      // Both ends on features: only a collapse along a feature line keeps the features.
      if (!is_feature(h)) {
        ++result_.kept_for_features;
        return false;
      }
      target_point = features_p >= features_q ? point(p) : point(q);
    } else if (features_p > 0) {
      target_point = point(p);
    } else if (features_q > 0) {
      target_point = point(q);
    }
    return try_collapse(h, target_point, touched);
  }

  std::vector<face_descriptor> faces_around(vertex_descriptor v) const {
    std::vector<face_descriptor> around;
    for (halfedge_descriptor g : halfedges_around_target(v, tm_))
      if (!is_border(g, tm_)) around.push_back(face(g, tm_));
    return around;
  }

  Triangle labelled(face_descriptor f) const {
    Triangle t;
    int k = 0;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, tm_), tm_)) {
      t.vertex[k] = v;
      t.point[k] = point(v);
      if (++k == 3) break;
    }
    return t;
  }

  /// Triangles around `centre` faces (two rings), except those in `skip`.
  std::vector<Triangle> neighbourhood(const std::vector<face_descriptor>& centre,
                                      const std::set<face_descriptor>& skip) const {
    std::set<face_descriptor> ring(centre.begin(), centre.end());
    for (int step = 0; step < 2; ++step) {
      std::set<face_descriptor> grown = ring;
      for (face_descriptor f : ring)
        for (vertex_descriptor v : vertices_around_face(halfedge(f, tm_), tm_))
          for (face_descriptor g : faces_around(v)) grown.insert(g);
      ring.swap(grown);
    }
    std::vector<Triangle> triangles;
    for (face_descriptor f : ring)
      if (!skip.count(f)) triangles.push_back(labelled(f));
    return triangles;
  }

  bool count_refusal(Local_check check) {
    if (check == Local_check::self_intersection)
      ++result_.refused_self_intersection;
    else if (check != Local_check::ok)
      ++result_.refused_fold;
    return check == Local_check::ok;
  }

  /// Collapses the edge of `h` to `target_point` if the exact checks pass.
  bool try_collapse(halfedge_descriptor h, const Point& target_point,
                    std::set<face_descriptor>& touched) {
    const vertex_descriptor p = source(h, tm_), q = target(h, tm_);
    const bool interior_edge = !is_border_edge(h, tm_);
    if (!CGAL::Euler::does_satisfy_link_condition(edge(h, tm_), tm_) ||
        (interior_edge && is_border(p, tm_) && is_border(q, tm_))) {
      ++result_.refused_topology;
      return false;
    }
    std::set<face_descriptor> vanishing;
    if (!is_border(h, tm_)) vanishing.insert(face(h, tm_));
    if (!is_border(opposite(h, tm_), tm_)) vanishing.insert(face(opposite(h, tm_), tm_));
    std::vector<face_descriptor> changed;
    for (vertex_descriptor v : {p, q})
      for (face_descriptor g : faces_around(v))
        if (!vanishing.count(g) && std::find(changed.begin(), changed.end(), g) == changed.end())
          changed.push_back(g);
    std::vector<Triangle> created;
    std::vector<Vector> reference;
    for (face_descriptor g : changed) {
      Triangle t = labelled(g);
      for (int k = 0; k < 3; ++k) {
        if (t.vertex[k] == p || t.vertex[k] == q) {
          t.vertex[k] = q;  // Euler::collapse_edge keeps the target
          t.point[k] = target_point;
        }
      }
      created.push_back(t);
      reference.push_back(face_normal(halfedge(g, tm_)));
    }
    std::set<face_descriptor> skip(changed.begin(), changed.end());
    skip.insert(vanishing.begin(), vanishing.end());
    if (!count_refusal(check_new_triangles(created, reference, neighbourhood(changed, skip), gt_)))
      return false;
    for (face_descriptor g : vanishing) touched.insert(g);
    const vertex_descriptor kept = CGAL::Euler::collapse_edge(edge(h, tm_), tm_);
    put(vpm_, kept, target_point);
    ++result_.collapsed;
    return true;
  }

  /// Figure 4.14(b): swaps the edge of `h` if it raises the worst shape factor of its two faces
  /// and passes the exact checks; the new edge must not be a new crease.
  bool flip(halfedge_descriptor h, std::set<face_descriptor>& touched) {
    const halfedge_descriptor o = opposite(h, tm_);
    const vertex_descriptor a = source(h, tm_), b = target(h, tm_);
    const vertex_descriptor c = target(next(h, tm_), tm_), d = target(next(o, tm_), tm_);
    if (c == d || halfedge(c, d, tm_).second) {
      ++result_.refused_topology;
      return false;
    }
    const double before = std::min(face_shape_factor(h), face_shape_factor(o));
    const double after = std::min(shape_factor(point(c), point(a), point(d)),
                                  shape_factor(point(d), point(b), point(c)));
    if (after <= before) {
      ++result_.refused_no_improvement;
      return false;
    }
    const Vector reference = face_normal(h) + face_normal(o);
    std::vector<Triangle> created = {Triangle{{c, a, d}, {point(c), point(a), point(d)}},
                                     Triangle{{d, b, c}, {point(d), point(b), point(c)}}};
    const std::vector<face_descriptor> changed = {face(h, tm_), face(o, tm_)};
    const std::set<face_descriptor> skip(changed.begin(), changed.end());
    if (!count_refusal(check_new_triangles(created, std::vector<Vector>{reference, reference},
                                           neighbourhood(changed, skip), gt_)))
      return false;
    if (new_crease(created)) {
      ++result_.kept_for_features;
      return false;
    }
    touched.insert(changed.begin(), changed.end());
    CGAL::Euler::flip_edge(h, tm_);
    ++result_.flipped;
    return true;
  }

  bool new_crease(const std::vector<Triangle>& created) const {
    auto normal = [](const Triangle& t) {
      return CGAL::cross_product(t.point[1] - t.point[0], t.point[2] - t.point[0]);
    };
    const Vector n1 = normal(created[0]), n2 = normal(created[1]);
    const double cosine = CGAL::to_double(n1 * n2) /
                          std::sqrt(CGAL::to_double(n1.squared_length() * n2.squared_length()));
    return 180.0 - std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / CGAL_PI <
           settings_.feature_angle_deg;
  }

  TriangleMesh& tm_;
  VertexPointMap vpm_;
  GeomTraits gt_;
  Sliver_settings settings_;
  Visitor& visitor_;
  Sliver_result result_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SLIVER_REMOVAL_SLIVER_REMOVER_H
