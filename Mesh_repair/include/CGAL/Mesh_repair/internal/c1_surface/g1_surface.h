// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_G1_SURFACE_H
#define CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_G1_SURFACE_H

// The smooth surface the micro-GA projects onto (Chen et al. 2.2): one triangular Bezier patch
// per primary triangle, built from vertex positions and vertex normals estimated by local
// derivative estimation (a weighted quadratic height fit in each vertex's tangent plane).
//
// The patches are the quartic G1 patches of Walton and Meek that shape prediction already uses
// (shape_prediction/bezier_patches.h): every edge gets one cubic boundary curve whose end
// tangents lie in the vertex tangent planes, computed once and shared by the edge's two
// triangles (no crack), and each patch's interior control points blend cross-boundary
// constructions that make its tangent plane along an edge depend on that edge's curve and end
// normals only. Two patches of a smooth edge therefore have the same tangent plane all along it:
// the surface is tangent-plane continuous (G1) over the whole mesh, not only at the vertices.
// (Goodman and Said's C1 split, clough_tocher.h, needs a common parameter plane: functional data
// of Table 1.)
//
// `tangent_scale` s in [0, 1] shortens both end tangents of every boundary curve to s times
// their length, keeping their directions. Each edge curve is still shared and still tangent to
// the vertex planes, so the surface stays G1 with the same vertex normals, and it bulges off the
// flat triangles about s times as much (measured in doc/mga_smooth.md): s trades fidelity to the
// smooth surface the input samples (s = 1) for closeness to the input triangles. s = 0 is the
// flat input triangles themselves (C0).
//
// At feature vertices (dihedral angle below the feature angle) each smooth sector of faces gets
// its own normal, so sharp edges stay sharp; the curve of a feature edge leaves its ends along
// the crease (the intersection of the two sectors' tangent planes), so it is shared and each
// patch stays consistent with its own sector's plane.
//
// A point is mapped onto the surface as the paper does: locate it in a primary triangle (walking
// from a nearby start triangle over the triangles' planes) and evaluate that triangle's patch at
// its barycentric coordinates.

#include <CGAL/Mesh_repair/internal/c1_surface/local_derivative_estimation.h>
#include <CGAL/Mesh_repair/internal/vec3.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/bezier_patches.h>

#include <CGAL/Simple_cartesian.h>

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

/// The tangent scale mga_smooth uses unless told otherwise: on both test saddles it minimises the
/// larger of the nodes' distances to the input triangles and to the true surface, the two being
/// equal there (doc/mga_smooth.md, "Distance to the input against fidelity").
constexpr double default_surface_tangent_scale = 0.45;

class G1_surface {
 public:
  using Triangle = std::array<int, 3>;
  struct Location {
    int triangle = -1;
    double b[3] = {1, 0, 0};
  };

  /// `feature_angle_deg`: an edge whose dihedral angle is below it is a feature edge.
  /// `tangent_scale` s in [0, 1]: the end tangents of the boundary curves are s times the
  /// point-normal ones (s = 1 Walton and Meek's patches, s = 0 the flat primary triangles).
  G1_surface(std::vector<Vec3> points, std::vector<Triangle> triangles, double feature_angle_deg,
             double tangent_scale = 1.0)
      : points_(std::move(points)), triangles_(std::move(triangles)) {
    build_adjacency();
    mark_feature_edges(feature_angle_deg);
    compute_corner_normals();
    for (std::size_t t = 0; t < triangles_.size(); ++t) frames_.push_back(plane_frame(int(t)));
    if (tangent_scale > 0) build_patches(tangent_scale);
  }

  std::size_t number_of_vertices() const { return points_.size(); }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const std::vector<Vec3>& points() const { return points_; }
  /// A triangle incident to vertex `v`, or -1.
  int triangle_of_vertex(int v) const { return vertex_triangle_[v]; }
  bool is_feature_vertex(int v) const { return feature_vertex_[v]; }
  bool is_border_vertex(int v) const { return border_vertex_[v]; }
  /// The vertices joined to `v` by a feature edge, each once.
  std::vector<int> feature_neighbours(int v) const {
    std::vector<int> result;
    for (int t : incident_[v])
      for (int i = 0; i < 3; ++i) {
        if (!feature_edge_[3 * t + i]) continue;
        const int a = triangles_[t][(i + 1) % 3], b = triangles_[t][(i + 2) % 3];
        if (a == v || b == v) result.push_back(a == v ? b : a);
      }
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }

  /// The point at parameter `t` (0 at `v`, 1 at `u`) of the surface's curve over the edge v-u:
  /// the shared boundary curve of its patches (the chord for tangent scale 0).
  Vec3 edge_point(int v, int u, double t) const {
    for (int f : incident_[v]) {
      const Triangle& c = triangles_[f];
      if (c[0] != u && c[1] != u && c[2] != u) continue;
      Location at;
      at.triangle = f;
      at.b[0] = at.b[1] = at.b[2] = 0;
      at.b[corner_of(f, v)] = 1 - t;
      at.b[corner_of(f, u)] = t;
      return evaluate(at);
    }
    return points_[v];  // not an edge
  }

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

