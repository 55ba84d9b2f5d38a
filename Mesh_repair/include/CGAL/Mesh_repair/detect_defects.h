// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_DETECT_DEFECTS_H
#define CGAL_MESH_REPAIR_DETECT_DEFECTS_H

/// \file detect_defects.h
/// `detect_defects`: every defect of thesis Table 4.1 with its location, without changing the
/// mesh. `add_soup_repair_report` combines it with what `read_mesh`'s soup stage found and
/// repaired; `write_json` and `summary` print it. See doc/detect_defects.md.

#include <CGAL/Mesh_repair/internal/background_task.h>
#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/detect_defects/border_cycles.h>
#include <CGAL/Mesh_repair/internal/detect_defects/coincident_elements.h>
#include <CGAL/Mesh_repair/internal/detect_defects/components.h>
#include <CGAL/Mesh_repair/defect_report.h>
#include <CGAL/Mesh_repair/internal/detect_defects/face_shapes.h>
#include <CGAL/Mesh_repair/internal/detect_defects/overlaps.h>
#include <CGAL/Mesh_repair/internal/detect_defects/proximity.h>
#include <CGAL/Mesh_repair/internal/detect_defects/report_output.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <map>
#include <set>

namespace CGAL {
namespace Mesh_repair {

namespace internal {
namespace detect {

struct Options {
  double tolerance = -1;           ///< absolute; negative: derive it
  double relative_tolerance = -1;  ///< fraction of the bounding-box diagonal; negative: unused
  double tolerance_fraction = 0.25;
  Shape_thresholds shapes;
  bool self_intersections = true;
  int histogram_bins = 10;
  /// Pairs kept by each enumeration whose output can be quadratic (intersecting and overlapping
  /// faces, gaps, T-junctions); 0: max(100000, 10 x faces), or x border vertices for gaps and
  /// T-junctions (internal/bounded_pairs.h). Past it the report marks the count a lower bound.
  std::size_t pair_limit = 0;
};

template <class Access, class Visitor>
class Defect_detector {
 public:
  Defect_detector(const Access& mesh, const Options& options, Visitor& visitor)
      : mesh_(mesh), options_(options), visitor_(visitor) {}

  Defect_report run() {
    report_.vertices = num_vertices(mesh_.pm);
    report_.faces = num_faces(mesh_.pm);
    report_.edges = num_edges(mesh_.pm);
    report_.triangle_mesh = CGAL::is_triangle_mesh(mesh_.pm);
    // Each step is one call so that cancellation between steps leaves a coherent partial report.
    // The all-faces box pass (CGAL's self_intersections, or without it the coplanar-overlap
    // pass, which needs the zero-area faces) runs on one thread while the light steps run on
    // another.
    const bool completed =
        start_self_intersections() && step("border cycles", &Defect_detector::border_cycles) &&
        step("face shapes", &Defect_detector::face_shapes) && start_overlap_pass() &&
        step("coincident elements", &Defect_detector::coincident_elements) &&
        step("gaps and T-junctions", &Defect_detector::gaps_and_t_junctions) &&
        step("connected components", &Defect_detector::components) &&
        step("quality histograms", &Defect_detector::quality) &&
        step("self-intersections", &Defect_detector::self_intersections) &&
        step("coplanar overlaps", &Defect_detector::overlaps);
    box_pass_.wait();
    report_.cancelled = !completed;
    return std::move(report_);
  }

 private:
  bool step(const char* name, void (Defect_detector::*run_step)()) {
    visitor_.start_step(name);
    const bool go_on = visitor_.progress(0.0);
    if (go_on) {
      (this->*run_step)();
      visitor_.progress(1.0);
    }
    visitor_.end_step(name);
    return go_on;
  }

  /// CGAL's sequential box pass, not its Parallel_tag one: the parallel version splits the
  /// boxes into 4x4 sub-problems over copies of the range and on 1.1M faces costs 2.7x the
  /// processor time (4.3 s against 1.6 s), so on few cores it is slower in wall time too.
  /// Running the sequential pass beside the other steps uses the second core instead.
  /// Started before anything else: CGAL's test skips zero-area faces itself.
  bool start_self_intersections() {
    if (!report_.triangle_mesh || !options_.self_intersections) return true;
    box_pass_.run([this] {
      intersecting_pairs_ = bounded_self_intersections(
          faces(mesh_.pm), mesh_.pm, options_.pair_limit,
          CGAL::parameters::vertex_point_map(mesh_.vpm).geom_traits(mesh_.gt));
    });
    return true;
  }

  bool start_overlap_pass() {
    if (!report_.triangle_mesh || options_.self_intersections) return true;
    box_pass_.run([this] {
      coplanar_overlaps_ = overlapping_coplanar_faces(mesh_, zero_area_, options_.pair_limit);
    });
    return true;
  }

