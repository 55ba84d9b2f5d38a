// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_BEZIER_PATCHES_H
#define CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_BEZIER_PATCHES_H

// Quartic triangular Bezier patches of Walton and Meek, thesis 5.5 (eq. 5.14-5.30): one patch
// per triangle of the initial (GA) triangulation, built from the triangle's three vertices and
// their unit normals only. Boundary curves are the point-normal cubics of thesis 4.3.1 with the
// chord as tangent direction, so two triangles sharing an edge share its curve; the interior
// control points blend the cross-boundary constructions G_{i,1}, G_{i,2} so that the tangent
// plane along a shared edge is the same from both sides (G1).
// `Bezier_patch_network::map` locates a point on the network (eq. 5.31) and returns the point of
// the patch with the same barycentric coordinates (eq. 5.17).

#include <CGAL/Mesh_repair/internal/cubic_curves.h>
#include <CGAL/Mesh_repair/internal/shape_prediction/box_hierarchy.h>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace shape_prediction {

/// One quartic triangular Bezier patch S(u,v,w) over the triangle (a, b, c): S(1,0,0) = a,
/// S(0,1,0) = b, S(0,0,1) = c, with the given unit normals there.
template <class Kernel>
class Quartic_triangle_patch {
 public:
  using Point_3 = typename Kernel::Point_3;
  using Vector_3 = typename Kernel::Vector_3;

  /// The three boundary cubics of a patch, in the order of the curves: 0 from C to B, 1 from B
  /// to A, 2 from A to C (corners A = P400 (u), B = P040 (v), C = P004 (w)).
  using Boundary_cubics = std::array<std::array<Point_3, 4>, 3>;

  Quartic_triangle_patch(const std::array<Point_3, 3>& corner,
                         const std::array<Vector_3, 3>& normal)
      : Quartic_triangle_patch(normal, boundary_cubics(corner, normal)) {}

  /// A patch over given boundary cubics: each end tangent must be orthogonal to the normal of
  /// its corner (as the point-normal cubics are). The interior construction (eq. 5.20-5.29) makes
  /// the tangent plane along an edge a function of that edge's curve and its two end normals
  /// only, so patches built from one shared network of such curves (e.g. with shortened end
  /// tangents, `boundary_cubic`) still meet with a common tangent plane (G1).
  Quartic_triangle_patch(const std::array<Vector_3, 3>& normal, const Boundary_cubics& cubic) {
    const Vector_3 NA = normal[0], NB = normal[1], NC = normal[2];
    const std::array<Vector_3, 3> n_start{NC, NB, NA}, n_end{NB, NA, NC};
    std::array<std::array<Point_3, 5>, 3> quartic;
    for (int i = 0; i < 3; ++i) quartic[i] = elevate(cubic[i]);  // eq. 5.18
    for (int j = 0; j <= 4; ++j) {                               // eq. 5.19
      control(0, j, 4 - j) = quartic[0][j];
      control(j, 4 - j, 0) = quartic[1][j];
      control(4 - j, 0, j) = quartic[2][j];
    }
    for (int i = 0; i < 3; ++i) {
      const Vector_3 d0 = cross_boundary(i, 0), d3 = cross_boundary(i, 3);  // eq. 5.24-5.26
      interior_g(i, cubic[i], n_start[i], n_end[i], d0, d3, g_[i][0], g_[i][1]);
    }
    for (int i = 0; i < 25; ++i) cd_[i] = to_array3(control_[i]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 2; ++j) gd_[i][j] = to_array3(g_[i][j]);
  }

  /// Eq. 5.17 with the interior control points of eq. 5.27-5.29; u + v + w = 1.
  Point_3 operator()(double u, double v, double w) const {
    double xyz[3];
    evaluate(u, v, w, xyz);
    return Point_3(xyz[0], xyz[1], xyz[2]);
  }

