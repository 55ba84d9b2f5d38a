// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_ADVANCING_FRONT_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_ADVANCING_FRONT_H

/// \file advancing_front.h
/// The heuristic element-filling algorithm of thesis section 4.4: an advancing front from the
/// hole's border that closes the corner of smallest angle with one triangle (< 75 degrees), two
/// (75-135) or three (> 135), places new nodes from averaged neighbour normals (eq. 4.8-4.12) at
/// the mean adjacent edge length, merges nodes closer than half an edge length, and checks every
/// new triangle with exact predicates (in the node's tangent plane against the front, and in 3D
/// against the triangles already added and the mesh around the hole). New nodes are projected
/// onto a quadric fitted to the hole's surroundings, so curved holes are filled curved. When a
/// placement fails, others are tried, and a stuck front's last loops are closed by a checked
/// minimum-area triangulation; every candidate patch gets the dispatcher's exact check. See
/// doc/advancing_front.md.

#include <CGAL/Mesh_repair/hole_filling/fill_options.h>
#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/front_mesh.h>
#include <CGAL/Mesh_repair/internal/hole_filling/guide_surface.h>
#include <CGAL/Mesh_repair/internal/hole_filling/patch_check.h>
#include <CGAL/Mesh_repair/internal/hole_filling/quadric_fit.h>
#include <CGAL/Mesh_repair/parameters.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

namespace internal {

/// Closest point on the minimum-weight triangulation of the border: the surface the front
/// advances on when no quadric describes the hole's surroundings (see guide_surface.h).
template <class PolygonMesh, class VertexPointMap>
Front_projection guide_projection(
    const PolygonMesh& pm, VertexPointMap vpm,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h) {
  std::vector<Vec3> border;
  for (auto c : halfedges_around_face(h, pm)) border.push_back(to_array(get(vpm, source(c, pm))));
  auto surface = std::make_shared<Guide_surface>(border);
  if (!surface->valid()) return [](const Vec3& p, const Vec3&) { return p; };
  return [surface](const Vec3& p, const Vec3&) { return surface->project(p); };
}

/// The quadric of the vertices within two rings of the hole's border, over the plane of the
/// border's vector area. Used only when it is a height field over that plane where the hole's
/// surroundings are: every face along the border must face the same side as the plane's normal
/// and agree with the quadric's normal there; otherwise new nodes stay where the front puts them.
template <class PolygonMesh, class VertexPointMap>
Front_projection hole_projection(const PolygonMesh& pm, VertexPointMap vpm,
                                 typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                                 bool* quadric_used = nullptr) {
  if (quadric_used != nullptr) *quadric_used = false;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  const Border_cycle_geometry g = cycle_geometry(h, pm, vpm);
  const auto guide = [&] { return guide_projection(pm, vpm, h); };
  if (norm(g.vector_area) == 0) return guide();
  const Vec3 axis = normalized(g.vector_area);
  std::unordered_set<vertex_descriptor> ring;
  std::vector<vertex_descriptor> layer;
  for (auto c : halfedges_around_face(h, pm)) {
    if (ring.insert(source(c, pm)).second) layer.push_back(source(c, pm));
  }
  for (int depth = 0; depth < 2; ++depth) {
    std::vector<vertex_descriptor> next_layer;
    for (vertex_descriptor v : layer) {
      for (auto around : halfedges_around_target(v, pm)) {
        if (ring.insert(source(around, pm)).second) next_layer.push_back(source(around, pm));
      }
    }
    layer.swap(next_layer);
  }
  std::vector<Vec3> points;
  for (vertex_descriptor v : ring) points.push_back(to_array(get(vpm, v)));
  auto quadric = std::make_shared<Quadric_height_field>(points, g.centroid, axis, g.diameter);
  if (!quadric->valid()) return guide();
  for (auto c : halfedges_around_face(h, pm)) {
    const auto o = opposite(c, pm);
    if (is_border(o, pm)) continue;
    const Vec3 face_normal = normalized(triangle_normal(
        get(vpm, source(o, pm)), get(vpm, target(o, pm)), get(vpm, target(next(o, pm), pm))));
    const Vec3 p = to_array(get(vpm, source(c, pm)));
    if (dot(face_normal, axis) <= 0.2 || dot(face_normal, quadric->normal_at(p)) <= 0.5)
      return guide();
  }
  if (quadric_used != nullptr) *quadric_used = true;
  return [quadric](const Vec3& p, const Vec3&) { return quadric->project(p); };
}

/// The front's layers compress: a corner above 135 degrees is trisected into chords of
/// 2 L sin(theta / 6) (0.77 L at 135 degrees) and a front node is merged only below half an
/// edge length, so asked for edges of L the front makes a patch denser than L. Asking for
/// 1.15 L gives the density of the surroundings: on the 126 holes of the bench table the median
/// patch has 0.97 times the faces of the region it replaces (1.14 times with 1.0); see
/// doc/advancing_front.md, "Patch density".
constexpr double front_spacing_factor = 1.15;

/// True when the triangle (a, b, c) has an angle below `limit_deg` (< 90), or a repeated point:
/// `smallest_angle_deg(a, b, c) < limit_deg` without its three arctangents.
inline bool has_angle_below(const Vec3& a, const Vec3& b, const Vec3& c, double limit_deg) {
  const double tangent = std::tan(limit_deg * CGAL_PI / 180.0);
  const Vec3* corners[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = sub(*corners[(k + 1) % 3], *corners[k]);
    const Vec3 w = sub(*corners[(k + 2) % 3], *corners[k]);
    if (!(norm(u) > 0) || !(norm(w) > 0)) return true;
    const double cosine_part = dot(u, w);  // |u||w| cos, positive below 90 degrees
    if (cosine_part > 0 && norm(cross(u, w)) < tangent * cosine_part) return true;
  }
  return false;
}

/// Smallest angle (degrees) of the triangle (a, b, c); 0 for a repeated point.
template <class Point>
double smallest_angle_deg(const Point& a, const Point& b, const Point& c) {
  const Vec3 p = to_array(a);
  const Vec3 q = to_array(b);
  const Vec3 r = to_array(c);
  const auto angle = [](const Vec3& o, const Vec3& x, const Vec3& y) {
    const Vec3 u = sub(x, o), w = sub(y, o);
    const double nu = norm(u), nw = norm(w);
    if (!(nu > 0) || !(nw > 0)) return 0.0;
    return std::atan2(norm(cross(u, w)), dot(u, w)) * 180.0 / CGAL_PI;
  };
  return std::min({angle(p, q, r), angle(q, r, p), angle(r, p, q)});
}

}  // namespace internal

