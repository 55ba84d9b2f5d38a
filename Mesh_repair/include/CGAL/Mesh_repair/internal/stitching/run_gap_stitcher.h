// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_STITCHING_RUN_GAP_STITCHER_H
#define CGAL_MESH_REPAIR_INTERNAL_STITCHING_RUN_GAP_STITCHER_H

// Named-parameter plumbing shared by stitch_gaps() and repair_t_junctions().

#include <CGAL/Mesh_repair/internal/stitching/gap_stitcher.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// `merge_tolerance`, else `relative_tolerance` times the bounding-box diagonal, else -1
/// (derived locally).
template <class PolygonMesh, class NamedParameters>
double absolute_tolerance(const PolygonMesh& pm, const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double absolute =
      choose_parameter(get_parameter(np, internal_np::merge_tolerance_t{}), -1.0);
  if (absolute >= 0) return absolute;
  const double relative =
      choose_parameter(get_parameter(np, internal_np::relative_tolerance_t{}), -1.0);
  if (relative < 0) return -1.0;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, pm));
  bool first = true;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (auto v : vertices(pm)) {
    const auto& p = get(vpm, v);
    const double xyz[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for (int i = 0; i < 3; ++i) {
      lo[i] = first ? xyz[i] : std::min(lo[i], xyz[i]);
      hi[i] = first ? xyz[i] : std::max(hi[i], xyz[i]);
    }
    first = false;
  }
  const double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
  return relative * std::sqrt(dx * dx + dy * dy + dz * dz);
}

template <class PolygonMesh>
using Vertex_list = std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>;

/// `stitch_gaps` / `repair_t_junctions` on plain settings (compiled once per mesh type);
/// `frozen` vertices neither move nor take T-junction nodes (see `Gap_stitcher`).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Stitch_result run_gap_stitcher(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits&,
                               const Stitch_settings& settings, Any_visitor visitor,
                               const Vertex_list<PolygonMesh>& frozen = {}) {
  Gap_stitcher<PolygonMesh, VertexPointMap, GeomTraits, Any_visitor> stitcher(pm, vpm, settings,
                                                                              visitor, frozen);
  Stitch_result result = stitcher.run();
  result.valid = CGAL::is_valid_polygon_mesh(pm);
  return result;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_STITCH_GAPS
extern
#endif
    template Stitch_result
    run_gap_stitcher<Core_mesh, Core_vpm, Core_traits>(Core_mesh&, Core_vpm, const Core_traits&,
                                                       const Stitch_settings&, Any_visitor,
                                                       const Vertex_list<Core_mesh>&);
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_STITCHING_RUN_GAP_STITCHER_H
