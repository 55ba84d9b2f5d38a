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

// CGAL's experimental::remove_self_intersections compiles on Polyhedron_3: automatic_repair runs
// it when asked (mesh_type_traits.h).
static_assert(CGAL::Mesh_repair::Supports_self_intersection_removal<Mesh>::value);

TEST(FaceGraphs, PolyhedronWithIdsGivesTheResultsOfSurfaceMesh) {
  face_graph_test::expect_results_of_surface_mesh<Mesh>();
}

}  // namespace
