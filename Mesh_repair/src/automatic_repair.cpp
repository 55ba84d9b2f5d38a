// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of the automatic_repair pipeline for Surface_mesh<Epick>
// (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_AUTOMATIC_REPAIR
#include <CGAL/Mesh_repair/automatic_repair.h>
