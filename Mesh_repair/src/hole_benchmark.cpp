// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's instantiation of the hole benchmark (punching, filling and measuring holes:
// hole_benchmark.h, bench_holes.h) for Surface_mesh<Epick> (internal/compiled_core.h).
#define CGAL_MESH_REPAIR_INSTANTIATE_HOLE_BENCHMARK
#include <CGAL/Mesh_repair/internal/compiled_core.h>
#include <CGAL/Mesh_repair/bench_holes.h>