  /// The surface point at a location: the patch of its triangle at its barycentric coordinates.
  Vec3 evaluate(const Location& location) const {
    const double* b = location.b;
    if (nets_.empty()) {  // tangent scale 0: the flat primary triangle
      const Triangle& t = triangles_[location.triangle];
      return b[0] * points_[t[0]] + b[1] * points_[t[1]] + b[2] * points_[t[2]];
    }
    return evaluate_net(nets_[location.triangle], b[0], b[1], b[2]);
  }

  /// Maps `p` onto the surface; `host` is the start triangle and receives the one found.
  Vec3 project(const Vec3& p, int& host) const {
    const Location location = locate(p, host);
    host = location.triangle;
    return evaluate(location);
  }

 private:
 private:
  // A Walton-Meek patch in plain doubles, compact (504 bytes instead of the 1.5 kB of
  // Quartic_triangle_patch, which keeps kernel points besides): the walk evaluates millions of
  // them, and 52,000 of them must stay cheap to reach in memory. `control` holds the 15
  // ordinates P_ijk (i + j + k = 4) in the order of `quartic_terms`, the three interior ones
  // unused; `g` holds G_{c,1}, G_{c,2} of the three curves c.
  struct Quartic_net {
    std::array<Vec3, 15> control;
    std::array<Vec3, 6> g;
  };
  struct Quartic_term {
    int i, j, k;
    double multinomial;
  };
  static constexpr std::array<Quartic_term, 15> quartic_terms = {{{0, 0, 4, 1},
                                                                  {0, 1, 3, 4},
                                                                  {0, 2, 2, 6},
                                                                  {0, 3, 1, 4},
                                                                  {0, 4, 0, 1},
                                                                  {1, 0, 3, 4},
                                                                  {1, 1, 2, 12},
                                                                  {1, 2, 1, 12},
                                                                  {1, 3, 0, 4},
                                                                  {2, 0, 2, 6},
                                                                  {2, 1, 1, 12},
                                                                  {2, 2, 0, 6},
                                                                  {3, 0, 1, 4},
                                                                  {3, 1, 0, 4},
                                                                  {4, 0, 0, 1}}};
  // Terms 6, 7 and 10 are the interior ordinates P112, P121, P211.

  // Eq. 5.27-5.29: a rational blend of two G points (their midpoint at the corner where both
  // weights vanish; its Bernstein weight is zero there).
  static Vec3 blend(double a, const Vec3& pa, double b, const Vec3& pb) {
    return a + b > 0 ? (1.0 / (a + b)) * (a * pa + b * pb) : 0.5 * (pa + pb);
  }

  // Quartic_triangle_patch::evaluate on the compact net (same sums, same blends, one reciprocal
  // per blend). Not shared with the patch class on purpose: evaluating the patch class's own
  // double copy (25 slots, a division per blend component, multinomials divided out per term)
  // took 42 ns against 21 ns here over armadillo's patches (2026-11-25 03:10 UTC), and changing
  // its arithmetic would change shape prediction's results in the last bits.
  static Vec3 evaluate_net(const Quartic_net& net, double u, double v, double w) {
    double pu[5], pv[5], pw[5];
    pu[0] = pv[0] = pw[0] = 1;
    for (int e = 1; e <= 4; ++e) {
      pu[e] = pu[e - 1] * u;
      pv[e] = pv[e - 1] * v;
      pw[e] = pw[e - 1] * w;
    }
    const auto& g = net.g;
    const Vec3 p112 = blend(u, g[5], v, g[0]);
    const Vec3 p121 = blend(w, g[1], u, g[2]);
    const Vec3 p211 = blend(v, g[3], w, g[4]);
    Vec3 sum;
    for (int n = 0; n < 15; ++n) {
      const Quartic_term& term = quartic_terms[n];
      const double weight = term.multinomial * pu[term.i] * pv[term.j] * pw[term.k];
      const Vec3& p = n == 6 ? p112 : (n == 7 ? p121 : (n == 10 ? p211 : net.control[n]));
      sum += weight * p;
    }
    return sum;
  }

