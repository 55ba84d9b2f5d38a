// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_CLEAN_HOLE_CONTOUR_H
#define CGAL_MESH_REPAIR_CLEAN_HOLE_CONTOUR_H

/// \file clean_hole_contour.h
/// Pernot, Moraru, Veron section 4: cleaning the contour of a hole before filling it. Three
/// optional steps: recursive deletion of the badly oriented triangles (two border edges, 4.1),
/// treatment of the degenerated triangles along the contour (aspect ratio Q, eq. 1, below a
/// threshold: collapse, delete or flip, 4.2) and homogenisation of the border edge lengths
/// (split above 1.5 x the mean, collapse below 0.7 x the mean, 4.3). See doc/clean_hole_contour.md.

#include <CGAL/Mesh_repair/internal/clean_hole_contour/local_operations.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What `clean_hole_contour()` did. `border_halfedge` is a border halfedge of the cleaned hole
/// (the one given may have been removed).
template <class PolygonMesh>
struct Contour_cleaning_result {
  typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge;
  std::size_t border_edges_before = 0, border_edges_after = 0;
  std::size_t badly_oriented_removed = 0;  ///< 4.1
  std::size_t badly_oriented_kept = 0;     ///< kept by the detail-preserving condition (Fig. 4b)
  std::size_t degenerate_collapsed = 0, degenerate_removed = 0, degenerate_flipped = 0;  ///< 4.2
  std::size_t degenerate_left = 0;  ///< no operation was valid (manifold, fold-free)
  std::size_t edges_split = 0, edges_collapsed = 0;  ///< 4.3
  std::size_t short_edges_left = 0;                  ///< collapse refused (manifold or fold)
  bool cancelled = false;
};

namespace internal {
namespace clean_hole_contour {

template <class PolygonMesh, class VertexPointMap>
class Contour_cleaner {
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

 public:
  Contour_cleaner(PolygonMesh& pm, VertexPointMap vpm, Contour_cleaning_result<PolygonMesh>& r)
      : pm_(pm), vpm_(vpm), result_(r) {}

  /// 4.1: deletes, recursively, the triangles with two border edges on this contour; with
  /// `preserve_details`, only those whose neighbour across the third edge has no border edge.
  void remove_badly_oriented(bool preserve_details) {
    bool changed = true;
    std::vector<face_descriptor> kept;
    while (changed && cycle_length(result_.border_halfedge, pm_) > 3) {
      changed = false;
      kept.clear();
      for (auto b : contour()) {
        const halfedge_descriptor g0 = opposite(b, pm_);  // in the face, along the border
        const halfedge_descriptor g1 = next(g0, pm_), g2 = next(g1, pm_);
        if (!is_border(opposite(g1, pm_), pm_) || is_border(opposite(g2, pm_), pm_)) continue;
        if (preserve_details && has_border_edge(face(opposite(g2, pm_), pm_))) {
          kept.push_back(face(g0, pm_));
          continue;
        }
        CGAL::Euler::remove_face(g2, pm_);
        result_.border_halfedge = g2;  // the third edge is a border edge now
        ++result_.badly_oriented_removed;
        changed = true;
        break;
      }
    }
    std::sort(kept.begin(), kept.end());
    result_.badly_oriented_kept = std::size_t(std::unique(kept.begin(), kept.end()) - kept.begin());
  }

  /// 4.2: every triangle touching the contour whose aspect ratio is below `threshold`: collapse
  /// its small edge if it has one, else delete it if its longest edge is on the border, else flip
  /// its longest edge. One operation at a time, then the contour is scanned again.
  void treat_degenerate(double threshold) {
    std::vector<face_descriptor> refused;
    const std::size_t budget = 10 * contour().size() + 10;
    for (std::size_t step = 0; step < budget; ++step) {
      const auto candidates = degenerate_faces(threshold, refused);
      if (candidates.empty()) break;
      if (!treat(candidates.front())) refused.push_back(candidates.front());
    }
    std::vector<face_descriptor> none;
    result_.degenerate_left = degenerate_faces(threshold, none).size();
  }

  /// 4.3: one pass over the edges of the contour as it is on entry, against the mean length of
  /// that contour: split above `split_ratio` x mean, collapse below `collapse_ratio` x mean.
  void homogenize(double split_ratio, double collapse_ratio) {
    std::vector<std::pair<vertex_descriptor, vertex_descriptor>> edges;
    double total = 0;
    for (auto b : contour()) {
      edges.emplace_back(source(b, pm_), target(b, pm_));
      total += length(b);
    }
    const double mean = total / double(edges.size());
    for (const auto& [s, t] : edges) {
      const auto found = halfedge(s, t, pm_);
      if (!found.second || !is_border(found.first, pm_)) continue;  // changed by a neighbour
      const halfedge_descriptor b = found.first;
      const double ratio = length(b) / mean;
      if (ratio > split_ratio)
        split_border_edge(b);
      else if (ratio < collapse_ratio)
        collapse_border_edge(b);
    }
  }

