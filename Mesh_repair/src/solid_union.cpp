// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's one copy of the union of intersecting solids (CGAL's corefinement, a heavy
// template of its own; a unit of its own so that it compiles beside the others).
#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union_impl.h>
