// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_MESH_TYPE_TRAITS_H
#define CGAL_MESH_REPAIR_MESH_TYPE_TRAITS_H

/// \file mesh_type_traits.h
/// What a mesh type supports beyond the graph concepts every operator needs.

#include <CGAL/Polyhedron_3_fwd.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <type_traits>

namespace CGAL {
namespace Mesh_repair {

/// Whether CGAL's `Polygon_mesh_processing::experimental::remove_self_intersections` (the
/// `repair_self_intersections` step of `automatic_repair`) compiles for `PolygonMesh`. It does
/// for `Surface_mesh` and `Polyhedron_3`; it does not for OpenMesh (CGAL's smoothing inside it
/// keeps `bool` dynamic properties, which OpenMesh stores in a `std::vector<bool>`). On a mesh
/// type without it, `automatic_repair` reports the step as not available
/// (`Repair_result::unavailable_steps`) instead of running it. Specialise it to `std::true_type`
/// for another mesh type on which CGAL's function compiles.
template <class PolygonMesh>
struct Supports_self_intersection_removal : std::false_type {};

template <class Point>
struct Supports_self_intersection_removal<CGAL::Surface_mesh<Point>> : std::true_type {};

template <class Traits, class Items, template <class, class, class> class HDS, class Alloc>
struct Supports_self_intersection_removal<CGAL::Polyhedron_3<Traits, Items, HDS, Alloc>>
    : std::true_type {};

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_MESH_TYPE_TRAITS_H
