// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The stitching suites' meshes and checks (stitch_test_meshes.h), compiled once.
#include "support/stitch_test_meshes.h"

#include "support/cgal_calls.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace stitch_test {

Mesh to_mesh(const Soup& soup) {
  Mesh mesh;
  mesh_repair_test::polygon_soup_to_polygon_mesh(soup.points, soup.faces, mesh);
  return mesh;
}

std::size_t border_cycle_count(const Mesh& mesh) {
  return mesh_repair_test::boundary_cycles(mesh).size();
}

std::size_t non_manifold_vertex_count(const Mesh& mesh) {
  return mesh_repair_test::non_manifold_vertex_count(mesh);
}

void add_grid_patch(Soup& soup, const Point& origin, const Vector& u, const Vector& v, int nu,
                    int nv) {
  const std::size_t base = soup.points.size();
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      soup.points.push_back(origin + (double(i) / nu) * u + (double(j) / nv) * v);
  auto at = [&](int i, int j) { return base + std::size_t(j) * (nu + 1) + i; };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      soup.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      soup.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
}

Soup cube_of_separate_faces(double inset, const std::array<int, 6>& resolution) {
  Soup soup;
  const double a = inset, b = 1.0 - inset, w = b - a;
  // Each face: origin, u, v with u x v pointing outwards.
  add_grid_patch(soup, Point(0, a, a), Vector(0, 0, w), Vector(0, w, 0), resolution[0],
                 resolution[0]);
  add_grid_patch(soup, Point(1, a, a), Vector(0, w, 0), Vector(0, 0, w), resolution[1],
                 resolution[1]);
  add_grid_patch(soup, Point(a, 0, a), Vector(w, 0, 0), Vector(0, 0, w), resolution[2],
                 resolution[2]);
  add_grid_patch(soup, Point(a, 1, a), Vector(0, 0, w), Vector(w, 0, 0), resolution[3],
                 resolution[3]);
  add_grid_patch(soup, Point(a, a, 0), Vector(0, w, 0), Vector(w, 0, 0), resolution[4],
                 resolution[4]);
  add_grid_patch(soup, Point(a, a, 1), Vector(w, 0, 0), Vector(0, w, 0), resolution[5],
                 resolution[5]);
  return soup;
}

Soup curved_patches(int nodes_below, int nodes_above, double gap) {
  Soup soup;
  auto add = [&](double y0, double y1, int nx, int ny) {
    const std::size_t base = soup.points.size();
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        const double x = 2.0 * i / nx, y = y0 + (y1 - y0) * j / ny;
        soup.points.emplace_back(x, y, 0.3 * std::sin(2 * x));
      }
    }
    auto at = [&](int i, int j) { return base + std::size_t(j) * (nx + 1) + i; };
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        soup.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        soup.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  };
  add(-1.0, -gap / 2, nodes_below, 4);
  add(gap / 2, 1.0, nodes_above, 4);
  return soup;
}

Soup cut_and_jitter(const Mesh& closed, int patch_count, double gap, unsigned seed) {
  CGAL::Random random(seed);
  std::vector<Point> centroids;
  for (face_descriptor f : faces(closed)) {
    Vector sum(0, 0, 0);
    for (vertex_descriptor v : vertices_around_face(halfedge(f, closed), closed))
      sum = sum + (closed.point(v) - CGAL::ORIGIN);
    centroids.push_back(CGAL::ORIGIN + sum / 3.0);
  }
  std::vector<Point> seeds;
  for (int k = 0; k < patch_count; ++k)
    seeds.push_back(centroids[std::size_t(random.get_int(0, int(centroids.size())))]);
  Soup soup;
  std::map<std::pair<int, vertex_descriptor>, std::size_t> copy;
  std::map<vertex_descriptor, std::set<int>> patches_of_vertex;
  std::vector<int> patch_of_face;
  std::size_t index = 0;
  for (face_descriptor f : faces(closed)) {
    int best = 0;
    for (int k = 1; k < patch_count; ++k)
      if (CGAL::squared_distance(centroids[index], seeds[std::size_t(k)]) <
          CGAL::squared_distance(centroids[index], seeds[std::size_t(best)]))
        best = k;
    patch_of_face.push_back(best);
    for (vertex_descriptor v : vertices_around_face(halfedge(f, closed), closed))
      patches_of_vertex[v].insert(best);
    ++index;
  }
  index = 0;
  for (face_descriptor f : faces(closed)) {
    const int patch = patch_of_face[index++];
    std::vector<std::size_t> polygon;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, closed), closed)) {
      auto [it, inserted] = copy.emplace(std::make_pair(patch, v), soup.points.size());
      if (inserted) {
        Point p = closed.point(v);
        if (gap > 0 && patches_of_vertex[v].size() > 1) {  // gap 0: exact copies
          Vector direction(random.get_double(-1, 1), random.get_double(-1, 1),
                           random.get_double(-1, 1));
          const double length = std::sqrt(direction.squared_length());
          if (length > 0) p = p + (random.get_double(0, gap / 2) / length) * direction;
        }
        soup.points.push_back(p);
      }
      polygon.push_back(it->second);
    }
    soup.faces.push_back(polygon);
  }
  return soup;
}

Soup crack_across(const Mesh& input, const Vector& normal, double gap) {
  Mesh closed = input;  // with property maps of its own

  std::vector<double> height;
  for (face_descriptor f : faces(closed)) {
    double sum = 0;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, closed), closed))
      sum += (closed.point(v) - CGAL::ORIGIN) * normal;
    height.push_back(sum / 3);
  }
  std::vector<double> sorted = height;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double cut = sorted[sorted.size() / 2];
  // Pieces of one side cut off by the other (a face above among faces below) change sides, so
  // each side is one piece and the crack one clean cut.
  auto upper = closed.add_property_map<face_descriptor, bool>("f:upper", false).first;
  {
    std::size_t k = 0;
    for (face_descriptor f : faces(closed)) upper[f] = height[k++] >= cut;
  }
  auto on_cut = closed.add_property_map<Mesh::Edge_index, bool>("e:on_cut", false).first;
  for (auto e : edges(closed)) {
    const halfedge_descriptor h = halfedge(e, closed);
    on_cut[e] = upper[face(h, closed)] != upper[face(opposite(h, closed), closed)];
  }
  auto piece = closed.add_property_map<face_descriptor, std::size_t>("f:piece", 0).first;
  const std::size_t pieces = CGAL::Polygon_mesh_processing::connected_components(
      closed, piece, CGAL::parameters::edge_is_constrained_map(on_cut));
  std::vector<std::size_t> size(pieces, 0);
  for (face_descriptor f : faces(closed)) ++size[piece[f]];
  std::size_t largest[2] = {pieces, pieces};
  for (face_descriptor f : faces(closed)) {
    std::size_t& best = largest[upper[f]];
    if (best == pieces || size[piece[f]] > size[best]) best = piece[f];
  }
  std::vector<bool> upper_of_face;
  for (face_descriptor f : faces(closed))
    upper_of_face.push_back(piece[f] == largest[upper[f]] ? upper[f] : !upper[f]);
  Soup soup;
  std::map<std::pair<bool, vertex_descriptor>, std::size_t> copy;
  std::size_t index = 0;
  for (face_descriptor f : faces(closed)) {
    const bool upper = upper_of_face[index++];
    std::vector<std::size_t> polygon;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, closed), closed)) {
      auto [it, inserted] = copy.emplace(std::make_pair(upper, v), soup.points.size());
      if (inserted) soup.points.push_back(closed.point(v) + (upper ? gap : 0.0) * normal);
      polygon.push_back(it->second);
    }
    soup.faces.push_back(polygon);
  }
  return soup;
}

std::size_t split_border_edges(Mesh& mesh, int every) {
  std::vector<halfedge_descriptor> border;
  for (halfedge_descriptor h : halfedges(mesh))
    if (is_border(h, mesh)) border.push_back(h);
  std::size_t splits = 0;
  for (std::size_t k = 0; k < border.size(); k += std::size_t(every)) {
    const halfedge_descriptor inner = opposite(border[k], mesh);
    const Point a = mesh.point(source(border[k], mesh)), b = mesh.point(target(border[k], mesh));
    const halfedge_descriptor to_new = CGAL::Euler::split_edge(inner, mesh);
    mesh.point(target(to_new, mesh)) = a + 0.4 * (b - a);
    CGAL::Euler::split_face(to_new, next(inner, mesh), mesh);
    ++splits;
  }
  return splits;
}

double max_distance_to_unit_sphere(const Mesh& mesh) {
  double worst = 0;
  for (vertex_descriptor v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    worst = std::max(
        worst, std::abs(std::sqrt(CGAL::to_double((p - CGAL::ORIGIN).squared_length())) - 1.0));
  }
  return worst;
}

bool self_intersects(const Mesh& mesh) {
  return mesh_repair_test::does_self_intersect(mesh);
}

}  // namespace stitch_test
