// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Every public operator on OpenMeshTriMesh gives the results it gives on Surface_mesh (one
// translation unit per mesh type: each instantiates every operator once more).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include "face_graph_operators.h"

#include <gtest/gtest.h>

namespace {

// Double coordinates, as CGAL's OpenMesh examples use (the default traits store floats).
struct Double_traits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Double_traits>;

TEST(FaceGraphs, OpenMeshTriMeshGivesTheResultsOfSurfaceMesh) {
  face_graph_test::expect_results_of_surface_mesh<Mesh>();
}

}  // namespace
