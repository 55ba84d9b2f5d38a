// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SOUP_EDGE_H
#define CGAL_MESH_REPAIR_INTERNAL_SOUP_EDGE_H

#include <algorithm>
#include <cstddef>
#include <utility>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// An edge of a polygon soup as a key: the indices of its two points, the smaller first, so that
/// the polygons on either side of it (in either direction) find one entry.
using Soup_edge = std::pair<std::size_t, std::size_t>;

inline Soup_edge soup_edge(std::size_t a, std::size_t b) {
  return Soup_edge(std::min(a, b), std::max(a, b));
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SOUP_EDGE_H
