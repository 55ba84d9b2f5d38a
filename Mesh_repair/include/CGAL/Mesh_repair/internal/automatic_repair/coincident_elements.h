// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_COINCIDENT_ELEMENTS_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_COINCIDENT_ELEMENTS_H

// The last step of automatic_repair: the output as a file shows it. A file stores positions, and
// a reader that merges coincident points (CGAL's read_polygon_mesh, which repairs the soup first)
// sees vertices at one position as one vertex. The step
// - removes faces that duplicate another one by position (the same three points, in either
//   orientation): either all of a group (part of a zero-volume wall between two shells, whose
//   outline then carries two faces per edge) or all but one (internal/zero_volume_walls.h);
// - removes isolated vertices (a file would keep them, a reader drops them);
// - stitches coincident borders again (CGAL's stitch_borders): the merges of coincident vertices
//   that keep the surface manifold;
// - counts what stays split: positions whose faces form several fans (non-manifold vertices) and
//   segments carried by more than two faces (non-manifold edges), by position, as a merging
//   reader sees them. `manifold` means none, by position and in the halfedge structure.
// Then the lines of `remaining` are listed again from the updated figures and what was left on
// purpose moves to `kept`.

#include <CGAL/Mesh_repair/internal/automatic_repair/contact_separation.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/repair_steps.h>
#include <CGAL/Mesh_repair/internal/detect_defects/coincident_elements.h>
#include <CGAL/Mesh_repair/internal/zero_volume_walls.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <set>
#include <type_traits>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// What the coincident-elements step found and changed.
struct Coincidence_census {
  std::size_t duplicated_faces_removed = 0;    ///< faces removed as duplicates by position
  std::size_t zero_volume_groups_removed = 0;  ///< groups removed whole (walls between shells)
  std::size_t isolated_vertices_removed = 0;
  std::size_t halfedge_pairs_stitched = 0;
  /// Vertices that stitching pinched (two fans of faces at one vertex), split again.
  std::size_t pinched_vertices_split = 0;
  std::size_t non_manifold_vertices = 0, non_manifold_edges = 0, coincident_vertices = 0;
  /// Every vertex at a non-manifold position lies in a connected component of its own.
  bool non_manifold_between_components_only = false;
  std::size_t duplicated_faces_left = 0;
  /// Positions of several vertices whose faces, merged, would form one fan (stitching could not
  /// join them: faces glued the wrong way round); the mesh is then rebuilt as a reader builds it.
  std::size_t mergeable_positions = 0;
  std::size_t rebuilt = 0;      ///< 1 when the mesh was rebuilt from its soup
  Contact_separation contacts;  ///< the vertices at shared positions moved apart
};

/// Vertices at one position (contacts) are moved apart by this fraction of the bounding-box
/// diagonal (contact_separation.h): far below any tolerance of the repair, far above the
/// rounding of a coordinate written with 17 digits.
constexpr double contact_separation_fraction = 1e-6;

template <class PolygonMesh, class VertexPointMap, class GeomTraits>
class Coincident_elements {
 public:
  using Graph_traits = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;

  Coincident_elements(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits)
      : pm_(pm), vpm_(vpm), traits_(traits), vim_(CGAL::get_initialized_vertex_index_map(pm)) {}

