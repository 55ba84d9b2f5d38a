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
#include <CGAL/Mesh_repair/optimization_result.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

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
  /// Reduction: every face carries the input nodes removed so far that are closest to it; a
  /// region is ranked by how far its removed node and carried points are from the plane of its
  /// boundary, and a new patch is refused when one of them is farther from it than the pass'
  /// bound (see doc/optimize_mesh.md, "Distance control").
  bool error_tracking = true;
  /// Reduction: one region per removable interior node (its star) instead of the triangles
  /// around all removable nodes of an element.
  bool single_node_regions = true;
  /// The pass' distance bound is the estimated error of the candidate at this many times the
  /// pass' face budget in the ranked list.
  double bound_rank_factor = 2;
  /// ... and at most at this fraction of the list: a pass only removes regions whose
  /// estimated error is below that quantile of the current candidates.
  double bound_quantile = 0.5;
  /// The bound is never below the largest distance already accepted: removals within it do not
  /// increase the error reached so far.
  bool keep_reached_bound = true;
  /// Reduction with single-node regions: regions of one pass may share polygon nodes (never
  /// faces); the removed nodes of a pass still form an independent set.
  bool share_polygon_nodes = true;

  Retriangulation_settings retriangulation;
};

template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Visitor>
class Optimizer {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Classification = Feature_classification<PolygonMesh, VertexPointMap, GeomTraits>;

  using Point = typename GeomTraits::Point_3;
  using Vertex_triangle = std::array<vertex_descriptor, 3>;
  using Carried_map =
      typename boost::property_map<PolygonMesh,
                                   CGAL::dynamic_face_property_t<std::vector<Point>>>::type;

  using Refused_map =
      typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<double>>::type;

  struct Candidate {
    double error;  // reduction with error tracking: estimated distance (else 0)
    double rank;   // eq. 7.4, times the region's size when ranking by estimated deviation
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
    if (reduction && options_.error_tracking) {
      carried_.emplace(get(CGAL::dynamic_face_property_t<std::vector<Point>>(), pm_));
      quantile_ = options_.bound_quantile;
      refused_.emplace(get(CGAL::dynamic_vertex_property_t<double>(), pm_));
      for (vertex_descriptor v : vertices(pm_)) put(*refused_, v, -1.0);
      CGAL::Bbox_3 box;
      for (vertex_descriptor v : vertices(pm_)) box += get(vpm_, v).bbox();
      const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
                   dz = box.zmax() - box.zmin();
      // Below this, distances are rounding noise (flat regions measure about 1e-17).
      error_floor_ = 1e-9 * std::sqrt(dx * dx + dy * dy + dz * dz);
    }
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
      if (replaced == 0 && reduction && carried_ && faces > options_.target_faces &&
          quantile_ < 1) {
        // Nothing under the distance bound could be removed: raise it.
        quantile_ = std::min(1.0, 2 * quantile_);
        continue;
      }
      if (replaced == 0) break;
      quantile_ = options_.bound_quantile;
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

  Vec3 unit_normal(face_descriptor f) const {
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
    std::vector<Vec3>& star = star_scratch_;
    star.clear();
    Vec3 mean{0, 0, 0};
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
  template <class NormalMap, class NodeFactorMap>
  std::vector<vertex_descriptor> node_order(const NormalMap& normals, std::size_t pass,
                                            NodeFactorMap& node_factors) const {
    std::vector<std::pair<double, vertex_descriptor>> ranked;
    for (vertex_descriptor v : vertices(pm_))
      if (halfedge(v, pm_) != GT::null_halfedge()) {
        ranked.emplace_back(node_weighing_factor(v, normals), v);
        put(node_factors, v, ranked.back().first);
      }
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

  template <class NormalMap, class AreaMap, class NodeFactorMap>
  std::vector<Candidate> rank(const Classification& classification, const NormalMap& normals,
                              const AreaMap& areas, const NodeFactorMap& node_factors) const {
    std::vector<Candidate> candidates;
    const bool reduction = options_.mode == Optimization_mode::reduction;
    std::vector<face_descriptor> affected;
    std::vector<Vec3> affected_normals;
    std::vector<vertex_descriptor> removed;
    if (reduction && options_.single_node_regions) {
      for (vertex_descriptor v : vertices(pm_)) {
        if (classification.type(v) != Node_type::interior) continue;
        affected.clear();
        add_star(v, pm_, affected);
        double area = 0;
        for (face_descriptor g : affected) area += get(areas, g);
        const double d = get(node_factors, v);
        removed.assign(1, v);
        const double error = estimated_error(affected, removed, normals, areas);
        candidates.push_back(
            {error, rank_of(d, area), d, face_descriptor(), vertex_descriptor(), false, {v, v, v}});
      }
    }
    for (face_descriptor f : faces(pm_)) {
      if (reduction && options_.single_node_regions) break;
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
      double error = 0;
      if (reduction) {
        removed.clear();
        for (vertex_descriptor v : vertices_around_face(halfedge(f, pm_), pm_))
          if (classification.type(v) == Node_type::interior) removed.push_back(v);
        error = estimated_error(affected, removed, normals, areas);
      }
      candidates.push_back(
          {error, rank_of(d, area), d, f, vertex_descriptor(), false, nodes_of(f)});
    }
    if (reduction) add_feature_node_candidates(classification, normals, areas, candidates);
    std::stable_sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
      return a.error < b.error || (a.error == b.error && a.rank < b.rank);
    });
    return candidates;
  }

