// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of the gap stitcher (stitch_gaps, repair_t_junctions) for
// Surface_mesh<Epick> (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_STITCH_GAPS
#include <CGAL/Mesh_repair/stitch_gaps.h>