  /// Removes the duplicated faces by position; returns how many faces were removed.
  std::size_t remove_duplicated_faces(Coincidence_census& census) {
    sort_positions();
    std::vector<std::pair<std::array<std::size_t, 3>, face_descriptor>> keyed;
    for (face_descriptor f : faces(pm_)) {
      const halfedge_descriptor h = halfedge(f, pm_);
      if (next(next(next(h, pm_), pm_), pm_) != h) continue;  // triangles only
      std::array<std::size_t, 3> key{position(source(h, pm_)), position(target(h, pm_)),
                                     position(target(next(h, pm_), pm_))};
      std::sort(key.begin(), key.end());
      if (key[0] == key[1] || key[1] == key[2]) continue;  // zero-length edge: degenerate
      keyed.emplace_back(key, f);
    }
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
      return a.first < b.first || (a.first == b.first && a.second < b.second);
    });
    std::vector<std::array<std::size_t, 3>> keys;
    std::vector<std::vector<face_descriptor>> groups;
    for (std::size_t i = 0; i < keyed.size();) {
      std::size_t j = i + 1;
      while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
      if (j - i > 1) {
        keys.push_back(keyed[i].first);
        groups.emplace_back();
        for (std::size_t k = i; k < j; ++k) groups.back().push_back(keyed[k].second);
      }
      i = j;
    }
    std::vector<Classes_along_edges> along(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const auto& key = keys[g];
      for (const auto& edge : {std::make_pair(key[0], key[1]), std::make_pair(key[1], key[2]),
                               std::make_pair(key[0], key[2])})
        along[g].push_back(classes_along(edge.first, edge.second, keys));
    }
    const Zero_volume_walls walls = choose_zero_volume_walls(along);
    std::vector<face_descriptor> doomed;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (walls.removed[g]) {
        doomed.insert(doomed.end(), groups[g].begin(), groups[g].end());
        ++census.zero_volume_groups_removed;
      } else {
        keep_most_glued(groups[g], doomed);
      }
    }
    for (face_descriptor f : doomed) CGAL::Euler::remove_face(halfedge(f, pm_), pm_);
    census.duplicated_faces_removed = doomed.size();
    return doomed.size();
  }

  /// Counts non-manifold vertices and edges and coincident vertices by position (the
  /// definitions of detect_defects).
  void count(Coincidence_census& census) const {
    const auto vim = CGAL::get_initialized_vertex_index_map(pm_);
    const auto fim = CGAL::get_initialized_face_index_map(pm_);
    const auto him = CGAL::get_initialized_halfedge_index_map(pm_);
    using Access =
        detect::Mesh_access<PolygonMesh, VertexPointMap, GeomTraits, std::decay_t<decltype(vim)>,
                            std::decay_t<decltype(fim)>, std::decay_t<decltype(him)>>;
    const Access access{pm_, vpm_, traits_, vim, fim, him};
    const auto positions = detect::position_ids(access);
    const auto found = detect::Coincidence_finder<Access>(access, positions).run();
    census.non_manifold_vertices = found.non_manifold_vertices.size();
    census.non_manifold_edges = found.non_manifold_edges.size();
    census.duplicated_faces_left = found.duplicated_face_indices.size();
    census.coincident_vertices = count_vertices(pm_) - positions.count;
    std::vector<bool> non_manifold(positions.count, false);
    for (const auto& v : found.non_manifold_vertices)
      non_manifold[positions.id_of_vertex[v.vertex]] = true;
    census.mergeable_positions = 0;
    for (std::size_t p = 0; p < positions.count; ++p)
      census.mergeable_positions += positions.shared[p] && !non_manifold[p] ? 1 : 0;
    for (const auto& e : found.non_manifold_edges)
      for (std::size_t v : {e.source, e.target}) non_manifold[positions.id_of_vertex[v]] = true;
    census.non_manifold_between_components_only =
        census.non_manifold_vertices + census.non_manifold_edges > 0 &&
        copies_in_distinct_components(positions.id_of_vertex, non_manifold);
  }

  /// True when each marked position holds several vertices, each in a connected component of
  /// its own (`position_of` maps vertex indices to positions); a vertex pinched in the halfedge
  /// structure, or two copies in one component, is a contact of a part with itself.
  template <class PositionOfVertex>
  bool copies_in_distinct_components(const PositionOfVertex& position_of,
                                     const std::vector<bool>& marked) const {
    std::vector<std::size_t> parent(num_vertices(pm_));
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&](std::size_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for (auto e : edges(pm_))
      parent[find(get(vim_, source(e, pm_)))] = find(get(vim_, target(e, pm_)));
    std::vector<std::set<std::size_t>> components(marked.size());
    std::vector<std::size_t> copies(marked.size(), 0);
    for (vertex_descriptor v : vertices(pm_)) {
      const std::size_t p = position_of[get(vim_, v)];
      if (!marked[p]) continue;
      ++copies[p];
      components[p].insert(find(get(vim_, v)));
    }
    for (std::size_t p = 0; p < marked.size(); ++p)
      if (marked[p] && (copies[p] < 2 || components[p].size() != copies[p])) return false;
    return true;
  }

  /// True when two vertices share a position (what stitching may merge).
  bool any_shared_position() {
    sort_positions();
    return positions_ < count_vertices(pm_);
  }

 private:
  void sort_positions() {
    if (sorted_) return;
    std::vector<vertex_descriptor> sorted(vertices(pm_).begin(), vertices(pm_).end());
    auto less = traits_.less_xyz_3_object();
    std::sort(sorted.begin(), sorted.end(), [&](vertex_descriptor a, vertex_descriptor b) {
      return less(get(vpm_, a), get(vpm_, b));
    });
    auto equal = traits_.equal_3_object();
    positions_ = 0;
    position_of_.assign(num_vertices(pm_), 0);
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      if (i == 0 || !equal(get(vpm_, sorted[i - 1]), get(vpm_, sorted[i]))) {
        ++positions_;
        vertices_at_.emplace_back();
      }
      position_of_[std::size_t(get(vim_, sorted[i]))] = positions_ - 1;
      vertices_at_.back().push_back(sorted[i]);
    }
    sorted_ = true;
  }

  std::size_t position(vertex_descriptor v) const {
    return position_of_[std::size_t(get(vim_, v))];
  }

  // The sorted positions of a triangle's corners.
  std::array<std::size_t, 3> key_of(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm_);
    std::array<std::size_t, 3> key{position(source(h, pm_)), position(target(h, pm_)),
                                   position(target(next(h, pm_), pm_))};
    std::sort(key.begin(), key.end());
    return key;
  }

  // The distinct classes of faces along the segment (p, q) by position, whatever their
  // vertices: faces on the same three positions count once (a surface given twice is not a wall),
  // with their index in `group_keys` (sorted) as class when they are a group of duplicates.
  std::vector<std::size_t> classes_along(
      std::size_t p, std::size_t q,
      const std::vector<std::array<std::size_t, 3>>& group_keys) const {
    std::vector<std::array<std::size_t, 3>> seen;
    for (vertex_descriptor v : vertices_at_[p])
      for (halfedge_descriptor h : halfedges_around_target(v, pm_)) {
        if (position(source(h, pm_)) != q) continue;
        if (!is_border(h, pm_)) seen.push_back(key_of(face(h, pm_)));
        if (!is_border(opposite(h, pm_), pm_)) seen.push_back(key_of(face(opposite(h, pm_), pm_)));
      }
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    std::vector<std::size_t> classes;
    for (std::size_t i = 0; i < seen.size(); ++i) {
      const auto it = std::lower_bound(group_keys.begin(), group_keys.end(), seen[i]);
      classes.push_back(it != group_keys.end() && *it == seen[i]
                            ? std::size_t(it - group_keys.begin())
                            : group_keys.size() + i);
    }
    return classes;
  }

  // Faces outside `group` glued to `f` through its halfedges.
  std::size_t glued_outside(face_descriptor f, const std::vector<face_descriptor>& group) const {
    std::size_t n = 0;
    for (halfedge_descriptor h : halfedges_around_face(halfedge(f, pm_), pm_)) {
      const face_descriptor g = face(opposite(h, pm_), pm_);
      if (g != Graph_traits::null_face() && std::find(group.begin(), group.end(), g) == group.end())
        ++n;
    }
    return n;
  }

  // Keeps the face of a group most glued to the rest of the surface (the first on a tie).
  void keep_most_glued(const std::vector<face_descriptor>& group,
                       std::vector<face_descriptor>& doomed) const {
    std::size_t kept = 0;
    for (std::size_t i = 1; i < group.size(); ++i)
      if (glued_outside(group[i], group) > glued_outside(group[kept], group)) kept = i;
    for (std::size_t i = 0; i < group.size(); ++i)
      if (i != kept) doomed.push_back(group[i]);
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  const GeomTraits& traits_;
  bool sorted_ = false;
  std::size_t positions_ = 0;
  typename CGAL::GetInitializedVertexIndexMap<PolygonMesh>::type vim_;
  std::vector<std::size_t> position_of_;  ///< by vertex index
  std::vector<std::vector<vertex_descriptor>> vertices_at_;
};

