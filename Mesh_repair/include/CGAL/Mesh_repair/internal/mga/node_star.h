// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_STAR_H
#define CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_STAR_H

// Index arrays of a triangle / quad mesh and the "star" of a node: its incident elements with the
// node first, the fitness of eq. 5 / eq. 8 for a trial position, and the fold test.

#include <CGAL/Mesh_repair/internal/c1_surface/vec3.h>
#include <CGAL/Mesh_repair/quality.h>

#include <algorithm>
#include <array>
#include <vector>

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
  };

  Node_star(const Polygon_arrays& mesh, int node) : mesh_(mesh), node_(node) {
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
      elements_.push_back(element);
    }
    // The worst element of the star may only get worse while it stays above 0.5 (a sum-only
    // fitness would trade a sliver for gains elsewhere, as the paper's Table 3 shows).
    double worst = 1;
    for (const Element& element : elements_) {
      Vec3 corners[4] = {mesh.points[node], element.corners[1], element.corners[2],
                         element.corners[3]};
      worst = std::min(worst, element_quality(corners, element.degree));
    }
    quality_floor_ = std::min(worst, 0.5);
  }

  int node() const { return node_; }
  const std::vector<Element>& elements() const { return elements_; }

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
    double sum = 0;
    Vec3 corners[4];
    for (const Element& element : elements_) {
      corners[0] = position;
      for (int i = 1; i < element.degree; ++i) corners[i] = element.corners[i];
      if (dot(cross(corners[1] - corners[0], corners[element.degree - 1] - corners[0]),
              element.reference_normal) <= 0)
        return -1;
      const double quality = element_quality(corners, element.degree);
      if (quality < quality_floor_) return -1;
      sum += quality;
    }
    return sum;
  }

  /// Exact fold test: every triangle of every element (for a quad, its corner triangles) keeps
  /// the orientation of its reference normal. `Orientation_3` is the traits' exact predicate.
  template <class Traits>
  bool keeps_orientation(const Vec3& position, const Traits& traits) const {
    using Point_3 = typename Traits::Point_3;
    auto orientation = traits.orientation_3_object();
    auto to_point = [](const Vec3& p) { return Point_3(p[0], p[1], p[2]); };
    for (const Element& element : elements_) {
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
  std::vector<Element> elements_;
  double quality_floor_ = 0;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_STAR_H