  /// `operator()` in doubles, from the control points converted once.
  void evaluate(double u, double v, double w, double* xyz) const {
    double pu[5], pv[5], pw[5];
    pu[0] = pv[0] = pw[0] = 1;
    for (int e = 1; e <= 4; ++e) {
      pu[e] = pu[e - 1] * u;
      pv[e] = pv[e - 1] * v;
      pw[e] = pw[e - 1] * w;
    }
    double inner[3][3];
    blend(u, gd_[2][1], v, gd_[0][0], inner[0]);
    blend(w, gd_[0][1], u, gd_[1][0], inner[1]);
    blend(v, gd_[1][1], w, gd_[2][0], inner[2]);
    xyz[0] = xyz[1] = xyz[2] = 0;
    for (int i = 0; i <= 4; ++i) {
      for (int j = 0; i + j <= 4; ++j) {
        const int k = 4 - i - j;
        const double b = multinomial(i, j, k) * pu[i] * pv[j] * pw[k];
        const double* p = (i == 1 && j == 1)   ? inner[0]
                          : (i == 1 && k == 1) ? inner[1]
                          : (j == 1 && k == 1) ? inner[2]
                                               : cd_[index(i, j)].data();
        xyz[0] += b * p[0];
        xyz[1] += b * p[1];
        xyz[2] += b * p[2];
      }
    }
  }

  const Point_3& boundary_control(int i, int j) const { return control_[index(i, j)]; }
  /// G_{curve,1} (k = 0) and G_{curve,2} (k = 1) of eq. 5.20-5.23, the points that `evaluate`
  /// blends into the three interior control points (eq. 5.27-5.29).
  const Point_3& interior_control(int curve, int k) const { return g_[curve][k]; }

 private:
  static int index(int i, int j) { return i * 5 + j; }  // k = 4 - i - j
  Point_3& control(int i, int j, int /*k*/) { return control_[index(i, j)]; }
  const Point_3& control(int i, int j, int /*k*/) const { return control_[index(i, j)]; }

  static double power(double x, int e) {
    double r = 1;
    for (int k = 0; k < e; ++k) r *= x;
    return r;
  }
  static double multinomial(int i, int j, int k) {
    static const double factorial[5] = {1, 1, 2, 6, 24};
    return 24.0 / (factorial[i] * factorial[j] * factorial[k]);
  }

 public:
  /// Eq. 4.2-4.7 with the chord direction as tangent at both ends (Walton and Meek): the curve of
  /// an edge depends on the edge only, so neighbouring patches share it.
  static std::array<Point_3, 4> boundary_cubic(const Point_3& q0, const Vector_3& n0,
                                               const Point_3& q1, const Vector_3& n1) {
    Vector_3 chord = q1 - q0;
    const double length = std::sqrt(CGAL::to_double(chord.squared_length()));
    if (length > 0) chord = chord / length;
    return make_cubic_boundary_curve(q0, n0, chord, q1, n1, chord).control;
  }

  /// `boundary_cubic` with each end tangent lengthened so that a circular arc is reproduced:
  /// Walton and Meek's tangent at an end making the angle alpha with the chord d has the length
  /// |d| cos(alpha) / (1 + 2 cos^2(alpha)) on a circular arc, where the arc needs
  /// |d| / (3 cos^2(alpha / 2)) (the classical 4/3 tan(theta / 4) of a cubic arc); at alpha = 60
  /// degrees the curve bulges only 0.75 times as much as the arc. The factor depends on the end
  /// only, so the curve is the same when the edge is walked the other way.
  static std::array<Point_3, 4> circular_boundary_cubic(const Point_3& q0, const Vector_3& n0,
                                                        const Point_3& q1, const Vector_3& n1) {
    std::array<Point_3, 4> c = boundary_cubic(q0, n0, q1, n1);
    const Vector_3 chord = q1 - q0;
    const auto factor_at = [&chord](const Point_3& end, const Point_3& inner) {
      const Vector_3 handle = inner - end;
      const double h2 = CGAL::to_double(handle.squared_length());
      const double d2 = CGAL::to_double(chord.squared_length());
      if (!(h2 > 0) || !(d2 > 0)) return 1.0;
      const double ca = std::abs(CGAL::to_double(handle * chord)) / std::sqrt(h2 * d2);
      // Bounded: beyond 70 degrees the arc is too steep over its chord to trust the normals.
      const double cos_alpha = std::max(ca, std::cos(70.0 * CGAL_PI / 180));
      const double cos_half_squared = 0.5 * (1 + cos_alpha);
      return (1 + 2 * cos_alpha * cos_alpha) / (3 * cos_alpha * cos_half_squared);
    };
    c[1] = c[0] + factor_at(c[0], c[1]) * (c[1] - c[0]);
    c[2] = c[3] + factor_at(c[3], c[2]) * (c[2] - c[3]);
    return c;
  }

