// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_SMOOTH_MESH_H
#define CGAL_MESH_REPAIR_SMOOTH_MESH_H

/// \file smooth_mesh.h
/// One smoothing run measured as `mesh_repair smooth` measures it: optional conversion to quads
/// (`triangles_to_quads`), one of three smoothers (the micro-GA of `mga_smooth`, the paper's
/// conjugate-gradient baseline, or CGAL's `angle_and_area_smoothing` then
/// `tangential_relaxation`), the worst and mean element quality before and after, and the largest
/// distance from the result to the input surface; `write_report` writes the report of
/// `mesh_repair smooth --report`. The tool and the Python `smooth` both call it. See
/// doc/mga_smooth.md.

#include <CGAL/Mesh_repair/internal/finite_distance_traits.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/mga_smooth.h>
#include <CGAL/Mesh_repair/quality.h>
#include <CGAL/Mesh_repair/triangles_to_quads.h>
#include <CGAL/Mesh_repair/visitor.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// The smoothers of `smooth_mesh`.
enum class Smoothing_method { mga, conjugate_gradient, cgal };

/// "mga", "cg" or "cgal": the names of `mesh_repair smooth --method`.
inline const char* to_string(Smoothing_method method) {
  switch (method) {
    case Smoothing_method::mga:
      return "mga";
    case Smoothing_method::conjugate_gradient:
      return "cg";
    case Smoothing_method::cgal:
      return "cgal";
  }
  return "unknown";
}

inline bool smoothing_method_from_string(const std::string& name, Smoothing_method& method) {
  for (Smoothing_method m :
       {Smoothing_method::mga, Smoothing_method::conjugate_gradient, Smoothing_method::cgal}) {
    if (name == to_string(m)) {
      method = m;
      return true;
    }
  }
  return false;
}

/// The options of `smooth_mesh`, with the defaults of `mesh_repair smooth`.
struct Smooth_mesh_options {
  Smoothing_method method = Smoothing_method::mga;
  bool quads = false;   ///< convert to quads first (not with `cgal`: triangles only)
  int iterations = -1;  ///< sweeps; negative: 3 for mga and cg, 1 for cgal
  unsigned int seed = 0;
  int threads = 1;
  int generations = 3;
  double feature_angle_deg = 120;
  double tangent_scale = 0.45;
  bool slide_feature_nodes = false;
};

/// Worst and mean quality over the triangles (alpha) and quads (beta) of a mesh; faces of other
/// degrees are counted apart and not measured.
struct Smoothing_quality {
  double worst = 1, mean = 0;
  std::size_t triangles = 0, quads = 0, others = 0;
};

/// The `Smoothing_quality` of `pm`.
template <class PolygonMesh>
Smoothing_quality smoothing_quality(const PolygonMesh& pm) {
  const auto vpm = get(CGAL::vertex_point, pm);
  Smoothing_quality q;
  double sum = 0;
  for (auto f : faces(pm)) {
    std::vector<typename boost::property_traits<decltype(vpm)>::value_type> p;
    for (auto v : vertices_around_face(halfedge(f, pm), pm)) p.push_back(get(vpm, v));
    double value;
    if (p.size() == 3) {
      value = alpha(p[0], p[1], p[2]);
      ++q.triangles;
    } else if (p.size() == 4) {
      value = quad_beta(p[0], p[1], p[2], p[3]);
      ++q.quads;
    } else {
      ++q.others;
      continue;
    }
    q.worst = std::min(q.worst, value);
    sum += value;
  }
  const std::size_t counted = q.triangles + q.quads;
  q.mean = counted ? sum / double(counted) : 0;
  if (!counted) q.worst = 0;
  return q;
}

/// What `smooth_mesh` did and measured.
struct Smooth_mesh_result {
  Smooth_mesh_options options;  ///< as run (`iterations` resolved)
  Smoothing_quality before, after;
  Quad_conversion_result conversion;  ///< with `quads`
  double conversion_seconds = 0;
  Mga_smooth_result smoothing;  ///< mga and cg
  double seconds = 0;           ///< the smoothing only
  double cpu_seconds = 0;       ///< of every thread of the process during the smoothing
  double max_distance_to_input = 0, diagonal = 0;
  std::size_t vertices = 0, faces = 0;
  bool cancelled = false;  ///< the visitor stopped the smoothing; the mesh is valid
};

namespace internal {

// Largest distance from a vertex of `pm` to the surface of `reference` (a triangle mesh).
template <class PolygonMesh>
double max_distance_to(const PolygonMesh& pm, const PolygonMesh& reference) {
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<PolygonMesh>;
  using Tree = Distance_tree<Kernel, Primitive>;
  Tree tree(faces(reference).first, faces(reference).second, reference);
  tree.accelerate_distance_queries();
  double largest = 0;
  for (auto v : vertices(pm))
    largest = std::max(
        largest, std::sqrt(CGAL::to_double(tree.squared_distance(get(CGAL::vertex_point, pm, v)))));
  return largest;
}

template <class PolygonMesh>
void run_smoother(PolygonMesh& pm, Smooth_mesh_result& result, Any_visitor visitor) {
  const Smooth_mesh_options& o = result.options;
  if (o.method == Smoothing_method::cgal) {  // no progress points: one step
    namespace PMP = CGAL::Polygon_mesh_processing;
    visitor.start_step("CGAL smoothing");
    PMP::angle_and_area_smoothing(pm, CGAL::parameters::number_of_iterations(o.iterations));
    PMP::tangential_relaxation(pm, CGAL::parameters::number_of_iterations(o.iterations));
    visitor.end_step("CGAL smoothing");
    return;
  }
  const auto np = parameters::feature_angle_deg(o.feature_angle_deg)
                      .number_of_threads(o.threads)
                      .max_generations(o.generations)
                      .random_seed(o.seed)
                      .number_of_iterations(o.iterations)
                      .surface_tangent_scale(o.tangent_scale)
                      .slide_feature_nodes(o.slide_feature_nodes)
                      .visitor(std::ref(visitor));
  result.smoothing =
      o.method == Smoothing_method::mga ? mga_smooth(pm, np) : conjugate_gradient_smooth(pm, np);
  result.cancelled = result.smoothing.cancelled;
}

}  // namespace internal

