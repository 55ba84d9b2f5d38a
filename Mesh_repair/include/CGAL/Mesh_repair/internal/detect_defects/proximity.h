// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_PROXIMITY_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_PROXIMITY_H

// Small gaps and T-junctions (thesis Table 4.1 row 2, sections 4.2-4.3): border vertices close
// to another border vertex, or to the interior of another border edge. One kd-tree of the
// border vertices answers both, through fuzzy-sphere range queries: no quadratic pass. The
// output itself can be quadratic (a self-overlapping star polygon whose long edges give a large
// derived tolerance: 1.77 M gaps on 5000 vertices), so both lists stop at a pair limit
// (internal/bounded_pairs.h).

#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/detect_defects/border_cycles.h>

#include <CGAL/Kd_tree.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <memory>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

/// A border vertex occurrence: where it is on which cycle.
template <class Access>
struct Border_vertex {
  typename Access::vertex_descriptor vertex;
  typename Access::Point point;
  std::size_t cycle = 0;
  std::size_t rank = 0;   ///< position along the cycle
  double arc_length = 0;  ///< from the cycle's first vertex
};

template <class Access>
class Border_proximity {
 public:
  using Point = typename Access::Point;
  using halfedge_descriptor = typename Access::halfedge_descriptor;
  using Point_map = CGAL::Pointer_property_map<Point>;
  using Base_traits = CGAL::Search_traits_3<typename Access::Traits>;
  using Traits = CGAL::Search_traits_adapter<std::size_t, typename Point_map::type, Base_traits>;
  using Tree = CGAL::Kd_tree<Traits>;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;

  Border_proximity(const Access& mesh,
                   const std::vector<Cycle_halfedges<halfedge_descriptor>>& cycles,
                   const std::vector<Border_cycle>& descriptions)
      : mesh_(mesh), cycles_(cycles), descriptions_(descriptions) {
    for (std::size_t c = 0; c < cycles.size(); ++c) {
      double arc = 0;
      for (std::size_t r = 0; r < cycles[c].size(); ++r) {
        const auto v = source(cycles[c][r], mesh.pm);
        border_.push_back({v, mesh.point(v), c, r, arc});
        points_.push_back(mesh.point(v));
        arc += edge_length(cycles[c][r]);
      }
    }
    std::vector<std::size_t> keys(points_.size());
    for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = i;
    tree_ = std::make_unique<Tree>(keys.begin(), keys.end(), typename Tree::Splitter(),
                                   Traits(CGAL::make_property_map(points_)));
    tree_->build();
  }

  /// Mean length of the border edges, or 0 without border.
  double mean_border_edge_length() const {
    double total = 0;
    std::size_t count = 0;
    for (const auto& d : descriptions_) {
      total += d.perimeter;
      count += d.edges;
    }
    return count > 0 ? total / double(count) : 0.0;
  }

  /// Border vertex pairs closer than `tolerance`, from different cycles or, on one cycle,
  /// farther apart along it than twice the tolerance. Pairs joined by a mesh edge are not gaps,
  /// nor coincident pairs at `non_manifold_points` (they are reported as non-manifold vertices:
  /// closing that "gap" would pinch the surface). At most `limit` pairs (0: the default
  /// limit of the border vertex count).
  Bounded_pairs<Small_gap> small_gaps(double tolerance,
                                      const std::set<Coordinates>& non_manifold_points,
                                      std::size_t limit = 0) const {
    return bounded_pairs<Small_gap>(pair_limit(limit, border_.size()), [&](auto& collector) {
      find_small_gaps(tolerance, non_manifold_points, collector);
    });
  }

  /// Border vertices within `tolerance` of the interior of a border edge they are not an end
  /// of, and farther than `tolerance` from both of its ends (closer, they are a gap pair). At
  /// most `limit` of them (0: the default limit of the border vertex count).
  Bounded_pairs<T_junction> t_junctions(double tolerance, std::size_t limit = 0) const {
    return bounded_pairs<T_junction>(pair_limit(limit, border_.size()), [&](auto& collector) {
      find_t_junctions(tolerance, collector);
    });
  }

