// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_ADVANCING_FRONT_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_ADVANCING_FRONT_H

/// \file advancing_front.h
/// The heuristic element-filling algorithm of thesis section 4.4: an advancing front from the
/// hole's border that closes the corner of smallest angle with one triangle (< 75 degrees), two
/// (75-135) or three (> 135), places new nodes from averaged neighbour normals (eq. 4.8-4.12) at
/// the mean adjacent edge length, merges nodes closer than half an edge length, and checks every
/// new triangle against the front with exact predicates. New nodes are projected onto a quadric
/// fitted to the hole's surroundings, so curved holes are filled curved. See
/// doc/advancing_front.md.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/front_mesh.h>
#include <CGAL/Mesh_repair/internal/hole_filling/guide_surface.h>
#include <CGAL/Mesh_repair/internal/hole_filling/quadric_fit.h>
#include <CGAL/Mesh_repair/parameters.h>

#include <algorithm>
#include <memory>
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
                                 typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h) {
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
  return [quadric](const Vec3& p, const Vec3&) { return quadric->project(p); };
}

/// The edge length wanted inside the hole: an inverse-square-distance blend of the border's
/// edge lengths, so the patch's density matches its surroundings everywhere (thesis 4.4) without
/// the drift of taking each node's two adjacent front edges, which shrink layer after layer
/// (see doc/advancing_front.md). The border is summarised by at most 64 runs of edges.
inline Front_size border_density(const Front_input& input) {
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
  return [samples](const Vec3& at, double adjacent) {
    double weights = 0, blend = 0;
    for (const auto& sample : *samples) {
      const double d2 = dot(sub(at, sample.first), sub(at, sample.first));
      if (d2 == 0) return sample.second;
      weights += 1.0 / d2;
      blend += sample.second / d2;
    }
    return weights > 0 ? blend / weights : adjacent;
  };
}

}  // namespace internal

/// Fills the hole of the border halfedge `border_halfedge` with the advancing front of thesis
/// section 4.4; appends what it creates to `patch`. Only `fill_hole()`/`fill_holes()` check
/// and roll back patches: call those unless you check the patch yourself.
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
///   \cgalParamNBegin{vertex_point_map} \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Hole_fill_report fill_hole_advancing_front(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    Fill_patch<PolygonMesh>& patch, const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  const bool fit = choose_parameter(get_parameter(np, internal_np::fit_quadric_t()), true);
  internal::Front_options options;
  options.smoothing_iterations =
      int(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 3u));

  Hole_fill_report report;
  report.requested = report.used = Fill_method::advancing_front;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> point_vertices;
  const internal::Front_input input =
      internal::front_input_from_border(pm, vpm, border_halfedge, point_vertices);
  const internal::Front_size size = internal::border_density(input);
  const internal::Front_projection projection =
      fit ? internal::hole_projection(pm, vpm, border_halfedge)
          : internal::Front_projection(
                [](const internal::Vec3& p, const internal::Vec3&) { return p; });
  const internal::Front_triangulation triangulation =
      internal::advance_front(input, projection, size, options);
  if (!triangulation.closed) {
    report.failure = triangulation.failure;
    return report;
  }
  if (!internal::insert_front_triangulation(pm, vpm, triangulation, point_vertices, patch)) {
    report.failure = "the mesh refused a triangle of the front (non-manifold configuration)";
    return report;
  }
  report.filled = true;
  report.faces_created = patch.faces.size();
  report.vertices_created = patch.vertices.size();
  return report;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_ADVANCING_FRONT_H
