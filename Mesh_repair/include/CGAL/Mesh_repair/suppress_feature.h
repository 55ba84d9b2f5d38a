// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_SUPPRESS_FEATURE_H
#define CGAL_MESH_REPAIR_SUPPRESS_FEATURE_H

/// \file suppress_feature.h
/// Feature suppression by hole repair (thesis 6.1): the faces of a feature are removed and
/// every hole this opens is filled with a predicted shape; each fill patch can then be taken
/// out as an implant (thesis 6.2, implant_patch.h). See doc/shape_prediction.md.

#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/parameters.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `suppress_feature` removed and filled.
template <class PolygonMesh>
struct Feature_suppression_result {
  std::size_t faces_removed = 0;
  std::size_t holes_opened = 0;  ///< border cycles the removal created or enlarged
  std::size_t holes_filled = 0;
  /// One report per opened hole; a hole bridged into an earlier ring hole is `skipped`.
  std::vector<Hole_fill_report> holes;
  /// The faces and vertices of each hole's patch (same order as `holes`): the implants.
  std::vector<Fill_patch<PolygonMesh>> patches;
  bool all_filled() const { return holes_filled + skipped() == holes_opened; }
  std::size_t skipped() const {
    std::size_t n = 0;
    for (const auto& h : holes) n += h.skipped ? 1 : 0;
    return n;
  }
};

/// Removes the faces `feature` of `pm` and fills every hole this opens (border cycles that
/// contain a halfedge that was not on the border before) with `fill_hole`, shape prediction by
/// default (thesis 6.1). Borders that were already open stay open.
///
/// \tparam FaceRange a range of `face_descriptor`; each face is removed once
/// \param np the parameters of `fill_holes` (every one is forwarded); `fill_method` defaults to
///   `Fill_method::shape_prediction` here
/// \returns the counts, one report and one patch per opened hole. `pm` stays valid; the
///   removed faces' elements are only marked removed (call `collect_garbage` on a `Surface_mesh`).
template <class PolygonMesh, class FaceRange,
          class NamedParameters = parameters::Default_named_parameters>
Feature_suppression_result<PolygonMesh> suppress_feature(
    PolygonMesh& pm, const FaceRange& feature,
    const NamedParameters& np = parameters::default_values()) {
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  internal::Fill_parameters<PolygonMesh, NamedParameters> p(pm, np);
  if (CGAL::parameters::is_default_parameter<NamedParameters, internal_np::fill_method_t>::value)
    p.options.method = Fill_method::shape_prediction;

  Feature_suppression_result<PolygonMesh> result;
  std::unordered_set<halfedge_descriptor> old_border;
  for (halfedge_descriptor h : halfedges(pm))
    if (is_border(h, pm)) old_border.insert(h);
  std::unordered_set<typename boost::graph_traits<PolygonMesh>::face_descriptor> removed;
  for (auto f : feature)
    if (removed.insert(f).second) CGAL::Euler::remove_face(halfedge(f, pm), pm);
  result.faces_removed = removed.size();

  std::vector<halfedge_descriptor> holes;
  for (halfedge_descriptor h : internal::border_cycles(pm)) {
    const auto cycle = halfedges_around_face(h, pm);
    if (std::any_of(cycle.begin(), cycle.end(),
                    [&](halfedge_descriptor c) { return !old_border.count(c); }))
      holes.push_back(h);
  }
  result.holes_opened = holes.size();
  result.patches.resize(holes.size());
  for (std::size_t k = 0; k < holes.size(); ++k) {
    if (!is_border(holes[k], pm)) {  // an earlier ring hole took this cycle in
      result.holes.emplace_back();
      result.holes.back().skipped = true;
      result.holes.back().failure = "filled with an earlier hole";
      continue;
    }
    result.holes.push_back(internal::fill_hole_with_options(
        pm, p.vpm, p.traits, holes[k], p.options, p.visitor.get(), result.patches[k]));
    result.holes_filled += result.holes.back().filled ? 1 : 0;
  }
  return result;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_SUPPRESS_FEATURE_H
