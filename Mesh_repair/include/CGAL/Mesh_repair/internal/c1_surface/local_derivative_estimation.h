// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_H
#define CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_H

// Local derivative estimation at a data point (Chen et al. 2.2, after Goodman, Said, Chang 1995):
// the gradient of the unknown function at a vertex is that of a local quadratic fitted to the
// neighbouring data by least squares, with weights 1/d^2 so that the nearest neighbours dominate.
// The same routine serves scattered functional data (u, v = x, y; h = f - f0) and surface meshes
// (u, v in the tangent plane of a first normal estimate, h the height above it).

#include <CGAL/Mesh_repair/internal/core_inline.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// One neighbour of the centre, in the centre's local coordinates: offset (u, v), height h.
struct Height_sample {
  double u, v, h;
};

/// Gradient (dh/du, dh/dv) at the origin of a weighted least-squares fit of
/// h = a u + b v + c u^2 + d u v + e v^2 (five or more samples) or of the plane h = a u + b v
/// (two to four samples). Returns {0, 0} without samples or when the fit is singular.
CGAL_MESH_REPAIR_CORE_INLINE std::array<double, 2> estimate_gradient(
    const std::vector<Height_sample>& samples);

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#ifndef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/c1_surface/local_derivative_estimation_impl.h>
#endif

#endif  // CGAL_MESH_REPAIR_INTERNAL_C1_SURFACE_LOCAL_DERIVATIVE_ESTIMATION_H