 private:
  void find_small_gaps(double tolerance, const std::set<Coordinates>& non_manifold_points,
                       Bounded_collector<Small_gap>& gaps) const {
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < border_.size(); ++i) {
      found.clear();
      tree_->search(std::back_inserter(found), Sphere(points_[i], tolerance, 0.0, tree_->traits()));
      for (std::size_t j : found) {
        if (j <= i || !is_gap(border_[i], border_[j], tolerance)) continue;
        if (points_[i] == points_[j] &&
            non_manifold_points.count(mesh_.coordinates(border_[i].vertex)))
          continue;
        Small_gap gap;
        gap.first = mesh_.index(border_[i].vertex);
        gap.second = mesh_.index(border_[j].vertex);
        gap.first_point = mesh_.coordinates(border_[i].vertex);
        gap.second_point = mesh_.coordinates(border_[j].vertex);
        gap.distance = distance(points_[i], points_[j]);
        gap.same_cycle = border_[i].cycle == border_[j].cycle;
        gaps.add(gap);
      }
    }
  }

  void find_t_junctions(double tolerance, Bounded_collector<T_junction>& junctions) const {
    std::vector<std::size_t> found;
    for (const auto& cycle : cycles_) {
      for (halfedge_descriptor h : cycle) {
        const Point& a = mesh_.point(source(h, mesh_.pm));
        const Point& b = mesh_.point(target(h, mesh_.pm));
        const double length = distance(a, b);
        const Point middle = CGAL::midpoint(a, b);
        found.clear();
        tree_->search(std::back_inserter(found),
                      Sphere(middle, 0.5 * length + tolerance, 0.0, tree_->traits()));
        for (std::size_t j : found) add_t_junction(h, a, b, border_[j], tolerance, junctions);
      }
    }
  }

  static double distance(const Point& p, const Point& q) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
  }
  double edge_length(halfedge_descriptor h) const {
    return distance(mesh_.point(source(h, mesh_.pm)), mesh_.point(target(h, mesh_.pm)));
  }

  bool is_gap(const Border_vertex<Access>& u, const Border_vertex<Access>& w,
              double tolerance) const {
    if (u.vertex == w.vertex) return false;
    if (distance(u.point, w.point) > tolerance) return false;
    if (halfedge(u.vertex, w.vertex, mesh_.pm).second) return false;
    if (u.cycle != w.cycle) return true;
    const double perimeter = descriptions_[u.cycle].perimeter;
    const double along = std::abs(u.arc_length - w.arc_length);
    return std::min(along, perimeter - along) > 2 * tolerance;
  }

  void add_t_junction(halfedge_descriptor h, const Point& a, const Point& b,
                      const Border_vertex<Access>& w, double tolerance,
                      Bounded_collector<T_junction>& junctions) const {
    const auto s = source(h, mesh_.pm), t = target(h, mesh_.pm);
    if (w.vertex == s || w.vertex == t) return;
    if (distance(w.point, a) <= tolerance || distance(w.point, b) <= tolerance) return;
    const auto ab = b - a;
    const double squared_length = CGAL::to_double(ab.squared_length());
    if (squared_length == 0) return;
    const double parameter = CGAL::to_double((w.point - a) * ab) / squared_length;
    if (parameter <= 0 || parameter >= 1) return;
    const Point foot = a + parameter * ab;
    const double gap = distance(w.point, foot);
    if (gap > tolerance) return;
    T_junction junction;
    junction.vertex = mesh_.index(w.vertex);
    junction.edge_source = mesh_.index(s);
    junction.edge_target = mesh_.index(t);
    junction.vertex_point = mesh_.coordinates(w.vertex);
    junction.foot = {CGAL::to_double(foot.x()), CGAL::to_double(foot.y()),
                     CGAL::to_double(foot.z())};
    junction.distance = gap;
    junctions.add(junction);
  }

  const Access& mesh_;
  const std::vector<Cycle_halfedges<halfedge_descriptor>>& cycles_;
  const std::vector<Border_cycle>& descriptions_;
  std::vector<Border_vertex<Access>> border_;
  std::vector<Point> points_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_PROXIMITY_H