  void border_cycles() {
    cycles_ = border_cycle_halfedges(mesh_);
    for (const auto& cycle : cycles_) report_.border_cycles.push_back(describe_cycle(mesh_, cycle));
    if (report_.triangle_mesh) find_ring_hole_islands(mesh_, cycles_, report_.border_cycles);
  }

  void coincident_elements() {
    const auto positions = position_ids(mesh_);
    auto found = Coincidence_finder<Access>(mesh_, positions).run();
    report_.non_manifold_edges = std::move(found.non_manifold_edges);
    report_.non_manifold_vertices = std::move(found.non_manifold_vertices);
    auto pairs = std::move(found.duplicated_face_indices);
    find_faces_on_same_vertices(mesh_, pairs);
    std::vector<typename Access::face_descriptor> face_of(num_faces(mesh_.pm));
    for (auto f : faces(mesh_.pm)) face_of[mesh_.index(f)] = f;
    for (const auto& p : pairs) {
      report_.duplicated_faces.push_back(mesh_.face_pair(face_of[p.first], face_of[p.second]));
      duplicated_.insert({std::min(p.first, p.second), std::max(p.first, p.second)});
    }
    report_.orientable = inconsistently_oriented_faces(mesh_, found.geometric_gluings,
                                                       report_.inconsistently_oriented_faces);
  }

  void face_shapes() { classify_faces(mesh_, options_.shapes, report_, zero_area_); }

  void gaps_and_t_junctions() {
    if (cycles_.empty()) {
      report_.tolerance = std::max(0.0, options_.tolerance);
      return;
    }
    Border_proximity<Access> proximity(mesh_, cycles_, report_.border_cycles);
    report_.tolerance = options_.tolerance;
    if (report_.tolerance < 0) {
      report_.tolerance = options_.tolerance_fraction * proximity.mean_border_edge_length();
      report_.tolerance_derived = true;
    }
    std::set<Coordinates> non_manifold_points;
    for (const auto& v : report_.non_manifold_vertices) non_manifold_points.insert(v.point);
    auto gaps = proximity.small_gaps(report_.tolerance, non_manifold_points, options_.pair_limit);
    report_.small_gaps = std::move(gaps.pairs);
    report_.small_gaps_truncated = gaps.truncated;
    auto junctions = proximity.t_junctions(report_.tolerance, options_.pair_limit);
    report_.t_junctions = std::move(junctions.pairs);
    report_.t_junctions_truncated = junctions.truncated;
  }

  void overlaps() {
    if (!report_.triangle_mesh) return;
    box_pass_.wait();
    // Overlapping faces intersect: among a truncated list of intersecting pairs, the overlaps
    // found are a lower bound too.
    const auto found = report_.self_intersections_checked
                           ? overlapping_among(mesh_, intersecting_pairs_.pairs, zero_area_)
                           : coplanar_overlaps_.pairs;
    report_.overlaps_truncated = report_.self_intersections_checked ? intersecting_pairs_.truncated
                                                                    : coplanar_overlaps_.truncated;
    for (const auto& pair : found)
      if (!duplicated_.count({pair.first, pair.second})) report_.overlaps.push_back(pair);
  }

  void self_intersections() {
    if (!options_.self_intersections || !report_.triangle_mesh) return;
    box_pass_.wait();
    for (const auto& p : intersecting_pairs_.pairs)
      report_.self_intersections.push_back(mesh_.face_pair(p.first, p.second));
    report_.self_intersections_truncated = intersecting_pairs_.truncated;
    std::sort(report_.self_intersections.begin(), report_.self_intersections.end(),
              [](const Face_pair& p, const Face_pair& q) {
                return std::make_pair(p.first, p.second) < std::make_pair(q.first, q.second);
              });
    report_.self_intersections_checked = true;
  }

  void components() {
    report_.components = connected_components(mesh_, report_.triangle_mesh);
    report_.closed = report_.faces > 0 && report_.border_cycles.empty();
  }

  void quality() {
    report_.quality = quality_statistics(mesh_.pm, mesh_.vpm, options_.histogram_bins);
  }

