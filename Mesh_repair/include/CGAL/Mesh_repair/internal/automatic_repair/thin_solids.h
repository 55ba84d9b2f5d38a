// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_THIN_SOLIDS_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_THIN_SOLIDS_H

// Thin closed components of an exact arrangement's outer surface (self_union_impl.h): where two
// faces of a part nearly meet, the arrangement keeps the wedge between them as a solid of its
// own, a sliver far thinner than it is long, whose faces the rounding of its points to doubles
// can fold across the faces around it.

#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace self_union {

using Face_pairs = std::vector<std::pair<Core_mesh::Face_index, Core_mesh::Face_index>>;

/// The connected components of a closed mesh thinner than `distance`: volume below area times
/// `distance` (slivers of the arrangement: thin wedges between faces that nearly meet).
class Thin_components {
 public:
  Thin_components(const Core_mesh& mesh, double distance)
      : component_(mesh.number_of_faces() + mesh.number_of_removed_faces()) {
    const std::size_t count = CGAL::Polygon_mesh_processing::connected_components(
        mesh, CGAL::make_property_map(component_));
    std::vector<double> area(count), volume(count);
    for (auto f : mesh.faces()) {
      const auto h = mesh.halfedge(f);
      const auto &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
                 &c = mesh.point(mesh.target(mesh.next(h)));
      area[component_[f]] += std::sqrt(CGAL::squared_area(a, b, c));
      volume[component_[f]] +=
          CGAL::determinant(a - CGAL::ORIGIN, b - CGAL::ORIGIN, c - CGAL::ORIGIN) / 6;
    }
    for (std::size_t c = 0; c < count; ++c)
      thin_.push_back(std::abs(volume[c]) < distance * area[c]);
  }
  bool is_thin(Core_mesh::Face_index f) const { return thin_[component_[f]]; }
  std::size_t component(Core_mesh::Face_index f) const { return component_[f]; }

 private:
  std::vector<std::size_t> component_;
  std::vector<bool> thin_;
};

/// `result` without its thin components (`Thin_components`) that have a face in `crossing`, in
/// `out`; the number of components dropped.
inline std::size_t drop_thin_crossing_components(const Core_mesh& result,
                                                 const Face_pairs& crossing, double distance,
                                                 Triangle_soup& out) {
  const Thin_components thin(result, distance);
  std::set<std::size_t> dropped;
  for (const auto& pair : crossing)
    for (auto f : {pair.first, pair.second})
      if (thin.is_thin(f)) dropped.insert(thin.component(f));
  if (dropped.empty()) return 0;
  out = Triangle_soup();
  std::vector<std::size_t> index(result.number_of_vertices() + result.number_of_removed_vertices(),
                                 std::size_t(-1));
  for (auto f : result.faces()) {
    if (dropped.count(thin.component(f))) continue;
    std::vector<std::size_t> polygon;
    for (auto v : vertices_around_face(result.halfedge(f), result)) {
      if (index[v] == std::size_t(-1)) {
        index[v] = out.points.size();
        out.points.push_back(result.point(v));
      }
      polygon.push_back(index[v]);
    }
    out.polygons.push_back(std::move(polygon));
  }
  return dropped.size();
}

/// True when the two faces of some pair of `crossing` lie in different components of `mesh`.
inline bool crosses_between_components(const Core_mesh& mesh, const Face_pairs& crossing) {
  const Thin_components components(mesh, 0);
  for (const auto& pair : crossing)
    if (components.component(pair.first) != components.component(pair.second)) return true;
  return false;
}

}  // namespace self_union
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_THIN_SOLIDS_H
