// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of curvature_variation for Surface_mesh<Epick>
// (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_CURVATURE_VARIATION
#include <CGAL/Mesh_repair/hole_filling/curvature_variation.h>
