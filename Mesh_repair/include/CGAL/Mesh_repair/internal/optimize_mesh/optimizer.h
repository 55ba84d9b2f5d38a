// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_OPTIMIZER_H
#define CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_OPTIMIZER_H

// The passes of thesis Fig. 7.1: classify (7.2.1-7.2.2), rank the elements by the weighing
// factor (7.2.3), remove and re-triangulate non-touching regions in that order (7.3), repeat.

#include <CGAL/Mesh_repair/internal/optimize_mesh/feature_classification.h>
#include <CGAL/Mesh_repair/internal/optimize_mesh/region.h>
#include <CGAL/Mesh_repair/internal/optimize_mesh/retriangulate_region.h>
#include <CGAL/Mesh_repair/internal/optimize_mesh/weighing_factor.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `optimize_mesh()` does to the regions it removes.
enum class Optimization_mode {
  reduction,  ///< thesis 7.2.3(a): remove the triangles around the nodes of an element
  quality     ///< thesis 7.2.3(b): re-triangulate the element and its edge neighbours
};

/// What `optimize_mesh()` did.
struct Optimization_result {
  std::size_t input_faces = 0, output_faces = 0;
  std::size_t passes = 0;
  std::size_t regions_replaced = 0;
  // Regions left as they were, by reason:
  std::size_t regions_duplicate_edge = 0;     ///< a new edge would duplicate an existing one
  std::size_t regions_fold_or_crease = 0;     ///< a new normal would turn away, or a crease appear
  std::size_t regions_self_intersection = 0;  ///< a new triangle would cross the surroundings
  std::size_t regions_not_better = 0;         ///< the GA did not beat the old triangles
  std::size_t regions_without_triangulation = 0;
  std::size_t regions_refused_by_mesh = 0;  ///< rolled back
  std::size_t corner_nodes = 0;             ///< "vertex" nodes at the first classification
  std::size_t feature_edges = 0;            ///< at the first classification
  bool target_reached = false;
  bool cancelled = false;
  const char* stop_reason = "";
};

namespace internal {
namespace optimize {

struct Optimizer_options {
  Optimization_mode mode = Optimization_mode::reduction;
  std::size_t target_faces = 0;
  double weighing_threshold = std::numeric_limits<double>::infinity();
  double feature_angle_deg = 135;
  std::size_t max_passes = 100;
  double quality_angle_deg = 35;
  bool size_weighted_ranking = true;  // quality mode looks at regions with a smaller angle
  unsigned int seed = 0;
  Retriangulation_settings retriangulation;
};

template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Visitor>
class Optimizer {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Classification = Feature_classification<PolygonMesh, VertexPointMap, GeomTraits>;

  struct Candidate {
    double rank;  // eq. 7.4, times the region's size when ranking by estimated deviation
    double weighing_factor;
    face_descriptor element;
    vertex_descriptor feature_node;
    bool is_feature_node;
    std::array<vertex_descriptor, 3> nodes;
  };

 public:
  Optimizer(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& gt,
            const Optimizer_options& options, Visitor& visitor)
      : pm_(pm), vpm_(vpm), gt_(gt), options_(options), visitor_(visitor) {}

  Optimization_result run() {
    Optimization_result result;
    result.input_faces = faces_count();
    const bool reduction = options_.mode == Optimization_mode::reduction;
    visitor_.start_step(reduction ? "mesh reduction" : "mesh quality");
    std::size_t faces = result.input_faces;
    result.stop_reason = "no region could be improved";
    for (std::size_t pass = 0; pass < options_.max_passes; ++pass) {
      if (reduction && faces <= options_.target_faces) {
        result.target_reached = true;
        result.stop_reason = "target reached";
        break;
      }
      const std::size_t replaced = run_pass(result, faces, pass == 0);
      ++result.passes;
      if (result.cancelled) {
        result.stop_reason = "cancelled";
        break;
      }
      if (replaced == 0) break;
      if (pass + 1 == options_.max_passes) result.stop_reason = "pass limit";
    }
    if (reduction && faces <= options_.target_faces) result.target_reached = true;
    result.output_faces = faces_count();
    visitor_.end_step(reduction ? "mesh reduction" : "mesh quality");
    return result;
  }

