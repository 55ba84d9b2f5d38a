// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_CUBIC_SURFACE_H
#define CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_CUBIC_SURFACE_H

// The smooth surface the micro-GA projects onto (Chen et al. 2.2): one cubic Bezier triangle per
// primary triangle, built from vertex positions and vertex normals estimated by local derivative
// estimation (a weighted quadratic height fit in each vertex's tangent plane).
//
// Every ordinate on a patch edge depends only on the edge's two vertices and their normals, so
// neighbouring patches share their boundary curve (no cracks), and all patches at a vertex share
// its tangent plane. Across the interior of an edge the tangent plane of a surface mesh can only
// be matched by a split scheme with compatible twists; for functional data that is the
// Clough-Tocher interpolant of clough_tocher.h (C1, Table 1). doc/mga_smooth.md explains the
// choice. At feature vertices (dihedral angle below the feature angle) each smooth sector of faces
// gets its own normal, so sharp edges stay sharp.
//
// A point is mapped onto the surface as the paper does: locate it in a primary triangle (walking
// from a nearby start triangle over the triangles' planes) and evaluate that triangle's patch at
// its barycentric coordinates.

#include <CGAL/Mesh_repair/internal/c1_surface/local_derivative_estimation.h>
#include <CGAL/Mesh_repair/internal/c1_surface/vec3.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

class Cubic_surface {
 public:
  using Triangle = std::array<int, 3>;
  struct Location {
    int triangle = -1;
    double b[3] = {1, 0, 0};
  };

