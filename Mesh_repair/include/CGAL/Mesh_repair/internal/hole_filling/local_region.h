// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_LOCAL_REGION_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_LOCAL_REGION_H

// A hole's neighbourhood copied into a `Surface_mesh` of its own, and the splice of a patch
// computed there back into the mesh. Holes are filled in parallel this way (fill_holes.h): each
// task only reads the shared mesh and writes its own copy, and the patches are spliced one after
// the other in hole order, so the result does not depend on the number of threads.

#include <CGAL/Mesh_repair/hole_filling/fill_result.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>
#include <CGAL/Mesh_repair/internal/hole_filling/patch_check.h>
#include <CGAL/Mesh_repair/internal/hole_filling/ring_holes.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Vertex rings copied around a hole: the methods read at most two rings of the border
/// (normals, the advancing front's quadric and context, Liepa's C2 fairing weights); one more
/// ring gives every copied vertex within two rings its whole star.
constexpr int local_region_ring_depth = 3;

/// A hole's neighbourhood as a mesh of its own.
template <class PolygonMesh, class Point>
struct Local_region {
  using Mesh = CGAL::Surface_mesh<Point>;
  using global_vertex = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using local_vertex = typename Mesh::Vertex_index;
  using local_halfedge = typename Mesh::Halfedge_index;

  Mesh mesh;
  /// Per local vertex index: the vertex of `PolygonMesh` it copies; null for the loose copies
  /// of faces that could not be attached (they only serve as obstacles).
  std::vector<global_vertex> global_of;
  std::vector<Point> copied_position;  ///< per local vertex, at copy time
  Hole_group<local_halfedge> group;
  bool usable = false;  ///< the group's border cycles are border cycles of the copy too
};

/// The vertices within `depth` edges of the border cycles of `cycles`, nearest first.
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vertices_near_cycles(
    const PolygonMesh& pm,
    const std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& cycles,
    int depth) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::unordered_set<vertex_descriptor> seen;
  std::vector<vertex_descriptor> reached;
  for (auto cycle : cycles)
    for (auto h : halfedges_around_face(cycle, pm))
      if (seen.insert(target(h, pm)).second) reached.push_back(target(h, pm));
  std::size_t layer_begin = 0;
  for (int d = 0; d < depth; ++d) {
    const std::size_t layer_end = reached.size();
    for (std::size_t i = layer_begin; i < layer_end; ++i)
      for (auto around : halfedges_around_target(reached[i], pm))
        if (seen.insert(source(around, pm)).second) reached.push_back(source(around, pm));
    layer_begin = layer_end;
  }
  return reached;
}

/// Finds the copies of the group's cycles; false when one is not a border cycle of the same
/// length in the copy (a border vertex whose star could not be attached).
template <class PolygonMesh, class Point, class LocalOf>
bool map_cycles(
    const PolygonMesh& pm,
    const Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& group,
    const LocalOf& local_of, Local_region<PolygonMesh, Point>& region) {
  using Local_halfedge = typename Local_region<PolygonMesh, Point>::local_halfedge;
  const auto map_cycle = [&](auto h, Local_halfedge& local) {
    const auto a = local_of.find(source(h, pm)), b = local_of.find(target(h, pm));
    if (a == local_of.end() || b == local_of.end()) return false;
    const auto found = halfedge(a->second, b->second, region.mesh);
    if (!found.second || !is_border(found.first, region.mesh)) return false;
    local = found.first;
    return cycle_halfedges(local, region.mesh).size() == cycle_halfedges(h, pm).size();
  };
  if (!map_cycle(group.outer, region.group.outer)) return false;
  region.group.islands.resize(group.islands.size());
  for (std::size_t i = 0; i < group.islands.size(); ++i)
    if (!map_cycle(group.islands[i], region.group.islands[i])) return false;
  return true;
}

