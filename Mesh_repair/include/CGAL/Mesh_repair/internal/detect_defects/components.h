// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_COMPONENTS_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_COMPONENTS_H

// Connected components (through edges) with their sizes, closedness and, for closed ones, the
// orientation of the bounded volume, decided like CGAL's is_outward_oriented: at the vertex of
// largest z of the component, with exact predicates.

#include <CGAL/Mesh_repair/internal/detect_defects/mesh_access.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

/// A read-write property map storing values in a vector indexed through an index map.
template <class Key, class IndexMap>
struct Indexed_map {
  using key_type = Key;
  using value_type = std::size_t;
  using reference = std::size_t&;
  using category = boost::lvalue_property_map_tag;
  IndexMap index;
  CGAL::Pointer_property_map<std::size_t>::type values;
  friend std::size_t& get(const Indexed_map& m, const Key& k) {
    return get(m.values, std::size_t(get(m.index, k)));
  }
  friend void put(const Indexed_map& m, const Key& k, std::size_t v) {
    put(m.values, std::size_t(get(m.index, k)), v);
  }
};

template <class Access>
std::vector<Connected_component> connected_components(const Access& mesh, bool triangle_mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename Access::vertex_descriptor;
  std::vector<std::size_t> component_of_face(num_faces(mesh.pm), 0);
  auto face_component = [&](typename Access::face_descriptor f) {
    return component_of_face[mesh.index(f)];
  };
  const std::size_t count =
      PMP::connected_components(mesh.pm,
                                Indexed_map<typename Access::face_descriptor, decltype(mesh.fim)>{
                                    mesh.fim, CGAL::make_property_map(component_of_face)},
                                CGAL::parameters::face_index_map(mesh.fim));
  std::vector<Connected_component> components(count);
  for (auto f : faces(mesh.pm)) ++components[face_component(f)].faces;
  std::vector<vertex_descriptor> highest(count,
                                         boost::graph_traits<typename Access::Mesh>::null_vertex());
  auto compare_z = mesh.gt.compare_z_3_object();
  for (vertex_descriptor v : vertices(mesh.pm)) {
    const auto h = halfedge(v, mesh.pm);
    if (h == boost::graph_traits<typename Access::Mesh>::null_halfedge()) continue;
    const auto f = is_border(h, mesh.pm) ? face(opposite(h, mesh.pm), mesh.pm) : face(h, mesh.pm);
    const std::size_t c = face_component(f);
    ++components[c].vertices;
    if (highest[c] == boost::graph_traits<typename Access::Mesh>::null_vertex() ||
        compare_z(mesh.point(highest[c]), mesh.point(v)) == CGAL::SMALLER)
      highest[c] = v;
  }
  for (auto h : halfedges(mesh.pm))
    if (is_border(h, mesh.pm))
      ++components[face_component(face(opposite(h, mesh.pm), mesh.pm))].border_edges;
  const auto np = CGAL::parameters::vertex_point_map(mesh.vpm).geom_traits(mesh.gt);
  for (std::size_t c = 0; c < count; ++c) {
    if (components[c].border_edges > 0 || !triangle_mesh) continue;
    components[c].orientation = PMP::internal::is_outward_oriented(highest[c], mesh.pm, np)
                                    ? Volume_orientation::outward
                                    : Volume_orientation::inward;
  }
  return components;
}

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_COMPONENTS_H