  const Access& mesh_;
  const Options& options_;
  Visitor& visitor_;
  Defect_report report_;
  std::vector<Cycle_halfedges<typename Access::halfedge_descriptor>> cycles_;
  std::vector<char> zero_area_;
  Bounded_pairs<std::pair<typename Access::face_descriptor, typename Access::face_descriptor>>
      intersecting_pairs_;
  std::set<std::pair<std::size_t, std::size_t>> duplicated_;
  Bounded_pairs<Face_pair> coplanar_overlaps_;
  Background_task box_pass_;
};

inline double bbox_diagonal(const CGAL::Bbox_3& b) {
  const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace detect
}  // namespace internal

namespace internal {
namespace detect {

/// The detection on a mesh accessor and plain options (compiled once per mesh type).
template <class Access>
Defect_report run_detection(const Access& access, const Options& options, Any_visitor visitor) {
  return Defect_detector<Access, Any_visitor>(access, options, visitor).run();
}

}  // namespace detect
}  // namespace internal

/// \ingroup PkgMeshRepair
/// Finds every defect of `pm` (thesis Table 4.1) with its location: border cycles with their
/// size and the cycles that look like islands of a ring hole (thesis 4.4), non-manifold edges
/// and vertices, duplicated faces, inconsistent orientation, badly shaped faces (zero area,
/// needles, caps), slivers (shape factor f, thesis eq. 4.13-4.14; aspect ratio Q, Pernot eq. 1),
/// small gaps and T-junctions between border elements, overlapping coplanar faces,
/// self-intersections, connected components, closedness and volume orientation, and quality
/// histograms. Every yes/no geometric decision is an exact predicate. `pm` is not modified.
///
/// Non-manifold edges and vertices, duplicated faces and inconsistent orientation are found in
/// a halfedge mesh where they can live: at vertices sharing a position and at pinched vertex
/// umbrellas. Files read with `read_mesh` had them split by the soup stage; combine both with
/// `add_soup_repair_report`.
///
/// \pre the vertex, halfedge and face index maps number the elements from 0 to their count
///      minus one (for a `Surface_mesh`: no garbage; call `collect_garbage()` after removals).
///
/// @tparam PolygonMesh a model of `FaceListGraph` (triangle meshes get every test; other faces
///         are skipped by the triangle-only tests)
/// @param pm the mesh
/// @param np optional named parameters among the following:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{merge_tolerance}
///     \cgalParamDescription{distance under which border vertices form a small gap or a
///       T-junction, in model units}
///     \cgalParamType{double}
///     \cgalParamDefault{0.25 times the mean border edge length (thesis 4.1: a small fraction
///       of the element edge length)}
///   \cgalParamNEnd
///   \cgalParamNBegin{relative_tolerance}
///     \cgalParamDescription{the same tolerance as a fraction of the bounding-box diagonal;
///       used when `merge_tolerance` is not given}
///     \cgalParamType{double}
///     \cgalParamDefault{unused}
///   \cgalParamNEnd
///   \cgalParamNBegin{shape_factor_threshold}
///     \cgalParamDescription{triangles with normalised shape factor f below it are slivers}
///     \cgalParamType{double} \cgalParamDefault{0.7 (thesis 4.5)}
///   \cgalParamNEnd
///   \cgalParamNBegin{aspect_ratio_threshold}
///     \cgalParamDescription{triangles with aspect ratio Q below it are slivers}
///     \cgalParamType{double} \cgalParamDefault{0.25 (Pernot 4.1)}
///   \cgalParamNEnd
///   \cgalParamNBegin{needle_threshold}
///     \cgalParamDescription{longest over shortest edge ratio above which a triangle is a
///       needle (CGAL's `is_needle_triangle_face`)}
///     \cgalParamType{double} \cgalParamDefault{10}
///   \cgalParamNEnd
///   \cgalParamNBegin{cap_threshold_deg}
///     \cgalParamDescription{largest angle, in degrees, above which a triangle is a cap
///       (CGAL's `is_cap_triangle_face`)}
///     \cgalParamType{double} \cgalParamDefault{160}
///   \cgalParamNEnd
///   \cgalParamNBegin{detect_self_intersections}
///     \cgalParamDescription{run CGAL's `self_intersections` (in parallel with TBB)}
///     \cgalParamType{bool} \cgalParamDefault{true}
///   \cgalParamNEnd
///   \cgalParamNBegin{histogram_bins}
///     \cgalParamDescription{number of bins of the quality histograms}
///     \cgalParamType{int} \cgalParamDefault{10}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress and cancellation, see `Default_visitor`; one step per
///       kind of defect}
///     \cgalParamDefault{`Default_visitor`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, geom_traits, vertex_index_map, face_index_map}
///     \cgalParamDescription{as in CGAL; defaults: the internal point map, the kernel of the
///       points, initialized index maps}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// @return the `Defect_report`; `cancelled` is set when the visitor stopped it.
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Defect_report detect_defects(const PolygonMesh& pm,
                             const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = typename GetGeomTraits<PolygonMesh, NamedParameters>::type;
  using VPM = typename GetVertexPointMap<PolygonMesh, NamedParameters>::const_type;
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, pm));
  const auto vim = CGAL::get_initialized_vertex_index_map(pm, np);
  const auto fim = CGAL::get_initialized_face_index_map(pm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(pm, np);

  internal::detect::Options options;
  options.tolerance = choose_parameter(get_parameter(np, internal_np::merge_tolerance_t{}), -1.0);
  options.relative_tolerance =
      choose_parameter(get_parameter(np, internal_np::relative_tolerance_t{}), -1.0);
  options.shapes.shape_factor =
      choose_parameter(get_parameter(np, internal_np::shape_factor_threshold_t{}), 0.7);
  options.shapes.aspect_ratio =
      choose_parameter(get_parameter(np, internal_np::aspect_ratio_threshold_t{}), 0.25);
  options.shapes.needle_ratio =
      choose_parameter(get_parameter(np, internal_np::needle_threshold_t{}), 10.0);
  options.shapes.cap_angle_deg =
      choose_parameter(get_parameter(np, internal_np::cap_threshold_deg_t{}), 160.0);
  options.self_intersections =
      choose_parameter(get_parameter(np, internal_np::detect_self_intersections_t{}), true);
  options.histogram_bins = choose_parameter(get_parameter(np, internal_np::histogram_bins_t{}), 10);
  if (options.tolerance < 0 && options.relative_tolerance >= 0 && num_vertices(pm) > 0)
    options.tolerance = options.relative_tolerance *
                        internal::detect::bbox_diagonal(CGAL::Polygon_mesh_processing::bbox(
                            pm, CGAL::parameters::vertex_point_map(vpm).geom_traits(gt)));

  internal::Visitor_parameter<NamedParameters> visitor(np);
  using Access =
      internal::detect::Mesh_access<PolygonMesh, VPM, GT, std::decay_t<decltype(vim)>,
                                    std::decay_t<decltype(fim)>, std::decay_t<decltype(him)>>;
  return internal::detect::run_detection(Access{pm, vpm, gt, vim, fim, him}, options,
                                         visitor.get());
}

/// Combines `report` (from `detect_defects` on the mesh that `read_mesh` built) with the soup
/// stage of that read. The soup stage splits non-manifold edges and vertices and reorients
/// faces before the mesh exists, so the mesh-level detection alone would under-count them.
/// Soup locations are soup point indices, which are the vertex indices of the mesh `read_mesh`
/// builds; through them, a non-manifold edge or vertex found by both stages (same positions) is
/// listed once. Duplicated, degenerate and reversed polygons the soup stage removed or flipped
/// are added to the counts of `counts(report)`.
template <class PolygonMesh>
void add_soup_repair_report(Defect_report& report, const Soup_repair_report& soup,
                            const PolygonMesh& pm_from_read_mesh) {
  report.has_soup_stage = true;
  report.soup_stage = soup;
  std::vector<Coordinates> point_of_index(num_vertices(pm_from_read_mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(pm_from_read_mesh);
  const auto vpm = get(CGAL::vertex_point, pm_from_read_mesh);
  for (auto v : vertices(pm_from_read_mesh)) {
    const auto& p = get(vpm, v);
    point_of_index[get(vim, v)] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                   CGAL::to_double(p.z())};
  }
  auto point = [&](std::size_t i) {
    return i < point_of_index.size() ? point_of_index[i] : Coordinates{0, 0, 0};
  };
  std::set<std::pair<Coordinates, Coordinates>> known_edges;
  for (const auto& e : report.non_manifold_edges)
    known_edges.insert(std::minmax(e.source_point, e.target_point));
  for (const auto& e : soup.non_manifold_edge_points) {
    Non_manifold_edge edge;
    edge.source = e.first;
    edge.target = e.second;
    edge.source_point = point(e.first);
    edge.target_point = point(e.second);
    edge.from_soup_stage = true;
    if (known_edges.insert(std::minmax(edge.source_point, edge.target_point)).second)
      report.non_manifold_edges.push_back(edge);
  }
  std::set<Coordinates> known_vertices;
  for (const auto& v : report.non_manifold_vertices) known_vertices.insert(v.point);
  for (std::size_t i : soup.non_manifold_vertex_points)
    if (known_vertices.insert(point(i)).second)
      report.non_manifold_vertices.push_back({i, point(i), true});
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h).
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {
using Core_access = Mesh_access<Core_mesh, Core_vpm, Core_traits,
                                CGAL::GetInitializedVertexIndexMap<Core_mesh>::const_type,
                                CGAL::GetInitializedFaceIndexMap<Core_mesh>::const_type,
                                CGAL::GetInitializedHalfedgeIndexMap<Core_mesh>::const_type>;
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_DETECT_DEFECTS
extern
#endif
    template Defect_report
    run_detection<Core_access>(const Core_access&, const Options&, Any_visitor);
}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_DETECT_DEFECTS_H