/// Copies into `region` the faces around the vertices within `depth` rings
/// of the cycles of `group`, connected as in `pm`, and, as loose triangles, the other faces of
/// `cache` (every face of the mesh, earlier patches included) whose box meets the box of the
/// cycles grown by half its diagonal: the obstacles the advancing front and the exact checks
/// look at. Only reads `pm` and `cache`.
template <class PolygonMesh, class VertexPointMap, class Point>
void copy_local_region(
    const PolygonMesh& pm, VertexPointMap vpm,
    const Hole_group<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& group,
    const Face_box_cache<PolygonMesh, VertexPointMap>* cache,
    Local_region<PolygonMesh, Point>& region, int depth = local_region_ring_depth) {
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Region = Local_region<PolygonMesh, Point>;
  std::vector<typename GT::halfedge_descriptor> cycles{group.outer};
  cycles.insert(cycles.end(), group.islands.begin(), group.islands.end());

  std::unordered_set<face_descriptor> copied;
  std::vector<face_descriptor> ring_faces;
  for (vertex_descriptor v : vertices_near_cycles(pm, cycles, depth))
    for (face_descriptor f : faces_around_target(halfedge(v, pm), pm))
      if (f != GT::null_face() && copied.insert(f).second) ring_faces.push_back(f);

  std::unordered_map<vertex_descriptor, typename Region::local_vertex> local_of;
  const auto new_vertex = [&](vertex_descriptor v, bool attached) {
    const auto local = add_vertex(region.mesh);
    put(get(CGAL::vertex_point, region.mesh), local, get(vpm, v));
    region.global_of.push_back(attached ? v : GT::null_vertex());
    region.copied_position.push_back(get(vpm, v));
    return local;
  };
  const auto add_loose = [&](face_descriptor f) {
    std::vector<typename Region::local_vertex> corners;
    for (auto h : halfedges_around_face(halfedge(f, pm), pm))
      corners.push_back(new_vertex(target(h, pm), false));
    CGAL::Euler::add_face(corners, region.mesh);
  };
  for (face_descriptor f : ring_faces) {
    std::vector<typename Region::local_vertex> corners;
    for (auto h : halfedges_around_face(halfedge(f, pm), pm)) {
      auto found = local_of.find(target(h, pm));
      if (found == local_of.end())
        found = local_of.emplace(target(h, pm), new_vertex(target(h, pm), true)).first;
      corners.push_back(found->second);
    }
    // A vertex at the edge of the copy may get two separate fans, which a halfedge mesh cannot
    // hold: such a face is kept as an obstacle only.
    if (CGAL::Euler::add_face(corners, region.mesh) == Region::Mesh::null_face()) add_loose(f);
  }
  if (cache != nullptr) {
    CGAL::Bbox_3 box;
    for (auto cycle : cycles)
      for (auto h : halfedges_around_face(cycle, pm)) box += get(vpm, target(h, pm)).bbox();
    const double margin = 0.5 * std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                          CGAL::square(box.ymax() - box.ymin()) +
                                          CGAL::square(box.zmax() - box.zmin()));
    box = CGAL::Bbox_3(box.xmin() - margin, box.ymin() - margin, box.zmin() - margin,
                       box.xmax() + margin, box.ymax() + margin, box.zmax() + margin);
    for (face_descriptor f : cache->overlapping(box, copied)) add_loose(f);
  }
  region.usable = map_cycles(pm, group, local_of, region);
}