 private:
  static Boundary_cubics boundary_cubics(const std::array<Point_3, 3>& corner,
                                         const std::array<Vector_3, 3>& normal) {
    // Curve 0: C -> B, 1: B -> A, 2: A -> C.
    return {boundary_cubic(corner[2], normal[2], corner[1], normal[1]),
            boundary_cubic(corner[1], normal[1], corner[0], normal[0]),
            boundary_cubic(corner[0], normal[0], corner[2], normal[2])};
  }

  static std::array<Point_3, 5> elevate(const std::array<Point_3, 4>& v) {
    std::array<Point_3, 5> e;
    e[0] = v[0];
    e[4] = v[3];
    for (int j = 1; j <= 3; ++j)
      e[j] = CGAL::ORIGIN +
             ((j * (v[j - 1] - CGAL::ORIGIN)) + ((4 - j) * (v[j] - CGAL::ORIGIN))) / 4.0;
    return e;
  }

  Vector_3 cross_boundary(int curve, int j) const {
    auto mid = [](const Point_3& p, const Point_3& q) { return CGAL::midpoint(p, q); };
    switch (curve) {
      case 0:
        return control(1, j, 3 - j) - mid(control(0, j + 1, 3 - j), control(0, j, 4 - j));
      case 1:
        return control(j, 3 - j, 1) - mid(control(j + 1, 3 - j, 0), control(j, 4 - j, 0));
      default:
        return control(3 - j, 1, j) - mid(control(3 - j, 0, j + 1), control(4 - j, 0, j));
    }
  }

  static Vector_3 unit(const Vector_3& v) {
    const double l = std::sqrt(CGAL::to_double(v.squared_length()));
    return l > 0 ? v / l : v;
  }

  // Eq. 5.20-5.23.
  static void interior_g(int /*curve*/, const std::array<Point_3, 4>& v, const Vector_3& n0,
                         const Vector_3& n1, const Vector_3& d0, const Vector_3& d3, Point_3& g1,
                         Point_3& g2) {
    const Vector_3 w0 = v[1] - v[0], w1 = v[2] - v[1], w2 = v[3] - v[2];
    const Vector_3 a0 = unit(CGAL::cross_product(n0, w0));
    const Vector_3 a2 = unit(CGAL::cross_product(n1, w2));
    const Vector_3 a1 = unit(a0 + a2);
    const double ww0 = CGAL::to_double(w0 * w0), ww2 = CGAL::to_double(w2 * w2);
    const double lambda0 = ww0 > 0 ? CGAL::to_double(d0 * w0) / ww0 : 0;
    const double lambda1 = ww2 > 0 ? CGAL::to_double(d3 * w2) / ww2 : 0;
    const double mu0 = CGAL::to_double(d0 * a0), mu1 = CGAL::to_double(d3 * a2);
    const Vector_3 v0 = v[0] - CGAL::ORIGIN, v1 = v[1] - CGAL::ORIGIN, v2 = v[2] - CGAL::ORIGIN,
                   v3 = v[3] - CGAL::ORIGIN;
    g1 = CGAL::ORIGIN + (v0 + 5 * v1 + 2 * v2) / 8.0 + (2.0 / 3) * lambda0 * w1 +
         (1.0 / 3) * lambda1 * w0 + (2.0 / 3) * mu0 * a1 + (1.0 / 3) * mu1 * a0;
    g2 = CGAL::ORIGIN + (2 * v1 + 5 * v2 + v3) / 8.0 + (1.0 / 3) * lambda0 * w2 +
         (2.0 / 3) * lambda1 * w1 + (1.0 / 3) * mu0 * a2 + (2.0 / 3) * mu1 * a1;
  }

