// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_STAR_H
#define CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_STAR_H

// Index arrays of a triangle / quad mesh and the "star" of a node: its incident elements with the
// node first, the fitness of eq. 5 / eq. 8 for a trial position, and the fold test.

#include <CGAL/Mesh_repair/internal/vec3.h>
#include <CGAL/Mesh_repair/quality.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Faces of degree 3 or 4 as index arrays, and for each vertex its incident faces.
struct Polygon_arrays {
  std::vector<Vec3> points;
  std::vector<std::array<int, 4>> faces;  // fourth index -1 for a triangle
  std::vector<int> incidence_start, incidence;

  int degree(int f) const { return faces[f][3] < 0 ? 3 : 4; }

  void build_incidence() {
    incidence_start.assign(points.size() + 1, 0);
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int i = 0; i < degree(int(f)); ++i) ++incidence_start[faces[f][i] + 1];
    for (std::size_t v = 0; v < points.size(); ++v) incidence_start[v + 1] += incidence_start[v];
    incidence.assign(incidence_start.back(), 0);
    std::vector<int> fill(incidence_start.begin(), incidence_start.end() - 1);
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int i = 0; i < degree(int(f)); ++i) incidence[fill[faces[f][i]]++] = int(f);
  }
};

/// Quality of one element: alpha (eq. 4) for a triangle, beta (eq. 7) for a quad.
inline double element_quality(const Vec3* corners, int degree) {
  return degree == 3 ? alpha(corners[0], corners[1], corners[2])
                     : quad_beta(corners[0], corners[1], corners[2], corners[3]);
}

/// The elements around one node, each rotated so that the node comes first.
class Node_star {
 public:
  struct Element {
    int degree;
    std::array<int, 4> ring;  // ring[0] is the node
    Vec3 reference_normal;    // normal before the move: a move that flips it is a fold
    Vec3 corners[4];          // positions of ring[1..degree-1] (fixed while the node moves)
    Vec3 fixed_edge;          // corners[2] - corners[1]
    double fixed_edge_squared = 0;
  };

  /// The elements of a star (a view of a per-thread buffer, valid until the next star is built
  /// on this thread).
  struct Elements {
    const Element* first;
    std::size_t count;
    const Element* begin() const { return first; }
    const Element* end() const { return first + count; }
    std::size_t size() const { return count; }
    bool empty() const { return count == 0; }
    const Element& operator[](std::size_t i) const { return first[i]; }
  };

  Node_star(const Polygon_arrays& mesh, int node) : mesh_(mesh), node_(node) {
    // The star is built once per node and search: reuse this thread's buffer (no allocation per
    // node once the largest valence has been seen).
    static thread_local std::vector<Element> buffer;
    buffer.clear();
    for (int k = mesh.incidence_start[node]; k < mesh.incidence_start[node + 1]; ++k) {
      const int f = mesh.incidence[k];
      Element element;
      element.degree = mesh.degree(f);
      int first = 0;
      while (mesh.faces[f][first] != node) ++first;
      for (int i = 0; i < element.degree; ++i)
        element.ring[i] = mesh.faces[f][(first + i) % element.degree];
      element.reference_normal = newell_normal(element, mesh.points[node]);
      for (int i = 1; i < element.degree; ++i) element.corners[i] = mesh.points[element.ring[i]];
      // Triangle: |V2 - V3|^2 does not depend on the node (eq. 4's denominator).
      element.fixed_edge = element.corners[2] - element.corners[1];
      element.fixed_edge_squared = dot(element.fixed_edge, element.fixed_edge);
      buffer.push_back(element);
    }
    elements_ = buffer.data();
    size_ = buffer.size();
    // All-triangle stars (the usual case) are also laid out by coordinate, two elements per SSE2
    // register, for `fitness`.
    static thread_local Triangle_lanes lanes;
    all_triangles_ = size_ <= Triangle_lanes::capacity;
    for (std::size_t i = 0; i < size_ && all_triangles_; ++i)
      all_triangles_ = elements_[i].degree == 3;
    if (all_triangles_) {
      for (std::size_t i = 0; i < ((size_ + 1) & ~std::size_t(1)); ++i) {
        const Element& e = elements_[i < size_ ? i : 0];  // padding repeats element 0
        for (int k = 0; k < 3; ++k) {
          lanes.b[k][i] = e.corners[1][k];
          lanes.c[k][i] = e.corners[2][k];
          lanes.n[k][i] = e.reference_normal[k];
        }
        lanes.fixed[i] = e.fixed_edge_squared;
      }
      lanes_ = &lanes;
    }
    // The worst element of the star may only get worse while it stays above 0.5 (a sum-only
    // fitness would trade a sliver for gains elsewhere, as the paper's Table 3 shows).
    double worst = 1;
    for (const Element& element : elements()) {
      Vec3 corners[4] = {mesh.points[node], element.corners[1], element.corners[2],
                         element.corners[3]};
      worst = std::min(worst, element_quality(corners, element.degree));
    }
    quality_floor_ = std::min(worst, 0.5);
  }

