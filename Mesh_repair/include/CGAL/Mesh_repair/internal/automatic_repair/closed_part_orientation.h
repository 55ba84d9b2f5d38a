// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_CLOSED_PART_ORIENTATION_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_CLOSED_PART_ORIENTATION_H

// Closed parts facing inward are turned outward, and the parts inside them with them. A closed
// part inside another keeps its orientation relative to its innermost container: facing the
// other way it bounds a cavity (CGAL's `orient_to_bound_a_volume` convention), facing the same
// way it is a solid inside a solid (the eyes inside a figure, a drawer inside a cabinet's box),
// and nothing in the geometry tells which was meant. So a mesh written inside out comes out
// outward with its cavities still cavities, and no part is made a cavity that was not one.
// Whether a part lies inside another is decided for every vertex with CGAL's
// `Side_of_triangle_mesh` (exact predicates), only for pairs whose boxes nest, within a budget
// of vertex tests proportional to the mesh; a part with some vertices inside another and some
// not crosses it, is a solid of its own (the tool's rule for assemblies) and faces outward.
// Open parts are left as they are.

#include <CGAL/Mesh_repair/internal/detect_defects/components.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// What `orient_closed_parts` changed and found.
struct Closed_part_orientation {
  std::size_t closed_parts = 0;
  std::size_t reversed_outward = 0;         ///< facing inward and inside no other part: now outward
  std::size_t reversed_with_container = 0;  ///< inside a part that was reversed: reversed too
  std::size_t nested = 0;                   ///< inside another closed part
  std::size_t crossing_parts = 0;  ///< partly inside another closed part: a solid of its own
  bool budget_reached = false;     ///< the nesting tests stopped; the rest count as not nested
};

/// The vertex tests of the nesting of closed parts stop beyond this many per face of the mesh
/// (and at least `min_nesting_tests`).
constexpr std::size_t nesting_tests_per_face = 20;
constexpr std::size_t min_nesting_tests = 1000000;

template <class PolygonMesh, class VertexPointMap, class GeomTraits>
class Closed_part_orienter {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Side = CGAL::Side_of_triangle_mesh<PolygonMesh, GeomTraits, VertexPointMap>;
  using Tree = typename Side::AABB_tree;

 public:
  Closed_part_orienter(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits)
      : pm_(pm), vpm_(vpm), traits_(traits) {}

  Closed_part_orientation run() {
    label_parts();
    Closed_part_orientation result;
    std::vector<std::size_t> closed;
    for (std::size_t c = 0; c < parts_.size(); ++c)
      if (parts_[c].closed && parts_[c].triangles) closed.push_back(c);
    result.closed_parts = closed.size();
    const auto np = CGAL::parameters::vertex_point_map(vpm_).geom_traits(traits_);
    for (std::size_t c : closed)
      parts_[c].outward =
          CGAL::Polygon_mesh_processing::internal::is_outward_oriented(parts_[c].highest, pm_, np);
    if (closed.size() > 1) nest(closed, result);
    // Containers before the parts inside them.
    std::sort(closed.begin(), closed.end(),
              [&](std::size_t a, std::size_t b) { return parts_[a].depth < parts_[b].depth; });
    std::vector<face_descriptor> reversed;
    for (std::size_t c : closed) {
      Part& part = parts_[c];
      const bool nested = part.parent < parts_.size() && !part.crossing;
      part.reversed = nested ? parts_[part.parent].reversed : !part.outward;
      result.nested += nested ? 1 : 0;
      result.crossing_parts += part.crossing ? 1 : 0;
      if (!part.reversed) continue;
      ++(nested ? result.reversed_with_container : result.reversed_outward);
      reversed.insert(reversed.end(), part.faces.begin(), part.faces.end());
    }
    if (!reversed.empty()) CGAL::Polygon_mesh_processing::reverse_face_orientations(reversed, pm_);
    return result;
  }

 private:
  struct Part {
    std::vector<face_descriptor> faces;
    std::vector<vertex_descriptor> vertices;
    vertex_descriptor highest = GT::null_vertex();
    CGAL::Bbox_3 box;
    bool closed = true, triangles = true, outward = true, crossing = false, reversed = false;
    std::size_t depth = 0;                 ///< closed parts it lies inside
    std::size_t parent = std::size_t(-1);  ///< the innermost of them (smallest box)
  };

