// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The OpenMesh meshes of the FaceGraph tests (test_face_graphs_openmesh.cpp): double
// coordinates, and a vertex point map that writes them exactly.
#ifndef MESH_REPAIR_TEST_OPENMESH_POINT_MAP_H
#define MESH_REPAIR_TEST_OPENMESH_POINT_MAP_H

#include <OpenMesh/Core/Mesh/Traits.hh>

#include "face_graph_operators.h"

#include <boost/property_map/property_map.hpp>

namespace face_graph_test {

// Double coordinates, as CGAL's OpenMesh examples use (the default traits store floats).
struct Double_traits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};

/// Kernel points over an OpenMesh mesh with double points, read and written exactly. CGAL 5.5.1's
/// own map (`OM_point_pmap`) casts every written coordinate to float, so that an operator's
/// output on OpenMesh would differ from Surface_mesh's in the last bits of every point it moves
/// or creates (and geometric decisions taken on those points could differ too).
template <class OpenMesh_mesh>
class Exact_openmesh_point_map {
 public:
  using key_type = typename boost::graph_traits<OpenMesh_mesh>::vertex_descriptor;
  using value_type = Point;
  using reference = Point;
  using category = boost::read_write_property_map_tag;

  Exact_openmesh_point_map() = default;
  explicit Exact_openmesh_point_map(const OpenMesh_mesh& mesh)
      : mesh_(const_cast<OpenMesh_mesh*>(&mesh)) {}

  friend Point get(const Exact_openmesh_point_map& map, key_type v) {
    const auto& p = map.mesh_->point(v);
    return Point(p[0], p[1], p[2]);
  }
  friend void put(const Exact_openmesh_point_map& map, key_type v, const Point& p) {
    map.mesh_->set_point(v, typename OpenMesh_mesh::Point(p.x(), p.y(), p.z()));
  }

 private:
  OpenMesh_mesh* mesh_ = nullptr;
};

}  // namespace face_graph_test

#endif  // MESH_REPAIR_TEST_OPENMESH_POINT_MAP_H
