// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_IMPLANT_PATCH_H
#define CGAL_MESH_REPAIR_IMPLANT_PATCH_H

/// \file implant_patch.h
/// Implant patches (thesis 6.2): a fill patch written as its own mesh, for instance the plate
/// that covers a skull defect, optionally thickened into a closed solid. See
/// doc/shape_prediction.md.

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// A new mesh made of the faces `faces` of `pm` (for instance `Fill_patch::faces`), with their
/// orientation.
template <class PolygonMesh, class FaceRange>
PolygonMesh extract_patch(const PolygonMesh& pm, const FaceRange& faces) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::const_type>::value_type;
  const auto vpm = get(CGAL::vertex_point, pm);
  std::unordered_map<vertex_descriptor, std::size_t> index;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  for (auto f : faces) {
    std::vector<std::size_t> polygon;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, pm), pm)) {
      auto inserted = index.emplace(v, points.size());
      if (inserted.second) points.push_back(get(vpm, v));
      polygon.push_back(inserted.first->second);
    }
    polygons.push_back(polygon);
  }
  PolygonMesh patch;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, patch);
  return patch;
}

/// A closed solid of thickness `thickness` from the open surface `patch`: the patch, a copy
/// offset by `thickness` against its angle-weighted vertex normals (eq. 5.30) with reversed
/// orientation, and a wall of two triangles per border edge. The offset is along normals, so
/// it stays free of self-intersections only while `thickness` is below the patch's smallest
/// radius of curvature.
template <class PolygonMesh>
PolygonMesh thicken_patch(const PolygonMesh& patch, double thickness) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::const_type>::value_type;
  const auto vpm = get(CGAL::vertex_point, patch);
  std::unordered_map<vertex_descriptor, std::size_t> index;
  std::vector<Point> points;
  for (vertex_descriptor v : vertices(patch)) {
    index.emplace(v, points.size());
    points.push_back(get(vpm, v));
  }
  const std::size_t n = points.size();
  std::vector<std::array<double, 3>> normal(n, {0, 0, 0});
  std::vector<std::vector<std::size_t>> polygons;
  for (auto f : faces(patch)) {
    std::vector<std::size_t> ids;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, patch), patch))
      ids.push_back(index[v]);
    polygons.push_back(ids);
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const Point& p = points[ids[k]];
      const auto a = points[ids[(k + ids.size() - 1) % ids.size()]] - p;
      const auto b = points[ids[(k + 1) % ids.size()]] - p;
      const auto c = CGAL::cross_product(b, a);
      const double lc = std::sqrt(CGAL::to_double(c.squared_length()));
      const double la = std::sqrt(CGAL::to_double(a.squared_length()));
      const double lb = std::sqrt(CGAL::to_double(b.squared_length()));
      if (lc == 0 || la == 0 || lb == 0) continue;
      const double angle =
          std::acos(std::max(-1.0, std::min(1.0, CGAL::to_double(a * b) / (la * lb))));
      for (int d = 0; d < 3; ++d) normal[ids[k]][d] += angle * CGAL::to_double(c[d]) / lc;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto& m = normal[i];
    const double l = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const Point& p = points[i];
    const double s = l > 0 ? thickness / l : 0;
    points.push_back(Point(p.x() - s * m[0], p.y() - s * m[1], p.z() - s * m[2]));
  }
  const std::size_t top_faces = polygons.size();
  for (std::size_t k = 0; k < top_faces; ++k) {
    std::vector<std::size_t> bottom(polygons[k].rbegin(), polygons[k].rend());
    for (std::size_t& id : bottom) id += n;
    polygons.push_back(bottom);
  }
  for (auto h : halfedges(patch)) {
    if (!is_border(h, patch)) continue;
    const std::size_t s = index[source(h, patch)], t = index[target(h, patch)];
    polygons.push_back({s, t, t + n});
    polygons.push_back({s, t + n, s + n});
  }
  PolygonMesh solid;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, solid);
  return solid;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_IMPLANT_PATCH_H
