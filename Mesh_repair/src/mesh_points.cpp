// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of mesh_points for Surface_mesh<Epick>
// (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_MESH_POINTS
#include <CGAL/Mesh_repair/internal/compiled_core.h>
#include <CGAL/Mesh_repair/mesh_points.h>