/// Smooths `pm` as `mesh_repair smooth` does and measures it: converts it to quads first with
/// `options.quads` (`triangles_to_quads`, same feature angle), measures the element quality,
/// smooths with `options.method`, measures the quality again and the largest distance from a
/// vertex to the input surface (triangulated). The options are not checked here: `threads` and
/// `generations` at least 1, `tangent_scale` in [0, 1], no `quads` with `cgal`.
/// \param visitor progress and cancellation (visitor.h); CGAL's smoothers cannot be cancelled
template <class PolygonMesh>
Smooth_mesh_result smooth_mesh(PolygonMesh& pm, const Smooth_mesh_options& options,
                               Any_visitor visitor) {
  Smooth_mesh_result result;
  result.options = options;
  if (result.options.iterations < 0)
    result.options.iterations = options.method == Smoothing_method::cgal ? 1 : 3;
  PolygonMesh reference = pm;
  CGAL::Polygon_mesh_processing::triangulate_faces(reference);
  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  if (options.quads) {
    const auto start = Clock::now();
    result.conversion =
        triangles_to_quads(pm, parameters::feature_angle_deg(options.feature_angle_deg));
    result.conversion_seconds = seconds_since(start);
  }
  result.before = smoothing_quality(pm);
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();  // all threads of the process
  internal::run_smoother(pm, result, visitor);
  result.seconds = seconds_since(start);
  result.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  result.after = smoothing_quality(pm);
  result.max_distance_to_input = internal::max_distance_to(pm, reference);
  result.diagonal = internal::mesh_bbox_diagonal(reference, get(CGAL::vertex_point, reference));
  result.vertices = vertices(pm).size();  // num_vertices counts removed ones too
  result.faces = faces(pm).size();
  return result;
}

/// Writes `q` as the `quality_before` / `quality_after` object of the smooth report.
inline void write_json(Json_writer& json, const Smoothing_quality& q) {
  json.begin_object();
  json.field("worst", q.worst).field("mean", q.mean);
  json.field("triangles", q.triangles).field("quads", q.quads);
  json.end_object();
}

/// Writes the report of `mesh_repair smooth --report`: `input`, `output` (null when `output` is
/// empty: no file was written), the options, the quality before and after, the distance to the
/// input, the times, and the conversion (with quads) and smoothing (mga and cg) counts.
inline void write_report(Json_writer& json, const std::string& input, const std::string& output,
                         const Smooth_mesh_result& r) {
  const Smooth_mesh_options& o = r.options;
  json.begin_object().field("input", input);
  if (output.empty())
    json.key("output").raw("null");
  else
    json.field("output", output);
  json.field("method", to_string(o.method));
  json.field("quads", o.quads).field("iterations", o.iterations).field("seed", o.seed);
  json.field("threads", o.threads).field("vertices", r.vertices).field("faces", r.faces);
  json.field("quality_measure", o.quads ? "beta (quads), alpha (triangles)" : "alpha");
  json.key("quality_before");
  write_json(json, r.before);
  json.key("quality_after");
  write_json(json, r.after);
  json.field("worst_quality_before", r.before.worst).field("mean_quality_before", r.before.mean);
  json.field("worst_quality_after", r.after.worst).field("mean_quality_after", r.after.mean);
  json.field("max_distance_to_input", r.max_distance_to_input);
  json.field("max_distance_to_input_relative", r.max_distance_to_input / r.diagonal);
  json.field("seconds", r.seconds).field("cpu_seconds", r.cpu_seconds);
  if (o.quads) {
    const Quad_conversion_result& c = r.conversion;
    json.key("conversion").begin_object();
    json.field("seconds", r.conversion_seconds).field("merged_pairs", c.merged_pairs);
    json.field("eliminated_nodes", c.eliminated_nodes).field("swapped_edges", c.swapped_edges);
    json.field("collapsed_elements", c.collapsed_elements);
    json.field("remaining_triangles", c.remaining_triangles);
    json.end_object();
  }
  if (o.method != Smoothing_method::cgal) {
    const Mga_smooth_result& s = r.smoothing;
    json.key("smoothing").begin_object();
    json.field("sweeps", s.sweeps).field("moves", s.moves);
    json.field("rejected_folds", s.rejected_folds).field("converged", s.converged);
    json.field("free_nodes", s.free_nodes).field("border_nodes", s.border_nodes);
    json.field("feature_nodes", s.feature_nodes).field("sliding_nodes", s.sliding_nodes);
    json.field("constrained_nodes", s.constrained_nodes);
    json.end_object();
  }
  json.end_object();
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h): the tool's smooth command and the
// Python module both call it.
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
namespace CGAL {
namespace Mesh_repair {
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_SMOOTH_MESH
extern
#endif
    template Smooth_mesh_result
    smooth_mesh<internal::Core_mesh>(internal::Core_mesh&, const Smooth_mesh_options&, Any_visitor);
#ifndef CGAL_MESH_REPAIR_INSTANTIATE_SMOOTH_MESH
extern
#endif
    template Smoothing_quality
    smoothing_quality<internal::Core_mesh>(const internal::Core_mesh&);
}  // namespace Mesh_repair
}  // namespace CGAL
#endif

#endif  // CGAL_MESH_REPAIR_SMOOTH_MESH_H
