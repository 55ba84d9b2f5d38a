// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_CLOUGH_TOCHER_H
#define CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_CLOUGH_TOCHER_H

// C1 interpolant of scattered functional data z = f(x, y) over a planar triangulation (Chen et
// al. 2.2, Table 1). Each triangle is split at its centroid into three cubic Bezier triangles
// (the Clough-Tocher split, the split-triangle family of Goodman and Said's interpolant). Vertex
// values and estimated gradients fix every ordinate except the three next to the outer edges;
// those make the derivative across each outer edge, in the direction perpendicular to the edge,
// linear along it, so two triangles sharing an edge agree on the full gradient there: the
// surface is C1 everywhere (the interior split edges are C1 by the classical centroid averaging).

#include <CGAL/Mesh_repair/internal/c1_surface/local_derivative_estimation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

class Clough_tocher_interpolant {
 public:
  using Point2 = std::array<double, 2>;
  using Triangle = std::array<int, 3>;

  /// Gradients are estimated from the data (local quadratic fit over the one- and two-rings).
  Clough_tocher_interpolant(std::vector<Point2> sites, std::vector<double> values,
                            std::vector<Triangle> triangles)
      : sites_(std::move(sites)), values_(std::move(values)), triangles_(std::move(triangles)) {
    estimate_gradients();
    for (const Triangle& t : triangles_) nets_.push_back(control_net(t));
  }

  const std::vector<Point2>& gradients() const { return gradients_; }

  /// The value of the C1 interpolant at (x, y), or of the piecewise-linear (C0) one; points
  /// outside the triangulation get the value of the nearest-barycentric triangle (extrapolated).
  double value(double x, double y) const { return evaluate(x, y, true); }
  double linear_value(double x, double y) const { return evaluate(x, y, false); }

 private:
  // Ordinates of the three cubic sub-triangles T_i = (P_{i+1}, P_{i+2}, C), each with the
  // Bezier indices (j, k, c) for the powers of the barycentrics of P_{i+1}, P_{i+2} and C.
  struct Net {
    std::array<std::array<double, 10>, 3> ordinates;
  };
  static int slot(int j, int k) {  // index of b_{j k (3-j-k)} in a 10-array
    static const int table[4][4] = {{0, 1, 2, 3}, {4, 5, 6, -1}, {7, 8, -1, -1}, {9, -1, -1, -1}};
    return table[j][k];
  }

  void estimate_gradients() {
    std::vector<std::set<int>> ring(sites_.size());
    for (const Triangle& t : triangles_)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (i != j) ring[t[i]].insert(t[j]);
    gradients_.assign(sites_.size(), {0, 0});
    for (std::size_t v = 0; v < sites_.size(); ++v) {
      std::set<int> neighbours = ring[v];
      if (neighbours.size() < 5)
        for (int n : ring[v]) neighbours.insert(ring[n].begin(), ring[n].end());
      neighbours.erase(int(v));
      std::vector<Height_sample> samples;
      for (int n : neighbours)
        samples.push_back(
            {sites_[n][0] - sites_[v][0], sites_[n][1] - sites_[v][1], values_[n] - values_[v]});
      gradients_[v] = estimate_gradient(samples);
    }
  }

  double directional(int vertex, const Point2& to) const {
    return gradients_[vertex][0] * (to[0] - sites_[vertex][0]) +
           gradients_[vertex][1] * (to[1] - sites_[vertex][1]);
  }

  Net control_net(const Triangle& t) const {
    const Point2 centroid = {(sites_[t[0]][0] + sites_[t[1]][0] + sites_[t[2]][0]) / 3,
                             (sites_[t[0]][1] + sites_[t[1]][1] + sites_[t[2]][1]) / 3};
    // toward_centroid[i] = a_i, the ordinate one third of the way from P_i to C.
    std::array<double, 3> toward_centroid, inner;
    std::array<double, 3> edge_inner;  // b_111 of sub-triangle i (the edge P_{i+1} P_{i+2})
    for (int i = 0; i < 3; ++i)
      toward_centroid[i] = values_[t[i]] + directional(t[i], centroid) / 3;
    Net net;
    for (int i = 0; i < 3; ++i) {
      const int j = t[(i + 1) % 3], k = t[(i + 2) % 3];
      auto& b = net.ordinates[i];
      const double fj = values_[j], fk = values_[k];
      const double ejk = fj + directional(j, sites_[k]) / 3,
                   ekj = fk + directional(k, sites_[j]) / 3;
      b[slot(3, 0)] = fj;
      b[slot(0, 3)] = fk;
      b[slot(2, 1)] = ejk;
      b[slot(1, 2)] = ekj;
      b[slot(2, 0)] = toward_centroid[(i + 1) % 3];
      b[slot(0, 2)] = toward_centroid[(i + 2) % 3];
      // Direction perpendicular to the edge, written in the sub-triangle's barycentrics as
      // (a_j, a_k, 1): (C - M) minus its component s (P_k - P_j) along the edge.
      const double ex = sites_[k][0] - sites_[j][0], ey = sites_[k][1] - sites_[j][1];
      const double mx = centroid[0] - 0.5 * (sites_[j][0] + sites_[k][0]);
      const double my = centroid[1] - 0.5 * (sites_[j][1] + sites_[k][1]);
      const double s = (mx * ex + my * ey) / (ex * ex + ey * ey);
      const double aj = -0.5 + s, ak = -0.5 - s;
      const double q20 = aj * fj + ak * ejk + b[slot(2, 0)];
      const double q02 = aj * ekj + ak * fk + b[slot(0, 2)];
      // Linear cross-boundary derivative: the middle coefficient is the mean of the end ones.
      edge_inner[i] = 0.5 * (q20 + q02) - aj * ejk - ak * ekj;
      b[slot(1, 1)] = edge_inner[i];
    }
    // d_i, two thirds of the way from P_i to C: mean of a_i and the two b_111 beside it.
    for (int i = 0; i < 3; ++i)
      inner[i] = (toward_centroid[i] + edge_inner[(i + 1) % 3] + edge_inner[(i + 2) % 3]) / 3;
    const double centre = (inner[0] + inner[1] + inner[2]) / 3;
    for (int i = 0; i < 3; ++i) {
      auto& b = net.ordinates[i];
      b[slot(1, 0)] = inner[(i + 1) % 3];
      b[slot(0, 1)] = inner[(i + 2) % 3];
      b[slot(0, 0)] = centre;
    }
    return net;
  }

  std::array<double, 3> barycentric(const Triangle& t, double x, double y) const {
    const Point2 &a = sites_[t[0]], &b = sites_[t[1]], &c = sites_[t[2]];
    const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    const double l1 = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
    const double l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
    return {1 - l1 - l2, l1, l2};
  }

  double evaluate(double x, double y, bool smooth) const {
    std::size_t best = 0;
    double best_min = -1e300;
    std::array<double, 3> lambda{};
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const auto l = barycentric(triangles_[t], x, y);
      const double smallest = std::min({l[0], l[1], l[2]});
      if (smallest > best_min) best_min = smallest, best = t, lambda = l;
      if (smallest >= 0) break;
    }
    const Triangle& t = triangles_[best];
    if (!smooth)
      return lambda[0] * values_[t[0]] + lambda[1] * values_[t[1]] + lambda[2] * values_[t[2]];
    // Sub-triangle i (opposite P_i) holds the point when lambda_i is the smallest; there the
    // barycentrics are (l_j - l_i, l_k - l_i, 3 l_i).
    int i = 0;
    if (lambda[1] < lambda[i]) i = 1;
    if (lambda[2] < lambda[i]) i = 2;
    const double bj = lambda[(i + 1) % 3] - lambda[i], bk = lambda[(i + 2) % 3] - lambda[i];
    const double bc = 3 * lambda[i];
    const auto& b = nets_[best].ordinates[i];
    const double factorial[4] = {1, 1, 2, 6};
    double sum = 0;
    for (int j = 0; j <= 3; ++j)
      for (int k = 0; j + k <= 3; ++k) {
        const int c = 3 - j - k;
        sum += 6.0 / (factorial[j] * factorial[k] * factorial[c]) * std::pow(bj, j) *
               std::pow(bk, k) * std::pow(bc, c) * b[slot(j, k)];
      }
    return sum;
  }

  std::vector<Point2> sites_;
  std::vector<double> values_;
  std::vector<Triangle> triangles_;
  std::vector<Point2> gradients_;
  std::vector<Net> nets_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_CLOUGH_TOCHER_H