 private:
  std::size_t faces_count() const {
    return std::size_t(std::distance(faces(pm_).begin(), faces(pm_).end()));
  }

  Unit_normal unit_normal(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    const auto& a = get(vpm_, source(h, pm_));
    const auto n = CGAL::cross_product(get(vpm_, target(h, pm_)) - a,
                                       get(vpm_, target(next(h, pm_), pm_)) - a);
    const double length = std::sqrt(CGAL::to_double(n.squared_length()));
    if (length == 0) return {0, 0, 0};
    return {CGAL::to_double(n.x()) / length, CGAL::to_double(n.y()) / length,
            CGAL::to_double(n.z()) / length};
  }

  double area(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    const auto& a = get(vpm_, source(h, pm_));
    const auto n = CGAL::cross_product(get(vpm_, target(h, pm_)) - a,
                                       get(vpm_, target(next(h, pm_), pm_)) - a);
    return 0.5 * std::sqrt(CGAL::to_double(n.squared_length()));
  }

  template <class NormalMap>
  double node_weighing_factor(vertex_descriptor v, const NormalMap& normals) const {
    std::vector<Unit_normal> star;
    Unit_normal mean{0, 0, 0};
    for (face_descriptor f : faces_around_target(halfedge(v, pm_), pm_)) {
      if (f == GT::null_face()) continue;
      star.push_back(get(normals, f));
      for (int k = 0; k < 3; ++k) mean[k] += star.back()[k];
    }
    const double length = std::sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    if (length > 0)
      for (double& c : mean) c /= length;
    return weighing_factor(mean, star);
  }

  // The most curved nodes are visited first, so they join the kept independent set; ties (flat
  // regions) are broken by a seeded shuffle that changes every pass, so no node stays kept
  // forever only because of its index.
  template <class NormalMap>
  std::vector<vertex_descriptor> node_order(const NormalMap& normals, std::size_t pass) const {
    std::vector<std::pair<double, vertex_descriptor>> ranked;
    for (vertex_descriptor v : vertices(pm_))
      if (halfedge(v, pm_) != GT::null_halfedge())
        ranked.emplace_back(node_weighing_factor(v, normals), v);
    CGAL::Random random(options_.seed + unsigned(pass) * 104729u);
    for (std::size_t i = ranked.size(); i > 1; --i)
      std::swap(ranked[i - 1], ranked[random.get_int(0, int(i))]);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<vertex_descriptor> order;
    order.reserve(ranked.size());
    for (const auto& r : ranked) order.push_back(r.second);
    return order;
  }

  std::array<vertex_descriptor, 3> nodes_of(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    return {source(h, pm_), target(h, pm_), target(next(h, pm_), pm_)};
  }

  bool is_triangle(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    return next(next(next(h, pm_), pm_), pm_) == h;
  }

  // Eq. 7.4 is scale-free. Times the square root of the region's area it is proportional to how
  // far the surface moves (a region of radius r whose normals turn by d moves by about r d / 2),
  // so small flat-ish regions are not emptied before large ones of the same shape.
  double rank_of(double d, double area) const {
    return options_.size_weighted_ranking ? d * std::sqrt(area) : d;
  }

