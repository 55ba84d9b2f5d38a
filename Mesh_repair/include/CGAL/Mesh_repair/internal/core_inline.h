// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CORE_INLINE_H
#define CGAL_MESH_REPAIR_INTERNAL_CORE_INLINE_H

// Functions that are not templates but instantiate heavy templates (Eigen's dense factorisations,
// CGAL's 2D Delaunay triangulation, AABB tree and hole triangulation) are declared in their header
// and defined in an `_impl.h` file beside it, CGAL's CGAL_HEADER_ONLY / CGAL_INLINE_FUNCTION
// pattern. A header-only user gets the definitions, inline, from the header; a user of the compiled
// core (CGAL_MESH_REPAIR_COMPILED_CORE, internal/compiled_core.h) links the one copy compiled in
// src/core_functions.cpp. Without this, every translation unit that includes the header
// instantiates and optimises those templates again, whether it calls the function or not (a
// non-template body, or a non-dependent call in a template, is instantiated where it is defined).

#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#define CGAL_MESH_REPAIR_CORE_INLINE
#else
#define CGAL_MESH_REPAIR_CORE_INLINE inline
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_CORE_INLINE_H
