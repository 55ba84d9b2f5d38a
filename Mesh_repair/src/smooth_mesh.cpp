// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of smooth_mesh (quad conversion, smoothing and its
// measurements, as `mesh_repair smooth` and the Python module run them) for Surface_mesh<Epick>
// (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_SMOOTH_MESH
#include <CGAL/Mesh_repair/internal/compiled_core.h>
#include <CGAL/Mesh_repair/smooth_mesh.h>