  using Patch_kernel = CGAL::Simple_cartesian<double>;
  using Patch = shape_prediction::Quartic_triangle_patch<Patch_kernel>;
  using Patch_point = Patch_kernel::Point_3;
  using Patch_vector = Patch_kernel::Vector_3;
  using Curve = std::array<Patch_point, 4>;

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
      face_area_[t] = 0.5 * norm(n);
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
    if (!(dot(tilted, first) > 0.5)) return first;
    // Nor may it stand more than 60 degrees off an incident face (the feature angle's 120 degree
    // dihedral, seen from the vertex): at such a fold of a scan the G1 patch's interior
    // construction shears the patch along the surface by up to 0.57 of an edge, whatever the
    // tangent lengths (armadillo: 3 triangles, nodes up to 1.7e-3 of the diagonal off the input).
    for (int t : incident_[v])
      if (dot(tilted, face_normal_[t]) < 0.5) return first;
    return tilted;
  }

  static Patch_point to_point(const Vec3& p) { return Patch_point(p[0], p[1], p[2]); }
  static Patch_vector to_vector(const Vec3& v) { return Patch_vector(v[0], v[1], v[2]); }

  // The boundary curve of the edge opposite corner i of triangle t, from corner i + 2 to corner
  // i + 1 (the direction in which the patch of t runs along it), its end tangents shortened by
  // `scale`. It is computed from the lower vertex index to the higher one and
  // reversed when needed, so the neighbour across the edge gets the very same control points: no
  // crack.
  Curve edge_curve(int t, int i, double scale) const {
    const int slot = 3 * t + i;
    int from = (i + 2) % 3, to = (i + 1) % 3;
    const bool reversed = triangles_[t][from] > triangles_[t][to];
    if (reversed) std::swap(from, to);
    const Vec3 &p = point(t, from), &q = point(t, to);
    const Vec3 &np = corner_normal_[3 * t + from], &nq = corner_normal_[3 * t + to];
    Curve curve;
    const int other = neighbour_[slot];
    if (feature_edge_[slot] && other >= 0) {
      // The neighbour's sector normals at p and q; crease_curve is symmetric in the two sides.
      const Vec3& mp = corner_normal_[3 * other + corner_of(other, triangles_[t][from])];
      const Vec3& mq = corner_normal_[3 * other + corner_of(other, triangles_[t][to])];
      curve = crease_curve(p, np, mp, q, nq, mq);
    } else {
      curve = Patch::boundary_cubic(to_point(p), to_vector(np), to_point(q), to_vector(nq));
    }
    curve[1] = curve[0] + scale * (curve[1] - curve[0]);
    curve[2] = curve[3] + scale * (curve[2] - curve[3]);
    if (reversed) std::reverse(curve.begin(), curve.end());
    return curve;
  }

  // A feature edge from p to q between two sectors (normals n and m at each end): the curve
  // leaves each end along the crease n x m, which lies in both sectors' tangent planes, so each
  // patch's corner stays consistent with its own normal. Where the crease is undefined (the
  // sectors' normals within 3 degrees at an end) the curve is the point-normal cubic of the mean
  // normals; where it runs across the edge (more than 60 degrees off the chord at an end), the
  // straight chord. Every test is symmetric in the two sides, so both build the same curve.
  static Curve crease_curve(const Vec3& p, const Vec3& np, const Vec3& mp, const Vec3& q,
                            const Vec3& nq, const Vec3& mq) {
    const Vec3 chord = q - p;
    const double d = norm(chord);
    const Vec3 crease[2] = {cross(np, mp), cross(nq, mq)};
    if (norm(crease[0]) < 0.05 || norm(crease[1]) < 0.05)
      return Patch::boundary_cubic(to_point(p), to_vector(normalized(np + mp)), to_point(q),
                                   to_vector(normalized(nq + mq)));
    Vec3 tangent[2];
    for (int e = 0; e < 2; ++e) {
      tangent[e] = normalized(crease[e]);
      const double along = dot(tangent[e], chord) / d;
      if (std::abs(along) < 0.5)
        return {to_point(p), to_point(p + (1.0 / 3.0) * chord), to_point(p + (2.0 / 3.0) * chord),
                to_point(q)};
      if (along < 0) tangent[e] = -1.0 * tangent[e];
    }
    return {to_point(p), to_point(p + (d / 3.0) * tangent[0]), to_point(q - (d / 3.0) * tangent[1]),
            to_point(q)};
  }

  Patch make_patch(int t, double scale) const {
    // Patch curves: 0 from C to B (opposite corner 0), 1 from B to A (opposite 2), 2 from A to C
    // (opposite 1); `edge_curve` runs in exactly these directions.
    const typename Patch::Boundary_cubics curves = {
        edge_curve(t, 0, scale), edge_curve(t, 2, scale), edge_curve(t, 1, scale)};
    const std::array<Patch_vector, 3> normals = {to_vector(corner_normal_[3 * t]),
                                                 to_vector(corner_normal_[3 * t + 1]),
                                                 to_vector(corner_normal_[3 * t + 2])};
    return Patch(normals, curves);
  }

  void build_patches(double scale) {
    nets_.reserve(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const Patch patch = make_patch(int(t), scale);
      Quartic_net net;
      auto to_vec3 = [](const Patch_point& p) { return Vec3(p.x(), p.y(), p.z()); };
      for (int n = 0; n < 15; ++n)
        if (n != 6 && n != 7 && n != 10)  // the interior ordinates are blends of `g`
          net.control[n] = to_vec3(patch.boundary_control(quartic_terms[n].i, quartic_terms[n].j));
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 2; ++k) net.g[2 * c + k] = to_vec3(patch.interior_control(c, k));
      nets_.push_back(net);
    }
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
  std::vector<Quartic_net> nets_;  // empty for tangent scale 0 (the flat triangles)
  std::vector<Plane_frame> frames_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_G1_SURFACE_H
