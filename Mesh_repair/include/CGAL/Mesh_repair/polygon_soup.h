// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_POLYGON_SOUP_H
#define CGAL_MESH_REPAIR_POLYGON_SOUP_H

/// \file polygon_soup.h
/// The polygon soup of the readers (io.h) and of the union of solids (automatic_repair), on its
/// own so that its users need not include the readers.

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// Points and polygons of point indices, as read from a file.
template <class Point>
struct Polygon_soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  /// Faces of the file with fewer than three vertices, left out of `polygons`.
  std::size_t short_polygons_skipped = 0;
  /// Header lines of no known keyword, skipped as free text (PLY, before the elements).
  std::size_t header_lines_skipped = 0;
};

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_POLYGON_SOUP_H
