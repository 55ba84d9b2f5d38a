// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_COMPILED_CORE_H
#define CGAL_MESH_REPAIR_INTERNAL_COMPILED_CORE_H

// The mesh type of the compiled core. The package is header-only; our own tool, tests, examples
// and benchmarks link the library `Mesh_repair::core` (Mesh_repair/src/), which instantiates every
// operator once for `Surface_mesh<Epick::Point_3>` and defines CGAL_MESH_REPAIR_COMPILED_CORE for
// its users. Each operator's header then declares those instantiations `extern`, so a translation
// unit that calls the operator on that mesh only parses the templates and never instantiates them.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

using Core_traits = CGAL::Exact_predicates_inexact_constructions_kernel;
using Core_mesh = CGAL::Surface_mesh<Core_traits::Point_3>;
using Core_vpm = Core_mesh::Property_map<Core_mesh::Vertex_index, Core_traits::Point_3>;
using Core_halfedge = boost::graph_traits<Core_mesh>::halfedge_descriptor;

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_COMPILED_CORE_H
