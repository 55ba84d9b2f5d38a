// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of the hole-filling dispatcher for Surface_mesh<Epick>
// (internal/compiled_core.h); the methods are in their own files.
#define CGAL_MESH_REPAIR_INSTANTIATE_FILL_HOLES
#include <CGAL/Mesh_repair/fill_holes.h>
