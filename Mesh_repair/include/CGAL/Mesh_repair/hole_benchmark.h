// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_BENCHMARK_H
#define CGAL_MESH_REPAIR_HOLE_BENCHMARK_H

/// \file hole_benchmark.h
/// Ground-truth benchmark of hole filling (thesis 5.7, Table 5.3): punch holes into a closed (or
/// open) mesh keeping the removed faces as the truth, let any method fill them, and measure the
/// fill against the truth. `mesh_repair bench holes` drives it; doc/bench_holes.md defines every
/// measure.
/// \code
/// auto punched = CGAL::Mesh_repair::punch_holes(mesh, MR::parameters::number_of_holes(3)
///                                                         .hole_radius(0.05).random_seed(7));
/// for (auto& hole : punched.holes) {
///   fill_hole(mesh, hole.border_halfedge, ...);
///   auto metrics = CGAL::Mesh_repair::measure_filled_hole(mesh, hole, punched.bbox_diagonal);
/// }
/// \endcode

#include <CGAL/Mesh_repair/internal/hole_benchmark/analytic.h>
#include <CGAL/Mesh_repair/internal/hole_benchmark/metrics.h>
#include <CGAL/Mesh_repair/internal/hole_benchmark/punch.h>
#include <CGAL/Mesh_repair/internal/hole_benchmark/types.h>
#include <CGAL/Mesh_repair/parameters.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <functional>
#include <map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// Punches holes into `pm` and keeps what it removed as the truth. Deterministic for a seed.
///
/// Each hole is grown from a random centre vertex as a topological disc of faces, in increasing
/// order of a normalised distance rho (edge-path distance from the centre, stretched for
/// elongated holes, over a crenellated radius for jagged ones); faces whose mean vertex rho is
/// below 1 are removed. A `ring` hole keeps the faces with rho below 0.45 as an island, so one
/// annulus is removed and the hole has two border cycles. A region whose border is shorter than
/// pi r (half a flat disc's perimeter) is the cap of a thin protrusion and is refused. Holes never
/// touch a border of the input and keep at least one ring of vertices away from each other; when
/// a centre would break a rule another is tried (`Punch_result::shortfall` says when fewer holes
/// than asked fit).
/// The removed faces are deleted with `CGAL::Euler::remove_face`, so the halfedge and face
/// descriptors of what remains are unchanged (no garbage collection).
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph`, triangulated
/// \param pm the mesh, modified
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_holes}
///     \cgalParamDescription{how many holes to punch}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{hole_radius}
///     \cgalParamDescription{hole radius as a fraction of the bounding-box diagonal}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.05}
///   \cgalParamNEnd
///   \cgalParamNBegin{hole_shape}
///     \cgalParamDescription{`Hole_shape::disc`, `jagged` (radius alternating +-30% over seven
///       teeth), `elongated` (semi-axes sqrt(3) r and r / sqrt(3)) or `ring`}
///     \cgalParamType{`Hole_shape`}
///     \cgalParamDefault{`Hole_shape::disc`}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the choice of centres and of the shapes' orientation}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the points of the vertices}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
auto punch_holes(PolygonMesh& pm, const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t number_of_holes =
      choose_parameter(get_parameter(np, internal_np::number_of_holes_t{}), std::size_t(1));
  const double radius_fraction =
      choose_parameter(get_parameter(np, internal_np::hole_radius_t{}), 0.05);
  const Hole_shape shape =
      choose_parameter(get_parameter(np, internal_np::hole_shape_t{}), Hole_shape::disc);
  const unsigned int seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, pm));
  return internal::hole_benchmark::punch_holes(pm, vpm, number_of_holes, radius_fraction, shape,
                                               seed);
}

/// The faces that now cover `hole` in `pm`: those reached from the hole side of its border
/// halfedges without crossing its border edges. `bounded` is set to false when that flood
/// reaches a face that lay outside the hole (the filler changed the hole's border).
template <class PolygonMesh, class Point>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> hole_patch_faces(
    const PolygonMesh& pm, const Punched_hole<PolygonMesh, Point>& hole, bool& bounded) {
  return internal::hole_benchmark::patch_faces(pm, hole, bounded);
}

/// Measures how well `hole` of `pm` was filled, against the removed patch, or against the exact
/// surface when `exact_distance` (unsigned distance to the true surface) is given for the
/// E norms. `diagonal` normalises the `_rel` values. `self_intersections` is left 0: count them
/// for all holes at once with `count_patch_self_intersections`.
/// \param np optional `vertex_point_map`.
template <class PolygonMesh, class Point,
          class NamedParameters = parameters::Default_named_parameters>
Hole_fill_metrics measure_filled_hole(
    const PolygonMesh& pm, const Punched_hole<PolygonMesh, Point>& hole, double diagonal,
    const std::function<double(const Point&)>& exact_distance = {},
    const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace impl = internal::hole_benchmark;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, pm));
  Hole_fill_metrics m;
  const auto patch = impl::patch_faces(pm, hole, m.bounded);
  m.patch_faces = patch.size();
  impl::measure_closure(pm, patch, hole, m);
  if (patch.empty()) return m;
  impl::measure_distances(pm, vpm, patch, hole, exact_distance, diagonal, m);
  impl::measure_hausdorff(pm, vpm, patch, hole, diagonal, m);
  impl::measure_normal_deviation(pm, vpm, hole, m);
  impl::measure_curvature_jump(pm, vpm, patch, hole, diagonal, m);
  impl::measure_quality(pm, vpm, patch, m);
  return m;
}

/// The distance from each of `points` to the truth of `hole`: the removed patch, or
/// `exact_distance` (unsigned distance to the true surface) when given; the distance the E norms
/// of `measure_filled_hole` integrate, for pictures of a fill coloured by its error.
template <class PolygonMesh, class Point>
std::vector<double> distances_to_truth(
    const Punched_hole<PolygonMesh, Point>& hole, const std::vector<Point>& points,
    const std::function<double(const Point&)>& exact_distance = {}) {
  const internal::hole_benchmark::Truth_distance<Point> distance(hole.removed_patch,
                                                                 exact_distance);
  std::vector<double> distances;
  distances.reserve(points.size());
  for (const Point& p : points) distances.push_back(distance(p));
  return distances;
}

/// For each patch of `patches` (face sets, one per hole), the number of pairs of intersecting
/// faces of `pm` with at least one face in that patch (CGAL's exact self-intersection test over
/// the whole mesh, so a patch poking through a distant part of the surface counts too).
template <class PolygonMesh, class FaceRanges>
std::vector<std::size_t> count_patch_self_intersections(const PolygonMesh& pm,
                                                        const FaceRanges& patches) {
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::map<face_descriptor, std::size_t> owner;
  std::size_t index = 0;
  for (const auto& patch : patches) {
    for (face_descriptor f : patch) owner.emplace(f, index);
    ++index;
  }
  std::vector<std::size_t> counts(index, 0);
  std::vector<std::pair<face_descriptor, face_descriptor>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(pm, std::back_inserter(pairs));
  for (const auto& [f, g] : pairs) {
    auto a = owner.find(f), b = owner.find(g);
    if (a != owner.end()) ++counts[a->second];
    if (b != owner.end() && (a == owner.end() || a->second != b->second)) ++counts[b->second];
  }
  return counts;
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h): the tool's bench command, the
// Python module and the suites punch and measure holes on Surface_mesh<Epick>.
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_HOLE_BENCHMARK
extern
#endif
    template Punch_result<internal::Core_mesh, internal::Core_traits::Point_3>
    internal::hole_benchmark::punch_holes<internal::Core_mesh, internal::Core_vpm>(
        internal::Core_mesh&, internal::Core_vpm, std::size_t, double, Hole_shape, unsigned int);
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_HOLE_BENCHMARK
extern
#endif
    template Hole_fill_metrics
    measure_filled_hole<internal::Core_mesh, internal::Core_traits::Point_3,
                        parameters::Default_named_parameters>(
        const internal::Core_mesh&,
        const Punched_hole<internal::Core_mesh, internal::Core_traits::Point_3>&, double,
        const std::function<double(const internal::Core_traits::Point_3&)>&,
        const parameters::Default_named_parameters&);
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_HOLE_BENCHMARK
extern
#endif
    template std::vector<std::size_t>
    count_patch_self_intersections<internal::Core_mesh,
                                   std::vector<std::vector<internal::Core_mesh::Face_index>>>(
        const internal::Core_mesh&,
        const std::vector<std::vector<internal::Core_mesh::Face_index>>&);
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_HOLE_BENCHMARK_H
