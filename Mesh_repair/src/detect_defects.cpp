// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of detect_defects for Surface_mesh<Epick>
// (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_DETECT_DEFECTS
#include <CGAL/Mesh_repair/detect_defects.h>