 private:
  std::vector<halfedge_descriptor> contour() const {
    std::vector<halfedge_descriptor> cycle;
    for (auto h : CGAL::halfedges_around_face(result_.border_halfedge, pm_)) cycle.push_back(h);
    return cycle;
  }

  double length(halfedge_descriptor h) const {
    return std::sqrt(CGAL::to_double(
        CGAL::squared_distance(get(vpm_, source(h, pm_)), get(vpm_, target(h, pm_)))));
  }

  bool has_border_edge(face_descriptor f) const {
    for (auto h : CGAL::halfedges_around_face(halfedge(f, pm_), pm_))
      if (is_border(opposite(h, pm_), pm_)) return true;
    return false;
  }

  double quality(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    return aspect_ratio(get(vpm_, source(h, pm_)), get(vpm_, target(h, pm_)),
                        get(vpm_, target(next(h, pm_), pm_)));
  }

  std::vector<face_descriptor> degenerate_faces(double threshold,
                                                const std::vector<face_descriptor>& refused) const {
    std::vector<face_descriptor> found;
    for (auto b : contour())
      for (auto g : CGAL::halfedges_around_target(target(b, pm_), pm_)) {
        if (is_border(g, pm_)) continue;
        const face_descriptor f = face(g, pm_);
        if (quality(f) < threshold &&
            std::find(refused.begin(), refused.end(), f) == refused.end() &&
            std::find(found.begin(), found.end(), f) == found.end())
          found.push_back(f);
      }
    return found;
  }

  Point midpoint(halfedge_descriptor h) const {
    return CGAL::midpoint(get(vpm_, source(h, pm_)), get(vpm_, target(h, pm_)));
  }

  /// Keeps a border endpoint where it is (the contour does not move inwards); midpoint otherwise.
  Point collapse_position(halfedge_descriptor h) const {
    const bool source_on_border = is_border_vertex(source(h, pm_), pm_);
    const bool target_on_border = is_border_vertex(target(h, pm_), pm_);
    if (source_on_border && !target_on_border) return get(vpm_, source(h, pm_));
    if (target_on_border && !source_on_border) return get(vpm_, target(h, pm_));
    return midpoint(h);
  }

  bool treat(face_descriptor f) {
    std::array<halfedge_descriptor, 3> e;
    int k = 0;
    for (auto h : CGAL::halfedges_around_face(halfedge(f, pm_), pm_)) e[std::size_t(k++)] = h;
    std::sort(e.begin(), e.end(),
              [&](halfedge_descriptor a, halfedge_descriptor b) { return length(a) < length(b); });
    const halfedge_descriptor shortest = e[0], longest = e[2];
    // "One small edge with respect to the two others" (Fig. 5a): shorter than half the middle one.
    if (length(shortest) < 0.5 * length(e[1])) {
      if (!border_collapse_keeps_a_hole(shortest)) return false;
      const vertex_descriptor kept =
          guarded_collapse(pm_, vpm_, shortest, collapse_position(shortest));
      if (kept == GT::null_vertex()) return false;
      retarget(kept);
      ++result_.degenerate_collapsed;
      return true;
    }
    if (is_border(opposite(longest, pm_), pm_)) return remove_cap(longest);
    if (!guarded_flip(pm_, vpm_, longest)) return false;
    ++result_.degenerate_flipped;
    return true;
  }

  bool border_collapse_keeps_a_hole(halfedge_descriptor h) const {
    const bool on_contour = is_border(h, pm_) || is_border(opposite(h, pm_), pm_);
    return !on_contour || cycle_length(result_.border_halfedge, pm_) > 3;
  }

  /// Fig. 5b: deletes the triangle whose longest edge is on the border, unless its apex is on a
  /// border already (a pinched, non-manifold vertex) or another of its edges is on the border.
  bool remove_cap(halfedge_descriptor longest) {
    const halfedge_descriptor n = next(longest, pm_), p = next(n, pm_);
    if (is_border(opposite(n, pm_), pm_) || is_border(opposite(p, pm_), pm_)) return false;
    if (is_border_vertex(target(n, pm_), pm_)) return false;
    CGAL::Euler::remove_face(longest, pm_);
    result_.border_halfedge = n;
    ++result_.degenerate_removed;
    return true;
  }

  void retarget(vertex_descriptor kept) {
    const halfedge_descriptor h = border_halfedge_at(kept, pm_);
    if (h != GT::null_halfedge()) result_.border_halfedge = h;
  }

  void split_border_edge(halfedge_descriptor b) {
    const Point middle = midpoint(b);
    const halfedge_descriptor inside = opposite(b, pm_);
    const halfedge_descriptor hnew = CGAL::Euler::split_edge(inside, pm_);
    put(vpm_, target(hnew, pm_), middle);
    CGAL::Euler::split_face(hnew, next(next(hnew, pm_), pm_), pm_);
    retarget(target(hnew, pm_));
    ++result_.edges_split;
  }

