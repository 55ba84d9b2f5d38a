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
  face_graph_test::expect_results_of_surface_mesh<Mesh>();
}

}  // namespace
