// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_OPEN_SHEETS_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_OPEN_SHEETS_H

// Which border cycles are the outline of an open sheet (a terrain, a scanned face, a CAD sheet)
// rather than a hole. The vector area of a closed polygon, |1/2 sum p_i x p_i+1|, is the area of
// the flat filling seen along its best direction, a lower bound for any surface the polygon
// bounds. When it is a large fraction of the area of the component the cycle borders, a filling
// would be as large as the surface itself: the cycle is that surface's outline, and filling it
// would mean inventing a second sheet (and, for a long outline, minutes of work). A hole cut in a
// closed surface is small against what is left: a cap of a sphere's half bounds 0.5 of the
// remaining hemisphere, a sphere with a 60-degree cap cut off 0.25.

#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/hole_filling/ring_holes.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// `x` with two decimals, for the reasons in the reports.
inline std::string two_decimals(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.2f", x);
  return text;
}

/// Vector area of the border cycle of `h` (see the file comment), model units squared.
template <class PolygonMesh, class VertexPointMap>
double cycle_vector_area(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                         const PolygonMesh& pm, VertexPointMap vpm) {
  Vec3 sum{0, 0, 0};
  for (auto e : cycle_halfedges(h, pm))
    sum = sum + cross(to_array(get(vpm, source(e, pm))), to_array(get(vpm, target(e, pm))));
  return 0.5 * norm(sum);
}

/// For each group, the vector area of its outer cycle over the area of the connected component
/// that the cycle borders (0 when that area is 0). Linear in the mesh size.
template <class PolygonMesh, class VertexPointMap, class Halfedge>
std::vector<double> sheet_border_ratios(PolygonMesh& pm, VertexPointMap vpm,
                                        const std::vector<Hole_group<Halfedge>>& groups) {
  std::vector<double> ratios(groups.size(), 0.0);
  if (groups.empty()) return ratios;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), pm);
  const std::size_t count = CGAL::Polygon_mesh_processing::connected_components(pm, component);
  std::vector<double> area(count, 0.0);
  for (auto f : faces(pm)) {  // a fan of triangles, for faces of any degree
    const Halfedge first = halfedge(f, pm);
    const Vec3 apex = to_array(get(vpm, source(first, pm)));
    for (Halfedge h = next(first, pm); target(h, pm) != source(first, pm); h = next(h, pm)) {
      const Vec3 b = to_array(get(vpm, source(h, pm))), c = to_array(get(vpm, target(h, pm)));
      area[get(component, f)] += 0.5 * norm(cross(b - apex, c - apex));
    }
  }
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const auto f = face(opposite(groups[k].outer, pm), pm);
    if (f == boost::graph_traits<PolygonMesh>::null_face()) continue;
    const double component_area = area[get(component, f)];
    if (component_area > 0)
      ratios[k] = cycle_vector_area(groups[k].outer, pm, vpm) / component_area;
  }
  return ratios;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_OPEN_SHEETS_H