  void label_parts() {
    const auto fim = CGAL::get_initialized_face_index_map(pm_);
    std::vector<std::size_t> part_of(num_faces(pm_), 0);
    const std::size_t count = CGAL::Polygon_mesh_processing::connected_components(
        pm_,
        detect::Indexed_map<face_descriptor, std::decay_t<decltype(fim)>>{
            fim, CGAL::make_property_map(part_of)},
        CGAL::parameters::face_index_map(fim));
    parts_.assign(count, Part());
    auto compare_z = traits_.compare_z_3_object();
    for (face_descriptor f : faces(pm_)) {
      Part& part = parts_[part_of[std::size_t(get(fim, f))]];
      part.faces.push_back(f);
      std::size_t corners = 0;
      for (auto h : halfedges_around_face(halfedge(f, pm_), pm_)) {
        ++corners;
        if (is_border(opposite(h, pm_), pm_)) part.closed = false;
        const vertex_descriptor v = target(h, pm_);
        part.box += get(vpm_, v).bbox();
        if (part.highest == GT::null_vertex() ||
            compare_z(get(vpm_, part.highest), get(vpm_, v)) == CGAL::SMALLER)
          part.highest = v;
      }
      part.triangles = part.triangles && corners == 3;
    }
    for (vertex_descriptor v : vertices(pm_)) {
      const auto h = halfedge(v, pm_);
      if (h == GT::null_halfedge()) continue;
      const face_descriptor f = is_border(h, pm_) ? face(opposite(h, pm_), pm_) : face(h, pm_);
      parts_[part_of[std::size_t(get(fim, f))]].vertices.push_back(v);
    }
  }

  static double volume(const CGAL::Bbox_3& box) {
    return (box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) * (box.zmax() - box.zmin());
  }

  static bool box_within(const CGAL::Bbox_3& inner, const CGAL::Bbox_3& outer) {
    for (int i = 0; i < 3; ++i)
      if (inner.min(i) < outer.min(i) || inner.max(i) > outer.max(i)) return false;
    return true;
  }

  // Pairs of closed parts whose boxes nest, by CGAL's box intersection; then the vertices of the
  // inner one against the outer one.
  void nest(const std::vector<std::size_t>& closed, Closed_part_orientation& result) {
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
    std::vector<Box> boxes;
    for (std::size_t c : closed) boxes.emplace_back(parts_[c].box, c);
    std::vector<std::pair<std::size_t, std::size_t>> candidates;  // (inner, outer)
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
      const std::size_t i = a.info(), j = b.info();
      if (box_within(parts_[i].box, parts_[j].box)) candidates.emplace_back(i, j);
      if (box_within(parts_[j].box, parts_[i].box)) candidates.emplace_back(j, i);
    });
    std::sort(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
      return a.second < b.second || (a.second == b.second && a.first < b.first);
    });
    const std::size_t budget =
        std::max(min_nesting_tests, nesting_tests_per_face * std::size_t(num_faces(pm_)));
    std::size_t tests = 0;
    std::unique_ptr<Tree> tree;
    std::size_t tree_part = parts_.size();
    for (const auto& [inner, outer] : candidates) {
      if (tests + parts_[inner].vertices.size() > budget) {
        result.budget_reached = true;
        break;
      }
      if (tree_part != outer) {
        tree = std::make_unique<Tree>(parts_[outer].faces.begin(), parts_[outer].faces.end(), pm_,
                                      vpm_);
        tree_part = outer;
      }
      const Side side(*tree, traits_);
      // Nested when every vertex is strictly inside; the first vertex outside (or on the outer
      // surface) ends the test: not nested when it is the first one tested, crossing otherwise.
      std::size_t inside = 0;
      for (vertex_descriptor v : parts_[inner].vertices) {
        ++tests;
        if (side(get(vpm_, v)) != CGAL::ON_BOUNDED_SIDE) break;
        ++inside;
      }
      Part& part = parts_[inner];
      if (inside == part.vertices.size()) {
        ++part.depth;
        if (part.parent >= parts_.size() ||
            volume(parts_[outer].box) < volume(parts_[part.parent].box))
          part.parent = outer;
      } else if (inside > 0) {
        part.crossing = true;
      }
    }
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  const GeomTraits& traits_;
  std::vector<Part> parts_;
};

/// Turns the closed triangulated parts of `pm` that face inward outward, with the parts inside
/// them (see above).
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Closed_part_orientation orient_closed_parts(PolygonMesh& pm, VertexPointMap vpm,
                                            const GeomTraits& traits) {
  return Closed_part_orienter<PolygonMesh, VertexPointMap, GeomTraits>(pm, vpm, traits).run();
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_CLOSED_PART_ORIENTATION_H