namespace internal {

/// `fill_hole_advancing_front` on plain options. `shared_cache`: the dispatcher's boxes of the
/// faces near the hole, or null (a cache of the whole mesh is then built when checking).
template <class PolygonMesh, class VPM, class GT>
Hole_fill_report fill_hole_advancing_front(
    PolygonMesh& pm, VPM vpm, const GT& traits,
    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const Advancing_front_options& front_options,
    Face_box_cache<PolygonMesh, VPM>* shared_cache) {
  const bool fit = front_options.fit_quadric;
  const bool check = front_options.check_self_intersections;
  internal::Front_options options;
  options.size_from_position_only = true;  // border_density ignores the adjacent edge length
  options.smoothing_iterations = int(front_options.smoothing_iterations);

  Hole_fill_report report;
  report.requested = report.used = Fill_method::advancing_front;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> point_vertices;
  // The dispatcher passes its cache of face boxes: building one per hole is a pass over the
  // whole mesh (4 s for 100 holes in a 1.2M-face mesh).
  using Cache = internal::Face_box_cache<PolygonMesh, VPM>;
  const internal::Front_input input =
      internal::front_input_from_border(pm, vpm, border_halfedge, point_vertices, shared_cache);
  const internal::Front_size size = internal::border_density(input, internal::front_spacing_factor);

  // A triangle is degenerate below 2 degrees, or below half the sharpest corner of the border
  // when the border itself forces a sharper one (every triangle at that corner is as sharp).
  double sharpest_corner = 180;
  for (std::size_t k = 0, n = input.cycle.size(); k < n; ++k) {
    const Vec3& a = input.points[input.cycle[(k + n - 1) % n]];
    const Vec3& v = input.points[input.cycle[k]];
    const Vec3& b = input.points[input.cycle[(k + 1) % n]];
    const Vec3 u = internal::sub(a, v), w = internal::sub(b, v);
    sharpest_corner = std::min(
        sharpest_corner,
        std::atan2(internal::norm(internal::cross(u, w)), internal::dot(u, w)) * 180.0 / CGAL_PI);
  }
  const double degenerate_deg = std::min(2.0, 0.5 * sharpest_corner);

  // The placements tried in turn: the fitted quadric (or the guide surface where no quadric
  // fits), then the guide surface, then the thesis' tangent planes; each with and without the
  // final relaxation; and, when the front gets stuck in all of them, the same placements (edge
  // length x 1, 0.85, 1.2, 0.7, 1.4) with the remaining front loops closed by the checked
  // minimum-area triangulation of `Advancing_front::close_remnant`. The first patch that is closed,
  // accepted by the mesh, free of self-intersections (the dispatcher's exact check: patch, ring and
  // every mesh face near it) and of degenerate triangles is kept; a patch with degenerate triangles
  // only when no other is. See doc/advancing_front.md.
  bool quadric_used = false;
  const Front_projection identity = [](const Vec3& p, const Vec3&) { return p; };
  std::vector<std::pair<Front_projection, const char*>> projections;
  if (fit) {
    Front_projection first = internal::hole_projection(pm, vpm, border_halfedge, &quadric_used);
    projections.emplace_back(std::move(first), quadric_used ? "quadric" : "guide surface");
    if (quadric_used) {
      // Built on first use only: the minimum-weight triangulation of the border is O(n^3).
      auto guide = std::make_shared<Front_projection>();
      const auto lazy = [guide, &pm, vpm, border_halfedge](const Vec3& p, const Vec3& n) {
        if (!*guide) *guide = internal::guide_projection(pm, vpm, border_halfedge);
        return (*guide)(p, n);
      };
      projections.emplace_back(Front_projection(lazy), "guide surface");
    }
  }
  projections.emplace_back(identity, "tangent planes");
  struct Variant {
    std::size_t projection;
    int smoothing;
    bool remnant;
    double size_factor;
  };
  std::vector<Variant> variants;
  for (std::size_t p = 0; p < projections.size(); ++p) {
    variants.push_back({p, options.smoothing_iterations, false, 1.0});
    if (options.smoothing_iterations > 0) variants.push_back({p, 0, false, 1.0});
  }
  // A stuck front depends on where its layers happened to meet: other element sizes meet
  // elsewhere. Without the closing of stuck fronts (the automatic method, which falls back to
  // Liepa instead) the other sizes are still tried, with the front alone.
  const bool close_stuck = front_options.close_stuck_front;
  for (double factor : {1.0, 0.85, 1.2, 0.7, 1.4}) {
    for (std::size_t p = 0; p < projections.size(); ++p) {
      if (close_stuck)
        variants.push_back({p, options.smoothing_iterations, true, factor});
      else if (factor != 1.0)
        variants.push_back({p, options.smoothing_iterations, false, factor});
    }
  }

  // The same exact check as the dispatcher's: the patch against itself, its ring and every face
  // of the mesh near it (the cache of face boxes is taken before the first patch is added).
  Cache own_cache(pm, vpm);
  if (check && shared_cache == nullptr) own_cache.build();
  Cache& face_cache = shared_cache != nullptr ? *shared_cache : own_cache;
  // One budget for the remnant closings of every attempt below (Front_options): a hole that
  // another part of the mesh passes through does not spend it in each of its 15 attempts.
  std::size_t remnant_visits_left = front_options.remnant_visits_per_hole;
  enum class Outcome { kept, degenerate, failed };
  std::string first_failure;
  std::size_t remnant_edges = 0;
  const auto attempt = [&](const Variant& variant, bool accept_degenerate) {
    internal::Front_options variant_options = options;
    variant_options.smoothing_iterations = variant.smoothing;
    variant_options.close_remnant = variant.remnant;
    variant_options.remnant_visits_left = &remnant_visits_left;
    const double factor = variant.size_factor;
    const internal::Front_size variant_size =
        factor == 1.0 ? size
                      : internal::Front_size([&size, factor](const Vec3& p, double adjacent) {
                          return factor * size(p, adjacent);
                        });
    // The first attempt defers the fans' 3D test to one test of the closed patch (most holes
    // pass it: half the exact tests); when that test fails, the front reruns with it.
    variant_options.defer_3d_test =
        &variant == &variants.front() && !variant.remnant && input.context_complete;
    internal::Front_triangulation triangulation = internal::advance_front(
        input, projections[variant.projection].first, variant_size, variant_options);
    if (variant_options.defer_3d_test && !(triangulation.closed && triangulation.exactly_checked)) {
      variant_options.defer_3d_test = false;
      triangulation = internal::advance_front(input, projections[variant.projection].first,
                                              variant_size, variant_options);
    }
    remnant_edges = triangulation.remnant_edges;
    if (!triangulation.closed) {
      if (first_failure.empty()) first_failure = triangulation.failure;
      return Outcome::failed;
    }
    Fill_patch<PolygonMesh> attempt_patch;
    internal::Patch_transaction<PolygonMesh, VPM> transaction(pm, vpm, {border_halfedge});
    if (!internal::insert_front_triangulation(pm, vpm, triangulation, point_vertices,
                                              attempt_patch)) {
      if (first_failure.empty())
        first_failure = "the mesh refused a triangle of the front (non-manifold configuration)";
      transaction.rollback(attempt_patch);
      return Outcome::failed;
    }
    // A patch the front has checked itself, exactly and completely (every triangle in its final
    // position against the patch, the ring and every mesh face near the hole:
    // `Front_triangulation::exactly_checked`), needs no second check.
    if (check && !triangulation.exactly_checked) {
      const std::size_t pairs =
          internal::patch_intersections_with_mesh(pm, attempt_patch, vpm, traits, face_cache);
      if (pairs > 0) {
        if (first_failure.empty())
          first_failure = "the patch self-intersects (" + std::to_string(pairs) +
                          " pairs of intersecting faces)";
        transaction.rollback(attempt_patch);
        return Outcome::failed;
      }
    }
    if (!accept_degenerate) {
      for (const auto& t : triangulation.triangles) {
        if (internal::has_angle_below(triangulation.points[t[0]], triangulation.points[t[1]],
                                      triangulation.points[t[2]], degenerate_deg)) {
          transaction.rollback(attempt_patch);
          return Outcome::degenerate;
        }
      }
    }
    patch.faces.insert(patch.faces.end(), attempt_patch.faces.begin(), attempt_patch.faces.end());
    patch.vertices.insert(patch.vertices.end(), attempt_patch.vertices.begin(),
                          attempt_patch.vertices.end());
    return Outcome::kept;
  };

  const Variant* kept = nullptr;
  const Variant* degenerate = nullptr;
  for (const Variant& variant : variants) {
    const Outcome outcome = attempt(variant, false);
    if (outcome == Outcome::kept) {
      kept = &variant;
      break;
    }
    if (outcome == Outcome::degenerate && degenerate == nullptr) degenerate = &variant;
  }
  if (kept == nullptr && degenerate != nullptr && attempt(*degenerate, true) == Outcome::kept) {
    kept = degenerate;
    report.notes.push_back("advancing front: no patch without a triangle sharper than " +
                           std::to_string(degenerate_deg) + " degrees; kept one with");
  }
  if (kept == nullptr) {
    report.failure = first_failure.empty() ? "the front failed" : first_failure;
    return report;
  }
  if (kept != &variants.front()) {
    std::string note =
        std::string("advancing front: nodes placed on the ") + projections[kept->projection].second;
    if (kept->smoothing == 0) note += ", without relaxation";
    if (kept->size_factor != 1.0) note += ", edge length x " + std::to_string(kept->size_factor);
    if (kept->remnant && remnant_edges > 0)
      note += "; the stuck front's last " + std::to_string(remnant_edges) +
              " edges closed by a checked minimum-area triangulation";
    report.notes.push_back(note + " (first attempt: " + first_failure + ")");
  }
  report.filled = true;
  report.faces_created = patch.faces.size();
  report.vertices_created = patch.vertices.size();
  return report;
}

}  // namespace internal

/// Fills the hole of the border halfedge `border_halfedge` with the advancing front of thesis
/// section 4.4; appends what it creates to `patch`. Tries several placements (and closes stuck
/// fronts) until a patch passes the exact self-intersection check against itself, its ring and
/// the mesh near it; rejected attempts are rolled back. On failure the mesh is unchanged.
/// `fill_hole()`/`fill_holes()` add island bridging, pinch welding and their own check.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{fit_quadric}
///     \cgalParamDescription{project the new nodes onto a quadric height field fitted to the
///       vertices within two rings of the border (used only where it is a height field over
///       the hole's plane); false gives the thesis' pure tangent-plane placement}
///     \cgalParamType{bool} \cgalParamDefault{true}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{tangential relaxation passes over the new nodes after the front
///       closes}
///     \cgalParamType{unsigned int} \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{check_self_intersections}
///     \cgalParamDescription{check each candidate patch exactly; without it the first closed
///       patch is kept (the front's own exact per-triangle tests still apply)}
///     \cgalParamType{bool} \cgalParamDefault{true}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits} \cgalParamDefault{the kernel of the points} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Hole_fill_report fill_hole_advancing_front(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = typename CGAL::GetGeomTraits<PolygonMesh, NamedParameters>::type;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  using VPM = std::remove_const_t<decltype(vpm)>;
  const GT traits = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  return internal::fill_hole_advancing_front(
      pm, vpm, traits, border_halfedge, patch, internal::advancing_front_options_from(np),
      static_cast<internal::Face_box_cache<PolygonMesh, VPM>*>(nullptr));
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_ADVANCING_FRONT
extern
#endif
    template Hole_fill_report
    fill_hole_advancing_front<Core_mesh, Core_vpm, Core_traits>(
        Core_mesh&, Core_vpm, const Core_traits&, Core_halfedge, Fill_patch<Core_mesh>&,
        const Advancing_front_options&, Face_box_cache<Core_mesh, Core_vpm>*);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_ADVANCING_FRONT_H
