// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_METRICS_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_METRICS_H

// Fidelity of a filled hole against the removed patch (or an exact surface distance).
// doc/bench_holes.md defines every number.

#include <CGAL/Mesh_repair/internal/curvature_variation/measures.h>
#include <CGAL/Mesh_repair/internal/finite_distance_traits.h>
#include <CGAL/Mesh_repair/internal/hole_benchmark/punch.h>
#include <CGAL/Mesh_repair/internal/hole_benchmark/types.h>
#include <CGAL/Mesh_repair/quality.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace hole_benchmark {

// Barycentric lattice level of the samples: (n+1)(n+2)/2 = 15 points per triangle.
constexpr int sample_lattice = 4;

// The faces now covering the hole: flood from the hole side of its border halfedges without
// crossing the hole's border edges. `bounded` turns false when the flood reaches a face that was
// outside the hole (a method changed the border), and the flood stops there.
template <class PolygonMesh, class Point>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> patch_faces(
    const PolygonMesh& pm, const Punched_hole<PolygonMesh, Point>& hole, bool& bounded) {
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  std::set<halfedge_descriptor> border_side;
  std::set<face_descriptor> outside, seen;
  std::vector<face_descriptor> stack, patch;
  for (const auto& entry : hole.border) {
    border_side.insert(entry.first);
    border_side.insert(opposite(entry.first, pm));
    outside.insert(face(opposite(entry.first, pm), pm));
  }
  for (const auto& entry : hole.border) {
    const face_descriptor f = face(entry.first, pm);
    if (f != GT::null_face() && !outside.count(f) && seen.insert(f).second) stack.push_back(f);
  }
  bounded = true;
  while (!stack.empty()) {
    const face_descriptor f = stack.back();
    stack.pop_back();
    patch.push_back(f);
    for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, pm), pm)) {
      if (border_side.count(h)) continue;
      const face_descriptor g = face(opposite(h, pm), pm);
      if (g == GT::null_face() || seen.count(g)) continue;
      if (outside.count(g)) {
        bounded = false;
        return patch;
      }
      seen.insert(g);
      stack.push_back(g);
    }
  }
  return patch;
}

// Weighted distance samples: E1 = sum w d / sum w, E2 = sqrt(sum w d^2 / sum w), Einf = max d.
struct Error_accumulator {
  double weight = 0, weighted_sum = 0, weighted_square_sum = 0, maximum = 0;
  std::size_t count = 0;
  void add(double distance, double w) {
    weight += w;
    weighted_sum += w * distance;
    weighted_square_sum += w * distance * distance;
    maximum = std::max(maximum, distance);
    ++count;
  }
  void store(double& e1, double& e2, double& einf) const {
    if (count == 0 || weight <= 0) return;
    e1 = weighted_sum / weight;
    e2 = std::sqrt(weighted_square_sum / weight);
    einf = maximum;
  }
};

template <class Point>
class Truth_distance {
 public:
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Truth_mesh = CGAL::Surface_mesh<Point>;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Truth_mesh>;
  using Tree = Distance_tree<Kernel, Primitive>;

  Truth_distance(const Truth_mesh& truth, const std::function<double(const Point&)>& exact)
      : exact_(exact) {
    if (!exact_) {
      tree_.insert(faces(truth).first, faces(truth).second, truth);
      tree_.accelerate_distance_queries();
    }
  }
  double operator()(const Point& p) const {
    if (exact_) return std::abs(exact_(p));
    return std::sqrt(CGAL::to_double(tree_.squared_distance(p)));
  }

 private:
  std::function<double(const Point&)> exact_;
  Tree tree_;
};

template <class PolygonMesh, class VertexPointMap, class Point>
void measure_distances(
    const PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& patch,
    const Punched_hole<PolygonMesh, Point>& hole,
    const std::function<double(const Point&)>& exact_distance, double diagonal,
    Hole_fill_metrics& m) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  const Truth_distance<Point> distance(hole.removed_patch, exact_distance);
  std::set<vertex_descriptor> border_vertices, new_vertices;
  for (const auto& entry : hole.border) border_vertices.insert(target(entry.first, pm));
  Error_accumulator samples, nodes;
  const int n = sample_lattice;
  const double per_triangle = double((n + 1) * (n + 2) / 2);
  for (auto f : patch) {
    std::vector<vertex_descriptor> corners;
    for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, pm), pm)) {
      corners.push_back(v);
      if (!border_vertices.count(v)) new_vertices.insert(v);
    }
    // A polygonal face is sampled as a fan of triangles.
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      const Point &a = get(vpm, corners[0]), &b = get(vpm, corners[k]),
                  &c = get(vpm, corners[k + 1]);
      const double area = std::sqrt(CGAL::to_double(CGAL::squared_area(a, b, c)));
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; i + j <= n; ++j) {
          const double u = double(i) / n, v = double(j) / n, w = 1.0 - u - v;
          const Point p = CGAL::barycenter(a, u, b, v, c, w);
          samples.add(distance(p), area / per_triangle);
        }
      }
    }
  }
  for (vertex_descriptor v : new_vertices) nodes.add(distance(get(vpm, v)), 1.0);
  m.samples = samples.count;
  m.patch_vertices = new_vertices.size();
  samples.store(m.e1, m.e2, m.einf);
  nodes.store(m.e1_nodes, m.e2_nodes, m.einf_nodes);
  if (diagonal > 0 && samples.count > 0) {
    m.e1_rel = m.e1 / diagonal;
    m.e2_rel = m.e2 / diagonal;
    m.einf_rel = m.einf / diagonal;
  }
}

