// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_PARAMETERS_H
#define CGAL_MESH_REPAIR_PARAMETERS_H

/// \file parameters.h
/// Chainable named parameters of Mesh_repair. They mix freely with CGAL's own:
/// \code
/// namespace MR = CGAL::Mesh_repair;
/// MR::detect_defects(mesh, MR::parameters::merge_tolerance(0.01).geom_traits(K()));
/// MR::detect_defects(mesh, MR::parameters::extend(CGAL::parameters::vertex_point_map(vpm))
///                              .merge_tolerance(0.01));
/// \endcode
/// Our own parameters are listed, with their meaning, in `internal/parameters_list.h`.
/// Parameters that CGAL already defines (`random_seed`, `geom_traits`, `vertex_point_map`,
/// `number_of_iterations`, `fairing_continuity`, `visitor`, ...) are reused, never redefined.

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Mesh_repair {

namespace internal_np {
#define MESH_REPAIR_PARAMETER(name) \
  struct name##_t {};
#include <CGAL/Mesh_repair/internal/parameters_list.h>
#undef MESH_REPAIR_PARAMETER
}  // namespace internal_np

/// A CGAL named-parameter pack that also offers Mesh_repair's own members. It derives from
/// `CGAL::Named_function_parameters`, so CGAL's `get_parameter` and `choose_parameter` read it.
template <typename T, typename Tag, typename Base>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base> {
  using Self = Named_parameters<T, Tag, Base>;
  using CGAL::Named_function_parameters<T, Tag, Base>::Named_function_parameters;
  Named_parameters(const CGAL::Named_function_parameters<T, Tag, Base>& np)
      : CGAL::Named_function_parameters<T, Tag, Base>(np) {}

#define MESH_REPAIR_PARAMETER(name)                                         \
  template <typename K>                                                     \
  Named_parameters<K, internal_np::name##_t, Self> name(const K& k) const { \
    return {k, *this};                                                      \
  }
#include <CGAL/Mesh_repair/internal/parameters_list.h>
#undef MESH_REPAIR_PARAMETER

  // CGAL's members too, so that a chain started with ours never falls back to CGAL's class.
#define CGAL_add_named_parameter(X, Y, Z)                               \
  template <typename K>                                                 \
  Named_parameters<K, CGAL::internal_np::X, Self> Z(const K& k) const { \
    return {k, *this};                                                  \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
};

/// Default of `feature_angle_deg` for the repair operators (`remove_slivers`, `optimize_mesh`):
/// an edge whose dihedral angle is below 135 degrees is a feature (thesis 4.5, 7.2.1).
constexpr double default_feature_angle_deg = 135.0;
/// Default of `feature_angle_deg` for smoothing and quad conversion (`mga_smooth`,
/// `triangles_to_quads`, `flip_edges_for_quality`): 120 degrees, measured on fandisk and the
/// saddles (doc/mga_smooth.md, "Feature angle"), where 135 fixes too many nodes of scans.
constexpr double default_smoothing_feature_angle_deg = 120.0;

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::default_values;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;

#define MESH_REPAIR_PARAMETER(name)                                                             \
  template <typename K>                                                                         \
  Named_parameters<K, internal_np::name##_t, CGAL::internal_np::No_property> name(const K& k) { \
    return {k};                                                                                 \
  }
#include <CGAL/Mesh_repair/internal/parameters_list.h>
#undef MESH_REPAIR_PARAMETER

// CGAL's parameters as free functions too, so a chain may start with any of them and still
// accept ours: `parameters::vertex_point_map(vpm).merge_tolerance(0.1)`.
#define CGAL_add_named_parameter(X, Y, Z)                                                   \
  template <typename K>                                                                     \
  Named_parameters<K, CGAL::internal_np::X, CGAL::internal_np::No_property> Z(const K& k) { \
    return {k};                                                                             \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

/// Continues a pack that began with CGAL's free functions, so Mesh_repair's members can follow.
template <typename T, typename Tag, typename Base>
Named_parameters<T, Tag, Base> extend(const CGAL::Named_function_parameters<T, Tag, Base>& np) {
  return np;
}

}  // namespace parameters
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_PARAMETERS_H
