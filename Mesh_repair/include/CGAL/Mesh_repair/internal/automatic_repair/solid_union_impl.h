// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_IMPL_H

#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/solid_soup.h>

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

#include <exception>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

CGAL_MESH_REPAIR_CORE_INLINE std::string union_of_solids(const std::vector<Triangle_soup>& solids,
                                                         Triangle_soup& out) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  if (solids.size() < 2) return "fewer than two parts";
  Core_mesh merged;
  std::string why = solid_union::to_solid(solids[0], merged);
  if (!why.empty()) return why;
  for (std::size_t i = 1; i < solids.size(); ++i) {
    Core_mesh next, result;
    why = solid_union::to_solid(solids[i], next);
    if (!why.empty()) return why;
    try {
      if (!PMP::corefine_and_compute_union(merged, next, result))
        return "CGAL's corefinement could not compute the union (its result would not be "
               "manifold)";
    } catch (const std::exception& e) {
      return std::string("CGAL's corefinement failed: ") + e.what();
    }
    merged = std::move(result);
  }
  solid_union::to_soup(merged, out);
  return {};
}

CGAL_MESH_REPAIR_CORE_INLINE std::string remove_self_intersections_of_solid(
    const Triangle_soup& solid, Triangle_soup& out, Solid_autorefinement& measures) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Core_mesh mesh;
  std::string why = solid_union::to_closed_mesh(solid, mesh);
  if (!why.empty()) return why;
  const Core_mesh before = mesh;
  measures.area_before = PMP::area(mesh);
  try {
    // The pieces kept are those outside the volume as the faces' orientation defines it.
    if (!PMP::is_outward_oriented(mesh)) PMP::reverse_face_orientations(mesh);
    if (!PMP::experimental::autorefine_and_remove_self_intersections(mesh))
      return "CGAL's autorefinement could not remove them all";
  } catch (const std::exception& e) {
    return std::string("CGAL's autorefinement failed: ") + e.what();
  }
  if (mesh.is_empty() || !CGAL::is_closed(mesh) || !mesh.is_valid(false))
    return "CGAL's autorefinement left an open or invalid part";
  if (PMP::does_self_intersect(mesh)) return "CGAL's autorefinement left self-intersections";
  if (!PMP::does_bound_a_volume(mesh)) return "the autorefined part bounds no volume";
  measures.area_after = PMP::area(mesh);
  measures.largest_distance =
      PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(before.points(), mesh);
  solid_union::to_soup(mesh, out);
  return {};
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_IMPL_H
