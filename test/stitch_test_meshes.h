// Meshes with gaps, overlaps and T-junctions built like the thesis figures (4.8, 4.16, 4.17), and
// the geometric facts the stitching tests check. Shared by test_stitch_gaps, test_t_junctions and
// test_remove_slivers.
#ifndef MESH_REPAIR_TEST_STITCH_TEST_MESHES_H
#define MESH_REPAIR_TEST_STITCH_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

namespace stitch_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = Mesh::Vertex_index;
using halfedge_descriptor = Mesh::Halfedge_index;
using face_descriptor = Mesh::Face_index;

struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
};

inline Mesh to_mesh(const Soup& soup) {
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.faces, mesh);
  return mesh;
}

inline std::size_t border_cycle_count(const Mesh& mesh) {
  std::vector<halfedge_descriptor> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  return cycles.size();
}

inline std::size_t non_manifold_vertex_count(const Mesh& mesh) {
  std::size_t count = 0;
  for (vertex_descriptor v : vertices(mesh))
    if (CGAL::Polygon_mesh_processing::is_non_manifold_vertex(v, mesh)) ++count;
  return count;
}

/// Appends an (nu x nv)-cell grid over the parallelogram origin + s*u + t*v, s,t in [0,1].
inline void add_grid_patch(Soup& soup, const Point& origin, const Vector& u, const Vector& v,
                           int nu, int nv) {
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

/// Figure 4.16: the unit cube as six separately meshed faces, face k an n_k x n_k grid shrunk
/// by `inset` on every side, so neighbouring faces have non-matching nodes and a gap of
/// inset * sqrt(2) between their borders.
inline Soup cube_of_separate_faces(double inset, const std::array<int, 6>& resolution) {
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

/// Figure 4.8: two patches of the curved surface z = 0.3 sin(2x) meeting along y = 0, the lower
/// one with `nodes_below` cells along x and the upper one with `nodes_above`, `gap` apart in y.
inline Soup curved_patches(int nodes_below, int nodes_above, double gap) {
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

/// Cuts `closed` into `patch_count` patches (faces go to the nearest of random seed faces, so
/// the cuts are curves), gives every patch its own copy of its vertices, then moves every copy of
/// a cut vertex independently by up to `gap / 2` (random direction), so the two sides of every cut
/// are at most `gap` apart, overlap or leave a gap, with non-matching positions.
inline Soup cut_and_jitter(const Mesh& closed, int patch_count, double gap, unsigned seed) {
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

/// Splits every `every`-th border edge of `mesh` at parameter 0.4 (with its incident triangle),
/// so that the nodes on the two sides of a cut stop matching (T-junctions).
inline std::size_t split_border_edges(Mesh& mesh, int every) {
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

/// Largest distance from a vertex of `mesh` to the analytic unit sphere.
inline double max_distance_to_unit_sphere(const Mesh& mesh) {
  double worst = 0;
  for (vertex_descriptor v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    worst = std::max(
        worst, std::abs(std::sqrt(CGAL::to_double((p - CGAL::ORIGIN).squared_length())) - 1.0));
  }
  return worst;
}

inline bool self_intersects(const Mesh& mesh) {
  return CGAL::Polygon_mesh_processing::does_self_intersect(mesh);
}

}  // namespace stitch_test

#endif  // MESH_REPAIR_TEST_STITCH_TEST_MESHES_H
