// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's one copy of the exact outer surface of a self-intersecting part (exact
// constructions and constrained triangulations, heavy templates of their own).
#include <CGAL/Mesh_repair/internal/automatic_repair/self_union_impl.h>
