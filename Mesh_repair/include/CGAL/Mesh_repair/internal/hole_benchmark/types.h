// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_TYPES_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_TYPES_H

// The types of the hole benchmark (hole_benchmark.h documents them).

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Surface_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// Shapes of punched holes. `ring` removes an annulus and leaves an island inside the hole.
enum class Hole_shape { disc, jagged, elongated, ring };

inline const char* to_string(Hole_shape shape) {
  switch (shape) {
    case Hole_shape::disc:
      return "disc";
    case Hole_shape::jagged:
      return "jagged";
    case Hole_shape::elongated:
      return "elongated";
    case Hole_shape::ring:
      return "ring";
  }
  return "unknown";
}

inline bool hole_shape_from_string(const std::string& name, Hole_shape& shape) {
  for (Hole_shape s :
       {Hole_shape::disc, Hole_shape::jagged, Hole_shape::elongated, Hole_shape::ring}) {
    if (name == to_string(s)) {
      shape = s;
      return true;
    }
  }
  return false;
}

/// One punched hole and its ground truth.
template <class PolygonMesh, class Point>
struct Punched_hole {
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  /// A border halfedge (null face) of the outer border cycle: what a filler is given.
  halfedge_descriptor border_halfedge;
  /// One border halfedge per island cycle (ring holes only).
  std::vector<halfedge_descriptor> island_border_halfedges;
  /// Every border halfedge the hole created (outer and islands), with the angle in degrees
  /// between the normal of the removed face and that of the kept face across the edge.
  std::vector<std::pair<halfedge_descriptor, double>> border;
  Point centre;                 ///< the centre vertex's position
  double requested_radius = 0;  ///< model units (F x bounding-box diagonal)
  double achieved_radius = 0;   ///< mean edge-path distance from the centre to the outer border
  std::size_t removed_faces = 0;
  std::size_t outer_border_edges = 0;
  double outer_perimeter = 0;
  /// The removed faces, as a mesh of their own: the truth the fill is compared with.
  CGAL::Surface_mesh<Point> removed_patch;
};

/// What `punch_holes` did.
template <class PolygonMesh, class Point>
struct Punch_result {
  std::vector<Punched_hole<PolygonMesh, Point>> holes;
  std::size_t requested = 0;  ///< holes asked for
  std::size_t attempts = 0;   ///< centre vertices tried
  double bbox_diagonal = 0;   ///< of the mesh before punching
  /// Why fewer holes than requested were punched (empty when all were).
  std::string shortfall;
};

/// Fidelity of one filled hole against its truth (see doc/bench_holes.md for the definitions).
/// Distances are in model units; `_rel` ones are divided by the bounding-box diagonal. Values
/// that cannot be measured (nothing filled) are NaN.
struct Hole_fill_metrics {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  bool filled = false;  ///< every border halfedge of the hole now has a face
  bool closed = false;  ///< filled, and the patch has no border edge left
  bool bounded = true;  ///< the patch is enclosed by the hole's border (no leak past it)
  std::size_t patch_faces = 0, patch_vertices = 0, samples = 0;
  double e1 = nan, e2 = nan, einf = nan;                    ///< over area-weighted samples
  double e1_rel = nan, e2_rel = nan, einf_rel = nan;        ///< divided by the diagonal
  double e1_nodes = nan, e2_nodes = nan, einf_nodes = nan;  ///< at new vertices (thesis 5.7)
  double hausdorff = nan, hausdorff_rel = nan;              ///< symmetric, patch vs removed patch
  double normal_deviation_max_deg = nan, normal_deviation_mean_deg = nan;
  /// Mean over the contour vertices of |mean curvature of their patch-side neighbours - of their
  /// outside neighbours| x diagonal (Pernot 7; 0 for a curvature-continuous fill).
  double curvature_jump = nan;
  double min_alpha = nan, mean_alpha = nan, min_angle_deg = nan;
  std::size_t self_intersections = 0;  ///< intersecting face pairs with a patch face
};

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_TYPES_H