template <class PolygonMesh, class VertexPointMap, class Point>
void measure_hausdorff(
    const PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& patch,
    const Punched_hole<PolygonMesh, Point>& hole, double diagonal, Hole_fill_metrics& m) {
  const CGAL::Surface_mesh<Point> patch_mesh = extract_faces<Point>(pm, vpm, patch);
  if (patch_mesh.is_empty() || !CGAL::is_triangle_mesh(patch_mesh) || hole.removed_patch.is_empty())
    return;
  m.hausdorff = CGAL::Polygon_mesh_processing::bounded_error_symmetric_Hausdorff_distance<
      CGAL::Sequential_tag>(patch_mesh, hole.removed_patch, 1e-4 * diagonal);
  if (diagonal > 0) m.hausdorff_rel = m.hausdorff / diagonal;
}

// |angle(patch face, outside face) - angle(removed face, outside face)| over the border edges.
template <class PolygonMesh, class VertexPointMap, class Point>
void measure_normal_deviation(const PolygonMesh& pm, VertexPointMap vpm,
                              const Punched_hole<PolygonMesh, Point>& hole, Hole_fill_metrics& m) {
  using GT = boost::graph_traits<PolygonMesh>;
  double maximum = 0, sum = 0;
  std::size_t count = 0;
  for (const auto& [h, true_angle] : hole.border) {
    if (face(h, pm) == GT::null_face()) continue;
    const double angle = face_angle_deg(face(h, pm), face(opposite(h, pm), pm), pm, vpm);
    const double deviation = std::abs(angle - true_angle);
    maximum = std::max(maximum, deviation);
    sum += deviation;
    ++count;
  }
  if (count == 0) return;
  m.normal_deviation_max_deg = maximum;
  m.normal_deviation_mean_deg = sum / double(count);
}

// Curvature jump across the hole's contour (Pernot 7, the measure of curvature_variation's
// benchmark): the contour is every vertex of the hole's border, the patch side the other vertices
// of the patch faces.
template <class PolygonMesh, class VertexPointMap, class Point>
void measure_curvature_jump(
    const PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& patch,
    const Punched_hole<PolygonMesh, Point>& hole, double diagonal, Hole_fill_metrics& m) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::set<vertex_descriptor> contour;
  for (const auto& entry : hole.border) {
    contour.insert(source(entry.first, pm));
    contour.insert(target(entry.first, pm));
  }
  Fill_patch<PolygonMesh> fill;
  fill.faces = patch;
  std::set<vertex_descriptor> inner;
  for (auto f : patch)
    for (auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
      if (!contour.count(v) && inner.insert(v).second) fill.vertices.push_back(v);
  if (fill.vertices.empty()) return;  // no inner vertex: no patch-side curvature
  m.curvature_jump = curvature_variation::contour_curvature_jump(pm, vpm, fill, diagonal);
}

template <class PolygonMesh, class VertexPointMap>
void measure_quality(
    const PolygonMesh& pm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& patch,
    Hole_fill_metrics& m) {
  if (patch.empty()) return;
  double min_alpha = 1, sum_alpha = 0, min_angle = 180;
  std::size_t triangles = 0;
  for (auto f : patch) {
    std::vector<typename boost::property_traits<VertexPointMap>::value_type> p;
    for (auto v : CGAL::vertices_around_face(halfedge(f, pm), pm)) p.push_back(get(vpm, v));
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      const double a = alpha(p[0], p[k], p[k + 1]);
      min_alpha = std::min(min_alpha, a);
      sum_alpha += a;
      min_angle = std::min(min_angle, min_max_angle_deg(p[0], p[k], p[k + 1]).first);
      ++triangles;
    }
  }
  m.min_alpha = min_alpha;
  m.mean_alpha = sum_alpha / double(std::max<std::size_t>(1, triangles));
  m.min_angle_deg = min_angle;
}

template <class PolygonMesh, class Point>
void measure_closure(
    const PolygonMesh& pm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& patch,
    const Punched_hole<PolygonMesh, Point>& hole, Hole_fill_metrics& m) {
  using GT = boost::graph_traits<PolygonMesh>;
  m.filled = !hole.border.empty();
  for (const auto& entry : hole.border)
    if (face(entry.first, pm) == GT::null_face()) m.filled = false;
  m.closed = m.filled && m.bounded;
  for (auto f : patch)
    for (auto h : CGAL::halfedges_around_face(halfedge(f, pm), pm))
      if (CGAL::is_border(opposite(h, pm), pm)) m.closed = false;
}

}  // namespace hole_benchmark
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_METRICS_H