/// Rebuilds `pm` as a reader that merges coincident points builds it: the faces as a polygon
/// soup, coincident points merged, oriented (CGAL's `orient_polygon_soup`, which keeps the
/// orientation of the first face of each component and splits non-manifold vertices and edges),
/// and built again in `pm` (emptied element by element, so its property maps stay). Returns false,
/// `pm` untouched, when that soup is not a polygon mesh (a face with two corners at one point).
template <class PolygonMesh, class VertexPointMap>
bool rebuild_as_read(PolygonMesh& pm, VertexPointMap vpm) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  PMP::polygon_mesh_to_polygon_soup(pm, points, polygons, CGAL::parameters::vertex_point_map(vpm));
  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return false;
  // The elements are listed before any is removed: Surface_mesh's begin() skips the elements
  // removed so far, so taking the first element again and again would be quadratic
  // (benchmarks.md, "OpenFOAM tutorials").
  using Traits = boost::graph_traits<PolygonMesh>;
  const std::vector<typename Traits::edge_descriptor> old_edges(edges(pm).begin(), edges(pm).end());
  const std::vector<typename Traits::face_descriptor> old_faces(faces(pm).begin(), faces(pm).end());
  const std::vector<typename Traits::vertex_descriptor> old_vertices(vertices(pm).begin(),
                                                                     vertices(pm).end());
  for (auto e : old_edges) remove_edge(e, pm);
  for (auto f : old_faces) remove_face(f, pm);
  for (auto v : old_vertices) remove_vertex(v, pm);
  PMP::polygon_soup_to_polygon_mesh(points, polygons, pm, CGAL::parameters::default_values(),
                                    CGAL::parameters::vertex_point_map(vpm));
  return true;
}