  int node() const { return node_; }
  Elements elements() const { return {elements_, size_}; }

  /// Search triangle of element e (Fig. 1): V1 = the node, V2 and V3 its neighbours in e.
  void search_triangle(std::size_t e, Vec3& v1, Vec3& v2, Vec3& v3) const {
    const Element& element = elements_[e];
    v1 = mesh_.points[node_];
    v2 = mesh_.points[element.ring[1]];
    v3 = mesh_.points[element.ring[element.degree - 1]];
  }

  /// Eq. 5 / eq. 8 with the node at `position`; -1 when an element would fold (inexact screen:
  /// the accepted move is re-checked with exact predicates) or fall below the quality floor.
  double fitness(const Vec3& position) const {
#ifdef __SSE2__
    if (all_triangles_) return triangle_fitness(position);
#endif
    double sum = 0;
    Vec3 corners[4];
    for (const Element& element : elements()) {
      const Vec3 ab = element.corners[1] - position;
      const Vec3 ac = element.corners[element.degree - 1] - position;
      const Vec3 normal = cross(ab, ac);
      if (dot(normal, element.reference_normal) <= 0) return -1;
      double quality;
      if (element.degree == 3) {
        // alpha (eq. 4), as quality.h computes it, sharing the cross product with the fold
        // screen and the node-independent edge with the previous calls.
        const double denominator = dot(ab, ab) + element.fixed_edge_squared + dot(ac, ac);
        quality = denominator == 0 ? 0 : 2.0 * std::sqrt(3.0) * norm(normal) / denominator;
      } else {
        corners[0] = position;
        for (int i = 1; i < 4; ++i) corners[i] = element.corners[i];
        quality = element_quality(corners, 4);
      }
      if (quality < quality_floor_) return -1;
      sum += quality;
    }
    return sum;
  }

#ifdef __SSE2__
  // The same numbers as the general loop (same operations, IEEE sqrt and division), two
  // triangles at a time; the sum is taken in element order, so the result is bit-identical.
  double triangle_fitness(const Vec3& position) const {
    const Triangle_lanes& l = *lanes_;
    double quality[Triangle_lanes::capacity];
    bool feasible = true;
    const __m128d px = _mm_set1_pd(position[0]), py = _mm_set1_pd(position[1]),
                  pz = _mm_set1_pd(position[2]), scale = _mm_set1_pd(2.0 * std::sqrt(3.0));
    for (std::size_t i = 0; i < size_; i += 2) {
      const __m128d abx = _mm_sub_pd(_mm_loadu_pd(l.b[0] + i), px),
                    aby = _mm_sub_pd(_mm_loadu_pd(l.b[1] + i), py),
                    abz = _mm_sub_pd(_mm_loadu_pd(l.b[2] + i), pz),
                    acx = _mm_sub_pd(_mm_loadu_pd(l.c[0] + i), px),
                    acy = _mm_sub_pd(_mm_loadu_pd(l.c[1] + i), py),
                    acz = _mm_sub_pd(_mm_loadu_pd(l.c[2] + i), pz);
      const __m128d nx = _mm_sub_pd(_mm_mul_pd(aby, acz), _mm_mul_pd(abz, acy)),
                    ny = _mm_sub_pd(_mm_mul_pd(abz, acx), _mm_mul_pd(abx, acz)),
                    nz = _mm_sub_pd(_mm_mul_pd(abx, acy), _mm_mul_pd(aby, acx));
      const __m128d side = _mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, _mm_loadu_pd(l.n[0] + i)),
                                                 _mm_mul_pd(ny, _mm_loadu_pd(l.n[1] + i))),
                                      _mm_mul_pd(nz, _mm_loadu_pd(l.n[2] + i)));
      const __m128d ab2 =
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(abx, abx), _mm_mul_pd(aby, aby)), _mm_mul_pd(abz, abz));
      const __m128d ac2 =
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(acx, acx), _mm_mul_pd(acy, acy)), _mm_mul_pd(acz, acz));
      const __m128d n2 =
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, nx), _mm_mul_pd(ny, ny)), _mm_mul_pd(nz, nz));
      const __m128d denominator = _mm_add_pd(_mm_add_pd(ab2, _mm_loadu_pd(l.fixed + i)), ac2);
      const __m128d q = _mm_div_pd(_mm_mul_pd(scale, _mm_sqrt_pd(n2)), denominator);
      _mm_storeu_pd(quality + i, q);
      double sides[2];
      _mm_storeu_pd(sides, side);
      double denominators[2];
      _mm_storeu_pd(denominators, denominator);
      for (std::size_t k = i; k < std::min(i + 2, size_); ++k) {
        if (sides[k - i] <= 0) feasible = false;
        if (denominators[k - i] == 0) quality[k] = 0;
      }
    }
    if (!feasible) return -1;
    double sum = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      if (quality[i] < quality_floor_) return -1;
      sum += quality[i];
    }
    return sum;
  }
