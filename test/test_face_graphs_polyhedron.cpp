// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Every public operator on Polyhedron_3, with and without Polyhedron_items_with_id_3, gives the
// results it gives on Surface_mesh. Both in one translation unit: they share its parsing and its
// Surface_mesh instantiations (test/CMakeLists.txt has the figures).
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>

#include "face_graph_operators.h"

#include <gtest/gtest.h>

namespace {

using Polyhedron = CGAL::Polyhedron_3<face_graph_test::Kernel>;
using Polyhedron_with_ids =
    CGAL::Polyhedron_3<face_graph_test::Kernel, CGAL::Polyhedron_items_with_id_3>;

TEST(FaceGraphs, PolyhedronGivesTheResultsOfSurfaceMesh) {
  face_graph_test::expect_results_of_surface_mesh<Polyhedron>();
}

TEST(FaceGraphs, PolyhedronWithIdsGivesTheResultsOfSurfaceMesh) {
  face_graph_test::expect_results_of_surface_mesh<Polyhedron_with_ids>();
}

TEST(FaceGraphs, PolyhedronRemovesSelfIntersectionsAsSurfaceMesh) {
  face_graph_test::expect_self_intersections_removed_as_on_surface_mesh<Polyhedron>();
}

TEST(FaceGraphs, PolyhedronWithIdsRemovesSelfIntersectionsAsSurfaceMesh) {
  face_graph_test::expect_self_intersections_removed_as_on_surface_mesh<Polyhedron_with_ids>();
}

}  // namespace