  /// `feature_angle_deg`: an edge whose dihedral angle is below it is a feature edge.
  /// `cubic_weight` w: the surface points are flat + w (cubic - flat), between the flat primary
  /// triangle (w = 0) and its cubic patch (w = 1), at the same barycentric coordinates.
  Cubic_surface(std::vector<Vec3> points, std::vector<Triangle> triangles, double feature_angle_deg,
                double cubic_weight = 1.0)
      : points_(std::move(points)), triangles_(std::move(triangles)) {
    build_adjacency();
    mark_feature_edges(feature_angle_deg);
    compute_corner_normals();
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      nets_.push_back(blend_with_flat(control_net(int(t)), cubic_weight));
      frames_.push_back(plane_frame(int(t)));
    }
  }

  std::size_t number_of_vertices() const { return points_.size(); }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const std::vector<Vec3>& points() const { return points_; }
  /// A triangle incident to vertex `v`, or -1.
  int triangle_of_vertex(int v) const { return vertex_triangle_[v]; }
  bool is_feature_vertex(int v) const { return feature_vertex_[v]; }
  bool is_border_vertex(int v) const { return border_vertex_[v]; }
  /// The estimated unit normal at `v` (for a feature vertex, that of its first sector).
  const Vec3& vertex_normal(int v) const { return vertex_normal_[v]; }

  /// Locates `p` in a primary triangle, walking from `start` across the edge with the most
  /// negative barycentric coordinate; outside the surface or after a bounded walk the
  /// coordinates are clamped to the last triangle.
  Location locate(const Vec3& p, int start) const {
    Location location;
    int current = start, previous = -1;
    for (int step = 0; step < 32; ++step) {
      plane_barycentric(current, p, location.b);
      int worst = 0;
      for (int i = 1; i < 3; ++i)
        if (location.b[i] < location.b[worst]) worst = i;
      const int next = neighbour_[3 * current + worst];
      if (location.b[worst] >= 0 || next < 0 || next == previous) break;
      previous = current;
      current = next;
    }
    location.triangle = current;
    clamp(location.b);
    return location;
  }

  /// The surface point at a location: flat + w (patch - flat).
  Vec3 evaluate(const Location& location) const {
    const auto& net = nets_[location.triangle];
    const double u = location.b[0], v = location.b[1], w = location.b[2];
    const double uu = u * u, vv = v * v, ww = w * w;
    const double weights[10] = {uu * u,     vv * v,     ww * w,     3 * uu * v, 3 * uu * w,
                                3 * vv * u, 3 * vv * w, 3 * ww * u, 3 * ww * v, 6 * u * v * w};
    Vec3 sum;
    for (int i = 0; i < 10; ++i) sum += weights[i] * net[i];
    return sum;
  }

  /// Maps `p` onto the surface; `host` is the start triangle and receives the one found.
  Vec3 project(const Vec3& p, int& host) const {
    const Location location = locate(p, host);
    host = location.triangle;
    return evaluate(location);
  }

 private:
  // Ordinates: b300 b030 b003 b210 b201 b120 b021 b102 b012 b111 (u, v, w for the corners 0 1 2).
  using Net = std::array<Vec3, 10>;

  void build_adjacency() {
    const std::size_t n = points_.size();
    neighbour_.assign(3 * triangles_.size(), -1);
    vertex_triangle_.assign(n, -1);
    incident_.assign(n, {});
    // Directed edges (a, b, slot of the opposite corner), sorted so that a twin (b, a) is found by
    // binary search: cheaper than a map for the ~150,000 edges of a 50,000-triangle mesh.
    std::vector<std::array<int, 3>> half_edges;
    half_edges.reserve(3 * triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      for (int i = 0; i < 3; ++i) {
        half_edges.push_back(
            {triangles_[t][(i + 1) % 3], triangles_[t][(i + 2) % 3], int(3 * t + i)});
        incident_[triangles_[t][i]].push_back(int(t));
        vertex_triangle_[triangles_[t][i]] = int(t);
      }
    }
    std::sort(half_edges.begin(), half_edges.end());
    border_vertex_.assign(n, false);
    for (const auto& h : half_edges) {
      const std::array<int, 3> key = {h[1], h[0], -1};
      auto twin = std::lower_bound(half_edges.begin(), half_edges.end(), key);
      if (twin != half_edges.end() && (*twin)[0] == h[1] && (*twin)[1] == h[0]) {
        neighbour_[h[2]] = (*twin)[2] / 3;
      } else {
        border_vertex_[h[0]] = border_vertex_[h[1]] = true;
      }
    }
    face_normal_.resize(triangles_.size());
    face_area_.resize(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const Vec3 n =
          cross(point(int(t), 1) - point(int(t), 0), point(int(t), 2) - point(int(t), 0));
      face_area_[t] = 0.5 * length(n);
      face_normal_[t] = normalized(n);
    }
  }

  const Vec3& point(int t, int corner) const { return points_[triangles_[t][corner]]; }

  void mark_feature_edges(double feature_angle_deg) {
    // Dihedral angle = pi - angle between the normals; below the threshold = sharp.
    const double cos_limit = std::cos(CGAL_PI - feature_angle_deg * CGAL_PI / 180.0);
    feature_edge_.assign(neighbour_.size(), false);
    feature_vertex_.assign(points_.size(), false);
    for (std::size_t slot = 0; slot < neighbour_.size(); ++slot) {
      const int other = neighbour_[slot];
      if (other < 0) continue;
      const int t = int(slot / 3);
      if (dot(face_normal_[t], face_normal_[other]) < cos_limit) feature_edge_[slot] = true;
    }
    prune_feature_spurs();
    for (std::size_t slot = 0; slot < neighbour_.size(); ++slot) {
      if (!feature_edge_[slot]) continue;
      feature_vertex_[triangles_[slot / 3][(slot + 1) % 3]] = true;
      feature_vertex_[triangles_[slot / 3][(slot + 2) % 3]] = true;
    }
  }

  // A feature is a line of sharp edges. A sharp edge that sticks out of a vertex where no other
  // sharp edge continues it is a spur: on a scan, noise makes many such short dangling pieces
  // (femur.off: 610 vertices end a single sharp edge, fandisk.off: 2). Spurs of up to
  // `max_spur_edges` edges are unmarked (removed from their free end, so a spur that reaches a
  // junction or a longer line keeps that line intact); longer dangling lines are kept, and a line
  // that ends on the border does not dangle.
  void prune_feature_spurs() {
    constexpr int max_spur_edges = 2;
    std::vector<int> degree(points_.size(), 0);
    auto ends = [&](std::size_t slot) {
      const Triangle& t = triangles_[slot / 3];
      return std::array<int, 2>{t[(slot + 1) % 3], t[(slot + 2) % 3]};
    };
    for (std::size_t slot = 0; slot < neighbour_.size(); ++slot)
      if (feature_edge_[slot] && int(slot / 3) < neighbour_[slot])  // each edge once
        for (int v : ends(slot)) ++degree[v];
    for (int pass = 0; pass < max_spur_edges; ++pass) {
      std::vector<std::size_t> spur_slots;
      for (std::size_t slot = 0; slot < neighbour_.size(); ++slot) {
        if (!feature_edge_[slot]) continue;
        const auto e = ends(slot);
        auto free_end = [&](int v) { return degree[v] == 1 && !border_vertex_[v]; };
        if (free_end(e[0]) || free_end(e[1])) spur_slots.push_back(slot);
      }
      if (spur_slots.empty()) break;
      for (std::size_t slot : spur_slots) {
        if (!feature_edge_[slot]) continue;
        if (int(slot / 3) < neighbour_[slot])
          for (int v : ends(slot)) --degree[v];
        feature_edge_[slot] = false;
      }
    }
  }

  bool shares_smooth_edge(int t, int u, int v) const {
    for (int i = 0; i < 3; ++i)
      if (neighbour_[3 * t + i] == u && triangles_[t][i] != v) return !feature_edge_[3 * t + i];
    return false;
  }

  void compute_corner_normals() {
    vertex_normal_.resize(points_.size());
    corner_normal_.resize(3 * triangles_.size());
    for (std::size_t v = 0; v < points_.size(); ++v) {
      if (incident_[v].empty()) continue;
      if (feature_vertex_[v]) {
        sector_normals(int(v));
      } else {
        vertex_normal_[v] = fitted_normal(int(v));
        for (int t : incident_[v]) corner_normal_[3 * t + corner_of(t, int(v))] = vertex_normal_[v];
      }
    }
  }

  int corner_of(int t, int v) const {
    return triangles_[t][0] == v ? 0 : (triangles_[t][1] == v ? 1 : 2);
  }

  // Faces around a feature vertex joined across smooth edges form sectors; each sector's normal
  // is the area-weighted mean of its faces' normals.
  void sector_normals(int v) {
    const auto& faces = incident_[v];
    std::vector<int> sector(faces.size());
    std::iota(sector.begin(), sector.end(), 0);
    auto find = [&](int i) {
      while (sector[i] != i) i = sector[i] = sector[sector[i]];
      return i;
    };
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j)
        if (shares_smooth_edge(faces[i], faces[j], v)) sector[find(int(i))] = find(int(j));
    std::vector<Vec3> sum(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i)
      sum[find(int(i))] += face_area_[faces[i]] * face_normal_[faces[i]];
    for (std::size_t i = 0; i < faces.size(); ++i)
      corner_normal_[3 * faces[i] + corner_of(faces[i], v)] = normalized(sum[find(int(i))]);
    vertex_normal_[v] = corner_normal_[3 * faces[0] + corner_of(faces[0], v)];
  }

  // Local derivative estimation on the surface: fit a height function over the tangent plane of
  // the area-weighted normal; the fitted gradient tilts that normal.
  Vec3 fitted_normal(int v) const {
    Vec3 first;
    // The ring as a sorted vector (the order of a std::set, without its allocations per node).
    static thread_local std::vector<int> ring;
    ring.clear();
    auto sort_unique = [] {
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    };
    for (int t : incident_[v]) {
      first += face_area_[t] * face_normal_[t];
      for (int c : triangles_[t]) ring.push_back(c);
    }
    sort_unique();
    first = normalized(first);
    if (ring.size() < 6) {
      const std::size_t one_ring = ring.size();
      for (std::size_t i = 0; i < one_ring; ++i)
        for (int t : incident_[ring[i]])
          for (int c : triangles_[t]) ring.push_back(c);
      sort_unique();
    }
    ring.erase(std::lower_bound(ring.begin(), ring.end(), v));
    Vec3 t1, t2;
    tangent_frame(first, t1, t2);
    static thread_local std::vector<Height_sample> samples;
    samples.clear();
    for (int n : ring) {
      const Vec3 d = points_[n] - points_[v];
      samples.push_back({dot(d, t1), dot(d, t2), dot(d, first)});
    }
    const auto gradient = estimate_gradient(samples);
    const Vec3 tilted = normalized(first - gradient[0] * t1 - gradient[1] * t2);
    // A wild fit (noisy or folded neighbourhood) must not flip the normal.
    return dot(tilted, first) > 0.5 ? tilted : first;
  }

  Net control_net(int t) const {
    const Vec3 &p0 = point(t, 0), &p1 = point(t, 1), &p2 = point(t, 2);
    const Vec3 &n0 = corner_normal_[3 * t], &n1 = corner_normal_[3 * t + 1],
               &n2 = corner_normal_[3 * t + 2];
    // Edge ordinate next to corner a toward b: one third along the edge, pulled into a's tangent
    // plane (depends on a, b and a's normal only, so both patches of an edge agree).
    auto edge = [](const Vec3& a, const Vec3& b, const Vec3& na) {
      return (1.0 / 3.0) * (2.0 * a + b - dot(b - a, na) * na);
    };
    Net b;
    b[0] = p0, b[1] = p1, b[2] = p2;
    b[3] = edge(p0, p1, n0), b[4] = edge(p0, p2, n0);
    b[5] = edge(p1, p0, n1), b[6] = edge(p1, p2, n1);
    b[7] = edge(p2, p0, n2), b[8] = edge(p2, p1, n2);
    Vec3 edge_mean;
    for (int i = 3; i < 9; ++i) edge_mean += (1.0 / 6.0) * b[i];
    const Vec3 centroid = (1.0 / 3.0) * (p0 + p1 + p2);
    b[9] = edge_mean + 0.5 * (edge_mean - centroid);
    return b;
  }

  // flat + w (patch - flat) is itself a cubic Bezier triangle: the flat triangle, degree-elevated
  // to three, has its ordinates at the thirds of the edges and at the centroid, so blending the
  // nets blends the surfaces (no cost per evaluation). Both patches of an edge blend the same
  // edge ordinates with the same chord points: still no crack.
  static Net blend_with_flat(Net net, double w) {
    if (w == 1) return net;
    const Vec3 p[3] = {net[0], net[1], net[2]};
    // Ordinates 3..8: b210 b201 b120 b021 b102 b012, i.e. next to corner a toward corner b.
    const int a[6] = {0, 0, 1, 1, 2, 2}, b[6] = {1, 2, 0, 2, 0, 1};
    for (int i = 0; i < 6; ++i) {
      const Vec3 flat = (1.0 / 3.0) * (2.0 * p[a[i]] + p[b[i]]);
      net[3 + i] = flat + w * (net[3 + i] - flat);
    }
    const Vec3 centroid = (1.0 / 3.0) * (p[0] + p[1] + p[2]);
    net[9] = centroid + w * (net[9] - centroid);
    return net;
  }

  // What the barycentric coordinates of a point projected on a triangle's plane need, computed
  // once: the walk evaluates them millions of times.
  struct Plane_frame {
    Vec3 origin, e1, e2;
    double d00 = 0, d01 = 0, d11 = 0, inverse_denominator = 0;
  };

  Plane_frame plane_frame(int t) const {
    Plane_frame f;
    f.origin = point(t, 0);
    f.e1 = point(t, 1) - point(t, 0), f.e2 = point(t, 2) - point(t, 0);
    f.d00 = dot(f.e1, f.e1), f.d01 = dot(f.e1, f.e2), f.d11 = dot(f.e2, f.e2);
    const double denominator = f.d00 * f.d11 - f.d01 * f.d01;
    f.inverse_denominator = denominator > 0 ? 1.0 / denominator : 0;
    return f;
  }

  void plane_barycentric(int t, const Vec3& p, double* b) const {
    const Plane_frame& f = frames_[t];
    if (f.inverse_denominator == 0) {  // degenerate primary triangle: stay at its first corner
      b[0] = 1, b[1] = b[2] = 0;
      return;
    }
    const Vec3 d = p - f.origin;
    const double d20 = dot(d, f.e1), d21 = dot(d, f.e2);
    b[1] = (f.d11 * d20 - f.d01 * d21) * f.inverse_denominator;
    b[2] = (f.d00 * d21 - f.d01 * d20) * f.inverse_denominator;
    b[0] = 1 - b[1] - b[2];
  }

  static void clamp(double* b) {
    double sum = 0;
    for (int i = 0; i < 3; ++i) sum += (b[i] = std::max(0.0, b[i]));
    if (sum <= 0) {
      b[0] = 1, b[1] = b[2] = 0;
      return;
    }
    for (int i = 0; i < 3; ++i) b[i] /= sum;
  }

  std::vector<Vec3> points_;
  std::vector<Triangle> triangles_;
  std::vector<int> neighbour_;  // 3 t + i -> triangle across the edge opposite corner i, or -1
  std::vector<bool> feature_edge_;
  std::vector<int> vertex_triangle_;
  std::vector<std::vector<int>> incident_;
  std::vector<bool> border_vertex_, feature_vertex_;
  std::vector<Vec3> face_normal_;
  std::vector<double> face_area_;
  std::vector<Vec3> vertex_normal_, corner_normal_;
  std::vector<Net> nets_;
  std::vector<Plane_frame> frames_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_CUBIC_SURFACE_H