  // Eq. 5.27-5.29 in doubles (at the opposite corner, where both weights vanish, the
  // midpoint; its weight in eq. 5.17 is zero there).
  static void blend(double a, const std::array<double, 3>& pa, double b,
                    const std::array<double, 3>& pb, double* out) {
    for (int c = 0; c < 3; ++c)
      out[c] = a + b <= 0 ? (pa[c] + pb[c]) / 2 : (a * pa[c] + b * pb[c]) / (a + b);
  }

  static std::array<double, 3> to_array3(const Point_3& p) {
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }

  std::array<Point_3, 25> control_;
  std::array<std::array<Point_3, 2>, 3> g_;                 // G_{i,1}, G_{i,2}
  std::array<std::array<double, 3>, 25> cd_;                // control_ in doubles
  std::array<std::array<std::array<double, 3>, 2>, 3> gd_;  // g_ in doubles
};

/// The patches over every triangle of a triangulation, and the mapping of eq. 5.31.
template <class Kernel>
class Bezier_patch_network {
 public:
  using Point_3 = typename Kernel::Point_3;
  using Vector_3 = typename Kernel::Vector_3;

  Bezier_patch_network(const std::vector<Point_3>& points, const std::vector<Vector_3>& normals,
                       const std::vector<std::array<int, 3>>& triangles)
      : points_(points), triangles_(triangles) {
    patches_.reserve(triangles.size());
    frames_.reserve(triangles.size());
    for (const auto& t : triangles) {
      const std::array<Point_3, 3> corner{points[t[0]], points[t[1]], points[t[2]]};
      const std::array<Vector_3, 3> normal{normals[t[0]], normals[t[1]], normals[t[2]]};
      using Patch = Quartic_triangle_patch<Kernel>;
      // Curve 0: C -> B, 1: B -> A, 2: A -> C (see Quartic_triangle_patch).
      patches_.emplace_back(
          normal, typename Patch::Boundary_cubics{
                      Patch::circular_boundary_cubic(corner[2], normal[2], corner[1], normal[1]),
                      Patch::circular_boundary_cubic(corner[1], normal[1], corner[0], normal[0]),
                      Patch::circular_boundary_cubic(corner[0], normal[0], corner[2], normal[2])});
      frames_.push_back(make_frame(points[t[0]], points[t[1]], points[t[2]]));
    }
    hierarchy_ = frame_boxes(frames_);
    neighbours_.assign(triangles.size(), {none_, none_, none_});
    std::map<std::pair<int, int>, std::pair<std::size_t, int>> by_edge;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        int a = triangles[i][(k + 1) % 3], b = triangles[i][(k + 2) % 3];
        if (a > b) std::swap(a, b);
        const auto [it, inserted] = by_edge.emplace(std::make_pair(a, b), std::make_pair(i, k));
        if (inserted) continue;
        neighbours_[i][k] = it->second.first;
        neighbours_[it->second.first][it->second.second] = i;
      }
    }
  }

  std::size_t size() const { return patches_.size(); }
  const Quartic_triangle_patch<Kernel>& patch(std::size_t i) const { return patches_[i]; }
  const std::array<int, 3>& triangle(std::size_t i) const { return triangles_[i]; }

  /// Eq. 5.31 then 5.17, on the normal line of x: the normal projection x' of `x` onto the
  /// nearest triangle of the network, then the point of the patches whose own normal projection
  /// is x' (the patch point on the line through x along the triangle's normal). Eq. 5.31 as
  /// written evaluates the patch at x''s barycentric coordinates; a Walton-Meek patch is not a
  /// height field in its own parametrisation (its points shift sideways where it stands steeply
  /// over its flat triangle), and on a deep cap that put the front's new nodes a median 1.5 edge
  /// lengths aside of where the front rules placed them (doc/shape_prediction.md, "Normal-line
  /// mapping"). When no such point is found (a patch folding over its triangle, or the line
  /// leaving the network), eq. 5.31's point is returned.
  Point_3 map(const Point_3& x) const {
    std::size_t best = 0;
    std::array<double, 3> bary{1.0 / 3, 1.0 / 3, 1.0 / 3};
    locate(x, best, bary);
    const double p[3] = {CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())};
    double out[3];
    if (on_normal_line(best, p, bary, out)) return Point_3(out[0], out[1], out[2]);
    return patches_[best](bary[0], bary[1], bary[2]);
  }

  /// Eq. 5.31 as written: the patch point at the barycentric coordinates of x's normal
  /// projection onto the nearest triangle.
  Point_3 map_at_foot_coordinates(const Point_3& x) const {
    std::size_t best = 0;
    std::array<double, 3> bary{1.0 / 3, 1.0 / 3, 1.0 / 3};
    locate(x, best, bary);
    return patches_[best](bary[0], bary[1], bary[2]);
  }

  /// The point of the patch network nearest to `x` (its foot point): from the patch and the
  /// coordinates `map` finds, three Gauss-Newton steps on that patch's barycentric coordinates,
  /// kept inside its triangle. A point already on the network stays where it is (`map` moves it
  /// by the difference between the patch and its flat triangle's parametrisation), so a
  /// smoothing that projects after each move does not drift along the patches.
  Point_3 project(const Point_3& x) const {
    std::size_t hint = size();
    return project(x, hint);
  }

  /// `project` warm-started on the patch `hint` (a previous result for a nearby point): when the
  /// foot point on that patch lies strictly inside its triangle it is kept, otherwise the
  /// nearest triangle is searched as in `project`; `hint` is set to the patch used.
  Point_3 project(const Point_3& x, std::size_t& hint) const {
    const double target[3] = {CGAL::to_double(x.x()), CGAL::to_double(x.y()),
                              CGAL::to_double(x.z())};
    double foot[3];
    if (hint < size()) {
      std::array<double, 3> bary{1.0 / 3, 1.0 / 3, 1.0 / 3};
      projected_distance(frames_[hint], target, bary);
      if (foot_point(hint, target, bary[1], bary[2], foot))
        return Point_3(foot[0], foot[1], foot[2]);
    }
    std::size_t t = 0;
    std::array<double, 3> bary{1.0 / 3, 1.0 / 3, 1.0 / 3};
    locate(x, t, bary);
    foot_point(t, target, bary[1], bary[2], foot);
    hint = t;
    return Point_3(foot[0], foot[1], foot[2]);
  }

 private:
  // Gauss-Newton steps towards the foot point of `target` on patch t from coordinates (v, w);
  // true when it ends strictly inside the triangle.
  bool foot_point(std::size_t t, const double* target, double v, double w, double* out) const {
    const Quartic_triangle_patch<Kernel>& patch = patches_[t];
    auto eval = [&patch](double a, double b, double* xyz) { patch.evaluate(1 - a - b, a, b, xyz); };
    const double h = 1e-6;  // forward differences of a quartic
    for (int iteration = 0; iteration < 3; ++iteration) {
      double s[3], sv[3], sw[3], dv[3], dw[3], r[3];
      eval(v, w, s);
      // Step into the triangle: towards the smaller coordinate sum.
      const double hv = v + w + h <= 1 ? h : -h, hw = hv;
      eval(v + hv, w, sv);
      eval(v, w + hw, sw);
      for (int k = 0; k < 3; ++k) {
        dv[k] = (sv[k] - s[k]) / hv;
        dw[k] = (sw[k] - s[k]) / hw;
        r[k] = s[k] - target[k];
      }
      const double a = dot3(dv, dv), b = dot3(dv, dw), c = dot3(dw, dw);
      const double gv = dot3(dv, r), gw = dot3(dw, r);
      const double det = a * c - b * b;
      if (!(det > 0)) break;
      v -= (c * gv - b * gw) / det;
      w -= (a * gw - b * gv) / det;
      v = std::max(v, 0.0);
      w = std::max(w, 0.0);
      if (v + w > 1) {
        const double sum = v + w;
        v /= sum;
        w /= sum;
      }
    }
    eval(v, w, out);
    return v > 0 && w > 0 && v + w < 1;
  }

 public:
 private:
  static double dot3(const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  // Eq. 5.31: the triangle nearest to `x` and the barycentric coordinates of x's closest point
  // on it (its normal projection when that falls inside). Through the box hierarchy, with the
  // lowest index among equal distances (the answer of a linear scan); left unchanged (the
  // caller's triangle and centroid) when no triangle has a finite distance (all degenerate).
  void locate(const Point_3& x, std::size_t& best, std::array<double, 3>& best_bary) const {
    const double p[3] = {CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())};
    double best_distance;
    std::array<double, 3> bary;
    const std::size_t t = hierarchy_.nearest(
        p, [&](std::size_t k) { return projected_distance(frames_[k], p, bary); }, best_distance);
    if (t == hierarchy_.size()) return;
    best = t;
    projected_distance(frames_[t], p, best_bary);
  }

  // A triangle of the network in doubles: corner a, edges ab and ac, their Gram matrix.
  struct Frame {
    double a[3], ab[3], ac[3], d00, d01, d11, det;
  };
  static double squared(double x) { return x * x; }

  static Frame make_frame(const Point_3& pa, const Point_3& pb, const Point_3& pc) {
    Frame f;
    const double a[3] = {CGAL::to_double(pa.x()), CGAL::to_double(pa.y()), CGAL::to_double(pa.z())};
    const double b[3] = {CGAL::to_double(pb.x()), CGAL::to_double(pb.y()), CGAL::to_double(pb.z())};
    const double c[3] = {CGAL::to_double(pc.x()), CGAL::to_double(pc.y()), CGAL::to_double(pc.z())};
    for (int k = 0; k < 3; ++k) {
      f.a[k] = a[k];
      f.ab[k] = b[k] - a[k];
      f.ac[k] = c[k] - a[k];
    }
    f.d00 = f.ab[0] * f.ab[0] + f.ab[1] * f.ab[1] + f.ab[2] * f.ab[2];
    f.d01 = f.ab[0] * f.ac[0] + f.ab[1] * f.ac[1] + f.ab[2] * f.ac[2];
    f.d11 = f.ac[0] * f.ac[0] + f.ac[1] * f.ac[1] + f.ac[2] * f.ac[2];
    f.det = f.d00 * f.d11 - f.d01 * f.d01;
    return f;
  }

  static Box_hierarchy frame_boxes(const std::vector<Frame>& frames) {
    std::vector<Box_hierarchy::Box> boxes;
    boxes.reserve(frames.size());
    for (const Frame& f : frames) {
      Box_hierarchy::Box box;
      for (int d = 0; d < 3; ++d) {
        const double a = f.a[d], b = a + f.ab[d], c = a + f.ac[d];
        box[d] = std::min({a, b, c});
        box[d + 3] = std::max({a, b, c});
      }
      boxes.push_back(box);
    }
    return Box_hierarchy(std::move(boxes));
  }

  // Squared distance from x to its closest point on triangle t, with that point's barycentric
  // coordinates (the normal projection when it falls inside, eq. 5.31).
  static double projected_distance(const Frame& f, const double* x, std::array<double, 3>& bary) {
    if (!(f.det > 0)) return std::numeric_limits<double>::infinity();
    const double ax[3] = {x[0] - f.a[0], x[1] - f.a[1], x[2] - f.a[2]};
    const double d20 = ax[0] * f.ab[0] + ax[1] * f.ab[1] + ax[2] * f.ab[2];
    const double d21 = ax[0] * f.ac[0] + ax[1] * f.ac[1] + ax[2] * f.ac[2];
    double v = (f.d11 * d20 - f.d01 * d21) / f.det;
    double w = (f.d00 * d21 - f.d01 * d20) / f.det;
    double u = 1 - v - w;
    if (u < 0 || v < 0 || w < 0) {
      u = std::max(u, 0.0);
      v = std::max(v, 0.0);
      w = std::max(w, 0.0);
      const double s = u + v + w;
      u /= s;
      v /= s;
      w /= s;
    }
    bary = {u, v, w};
    double d = 0;
    for (int k = 0; k < 3; ++k) d += squared(ax[k] - v * f.ab[k] - w * f.ac[k]);
    return d;
  }

  // Newton steps on patch t's coordinates (v, w) towards the patch point whose normal projection
  // onto t's plane has the coordinates of x's, each step cut where it would leave the triangle
  // (a quartic is meaningless outside its triangle); a step that cannot move without leaving
  // continues on the neighbour across that edge (at most `max_hops`). True, with the point in
  // `out`, when the steps converge.
  bool on_normal_line(std::size_t t, const double* x, std::array<double, 3> start,
                      double* out) const {
    constexpr int max_hops = 16, max_steps = 12;
    double v = start[1], w = start[2];
    for (int hop = 0; hop <= max_hops; ++hop) {
      const Frame& f = frames_[t];
      const Quartic_triangle_patch<Kernel>& patch = patches_[t];
      double xv, xw;
      plane_coordinates(f, x, xv, xw);
      int leave = -1;  // the corner opposite the edge a blocked step points across
      for (int step = 0; step < max_steps && leave < 0; ++step) {
        double s[3], sv[3], sw[3];
        const double h = v + w + 1e-6 <= 1 ? 1e-6 : -1e-6;  // differences into the triangle
        patch.evaluate(1 - v - w, v, w, s);
        patch.evaluate(1 - v - w - h, v + h, w, sv);
        patch.evaluate(1 - v - w - h, v, w + h, sw);
        double s0, s1, a0, a1, b0, b1;
        plane_coordinates(f, s, s0, s1);
        plane_coordinates(f, sv, a0, a1);
        plane_coordinates(f, sw, b0, b1);
        const double j00 = (a0 - s0) / h, j10 = (a1 - s1) / h, j01 = (b0 - s0) / h,
                     j11 = (b1 - s1) / h;
        const double r0 = s0 - xv, r1 = s1 - xw, det = j00 * j11 - j01 * j10;
        if (!(std::abs(det) > 1e-12)) return false;  // the patch folds over its triangle here
        const double dv = -(j11 * r0 - j01 * r1) / det, dw = -(j00 * r1 - j10 * r0) / det;
        if (std::abs(dv) + std::abs(dw) < 1e-10) {
          patch.evaluate(1 - v - w, v, w, out);
          return true;
        }
        // The largest fraction of the step that stays in the triangle, and the edge that cuts it.
        double fraction = 1;
        const double coordinate[3] = {1 - v - w, v, w}, change[3] = {-dv - dw, dv, dw};
        for (int k = 0; k < 3; ++k) {
          if (change[k] < 0 && coordinate[k] + fraction * change[k] < 0) {
            fraction = std::max(0.0, coordinate[k] / -change[k]);
            leave = k;
          }
        }
        v += fraction * dv;
        w += fraction * dw;
        if (fraction > 1e-9) leave = -1;  // moved: try the next step from the edge
      }
      if (leave < 0) return false;  // no convergence inside this patch
      const std::size_t next = neighbours_[t][leave];
      if (next == none_) return false;  // the solution lies outside the network
      double edge_point[3];
      patch.evaluate(std::max(0.0, 1 - v - w), std::max(0.0, v), std::max(0.0, w), edge_point);
      std::array<double, 3> nb;
      projected_distance(frames_[next], edge_point, nb);
      t = next;
      v = nb[1];
      w = nb[2];
    }
    return false;
  }

  // Coordinates (v, w) of the normal projection of x onto the plane of f (unclamped).
  static void plane_coordinates(const Frame& f, const double* x, double& v, double& w) {
    const double ax[3] = {x[0] - f.a[0], x[1] - f.a[1], x[2] - f.a[2]};
    const double d20 = ax[0] * f.ab[0] + ax[1] * f.ab[1] + ax[2] * f.ab[2];
    const double d21 = ax[0] * f.ac[0] + ax[1] * f.ac[1] + ax[2] * f.ac[2];
    v = (f.d11 * d20 - f.d01 * d21) / f.det;
    w = (f.d00 * d21 - f.d01 * d20) / f.det;
  }

  std::vector<Point_3> points_;
  std::vector<std::array<int, 3>> triangles_;
  static constexpr std::size_t none_ = std::size_t(-1);
  // Per triangle, per corner k: the triangle across the edge opposite corner k, or none_.
  std::vector<std::array<std::size_t, 3>> neighbours_;
  std::vector<Quartic_triangle_patch<Kernel>> patches_;
  std::vector<Frame> frames_;
  Box_hierarchy hierarchy_;
};

}  // namespace shape_prediction
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SHAPE_PREDICTION_BEZIER_PATCHES_H
