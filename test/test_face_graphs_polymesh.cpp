// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Every public operator on OpenMeshPolyMesh gives the results it gives on Surface_mesh (one
// translation unit per mesh type: each instantiates every operator once more).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_PolyMesh_ArrayKernelT.h>

#include "face_graph_operators.h"

#include <gtest/gtest.h>

namespace {

// Double coordinates, as CGAL's OpenMesh examples use (the default traits store floats).
struct Double_traits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<Double_traits>;

TEST(FaceGraphs, OpenMeshPolyMeshGivesTheResultsOfSurfaceMesh) {
  const auto reference = face_graph_test::run_every_operator<face_graph_test::Surface_mesh>();
  const auto results = face_graph_test::run_every_operator<Mesh>();
  ASSERT_EQ(results.size(), reference.size());
  for (const auto& [name, expected] : reference) {
    const auto& got = results.at(name);
    EXPECT_EQ(got.counts, expected.counts) << name;
    EXPECT_EQ(got.faces.size(), expected.faces.size()) << name;
    EXPECT_TRUE(got.faces == expected.faces) << name << ": the output meshes differ";
    EXPECT_EQ(expected.counts.at("valid"), 1.0) << name;
  }
}

}  // namespace