/// Adds the faces `local_faces` of `local` to `pm` through `global_of`. A face that cannot be
/// attached yet (its corners' fans not joined) is retried after the others, so any order in
/// which the method created its faces works.
template <class PolygonMesh, class LocalMesh>
bool splice_faces(
    PolygonMesh& pm, const LocalMesh& local,
    const std::vector<typename LocalMesh::Face_index>& local_faces,
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& global_of,
    Fill_patch<PolygonMesh>& patch) {
  using GT = boost::graph_traits<PolygonMesh>;
  std::vector<std::vector<typename GT::vertex_descriptor>> pending;
  for (auto f : local_faces) {
    if (local.is_removed(f)) continue;
    std::vector<typename GT::vertex_descriptor> corners;
    for (auto h : halfedges_around_face(halfedge(f, local), local)) {
      if (global_of[target(h, local)] == GT::null_vertex()) return false;
      corners.push_back(global_of[target(h, local)]);
    }
    pending.push_back(corners);
  }
  while (!pending.empty()) {
    std::vector<std::vector<typename GT::vertex_descriptor>> refused;
    for (const auto& corners : pending) {
      const auto f = CGAL::Euler::add_face(corners, pm);
      if (f == GT::null_face())
        refused.push_back(corners);
      else
        patch.faces.push_back(f);
    }
    if (refused.size() == pending.size()) return false;
    pending.swap(refused);
  }
  return true;
}

/// The halfedges around a vertex (and how many of them are border halfedges) as its circulation
/// meets them: a face attached to the wrong gap of a vertex with several border gaps leaves the
/// same faces but splits the vertex's star, which this sees.
template <class Mesh>
std::pair<std::size_t, std::size_t> star_shape(
    typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& mesh) {
  std::pair<std::size_t, std::size_t> shape{0, 0};
  for (auto h : halfedges_around_target(v, mesh)) {
    ++shape.first;
    shape.second += is_border(h, mesh) ? 1 : 0;
  }
  return shape;
}

/// True when every corner of the spliced faces has the same star in `pm` as in the copy.
template <class PolygonMesh, class LocalMesh>
bool same_stars(
    const PolygonMesh& pm, const LocalMesh& local,
    const std::vector<typename LocalMesh::Face_index>& local_faces,
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& global_of) {
  for (auto f : local_faces) {
    if (local.is_removed(f)) continue;
    for (auto h : halfedges_around_face(halfedge(f, local), local))
      if (star_shape(target(h, local), local) != star_shape(global_of[target(h, local)], pm))
        return false;
  }
  return true;
}

/// Adds the patch computed in `region` to `pm`: its new vertices (in the patch's order), its
/// faces (attached to the hole's border halfedges through the copied vertices) and the new
/// positions of the copied vertices it moved, which must be border vertices of the hole or
/// their neighbours (`movable`). Appends what it adds to `patch`; false when the patch cannot be
/// reproduced (the caller rolls `patch` back).
template <class PolygonMesh, class VertexPointMap, class Point>
bool splice_local_patch(
    PolygonMesh& pm, VertexPointMap vpm, const Local_region<PolygonMesh, Point>& region,
    const Fill_patch<typename Local_region<PolygonMesh, Point>::Mesh>& local_patch,
    const std::unordered_set<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& movable,
    Fill_patch<PolygonMesh>& patch) {
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  const auto local_vpm = get(CGAL::vertex_point, region.mesh);
  std::vector<vertex_descriptor> global_of = region.global_of;
  global_of.resize(num_vertices(region.mesh) + region.mesh.number_of_removed_vertices(),
                   GT::null_vertex());
  for (auto v : local_patch.vertices) {
    if (global_of[v] != GT::null_vertex() || region.mesh.is_removed(v)) continue;
    global_of[v] = add_vertex(pm);
    put(vpm, global_of[v], get(local_vpm, v));
    patch.vertices.push_back(global_of[v]);
  }
  if (!splice_faces(pm, region.mesh, local_patch.faces, global_of, patch)) return false;
  if (!same_stars(pm, region.mesh, local_patch.faces, global_of)) return false;
  for (std::size_t i = 0; i < region.copied_position.size(); ++i) {
    const auto v = typename Local_region<PolygonMesh, Point>::local_vertex(std::uint32_t(i));
    if (region.mesh.is_removed(v) || get(local_vpm, v) == region.copied_position[i]) continue;
    if (global_of[i] == GT::null_vertex() || movable.count(global_of[i]) == 0) return false;
    put(vpm, global_of[i], get(local_vpm, v));
  }
  return true;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_FILLING_LOCAL_REGION_H
