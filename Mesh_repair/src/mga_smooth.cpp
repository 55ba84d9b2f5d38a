// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of mga_smooth and conjugate_gradient_smooth for
// Surface_mesh<Epick> (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_MGA_SMOOTH
#include <CGAL/Mesh_repair/internal/compiled_core.h>
#include <CGAL/Mesh_repair/mga_smooth.h>