  // How far the removed nodes and the input points carried by `region_faces` are from the plane
  // through the mean of the region's boundary nodes, normal to the area-weighted mean normal: an
  // estimate, before any re-triangulation, of the distance the removal causes. 0 without error
  // tracking.
  template <class NormalMap, class AreaMap>
  double estimated_error(const std::vector<face_descriptor>& region_faces,
                         const std::vector<vertex_descriptor>& removed, const NormalMap& normals,
                         const AreaMap& areas) const {
    if (!carried_) return 0;
    double n[3] = {0, 0, 0}, c[3] = {0, 0, 0};
    int count = 0;
    for (face_descriptor f : region_faces) {
      const Vec3& u = get(normals, f);
      const double a = get(areas, f);
      for (int k = 0; k < 3; ++k) n[k] += a * u[k];
      for (vertex_descriptor v : vertices_around_face(halfedge(f, pm_), pm_)) {
        if (std::find(removed.begin(), removed.end(), v) != removed.end()) continue;
        const Point& p = get(vpm_, v);
        c[0] += CGAL::to_double(p.x());
        c[1] += CGAL::to_double(p.y());
        c[2] += CGAL::to_double(p.z());
        ++count;
      }
    }
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length == 0 || count == 0) return std::numeric_limits<double>::max();
    for (int k = 0; k < 3; ++k) {
      n[k] /= length;
      c[k] /= count;
    }
    auto distance = [&](const Point& p) {
      return std::abs(n[0] * (CGAL::to_double(p.x()) - c[0]) +
                      n[1] * (CGAL::to_double(p.y()) - c[1]) +
                      n[2] * (CGAL::to_double(p.z()) - c[2]));
    };
    double error = 0;
    for (vertex_descriptor v : removed) error = std::max(error, distance(get(vpm_, v)));
    for (face_descriptor f : region_faces)
      for (const Point& p : get(*carried_, f)) error = std::max(error, distance(p));
    return error;
  }

  // The exact distance check of a new patch: every removed node and every point carried by the
  // region's faces goes to its closest new triangle; refused when one is farther than the bound.
  bool patch_within_bound(const Region<PolygonMesh>& region,
                          const std::vector<Vertex_triangle>& triangles) {
    patch_points_.clear();
    for (face_descriptor f : region.faces) {
      const auto& carried = get(*carried_, f);
      patch_points_.insert(patch_points_.end(), carried.begin(), carried.end());
    }
    for (vertex_descriptor v : region.removed) patch_points_.push_back(get(vpm_, v));
    assignment_.clear();
    if (triangles.empty()) return patch_points_.empty();
    std::vector<typename GeomTraits::Triangle_3> patch;
    for (const Vertex_triangle& t : triangles)
      patch.emplace_back(get(vpm_, t[0]), get(vpm_, t[1]), get(vpm_, t[2]));
    auto squared_distance = gt_.compute_squared_distance_3_object();
    const double bound2 = pass_bound_ * pass_bound_;
    double worst = 0;
    for (const Point& p : patch_points_) {
      double best = std::numeric_limits<double>::infinity();
      int closest = 0;
      for (int k = 0; k < int(patch.size()); ++k) {
        const double d2 = CGAL::to_double(squared_distance(p, patch[k]));
        if (d2 < best) {
          best = d2;
          closest = k;
        }
      }
      worst = std::max(worst, best);
      assignment_.push_back(closest);
    }
    excess_ = std::sqrt(worst);
    return worst <= bound2;
  }

