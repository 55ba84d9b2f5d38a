// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_MESH_COUNTS_H
#define CGAL_MESH_REPAIR_INTERNAL_MESH_COUNTS_H

// Element counts that skip removed elements. BGL's num_faces/num_vertices on a Surface_mesh
// count the capacity, removed elements included, until collect_garbage(); a report that counts
// what an operation removed must not use them.

#include <boost/graph/graph_traits.hpp>

#include <iterator>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

template <class PolygonMesh>
std::size_t count_faces(const PolygonMesh& pm) {
  return std::size_t(std::distance(faces(pm).begin(), faces(pm).end()));
}

template <class PolygonMesh>
std::size_t count_vertices(const PolygonMesh& pm) {
  return std::size_t(std::distance(vertices(pm).begin(), vertices(pm).end()));
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_MESH_COUNTS_H