  template <class NormalMap, class AreaMap>
  std::vector<Candidate> rank(const Classification& classification, const NormalMap& normals,
                              const AreaMap& areas) const {
    std::vector<Candidate> candidates;
    const bool reduction = options_.mode == Optimization_mode::reduction;
    std::vector<face_descriptor> affected;
    std::vector<Unit_normal> affected_normals;
    for (face_descriptor f : faces(pm_)) {
      if (!is_triangle(f)) continue;
      affected.clear();
      if (reduction) {
        for (vertex_descriptor v : vertices_around_face(halfedge(f, pm_), pm_))
          if (classification.type(v) == Node_type::interior) add_star(v, pm_, affected);
      } else {
        for (halfedge_descriptor h : halfedges_around_face(halfedge(f, pm_), pm_))
          if (!classification.is_feature(h)) affected.push_back(face(opposite(h, pm_), pm_));
        if (affected.empty() || !needs_quality(f, affected)) continue;
      }
      if (affected.empty()) continue;
      affected_normals.clear();
      double area = 0;
      for (face_descriptor g : affected) {
        if (g != f) affected_normals.push_back(get(normals, g));
        area += get(areas, g);
      }
      const double d = weighing_factor(get(normals, f), affected_normals);
      candidates.push_back({rank_of(d, area), d, f, vertex_descriptor(), false, nodes_of(f)});
    }
    if (reduction) add_feature_node_candidates(classification, normals, areas, candidates);
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& a, const auto& b) { return a.rank < b.rank; });
    return candidates;
  }

  bool needs_quality(face_descriptor f, const std::vector<face_descriptor>& neighbours) const {
    auto smallest = [this](face_descriptor g) {
      const auto n = nodes_of(g);
      return min_max_angle_deg(get(vpm_, n[0]), get(vpm_, n[1]), get(vpm_, n[2])).first;
    };
    double angle = smallest(f);
    for (face_descriptor g : neighbours) angle = std::min(angle, smallest(g));
    return angle < options_.quality_angle_deg;
  }

  // A removable edge-feature node: eq. 7.4 on each side of its feature line, the larger counts.
  template <class NormalMap, class AreaMap>
  void add_feature_node_candidates(const Classification& classification, const NormalMap& normals,
                                   const AreaMap& areas, std::vector<Candidate>& candidates) const {
    for (vertex_descriptor v : vertices(pm_)) {
      if (classification.type(v) != Node_type::removable_edge_feature) continue;
      Region<PolygonMesh> region;
      if (!feature_node_region(v, pm_, classification, region)) continue;
      double d = 0, area = 0;
      for (const auto& polygon : region.polygons) {
        if (polygon.faces.empty()) continue;
        std::vector<Unit_normal> side;
        for (std::size_t i = 1; i < polygon.faces.size(); ++i)
          side.push_back(get(normals, polygon.faces[i]));
        for (face_descriptor g : polygon.faces) area += get(areas, g);
        d = std::max(d, weighing_factor(get(normals, polygon.faces.front()), side));
      }
      d = std::max(d, feature_line_deviation(v, classification));
      candidates.push_back({rank_of(d, area), d, face_descriptor(), v, true, {v, v, v}});
    }
  }

  // Eq. 7.1-7.2 applied to the unit directions of the feature line before and after the node,
  // so that a node on a curved feature line between two flat sides is not taken for flat.
  double feature_line_deviation(vertex_descriptor v, const Classification& classification) const {
    vertex_descriptor a, b;
    if (!classification.feature_neighbours(v, a, b)) return 0;
    auto direction = [this](vertex_descriptor from, vertex_descriptor to) {
      const auto d = get(vpm_, to) - get(vpm_, from);
      const double length = std::sqrt(CGAL::to_double(d.squared_length()));
      return Unit_normal{CGAL::to_double(d.x()) / length, CGAL::to_double(d.y()) / length,
                         CGAL::to_double(d.z()) / length};
    };
    return normal_deviation(direction(a, v), direction(v, b));
  }

  template <class MarkMap>
  bool untouched(const Region<PolygonMesh>& region, const MarkMap& marks) const {
    for (vertex_descriptor v : region.removed)
      if (get(marks, v)) return false;
    for (const auto& polygon : region.polygons)
      for (vertex_descriptor v : polygon.nodes)
        if (get(marks, v)) return false;
    return true;
  }