  // A replaced region changes the stars of its polygon nodes and the surroundings (faces across
  // the polygon edges, faces around the polygon nodes) of their neighbours: their refusals are
  // forgotten.
  void forget_refusals(const Region<PolygonMesh>& region) {
    for (const auto& polygon : region.polygons)
      for (vertex_descriptor v : polygon.nodes) {
        put(*refused_, v, -1.0);
        for (vertex_descriptor w : vertices_around_target(halfedge(v, pm_), pm_))
          put(*refused_, w, -1.0);
      }
  }

  // After a replacement: the new faces carry the points assigned to them by
  // `patch_within_bound`.
  void distribute_points(const std::vector<Vertex_triangle>& triangles) {
    std::vector<face_descriptor> new_faces;
    for (const Vertex_triangle& t : triangles) {
      face_descriptor f = GT::null_face();
      const auto h = halfedge(t[0], t[1], pm_);
      if (h.second) {
        for (halfedge_descriptor g : {h.first, opposite(h.first, pm_)})
          if (!is_border(g, pm_) && target(next(g, pm_), pm_) == t[2]) f = face(g, pm_);
      }
      new_faces.push_back(f);
    }
    // Gathered per face, then put once: a dynamic property map may only give a const reference
    // (Polyhedron_3 keeps dynamic properties in an unordered_map). A face met twice shares the
    // slot of its first triangle.
    std::vector<std::size_t> slot(new_faces.size());
    for (std::size_t j = 0; j < new_faces.size(); ++j)
      slot[j] = std::size_t(std::find(new_faces.begin(), new_faces.end(), new_faces[j]) -
                            new_faces.begin());
    std::vector<std::vector<Point>> points(new_faces.size());
    for (std::size_t i = 0; i < assignment_.size(); ++i)
      points[slot[assignment_[i]]].push_back(patch_points_[i]);
    for (std::size_t j = 0; j < new_faces.size(); ++j)
      if (slot[j] == j && new_faces[j] != GT::null_face())
        put(*carried_, new_faces[j], std::move(points[j]));
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
      double d = 0, area = 0, error = 0;
      const std::vector<vertex_descriptor> removed{v};
      for (const auto& polygon : region.polygons) {
        if (polygon.faces.empty()) continue;
        error = std::max(error, estimated_error(polygon.faces, removed, normals, areas));
        std::vector<Vec3> side;
        for (std::size_t i = 1; i < polygon.faces.size(); ++i)
          side.push_back(get(normals, polygon.faces[i]));
        for (face_descriptor g : polygon.faces) area += get(areas, g);
        d = std::max(d, weighing_factor(get(normals, polygon.faces.front()), side));
      }
      d = std::max(d, feature_line_deviation(v, classification));
      candidates.push_back({error, rank_of(d, area), d, face_descriptor(), v, true, {v, v, v}});
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
      return Vec3{CGAL::to_double(d.x()) / length, CGAL::to_double(d.y()) / length,
                  CGAL::to_double(d.z()) / length};
    };
    return normal_deviation(direction(a, v), direction(v, b));
  }

  template <class MarkMap>
  bool untouched(const Region<PolygonMesh>& region, const MarkMap& marks) const {
    for (vertex_descriptor v : region.removed)
      if (get(marks, v)) return false;
    if (shared_polygons_) return true;
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
    auto normals = get(CGAL::dynamic_face_property_t<Vec3>(), pm_);
    auto areas = get(CGAL::dynamic_face_property_t<double>(), pm_);
    for (face_descriptor f : faces(pm_)) {
      put(normals, f, unit_normal(f));
      put(areas, f, area(f));
    }
    Classification classification(pm_, vpm_, gt_, options_.feature_angle_deg);
    auto node_factors = get(CGAL::dynamic_vertex_property_t<double>(), pm_);
    classification.classify(node_order(normals, result.passes, node_factors));
    if (first) {
      result.corner_nodes = classification.count(Node_type::vertex);
      for (auto e : edges(pm_)) result.feature_edges += classification.is_feature(e);
    }
    const std::vector<Candidate> candidates = rank(classification, normals, areas, node_factors);
    // char, not bool: OpenMesh stores a bool property in a std::vector<bool>, whose
    // elements its property map cannot return by reference (does not compile).
    auto marks = get(CGAL::dynamic_vertex_property_t<char>(), pm_);
    for (vertex_descriptor v : vertices(pm_)) put(marks, v, false);

    const bool reduction = options_.mode == Optimization_mode::reduction;
    shared_polygons_ = reduction && options_.single_node_regions && options_.share_polygon_nodes;
    const std::size_t start_faces = face_count;
    const std::size_t remaining =
        face_count > options_.target_faces ? face_count - options_.target_faces : 0;
    // Half of what remains per pass, so later passes re-rank the coarser mesh by eq. 7.4.
    const std::size_t pass_budget = std::min(remaining, std::max<std::size_t>(remaining / 2, 64));
    Retriangulation_settings settings = options_.retriangulation;
    Region_retriangulator<PolygonMesh, VertexPointMap, GeomTraits, Classification> retriangulate(
        pm_, vpm_, gt_, classification, settings);
    if (reduction && carried_ && !candidates.empty()) {
      // The pass' bound: the estimated error of a candidate far enough down the ranked list that
      // the regions before it can fill the pass' budget (most are skipped because they touch an
      // earlier region).
      const std::size_t at = std::min(
          {candidates.size() - 1, std::size_t(options_.bound_rank_factor * double(pass_budget)),
           std::size_t(quantile_ * double(candidates.size()))});
      pass_bound_ = std::max(candidates[at].error, error_floor_);
      if (options_.keep_reached_bound) pass_bound_ = std::max(pass_bound_, reached_);
      if (quantile_ >= 1) pass_bound_ = std::numeric_limits<double>::infinity();
      retriangulate.accept_patch = [this](const Region<PolygonMesh>& region,
                                          const std::vector<Vertex_triangle>& triangles) {
        return patch_within_bound(region, triangles);
      };
    }
    Progress_reporter<Visitor> report(visitor_, candidates.size());
    std::size_t replaced = 0, visited = 0;
    for (const Candidate& candidate : candidates) {
      if (!report(++visited)) {
        result.cancelled = true;
        break;
      }
      if (candidate.weighing_factor > options_.weighing_threshold) continue;
      if (reduction && start_faces - face_count >= pass_budget) break;
      // A node whose neighbourhood has not changed since it was refused is refused again
      // (refusals are deterministic), unless the refusal was the distance bound and the
      // bound has grown past the distance found then.
      const vertex_descriptor node =
          candidate.is_feature_node ? candidate.feature_node : candidate.nodes[0];
      const bool cached = carried_ && (candidate.is_feature_node || options_.single_node_regions);
      if (cached) {
        const double refused = get(*refused_, node);
        if (refused >= 0 && refused > pass_bound_) continue;
      }
      if (get(marks, candidate.nodes[0]) || get(marks, candidate.nodes[1]) ||
          get(marks, candidate.nodes[2]))
        continue;
      Region<PolygonMesh> region;
      const bool built =
          candidate.is_feature_node
              ? feature_node_region(candidate.feature_node, pm_, classification, region)
          : !reduction ? edge_region(candidate.element, pm_, classification, region)
          : options_.single_node_regions
              ? star_region(candidate.nodes[0], pm_, classification, region)
              : node_region(candidate.element, pm_, classification, region);
      if (!built || !untouched(region, marks)) continue;
      settings.ga.random_seed =
          options_.seed + unsigned(result.regions_replaced) * 7919u + unsigned(visited);
      const std::size_t old_faces = region.faces.size();
      const Region_outcome outcome = retriangulate(region);
      if (cached && outcome != Region_outcome::replaced)
        put(*refused_, node,
            outcome == Region_outcome::too_far ? excess_ : std::numeric_limits<double>::infinity());
      switch (outcome) {
        case Region_outcome::replaced: {
          if (retriangulate.accept_patch) distribute_points(retriangulate.last_triangles());
          if (carried_) {
            forget_refusals(region);
            reached_ = std::max(reached_, excess_);
          }
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
        case Region_outcome::too_far:
          ++result.regions_too_far;
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
  std::optional<Carried_map> carried_;  // input points removed so far, by closest face
  // Per node: -1, or why its region was last refused (the distance found, or infinity for a
  // shape or validity refusal); reset when the node's neighbourhood changes.
  std::optional<Refused_map> refused_;
  double excess_ = 0;
  mutable std::vector<Vec3> star_scratch_;
  double reached_ = 0;  // largest distance of an accepted patch
  bool shared_polygons_ = false;
  double quantile_ = 0.5;
  double error_floor_ = 0;
  double pass_bound_ = std::numeric_limits<double>::infinity();
  std::vector<Point> patch_points_;
  std::vector<int> assignment_;
};

}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif
