// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_RETRIANGULATE_REGION_H
#define CGAL_MESH_REPAIR_INTERNAL_OPTIMIZE_MESH_RETRIANGULATE_REGION_H

// Thesis 7.3: re-triangulation of an emptied region by the shared GA (internal/genetic), with
// the fitness of eq. 7.6-7.9, then the exact acceptance tests and the replacement in the mesh
// (rolled back if the mesh refuses a face).

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel/global_functions.h>

#include <CGAL/Mesh_repair/internal/genetic/ga_triangulation.h>
#include <CGAL/Mesh_repair/internal/optimize_mesh/patch_checks.h>
#include <CGAL/Mesh_repair/internal/optimize_mesh/region.h>
#include <CGAL/Mesh_repair/quality.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace optimize {

enum class Region_outcome {
  replaced,
  no_triangulation,   // the GA found no triangulation with valid chords
  duplicate_edge,     // a new edge exists already outside the region (non-manifold)
  fold_or_crease,     // a new normal turns away, a triangle is flat, or a crease/fold appears
  self_intersection,  // a new triangle crosses a surrounding one
  not_better,         // the old triangles are kept
  too_far,            // the new patch is farther than the error bound from removed points
  mesh_refused        // the mesh refused a face: rolled back
};

struct Retriangulation_settings {
  genetic::Shape_smoothness_fitness fitness;
  genetic::Ga_options ga;
  double feature_cosine = 0;       // cos of the feature angle
  bool quality_mode = false;       // accept only when fitness and minimum angle both improve
  double min_angle_floor_deg = 0;  // reduction: new smallest angle >= min(old, floor)
  /// Polygons of at most this many nodes are triangulated by enumerating all their
  /// triangulations (genetic::all_triangulations_by_fitness: the optimum the GA converges to)
  /// instead of running the GA; 0 = always the GA.
  int exhaustive_max_nodes = 0;
  /// How many of the enumerated triangulations, best fitness first, are tried against the exact
  /// tests before the region is given up.
  int exhaustive_tries = 3;
};

template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Classification>
class Region_retriangulator {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename GeomTraits::Point_3;
  using Vector = typename GeomTraits::Vector_3;
  using Vertex_triangle = std::array<vertex_descriptor, 3>;

 public:
  Region_retriangulator(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& gt,
                        const Classification& classification,
                        const Retriangulation_settings& settings)
      : pm_(pm), vpm_(vpm), gt_(gt), classification_(classification), settings_(settings) {}

  Region_outcome operator()(const Region<PolygonMesh>& region) {
    std::vector<Vertex_triangle> triangles;
    std::vector<int> polygon_of;  // which polygon each new triangle fills
    for (std::size_t p = 0; p < region.polygons.size(); ++p) {
      std::vector<Vertex_triangle> patch;
      const Region_outcome outcome = triangulate_polygon(region, region.polygons[p], patch);
      if (outcome != Region_outcome::replaced) return outcome;
      triangles.insert(triangles.end(), patch.begin(), patch.end());
      polygon_of.insert(polygon_of.end(), patch.size(), int(p));
    }
    if (!acceptable_shape(region, triangles)) return Region_outcome::not_better;
    if (accept_patch && !accept_patch(region, triangles)) return Region_outcome::too_far;
    if (!intersection_free(region, triangles)) return Region_outcome::self_intersection;
    last_triangles_ = triangles;
    return replace(region, triangles) ? Region_outcome::replaced : Region_outcome::mesh_refused;
  }

  /// Optional extra test on the whole new patch (the optimiser's distance bound), run after the
  /// shape tests and before the intersection tests.
  std::function<bool(const Region<PolygonMesh>&, const std::vector<Vertex_triangle>&)> accept_patch;

  /// The triangles of the last replaced region.
  const std::vector<Vertex_triangle>& last_triangles() const { return last_triangles_; }

 private:
  // The map's own reference type: a point map that converts (OpenMesh's stores OpenMesh::Vec3d)
  // returns a Point by value, and `const Point&` would dangle.
  typename boost::property_traits<VertexPointMap>::reference point(vertex_descriptor v) const {
    return get(vpm_, v);
  }

  Vector face_normal(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    const Point& a = point(source(h, pm_));
    return CGAL::cross_product(point(target(h, pm_)) - a, point(target(next(h, pm_), pm_)) - a);
  }

  // GA on one polygon, then the exact tests; falls back to the GA's dynamic-programming seed
  // when the GA's best fails them.
  Region_outcome triangulate_polygon(const Region<PolygonMesh>& region,
                                     const Region_polygon<PolygonMesh>& polygon,
                                     std::vector<Vertex_triangle>& patch) {
    const int n = int(polygon.nodes.size());
    if (n == 2) return Region_outcome::replaced;
    std::vector<Point> points;
    std::vector<Vector> outside(n, Vector(0, 0, 0));
    for (int i = 0; i < n; ++i) {
      points.push_back(point(polygon.nodes[i]));
      const halfedge_descriptor h = polygon.inner[i];
      if (h == GT::null_halfedge() || is_border(opposite(h, pm_), pm_)) continue;
      const Vector v = face_normal(face(opposite(h, pm_), pm_));
      const double length = std::sqrt(CGAL::to_double(v.squared_length()));
      if (length > 0) outside[i] = v / length;
    }
    Vector reference(0, 0, 0);
    for (face_descriptor f : polygon.faces) reference = reference + face_normal(f);
    std::vector<std::vector<genetic::Triangle>> candidates;
    if (n == 3) {
      candidates.push_back({genetic::Triangle{0, 1, 2}});
    } else if (n <= settings_.exhaustive_max_nodes) {
      // Exact shortcut: all Catalan(n - 2) triangulations, best fitness (eq. 7.9) first.
      const genetic::Chord_table table = genetic::valid_chords<GeomTraits>(points);
      auto all = genetic::all_triangulations_by_fitness<GeomTraits>(points, outside, table,
                                                                    settings_.fitness);
      if (all.empty()) return Region_outcome::no_triangulation;
      for (std::size_t k = 0; k < all.size() && int(k) < settings_.exhaustive_tries; ++k)
        candidates.push_back(std::move(all[k].second));
    } else {
      const genetic::Chord_table table = genetic::valid_chords<GeomTraits>(points);
      genetic::Ga_result result = genetic::ga_triangulate<GeomTraits>(
          points, outside, table, settings_.fitness, settings_.ga);
      if (!result.found) return Region_outcome::no_triangulation;
      candidates.push_back(result.triangles);
      auto seed = genetic::min_dihedral_triangulation<GeomTraits>(points, outside, table);
      if (seed) candidates.push_back(*seed);
    }
    Region_outcome failure = Region_outcome::no_triangulation;
    for (const auto& candidate : candidates) {
      patch.clear();
      for (const genetic::Triangle& t : candidate)
        patch.push_back({polygon.nodes[t[0]], polygon.nodes[t[1]], polygon.nodes[t[2]]});
      const Region_outcome outcome =
          !combinatorially_valid(region, polygon, patch)    ? Region_outcome::duplicate_edge
          : !geometrically_valid(polygon, patch, reference) ? Region_outcome::fold_or_crease
                                                            : Region_outcome::replaced;
      if (outcome == Region_outcome::replaced) return outcome;
      if (failure == Region_outcome::no_triangulation) failure = outcome;
    }
    return failure;
  }

  static bool polygon_edge(const Region_polygon<PolygonMesh>& polygon, vertex_descriptor a,
                           vertex_descriptor b, halfedge_descriptor& inner) {
    const std::size_t n = polygon.nodes.size();
    for (std::size_t i = 0; i < n; ++i) {
      const vertex_descriptor s = polygon.nodes[i], t = polygon.nodes[(i + 1) % n];
      if ((s == a && t == b) || (s == b && t == a)) {
        inner = polygon.inner[i];
        return true;
      }
    }
    return false;
  }

  // A new edge may not already exist outside the region (non-manifold edge otherwise).
  bool combinatorially_valid(const Region<PolygonMesh>& region,
                             const Region_polygon<PolygonMesh>& polygon,
                             const std::vector<Vertex_triangle>& patch) const {
    for (const Vertex_triangle& t : patch) {
      for (int c = 0; c < 3; ++c) {
        const vertex_descriptor a = t[c], b = t[(c + 1) % 3];
        halfedge_descriptor inner;
        if (polygon_edge(polygon, a, b, inner) && inner != GT::null_halfedge()) continue;
        const auto existing = halfedge(a, b, pm_);
        if (!existing.second) continue;
        if (polygon.nodes.size() > 2 && polygon_edge(polygon, a, b, inner)) {
          // The feature chord where a and b already bound a face of the star: that face's edge
          // carries the chord once the star is gone.
          bool in_region = false;
          for (halfedge_descriptor h : {existing.first, opposite(existing.first, pm_)})
            in_region |= !is_border(h, pm_) && region.contains(face(h, pm_));
          if (in_region) continue;
          return false;
        }
        for (halfedge_descriptor h : {existing.first, opposite(existing.first, pm_)})
          if (is_border(h, pm_) || !region.contains(face(h, pm_))) return false;
      }
    }
    return true;
  }

  // No degenerate triangle, every normal on the side of the old region's (exact Angle_3), and
  // exact dihedral tests across every edge of the patch.
  bool geometrically_valid(const Region_polygon<PolygonMesh>& polygon,
                           const std::vector<Vertex_triangle>& patch,
                           const Vector& reference) const {
    auto collinear = gt_.collinear_3_object();
    auto angle = gt_.angle_3_object();
    for (const Vertex_triangle& t : patch) {
      if (collinear(point(t[0]), point(t[1]), point(t[2]))) return false;
      if (angle(point(t[0]), point(t[1]), point(t[2]), reference) != CGAL::ACUTE) return false;
    }
    for (std::size_t i = 0; i < patch.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const vertex_descriptor a = patch[i][c], b = patch[i][(c + 1) % 3],
                                own = patch[i][(c + 2) % 3];
        halfedge_descriptor inner;
        if (polygon_edge(polygon, a, b, inner)) {
          if (inner == GT::null_halfedge() || is_border(opposite(inner, pm_), pm_)) continue;
          const vertex_descriptor across = target(next(opposite(inner, pm_), pm_), pm_);
          if (!dihedral_acceptable(point(a), point(b), point(own), point(across),
                                   classification_.is_feature(inner), settings_.feature_cosine,
                                   gt_))
            return false;
          continue;
        }
        for (std::size_t j = i + 1; j < patch.size(); ++j) {
          const int other = shares_edge(patch[j], a, b);
          if (other < 0) continue;
          if (!dihedral_acceptable(point(a), point(b), point(own), point(patch[j][other]), false,
                                   settings_.feature_cosine, gt_))
            return false;
        }
      }
    }
    return true;
  }

  // Index of the third vertex of `t` when it contains edge (a, b), else -1.
  static int shares_edge(const Vertex_triangle& t, vertex_descriptor a, vertex_descriptor b) {
    int has = 0, third = -1;
    for (int k = 0; k < 3; ++k) {
      if (t[k] == a || t[k] == b)
        ++has;
      else
        third = k;
    }
    return has == 2 ? third : -1;
  }

  std::array<Point, 3> points_of(const Vertex_triangle& t) const {
    return {point(t[0]), point(t[1]), point(t[2])};
  }

  double min_angle_deg(const std::vector<Vertex_triangle>& triangles) const {
    double smallest = 180;
    for (const Vertex_triangle& t : triangles)
      smallest = std::min(smallest, min_max_angle_deg(point(t[0]), point(t[1]), point(t[2])).first);
    return smallest;
  }

  std::vector<Vertex_triangle> old_triangles(const Region<PolygonMesh>& region) const {
    std::vector<Vertex_triangle> old;
    for (face_descriptor f : region.faces) {
      const halfedge_descriptor h = halfedge(f, pm_);
      old.push_back({source(h, pm_), target(h, pm_), target(next(h, pm_), pm_)});
    }
    return old;
  }

  // "Never worse than the region it replaced" (see doc/optimize_mesh.md): in quality mode the
  // fitness of eq. 7.9 and the smallest angle must both improve; in reduction mode the smallest
  // angle must not fall below min(old smallest angle, floor).
  bool acceptable_shape(const Region<PolygonMesh>& region,
                        const std::vector<Vertex_triangle>& triangles) const {
    const std::vector<Vertex_triangle> old = old_triangles(region);
    const double old_min = min_angle_deg(old), new_min = min_angle_deg(triangles);
    if (!settings_.quality_mode) return new_min >= std::min(old_min, settings_.min_angle_floor_deg);
    if (new_min < old_min) return false;
    const auto& polygon = region.polygons.front();
    return patch_fitness(polygon, triangles) > patch_fitness(polygon, old) + 1e-12 ||
           new_min > old_min;
  }

  double patch_fitness(const Region_polygon<PolygonMesh>& polygon,
                       const std::vector<Vertex_triangle>& triangles) const {
    const int n = int(polygon.nodes.size());
    std::vector<Point> points;
    std::vector<Vector> outside(n, Vector(0, 0, 0));
    for (int i = 0; i < n; ++i) {
      points.push_back(point(polygon.nodes[i]));
      const halfedge_descriptor h = polygon.inner[i];
      if (h == GT::null_halfedge() || is_border(opposite(h, pm_), pm_)) continue;
      const Vector v = face_normal(face(opposite(h, pm_), pm_));
      const double length = std::sqrt(CGAL::to_double(v.squared_length()));
      if (length > 0) outside[i] = v / length;
    }
    std::vector<genetic::Triangle> indexed;
    for (const Vertex_triangle& t : triangles) {
      genetic::Triangle index;
      for (int c = 0; c < 3; ++c)
        index[c] = int(std::find(polygon.nodes.begin(), polygon.nodes.end(), t[c]) -
                       polygon.nodes.begin());
      std::sort(index.begin(), index.end());
      indexed.push_back(index);
    }
    const genetic::Chord_table table = genetic::valid_chords<GeomTraits>(points);
    return genetic::evaluate_triangulation<GeomTraits>(points, outside, table, indexed,
                                                       settings_.fitness);
  }

  // Exact test of every new triangle against the faces around the polygon nodes that stay, and
  // against the other new triangles.
  bool intersection_free(const Region<PolygonMesh>& region,
                         const std::vector<Vertex_triangle>& triangles) const {
    std::vector<face_descriptor> around;
    for (const auto& polygon : region.polygons)
      for (vertex_descriptor v : polygon.nodes)
        for (face_descriptor f : faces_around_target(halfedge(v, pm_), pm_))
          if (f != GT::null_face() && !region.contains(f) &&
              std::find(around.begin(), around.end(), f) == around.end())
            around.push_back(f);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      const auto tp = points_of(triangles[i]);
      const auto box = tp[0].bbox() + tp[1].bbox() + tp[2].bbox();
      for (face_descriptor f : around) {
        const Vertex_triangle g = old_triangles_of(f);
        const auto gp = points_of(g);
        if (!CGAL::do_overlap(box, gp[0].bbox() + gp[1].bbox() + gp[2].bbox())) continue;
        if (triangles_intersect(triangles[i], tp, g, gp, gt_)) return false;
      }
      for (std::size_t j = i + 1; j < triangles.size(); ++j)
        if (triangles_intersect(triangles[i], tp, triangles[j], points_of(triangles[j]), gt_))
          return false;
    }
    return true;
  }

  Vertex_triangle old_triangles_of(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    return {source(h, pm_), target(h, pm_), target(next(h, pm_), pm_)};
  }

  // Topological replacement with Euler operations that never delete a polygon node: the region
  // is first merged into one polygonal face per polygon (removing its inner nodes), then split
  // along the chords of the new triangles. Every precondition was checked before: the region is
  // a disc bounded by simple polygons and no chord exists elsewhere.
  bool replace(const Region<PolygonMesh>& region, const std::vector<Vertex_triangle>& triangles) {
    std::vector<std::pair<vertex_descriptor, vertex_descriptor>> inner_edges;
    for (face_descriptor f : region.faces)
      for (halfedge_descriptor h : halfedges_around_face(halfedge(f, pm_), pm_)) {
        const face_descriptor across = face(opposite(h, pm_), pm_);
        if (across == GT::null_face() || !region.contains(across) || is_removed(region, h))
          continue;
        if (source(h, pm_) < target(h, pm_))
          inner_edges.emplace_back(source(h, pm_), target(h, pm_));
      }
    for (vertex_descriptor v : region.removed) {
      if (is_border(v, pm_)) {
        if (!remove_border_node(v)) return false;
        continue;
      }
      CGAL::Euler::remove_center_vertex(halfedge(v, pm_), pm_);
    }
    for (const auto& [a, b] : inner_edges) {
      const auto h = halfedge(a, b, pm_);
      if (h.second && face(h.first, pm_) != face(opposite(h.first, pm_), pm_))
        CGAL::Euler::join_face(h.first, pm_);
    }
    for (const Vertex_triangle& t : triangles)
      for (int c = 0; c < 3; ++c)
        if (!halfedge(t[c], t[(c + 1) % 3], pm_).second && !split_along(t[c], t[(c + 1) % 3]))
          return false;
    return true;
  }

  bool is_removed(const Region<PolygonMesh>& region, halfedge_descriptor h) const {
    for (vertex_descriptor v : region.removed)
      if (source(h, pm_) == v || target(h, pm_) == v) return true;
    return false;
  }

  // A border feature node: its fan becomes one face, the chord between its two border
  // neighbours cuts off the triangle holding it, and that triangle is removed.
  bool remove_border_node(vertex_descriptor v) {
    halfedge_descriptor first = GT::null_halfedge(), last = GT::null_halfedge();
    std::vector<halfedge_descriptor> spokes;
    for (halfedge_descriptor h : halfedges_around_source(v, pm_)) {
      if (is_border(opposite(h, pm_), pm_))
        first = h;
      else if (is_border(h, pm_))
        last = h;
      else
        spokes.push_back(h);
    }
    if (first == GT::null_halfedge() || last == GT::null_halfedge()) return false;
    for (halfedge_descriptor h : spokes) CGAL::Euler::join_face(h, pm_);
    const vertex_descriptor a = target(first, pm_), b = target(last, pm_);
    if (!split_along(a, b)) return false;
    CGAL::Euler::remove_face(first, pm_);
    return true;
  }

  // Splits the face holding both x and y along the new edge x-y.
  bool split_along(vertex_descriptor x, vertex_descriptor y) {
    for (halfedge_descriptor h : halfedges_around_target(x, pm_)) {
      if (is_border(h, pm_)) continue;
      for (halfedge_descriptor g : halfedges_around_face(h, pm_)) {
        if (target(g, pm_) != y) continue;
        if (next(h, pm_) == g || next(g, pm_) == h) return false;
        CGAL::Euler::split_face(h, g, pm_);
        return true;
      }
    }
    return false;
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  const GeomTraits& gt_;
  const Classification& classification_;
  const Retriangulation_settings& settings_;
  std::vector<Vertex_triangle> last_triangles_;
};

}  // namespace optimize
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif
