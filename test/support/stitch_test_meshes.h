// Meshes with gaps, overlaps and T-junctions built like the thesis figures (4.8, 4.16, 4.17), and
// the geometric facts the stitching tests check. Shared by test_stitch_gaps, test_t_junctions and
// test_remove_slivers; compiled once in the test-support library (stitch_test_meshes.cpp).
#ifndef MESH_REPAIR_TEST_STITCH_TEST_MESHES_H
#define MESH_REPAIR_TEST_STITCH_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstddef>
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

Mesh to_mesh(const Soup& soup);

std::size_t border_cycle_count(const Mesh& mesh);

std::size_t non_manifold_vertex_count(const Mesh& mesh);

/// Appends an (nu x nv)-cell grid over the parallelogram origin + s*u + t*v, s,t in [0,1].
void add_grid_patch(Soup& soup, const Point& origin, const Vector& u, const Vector& v, int nu,
                    int nv);

/// Figure 4.16: the unit cube as six separately meshed faces, face k an n_k x n_k grid shrunk
/// by `inset` on every side, so neighbouring faces have non-matching nodes and a gap of
/// inset * sqrt(2) between their borders.
Soup cube_of_separate_faces(double inset, const std::array<int, 6>& resolution);

/// Figure 4.8: two patches of the curved surface z = 0.3 sin(2x) meeting along y = 0, the lower
/// one with `nodes_below` cells along x and the upper one with `nodes_above`, `gap` apart in y.
Soup curved_patches(int nodes_below, int nodes_above, double gap);

/// Cuts `closed` into `patch_count` patches (faces go to the nearest of random seed faces, so
/// the cuts are curves), gives every patch its own copy of its vertices, then moves every copy of
/// a cut vertex independently by up to `gap / 2` (random direction), so the two sides of every cut
/// are at most `gap` apart, overlap or leave a gap, with non-matching positions.
Soup cut_and_jitter(const Mesh& closed, int patch_count, double gap, unsigned seed);

/// `closed` cut across by the plane of unit `normal` through the median face centroid (faces go
/// by their centroid, so the cut runs along edges), the upper side with its own copies of the cut
/// vertices and moved by `gap` along `normal`: a crack whose sides are `gap` apart.
Soup crack_across(const Mesh& closed, const Vector& normal, double gap);

/// Splits every `every`-th border edge of `mesh` at parameter 0.4 (with its incident triangle),
/// so that the nodes on the two sides of a cut stop matching (T-junctions).
std::size_t split_border_edges(Mesh& mesh, int every);

/// Largest distance from a vertex of `mesh` to the analytic unit sphere.
double max_distance_to_unit_sphere(const Mesh& mesh);

bool self_intersects(const Mesh& mesh);

}  // namespace stitch_test

#endif  // MESH_REPAIR_TEST_STITCH_TEST_MESHES_H