  template <class MarkMap>
  void mark(const Region<PolygonMesh>& region, MarkMap& marks) const {
    for (vertex_descriptor v : region.removed) put(marks, v, true);
    for (const auto& polygon : region.polygons)
      for (vertex_descriptor v : polygon.nodes) put(marks, v, true);
  }

  std::size_t run_pass(Optimization_result& result, std::size_t& face_count, bool first) {
    auto normals = get(CGAL::dynamic_face_property_t<Unit_normal>(), pm_);
    auto areas = get(CGAL::dynamic_face_property_t<double>(), pm_);
    for (face_descriptor f : faces(pm_)) {
      put(normals, f, unit_normal(f));
      put(areas, f, area(f));
    }
    Classification classification(pm_, vpm_, gt_, options_.feature_angle_deg);
    classification.classify(node_order(normals, result.passes));
    if (first) {
      result.corner_nodes = classification.count(Node_type::vertex);
      for (auto e : edges(pm_)) result.feature_edges += classification.is_feature(e);
    }
    const std::vector<Candidate> candidates = rank(classification, normals, areas);
    auto marks = get(CGAL::dynamic_vertex_property_t<bool>(), pm_);
    for (vertex_descriptor v : vertices(pm_)) put(marks, v, false);

    const bool reduction = options_.mode == Optimization_mode::reduction;
    const std::size_t start_faces = face_count;
    const std::size_t remaining =
        face_count > options_.target_faces ? face_count - options_.target_faces : 0;
    // Half of what remains per pass, so later passes re-rank the coarser mesh by eq. 7.4.
    const std::size_t pass_budget = std::min(remaining, std::max<std::size_t>(remaining / 2, 64));
    Retriangulation_settings settings = options_.retriangulation;
    Region_retriangulator<PolygonMesh, VertexPointMap, GeomTraits, Classification> retriangulate(
        pm_, vpm_, gt_, classification, settings);
    Progress_reporter<Visitor> report(visitor_, candidates.size());
    std::size_t replaced = 0, visited = 0;
    for (const Candidate& candidate : candidates) {
      if (!report(++visited)) {
        result.cancelled = true;
        break;
      }
      if (candidate.weighing_factor > options_.weighing_threshold) continue;
      if (reduction && start_faces - face_count >= pass_budget) break;
      if (get(marks, candidate.nodes[0]) || get(marks, candidate.nodes[1]) ||
          get(marks, candidate.nodes[2]))
        continue;
      Region<PolygonMesh> region;
      const bool built =
          candidate.is_feature_node
              ? feature_node_region(candidate.feature_node, pm_, classification, region)
          : reduction ? node_region(candidate.element, pm_, classification, region)
                      : edge_region(candidate.element, pm_, classification, region);
      if (!built || !untouched(region, marks)) continue;
      settings.ga.random_seed =
          options_.seed + unsigned(result.regions_replaced) * 7919u + unsigned(visited);
      const std::size_t old_faces = region.faces.size();
      switch (retriangulate(region)) {
        case Region_outcome::replaced: {
          mark(region, marks);
          std::size_t new_faces = 0;
          for (const auto& polygon : region.polygons)
            new_faces += polygon.nodes.size() > 2 ? polygon.nodes.size() - 2 : 0;
          face_count = face_count - old_faces + new_faces;
          ++replaced;
          ++result.regions_replaced;
          break;
        }
        case Region_outcome::duplicate_edge:
          ++result.regions_duplicate_edge;
          break;
        case Region_outcome::fold_or_crease:
          ++result.regions_fold_or_crease;
          break;
        case Region_outcome::self_intersection:
          ++result.regions_self_intersection;
          break;
        case Region_outcome::not_better:
          ++result.regions_not_better;
          break;
        case Region_outcome::no_triangulation:
          ++result.regions_without_triangulation;
          break;
        case Region_outcome::mesh_refused:
          ++result.regions_refused_by_mesh;
          break;
      }
    }
    return replaced;
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  const GeomTraits& gt_;
  Optimizer_options options_;
  Visitor& visitor_;
};

}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif
