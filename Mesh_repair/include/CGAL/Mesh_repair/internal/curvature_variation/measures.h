// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MEASURES_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MEASURES_H

// What the comparison with Liepa's fairing (Pernot 7, Fig. 13) measures across a hole contour:
// the discrete mean curvature on both sides of the contour, the dihedral angle across the
// former border edges, and a simple ball-shaped hole punch for tests and benchmarks.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

/// Discrete mean curvature magnitude at v: |cotangent Laplacian| / (2 x barycentric area).
template <class PolygonMesh, class VertexPointMap>
double mean_curvature(const PolygonMesh& pm, VertexPointMap vpm,
                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor v) {
  Vec3 laplacian{0, 0, 0};
  double area = 0;
  const Vec3 pv = to_array(get(vpm, v));
  for (auto h : CGAL::halfedges_around_target(v, pm)) {
    const Vec3 pu = to_array(get(vpm, source(h, pm)));
    double weight = 0;
    for (auto g : {h, opposite(h, pm)}) {
      if (is_border(g, pm)) continue;
      const Vec3 pw = to_array(get(vpm, target(next(g, pm), pm)));
      const Vec3 a = sub(pv, pw), b = sub(pu, pw);
      const double s = norm(cross(a, b));
      if (s > 0) weight += 0.5 * dot(a, b) / s;
    }
    for (int k = 0; k < 3; ++k) laplacian[k] += weight * (pu[k] - pv[k]);
    if (!is_border(h, pm)) {
      const Vec3 pw = to_array(get(vpm, target(next(h, pm), pm)));
      area += norm(cross(sub(pu, pv), sub(pw, pv))) / 6.0;
    }
  }
  return area > 0 ? norm(laplacian) / (2.0 * area) : 0.0;
}

/// Curvature jump across the contour of one patch: for each contour vertex, the mean curvature
/// averaged over its patch-side neighbours minus the one averaged over its outside neighbours,
/// in absolute value, averaged over the contour. Multiplied by `scale` (e.g. the bounding-box
/// diagonal) so that it is dimensionless.
template <class PolygonMesh, class VertexPointMap>
double contour_curvature_jump(const PolygonMesh& pm, VertexPointMap vpm,
                              const Fill_patch<PolygonMesh>& patch, double scale) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::set<vertex_descriptor> inner(patch.vertices.begin(), patch.vertices.end());
  std::set<vertex_descriptor> contour;
  std::set<vertex_descriptor> patch_face_vertices;
  for (auto f : patch.faces)
    for (auto v : CGAL::vertices_around_face(halfedge(f, pm), pm)) {
      patch_face_vertices.insert(v);
      if (!inner.count(v)) contour.insert(v);
    }
  double jump_sum = 0;
  std::size_t counted = 0;
  for (auto c : contour) {
    double inside = 0, outside = 0;
    int n_in = 0, n_out = 0;
    for (auto u : CGAL::vertices_around_target(halfedge(c, pm), pm)) {
      if (inner.count(u)) {
        inside += mean_curvature(pm, vpm, u);
        ++n_in;
      } else if (!patch_face_vertices.count(u)) {
        outside += mean_curvature(pm, vpm, u);
        ++n_out;
      }
    }
    if (n_in == 0 || n_out == 0) continue;
    jump_sum += std::abs(inside / n_in - outside / n_out);
    ++counted;
  }
  return counted > 0 ? scale * jump_sum / double(counted) : 0.0;
}

/// Mean angle (degrees) between the normals of the two faces of each edge joining two contour
/// vertices with one face in the patch and one outside (the former border edges).
template <class PolygonMesh, class VertexPointMap>
double contour_normal_deviation_deg(const PolygonMesh& pm, VertexPointMap vpm,
                                    const Fill_patch<PolygonMesh>& patch) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::set<face_descriptor> patch_faces(patch.faces.begin(), patch.faces.end());
  auto normal = [&](face_descriptor f) {
    auto h = halfedge(f, pm);
    const Vec3 a = to_array(get(vpm, source(h, pm))), b = to_array(get(vpm, target(h, pm))),
               c = to_array(get(vpm, target(next(h, pm), pm)));
    Vec3 n = cross(sub(b, a), sub(c, a));
    const double l = norm(n);
    if (l > 0)
      for (double& x : n) x /= l;
    return n;
  };
  double sum = 0;
  std::size_t count = 0;
  for (auto f : patch.faces)
    for (auto h : CGAL::halfedges_around_face(halfedge(f, pm), pm)) {
      auto o = opposite(h, pm);
      if (is_border(o, pm) || patch_faces.count(face(o, pm))) continue;
      const double cosine = std::clamp(dot(normal(f), normal(face(o, pm))), -1.0, 1.0);
      sum += std::acos(cosine) * 180.0 / CGAL_PI;
      ++count;
    }
  return count > 0 ? sum / double(count) : 0.0;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MEASURES_H