#endif

  /// Exact fold test: every triangle of every element (for a quad, its corner triangles) keeps
  /// the orientation of its reference normal. `Orientation_3` is the traits' exact predicate.
  template <class Traits>
  bool keeps_orientation(const Vec3& position, const Traits& traits) const {
    using Point_3 = typename Traits::Point_3;
    auto orientation = traits.orientation_3_object();
    auto to_point = [](const Vec3& p) { return Point_3(p[0], p[1], p[2]); };
    for (const Element& element : elements()) {
      Vec3 corners[4];
      corners[0] = position;
      for (int i = 1; i < element.degree; ++i) corners[i] = mesh_.points[element.ring[i]];
      for (int c = 0; c < element.degree; ++c) {
        if (element.degree == 3 && c > 0) break;
        const Vec3& a = corners[c];
        const Vec3& b = corners[(c + 1) % element.degree];
        const Vec3& d = corners[(c + element.degree - 1) % element.degree];
        if (orientation(to_point(a), to_point(b), to_point(d),
                        to_point(a + element.reference_normal)) != CGAL::POSITIVE)
          return false;
      }
    }
    return true;
  }

 private:
  Vec3 newell_normal(const Element& element, const Vec3& node_point) const {
    Vec3 normal;
    for (int i = 0; i < element.degree; ++i) {
      const Vec3& a = i == 0 ? node_point : mesh_.points[element.ring[i]];
      const int j = (i + 1) % element.degree;
      const Vec3& b = j == 0 ? node_point : mesh_.points[element.ring[j]];
      normal += cross(a, b);
    }
    return normal;
  }

  const Polygon_arrays& mesh_;
  int node_;
  struct Triangle_lanes {
    static constexpr std::size_t capacity = 32;  // larger or mixed stars: the general loop
    double b[3][capacity], c[3][capacity], n[3][capacity], fixed[capacity];
  };
  const Element* elements_ = nullptr;
  const Triangle_lanes* lanes_ = nullptr;
  bool all_triangles_ = false;
  std::size_t size_ = 0;
  double quality_floor_ = 0;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_STAR_H