/// The verification figures of `result` from `pm` as it is now.
template <class PolygonMesh>
void verify_again(const PolygonMesh& pm, const Repair_options& options,
                  const Coincidence_census& census, Repair_result& result, bool faces_changed) {
  result.valid = CGAL::is_valid_polygon_mesh(pm);
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(pm, std::back_inserter(pinched));
  result.non_manifold_vertices_left = census.non_manifold_vertices;
  result.non_manifold_edges_left = census.non_manifold_edges;
  result.non_manifold_only_between_components = census.non_manifold_between_components_only;
  result.coincident_vertices_left = census.coincident_vertices;
  result.manifold =
      pinched.empty() && census.non_manifold_vertices == 0 && census.non_manifold_edges == 0;
  result.border_cycles_left = border_cycles(pm).size();
  result.closed = result.border_cycles_left == 0;
  if (faces_changed && options.detect_self_intersections) {
    set_output_self_intersections(pm, result, census.halfedge_pairs_stitched > 0);
  }
  result.output_vertices = count_vertices(pm);
  result.output_faces = count_faces(pm);
}

template <class PolygonMesh, class VertexPointMap, class GeomTraits, class Point>
void step_coincident_elements(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                              const Repair_options& options, const std::vector<Point>& hole_points,
                              Repair_result& result, Any_visitor visitor) {
  Step_timer timer(result, "coincident elements", visitor);
  Coincidence_census census;
  bool changed = false;
  {
    Coincident_elements<PolygonMesh, VertexPointMap, GeomTraits> elements(pm, vpm, traits);
    changed = elements.remove_duplicated_faces(census) > 0;
  }
  census.isolated_vertices_removed = CGAL::Polygon_mesh_processing::remove_isolated_vertices(pm);
  Coincident_elements<PolygonMesh, VertexPointMap, GeomTraits> elements(pm, vpm, traits);
  if (changed || elements.any_shared_position()) {
    census.halfedge_pairs_stitched =
        CGAL::Polygon_mesh_processing::stitch_borders(pm, CGAL::parameters::vertex_point_map(vpm));
    changed = changed || census.halfedge_pairs_stitched > 0;
  }
  changed = changed || census.isolated_vertices_removed > 0;
  // Stitching can join two fans of faces at one vertex (two sheets that touch there): the
  // halfedge structure is then no valid polygon mesh. Such vertices are split again, one per
  // fan, and kept like the other contacts.
  census.pinched_vertices_split = CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(
      pm, CGAL::parameters::vertex_point_map(vpm));
  Coincident_elements<PolygonMesh, VertexPointMap, GeomTraits>(pm, vpm, traits).count(census);
  if (census.mergeable_positions > 0 && rebuild_as_read(pm, vpm)) {
    census.rebuilt = 1;
    census.halfedge_pairs_stitched +=
        CGAL::Polygon_mesh_processing::stitch_borders(pm, CGAL::parameters::vertex_point_map(vpm));
    census.pinched_vertices_split += CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(
        pm, CGAL::parameters::vertex_point_map(vpm));
    changed = true;
    Coincident_elements<PolygonMesh, VertexPointMap, GeomTraits>(pm, vpm, traits).count(census);
  }
  // Merging coincident points may join an open hole's border to another (two sheets whose
  // outlines coincide): the hole records must say what the written mesh shows. Before the
  // contacts move: the records hold the borders' positions.
  if (changed)
    reconcile_open_holes(pm, vpm, hole_points,
                         "merging coincident points joined its border to another one", timer,
                         result);
  if (census.coincident_vertices > 0) {
    census.contacts = separate_contacts(pm, vpm, traits,
                                        contact_separation_fraction * mesh_bbox_diagonal(pm, vpm));
    if (census.contacts.vertices_moved > 0) {
      changed = true;
      Coincident_elements<PolygonMesh, VertexPointMap, GeomTraits>(pm, vpm, traits).count(census);
    }
  }
  verify_again(pm, options, census, result, changed);
  timer.count("duplicated_faces_removed", double(census.duplicated_faces_removed));
  timer.count("zero_volume_groups_removed", double(census.zero_volume_groups_removed));
  timer.count("isolated_vertices_removed", double(census.isolated_vertices_removed));
  timer.count("halfedge_pairs_stitched", double(census.halfedge_pairs_stitched));
  timer.count("pinched_vertices_split", double(census.pinched_vertices_split));
  timer.count("non_manifold_vertices_kept", double(census.non_manifold_vertices));
  timer.count("non_manifold_edges_kept", double(census.non_manifold_edges));
  if (census.contacts.vertices_moved + census.contacts.moves_undone > 0) {
    timer.count("contact_vertices_moved_apart", double(census.contacts.vertices_moved));
    timer.count("contact_moves_undone", double(census.contacts.moves_undone));
  }
  if (census.contacts.skipped)
    timer.step().notes.push_back("contacts not moved apart: too many intersecting pairs to check");
  timer.count("coincident_vertices_kept", double(census.coincident_vertices));
  timer.count("duplicated_faces_left", double(census.duplicated_faces_left));
  timer.count("rebuilt_as_read", double(census.rebuilt));
  timer.count("valid", result.valid);
  timer.count("manifold", result.manifold);
  timer.count("border_cycles_left", double(result.border_cycles_left));
  if (census.non_manifold_vertices + census.non_manifold_edges > 0)
    timer.step().notes.push_back(
        "vertices where separate sheets of the surface touch are kept split: merging them would "
        "make the halfedge structure non-manifold; a reader that merges coincident points sees "
        "the non-manifold vertices and edges");
}

