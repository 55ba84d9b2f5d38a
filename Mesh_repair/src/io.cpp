// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of reading and writing Surface_mesh<Epick> (io.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_IO
#include <CGAL/Mesh_repair/io.h>
