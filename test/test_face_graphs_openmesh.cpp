// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Every public operator on OpenMesh's PolyMesh and TriMesh gives the results it gives on
// Surface_mesh. Both in one translation unit: they share its parsing and its Surface_mesh
// instantiations (test/CMakeLists.txt has the figures).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_PolyMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include "face_graph_operators.h"
#include "openmesh_point_map.h"

#include <gtest/gtest.h>

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<face_graph_test::Double_traits>;
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<face_graph_test::Double_traits>;

// The operators are given exact points on OpenMesh (CGAL's own map writes floats,
// openmesh_point_map.h); with it every result is the one of Surface_mesh.
template <>
struct face_graph_test::Exact_point_map<PolyMesh> {
  static constexpr bool specialised = true;
  using type = face_graph_test::Exact_openmesh_point_map<PolyMesh>;
};
template <>
struct face_graph_test::Exact_point_map<TriMesh> {
  static constexpr bool specialised = true;
  using type = face_graph_test::Exact_openmesh_point_map<TriMesh>;
};

namespace {

TEST(FaceGraphs, OpenMeshPolyMeshGivesTheResultsOfSurfaceMesh) {
  face_graph_test::expect_results_of_surface_mesh<PolyMesh>();
}

TEST(FaceGraphs, OpenMeshPolyMeshRemovesSelfIntersectionsAsSurfaceMesh) {
  face_graph_test::expect_self_intersections_removed_as_on_surface_mesh<PolyMesh>();
}

TEST(FaceGraphs, OpenMeshTriMeshGivesTheResultsOfSurfaceMesh) {
  face_graph_test::expect_results_of_surface_mesh<TriMesh>();
}

TEST(FaceGraphs, OpenMeshTriMeshRemovesSelfIntersectionsAsSurfaceMesh) {
  face_graph_test::expect_self_intersections_removed_as_on_surface_mesh<TriMesh>();
}

}  // namespace