  void collapse_border_edge(halfedge_descriptor b) {
    if (cycle_length(result_.border_halfedge, pm_) <= 3) {
      ++result_.short_edges_left;
      return;
    }
    // Collapse to one of the two extremities (Pernot 4.3). The removed extremity's other contour
    // edge absorbs `b`, so remove the one whose other edge is the shorter: an edge split in two
    // halves becomes one edge again after one collapse, instead of leaving its second half short
    // and collapsing it too.
    const Point at_source = get(vpm_, source(b, pm_)), at_target = get(vpm_, target(b, pm_));
    const bool keep_source = length(next(b, pm_)) < length(prev(b, pm_));
    for (const Point& position :
         {keep_source ? at_source : at_target, keep_source ? at_target : at_source}) {
      const vertex_descriptor kept = guarded_collapse(pm_, vpm_, b, position);
      if (kept == GT::null_vertex()) continue;
      retarget(kept);
      ++result_.edges_collapsed;
      return;
    }
    ++result_.short_edges_left;
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  Contour_cleaning_result<PolygonMesh>& result_;
};

}  // namespace clean_hole_contour
}  // namespace internal

/// \ingroup PkgMeshRepairHoleFilling
/// Cleans the contour of the hole of `border_halfedge` (Pernot 4), each step optional. Every
/// change is checked beforehand to keep the mesh manifold and fold-free (exact orientation of
/// every changed triangle); a change that would not is skipped and counted in the result.
/// Vertices near the contour may move or disappear ("an uncertainty area", Pernot 4).
///
/// \param pm a triangle mesh, `face(border_halfedge, pm) == null_face()`
/// \param border_halfedge a border halfedge of the hole
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{remove_badly_oriented_triangles}
///     \cgalParamDescription{run 4.1} \cgalParamType{bool} \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{preserve_contour_details}
///     \cgalParamDescription{4.1 deletes a triangle only if its neighbour has no border edge
///       (Fig. 4b)} \cgalParamType{bool} \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{treat_degenerate_triangles}
///     \cgalParamDescription{run 4.2} \cgalParamType{bool} \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{aspect_ratio_threshold}
///     \cgalParamDescription{triangles with Q (eq. 1) below it are degenerated}
///     \cgalParamType{double} \cgalParamDefault{0.25}
///   \cgalParamNEnd
///   \cgalParamNBegin{homogenize_edge_lengths}
///     \cgalParamDescription{run 4.3} \cgalParamType{bool} \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_length_ratio}
///     \cgalParamDescription{border edges longer than this times the mean are split}
///     \cgalParamType{double} \cgalParamDefault{1.5}
///   \cgalParamNEnd
///   \cgalParamNBegin{collapse_length_ratio}
///     \cgalParamDescription{border edges shorter than this times the mean are collapsed}
///     \cgalParamType{double} \cgalParamDefault{0.7}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress and cancellation (between steps)}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Contour_cleaning_result<PolygonMesh> clean_hole_contour(
    PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border_halfedge,
    const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  CGAL_precondition(is_border(border_halfedge, pm));
  using Vpm = typename GetVertexPointMap<PolygonMesh, NamedParameters>::type;
  const Vpm vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_property_map(CGAL::vertex_point, pm));
  const bool badly_oriented =
      choose_parameter(get_parameter(np, internal_np::remove_badly_oriented_triangles_t()), true);
  const bool preserve_details =
      choose_parameter(get_parameter(np, internal_np::preserve_contour_details_t()), true);
  const bool degenerate =
      choose_parameter(get_parameter(np, internal_np::treat_degenerate_triangles_t()), true);
  const double threshold =
      choose_parameter(get_parameter(np, internal_np::aspect_ratio_threshold_t()), 0.25);
  const bool homogenize =
      choose_parameter(get_parameter(np, internal_np::homogenize_edge_lengths_t()), true);
  const double split_ratio =
      choose_parameter(get_parameter(np, internal_np::split_length_ratio_t()), 1.5);
  const double collapse_ratio =
      choose_parameter(get_parameter(np, internal_np::collapse_length_ratio_t()), 0.7);
  internal::Visitor_parameter<NamedParameters> visitor_parameter(np);
  Any_visitor visitor = visitor_parameter.get();

  Contour_cleaning_result<PolygonMesh> result;
  result.border_halfedge = border_halfedge;
  result.border_edges_before = internal::clean_hole_contour::cycle_length(border_halfedge, pm);
  internal::clean_hole_contour::Contour_cleaner<PolygonMesh, Vpm> cleaner(pm, vpm, result);
  auto run = [&](bool enabled, const char* name, auto&& step) {
    if (!enabled || result.cancelled) return;
    visitor.start_step(name);
    step();
    visitor.end_step(name);
    result.cancelled = !visitor.progress(1.0);
  };
  run(badly_oriented, "contour: badly oriented triangles",
      [&] { cleaner.remove_badly_oriented(preserve_details); });
  run(degenerate, "contour: degenerated triangles", [&] { cleaner.treat_degenerate(threshold); });
  run(homogenize, "contour: edge lengths",
      [&] { cleaner.homogenize(split_ratio, collapse_ratio); });
  result.border_edges_after =
      internal::clean_hole_contour::cycle_length(result.border_halfedge, pm);
  return result;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_CLEAN_HOLE_CONTOUR_H
