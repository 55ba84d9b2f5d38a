// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Every public operator on PolyhedronWithIds gives the results it gives on Surface_mesh (one
// translation unit per mesh type: each instantiates every operator once more).
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>

#include "face_graph_operators.h"

#include <gtest/gtest.h>

namespace {

using Mesh = CGAL::Polyhedron_3<face_graph_test::Kernel, CGAL::Polyhedron_items_with_id_3>;

TEST(FaceGraphs, PolyhedronWithIdsGivesTheResultsOfSurfaceMesh) {
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
