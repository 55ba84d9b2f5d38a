// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's one copy of the non-template functions that instantiate heavy templates
// (internal/core_inline.h): with CGAL_MESH_REPAIR_COMPILED_CORE their headers only declare them.
#include <CGAL/Mesh_repair/internal/c1_surface/local_derivative_estimation_impl.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/multifrontal_cholesky_impl.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/nested_dissection_impl.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/topological_grid_impl.h>
#include <CGAL/Mesh_repair/internal/hole_filling/guide_surface_impl.h>
#include <CGAL/Mesh_repair/internal/least_squares_impl.h>
#include <CGAL/Mesh_repair/internal/stitching/merge_point_impl.h>