/// Moves what was left on purpose from `remaining` to `kept`, and says what "non-manifold"
/// means. The lines are those of `list_remaining`.
inline void sort_out_kept(Repair_result& result, const Repair_options& options) {
  auto has = [](const std::string& line, const char* text) {
    return line.find(text) != std::string::npos;
  };
  std::vector<std::string> remaining;
  bool border_line = false;
  for (const std::string& line : result.remaining) {
    if (has(line, "larger than the size limit") || has(line, "outline(s) of open sheets") ||
        has(line, "between separate components") ||
        (has(line, "(already in the input)") && !options.repair_self_intersections)) {
      result.kept.push_back(line);
    } else if (line == "non-manifold vertices remain" &&
               result.non_manifold_vertices_left + result.non_manifold_edges_left > 0 &&
               result.non_manifold_only_between_components) {
      result.kept.push_back(std::to_string(result.non_manifold_vertices_left) +
                            " non-manifold vertex(es) and " +
                            std::to_string(result.non_manifold_edges_left) +
                            " non-manifold edge(s) where separate components touch (each stays "
                            "a solid of its own; a reader that merges coincident points sees "
                            "them)");
    } else if (line == "non-manifold vertices remain" &&
               result.non_manifold_vertices_left + result.non_manifold_edges_left > 0) {
      remaining.push_back(std::to_string(result.non_manifold_vertices_left) +
                          " non-manifold vertex(es) and " +
                          std::to_string(result.non_manifold_edges_left) +
                          " non-manifold edge(s) where sheets of the surface touch (kept split "
                          "in the mesh; a reader that merges coincident points sees them)");
    } else {
      border_line = border_line || has(line, "border cycle(s) remain");
      remaining.push_back(line);
    }
  }
  // Holes left open, each with the islands it was to be filled with.
  std::size_t explained = 0;
  for (const auto& hole : result.holes.holes)
    if (!hole.filled) explained += 1 + hole.island_cycles;
  if (!border_line && result.border_cycles_left > explained)
    remaining.push_back(std::to_string(result.border_cycles_left - explained) +
                        " border cycle(s) remain besides the holes listed");
  result.remaining = std::move(remaining);
}

/// `run_repair_pipeline`, then the coincident-elements step, the orientation of closed parts and
/// the final lists.
template <class PolygonMesh, class VertexPointMap, class GeomTraits>
Repair_result run_automatic_repair(PolygonMesh& pm, VertexPointMap vpm, const GeomTraits& traits,
                                   const Repair_options& options, Any_visitor visitor) {
  std::vector<typename boost::property_traits<VertexPointMap>::value_type> hole_points;
  Repair_result result = run_repair_pipeline(pm, vpm, traits, options, visitor, hole_points);
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> limit;
  if (options.fill.number_of_threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  std::size_t(options.fill.number_of_threads));
#endif
  if (!result.cancelled)
    step_coincident_elements(pm, vpm, traits, options, hole_points, result, visitor);
  if (!result.cancelled && options.orient_closed_parts)
    step_orient_closed_parts(pm, vpm, traits, visitor, result);
  result.remaining.clear();
  list_remaining(result);
  sort_out_kept(result, options);
  return result;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_COINCIDENT_ELEMENTS_H
