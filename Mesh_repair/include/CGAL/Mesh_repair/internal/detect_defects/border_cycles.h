// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_BORDER_CYCLES_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_BORDER_CYCLES_H

// Border cycles with their size, and which of them are islands lying inside another hole (the
// ring-hole test of thesis 4.4, shared with hole filling).

#include <CGAL/Mesh_repair/internal/detect_defects/mesh_access.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/hole_filling/ring_holes.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

/// One border cycle as halfedges, kept while detecting (gaps and T-junctions walk them too).
template <class Halfedge>
using Cycle_halfedges = std::vector<Halfedge>;

/// The border cycles of the mesh (the shared `internal::border_cycles`), each as its halfedges.
template <class Access>
std::vector<Cycle_halfedges<typename Access::halfedge_descriptor>> border_cycle_halfedges(
    const Access& mesh) {
  std::vector<Cycle_halfedges<typename Access::halfedge_descriptor>> cycles;
  for (auto h : internal::border_cycles(mesh.pm)) cycles.push_back(cycle_halfedges(h, mesh.pm));
  return cycles;
}

/// Vector area (Newell) of a closed polygon: its direction is the normal of the best-fitting
/// plane, its norm the area of a flat patch closing it.
inline Coordinates vector_area(const std::vector<Coordinates>& polygon) {
  Coordinates sum{0, 0, 0};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto c = internal::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    for (int k = 0; k < 3; ++k) sum[k] += 0.5 * c[k];
  }
  return sum;
}

template <class Access>
Border_cycle describe_cycle(const Access& mesh,
                            const Cycle_halfedges<typename Access::halfedge_descriptor>& cycle) {
  Border_cycle result;
  result.edges = cycle.size();
  std::vector<Coordinates> polygon;
  polygon.reserve(cycle.size());
  for (auto h : cycle) {
    result.vertices.push_back(mesh.index(source(h, mesh.pm)));
    polygon.push_back(mesh.coordinates(source(h, mesh.pm)));
  }
  result.first_point = polygon.front();
  result.bbox.min = result.bbox.max = polygon.front();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    result.perimeter +=
        internal::norm(internal::sub(polygon[(i + 1) % polygon.size()], polygon[i]));
    for (int k = 0; k < 3; ++k) {
      result.bbox.min[k] = std::min(result.bbox.min[k], polygon[i][k]);
      result.bbox.max[k] = std::max(result.bbox.max[k], polygon[i][k]);
    }
  }
  // Relative to the first point, so a small hole far from the origin keeps its precision.
  std::vector<Coordinates> centred;
  for (const auto& p : polygon) centred.push_back(internal::sub(p, polygon.front()));
  result.area = internal::norm(vector_area(centred));
  return result;
}

/// Thesis 4.4: marks the cycles that are islands of a ring hole, with the test `fill_holes`
/// uses to bridge them (`internal::ring_hole_owners`), so both always agree.
template <class Access>
void find_ring_hole_islands(
    const Access& mesh,
    const std::vector<Cycle_halfedges<typename Access::halfedge_descriptor>>& cycles,
    std::vector<Border_cycle>& descriptions) {
  std::vector<typename Access::halfedge_descriptor> first;
  for (const auto& cycle : cycles) first.push_back(cycle.front());
  const std::vector<long> owner = ring_hole_owners(mesh.pm, mesh.vpm, first);
  for (std::size_t i = 0; i < cycles.size(); ++i) descriptions[i].island_of = owner[i];
}

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_BORDER_CYCLES_H
