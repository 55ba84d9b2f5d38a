// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_IO_H
#define CGAL_MESH_REPAIR_IO_H

/// \file io.h
/// Reading and writing meshes the way a repair tool must: every file is read as a polygon soup
/// by our own strict readers (internal/readers/: every header and record checked, no CGAL
/// reader sees the bytes), validated (finite coordinates, indices in range), repaired and
/// oriented with CGAL, and only then turned into a mesh; every change of that soup stage is
/// counted in a `Soup_repair_report`. Writing goes to a temporary file renamed over the target,
/// so a failed or interrupted write never leaves a half-written file.
///
/// Formats: OFF (ASCII and binary, [ST][C][N][4][n]OFF), OBJ, STL (ASCII and binary) and PLY
/// (ASCII, binary little- and big-endian; faces and tristrips), chosen by extension.
///
/// Limits, each refused with one line naming the file, the line or byte offset and the reason:
/// - counts a header declares must fit in the file's size (checked before any allocation);
/// - a face has at most `internal::readers::max_polygon_vertices` (10000) vertices: CGAL's
///   soup repair and orientation are not linear in a polygon's size;
/// - a text line is at most 64 MB.
/// Memory while reading a file of S bytes: the soup itself, at most about 20 S + 50 MB (see
/// doc/fuzzing.md for the measured figures). Faces with fewer than three vertices are left
/// out of the soup and counted as degenerate polygons removed.

#include <CGAL/Mesh_repair/file_safety.h>
#include <CGAL/Mesh_repair/internal/readers/read_soup.h>
#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/polygon_soup.h>
#include <CGAL/Mesh_repair/soup_repair_report.h>
#include <CGAL/Mesh_repair/internal/face_triangulation.h>
#include <CGAL/Mesh_repair/internal/polygon_projection.h>
#include <CGAL/Mesh_repair/internal/soup_validation.h>
#include <CGAL/Mesh_repair/internal/soup_edge.h>
#include <CGAL/Mesh_repair/internal/soup_internal_walls.h>
#include <CGAL/Mesh_repair/internal/soup_to_mesh.h>
#include <CGAL/Mesh_repair/internal/zero_volume_walls.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// Options of `read_mesh`.
struct Read_options {
  bool repair_soup = true;  ///< run CGAL's polygon-soup repair and orientation
  bool triangulate = true;  ///< split faces with more than three sides into triangles
  /// Duplicated polygons (the same points in either orientation) are all removed, instead of
  /// all but one as CGAL's `read_polygon_mesh` does, when that leaves fewer edges with more
  /// than two polygons: the wall between two closed shells that share a face, whose removal
  /// joins the shells; and internal walls written once (a sheet whose outline is all
  /// non-manifold edges, inside the closed surface the rest of its part forms) are removed,
  /// counted in `internal_walls_removed`. `mesh_repair repair` sets it; `check` and the
  /// read-back of a written file keep CGAL's rule.
  bool remove_zero_volume_walls = false;
};

/// Reads a mesh file's bytes held in memory (`format` "OFF", "OBJ", "STL" or "PLY"; `name`
/// for the messages) into a validated soup. Returns an empty string on success, else one line.
template <class Point>
std::string read_polygon_soup_from_memory(const char* data, std::size_t size,
                                          const std::string& format, const std::string& name,
                                          Polygon_soup<Point>& soup) {
  internal::readers::Byte_reader in(data, size);
  internal::readers::Read_counts counts;
  std::string error =
      internal::readers::read_soup(in, format, name, soup.points, soup.polygons, counts);
  soup.short_polygons_skipped = counts.short_polygons;
  soup.header_lines_skipped = counts.header_lines_skipped;
  if (error.empty())
    error = internal::validate_soup(name, soup.points, soup.polygons, counts.line_statements,
                                    counts.short_polygons);
  if (!error.empty()) soup.points.clear(), soup.polygons.clear();  // nothing half-read
  return error;
}

namespace internal {

/// Opens `filename` and hands its bytes to `read` (a callable taking a `readers::Byte_reader&`
/// and returning an empty string or one line), after refusing a file that is mostly unwritten
/// (`readers::min_unwritten_bytes`). The file is closed on every path.
template <class Read>
std::string read_file_bytes(const std::string& filename, Read&& read) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(filename.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) return filename + ": cannot be opened for reading";
  struct stat info;
  if (::fstat(::fileno(file.get()), &info) != 0 || !S_ISREG(info.st_mode))
    return filename + ": not a regular file";
  const std::uintmax_t size = std::uintmax_t(info.st_size);
  std::uintmax_t first_hole = 0;
  const std::uintmax_t unwritten = readers::unwritten_bytes(::fileno(file.get()), size, first_hole);
  if (unwritten >= readers::min_unwritten_bytes && unwritten > size / 2)
    return filename + ": byte " + std::to_string(first_hole) + ": a sparse file, " +
           std::to_string(unwritten) + " of its " + std::to_string(size) +
           " bytes were never written (a preallocated or truncated file, not mesh data)";
  readers::Byte_reader in(file.get(), size);
  return read(in);
}

}  // namespace internal

/// Reads `filename` (OFF, OBJ, STL or PLY, by extension) into a polygon soup and validates it.
/// Returns an empty string on success, else one line saying what is wrong with the file and
/// where. Never throws; never modifies the file.
template <class Point>
std::string read_polygon_soup(const std::string& filename, Polygon_soup<Point>& soup) {
  soup.points.clear();
  soup.polygons.clear();
  soup.short_polygons_skipped = 0;
  soup.header_lines_skipped = 0;
  std::string error = internal::precheck_mesh_file(filename);
  if (!error.empty()) return error;
  internal::readers::Read_counts counts;
  error = internal::read_file_bytes(filename, [&](internal::readers::Byte_reader& in) {
    return internal::readers::read_soup(in, internal::format_name(filename), filename, soup.points,
                                        soup.polygons, counts);
  });
  soup.short_polygons_skipped = counts.short_polygons;
  soup.header_lines_skipped = counts.header_lines_skipped;
  if (error.empty())
    error = internal::validate_soup(filename, soup.points, soup.polygons, counts.line_statements,
                                    counts.short_polygons);
  if (!error.empty()) soup.points.clear(), soup.polygons.clear();  // nothing half-read
  return error;
}

namespace internal {

// Counts what `orient_polygon_soup` reports, with locations.
struct Orientation_counter : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  Soup_repair_report* report;
  std::set<Soup_edge> seen_edges;
  std::set<std::size_t> seen_vertices;
  explicit Orientation_counter(Soup_repair_report* r) : report(r) {}
  // CGAL calls this once per polygon around the edge; count each edge once.
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t) {
    if (!seen_edges.insert(soup_edge(a, b)).second) return;
    ++report->non_manifold_edges;
    report->non_manifold_edge_points.emplace_back(a, b);
  }
  void non_manifold_vertex(std::size_t v, std::size_t) {
    if (!seen_vertices.insert(v).second) return;
    ++report->non_manifold_vertices;
    report->non_manifold_vertex_points.push_back(v);
  }
  void duplicated_vertex(std::size_t, std::size_t) { ++report->vertices_duplicated; }
  void polygon_orientation_reversed(std::size_t) { ++report->polygons_reversed; }
};

}  // namespace internal

namespace internal {

/// A polygon in a form shared by its duplicates: rotated to start at its smallest point index,
/// in the direction whose second index is the smaller.
inline std::vector<std::size_t> canonical_polygon(const std::vector<std::size_t>& polygon) {
  const std::size_t n = polygon.size();
  const std::size_t first =
      std::size_t(std::min_element(polygon.begin(), polygon.end()) - polygon.begin());
  const bool forward = polygon[(first + 1) % n] <= polygon[(first + n - 1) % n];
  std::vector<std::size_t> key(n);
  for (std::size_t k = 0; k < n; ++k)
    key[k] = polygon[forward ? (first + k) % n : (first + n - k) % n];
  return key;
}

/// Removes every polygon of the groups of duplicated polygons that form zero-volume walls between
/// two shells (`choose_zero_volume_walls`). Returns the walls and the polygons removed.
inline std::pair<std::size_t, std::size_t> remove_zero_volume_walls(
    std::vector<std::vector<std::size_t>>& polygons) {
  // Candidates: polygons on the same sorted point indices, then the same cyclic sequence.
  std::vector<std::pair<std::vector<std::size_t>, std::size_t>> keyed;
  keyed.reserve(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    std::vector<std::size_t> sorted = polygons[i];
    std::sort(sorted.begin(), sorted.end());
    keyed.emplace_back(std::move(sorted), i);
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i + 1;
    while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    if (j - i > 1) {
      std::map<std::vector<std::size_t>, std::vector<std::size_t>> same;
      for (std::size_t k = i; k < j; ++k)
        same[canonical_polygon(polygons[keyed[k].second])].push_back(keyed[k].second);
      for (auto& entry : same)
        if (entry.second.size() > 1) groups.push_back(std::move(entry.second));
    }
    i = j;
  }
  if (groups.empty()) return {0, 0};
  // The distinct polygons along each edge of a group (a group of duplicates counts once: a
  // surface given twice is not a wall).
  std::vector<std::size_t> class_of(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) class_of[i] = groups.size() + i;
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t i : groups[g]) class_of[i] = g;
  std::map<Soup_edge, std::vector<std::size_t>> classes;
  for (const auto& group : groups) {
    const auto& p = polygons[group.front()];
    for (std::size_t k = 0; k < p.size(); ++k) classes[soup_edge(p[k], p[(k + 1) % p.size()])];
  }
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const auto& p = polygons[i];
    for (std::size_t k = 0; k < p.size(); ++k) {
      auto it = classes.find(soup_edge(p[k], p[(k + 1) % p.size()]));
      if (it != classes.end()) it->second.push_back(class_of[i]);
    }
  }
  for (auto& entry : classes) {
    std::sort(entry.second.begin(), entry.second.end());
    entry.second.erase(std::unique(entry.second.begin(), entry.second.end()), entry.second.end());
  }
  std::vector<Classes_along_edges> along(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto& p = polygons[groups[g].front()];
    for (std::size_t k = 0; k < p.size(); ++k)
      along[g].push_back(classes[soup_edge(p[k], p[(k + 1) % p.size()])]);
  }
  const Zero_volume_walls walls = choose_zero_volume_walls(along);
  std::vector<bool> doomed(polygons.size(), false);
  std::size_t removed = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (!walls.removed[g]) continue;
    removed += groups[g].size();
    for (std::size_t i : groups[g]) doomed[i] = true;
  }
  soup_walls::erase_polygons(polygons, doomed);
  return {walls.walls, removed};
}

}  // namespace internal

/// Repairs and orients a soup in place with CGAL (`repair_polygon_soup`'s steps, one by one so
/// each is counted, then `orient_polygon_soup`, which duplicates non-manifold vertices). With
/// `remove_zero_volume_walls`, duplicated polygons forming a zero-volume wall are all removed
/// before CGAL removes the other duplicates (see `Read_options`).
template <class Point>
Soup_repair_report repair_polygon_soup(Polygon_soup<Point>& soup,
                                       bool remove_zero_volume_walls = false) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Traits = typename CGAL::Kernel_traits<Point>::Kernel;
  Soup_repair_report report;
  report.input_points = soup.points.size();
  report.input_polygons = soup.polygons.size();
  auto& points = soup.points;
  auto& polygons = soup.polygons;
  Traits traits;

  report.points_merged = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  report.polygons_simplified =
      PMP::internal::simplify_polygons_in_polygon_soup(points, polygons, traits);
  report.polygons_split =
      PMP::internal::split_pinched_polygons_in_polygon_soup(points, polygons, traits);
  report.degenerate_polygons_removed =
      PMP::internal::remove_invalid_polygons_in_polygon_soup(points, polygons);
  if (remove_zero_volume_walls) {
    const auto walls = internal::remove_zero_volume_walls(polygons);
    report.zero_volume_walls_removed = walls.first;
    report.duplicated_polygons_removed = walls.second;
  }
  report.duplicated_polygons_removed +=
      PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  if (remove_zero_volume_walls) {
    const auto walls = internal::remove_internal_walls(points, polygons);
    report.internal_walls_removed = walls.first;
    report.internal_wall_polygons_removed = walls.second;
  }
  report.isolated_points_removed = PMP::remove_isolated_points_in_polygon_soup(points, polygons);

  internal::Orientation_counter counter(&report);
  report.orientable =
      PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(counter));
  return report;
}

/// Adds the changes counted in `more` (a second repair pass) to `report`.
inline void add_soup_changes(Soup_repair_report& report, const Soup_repair_report& more) {
  report.points_merged += more.points_merged;
  report.polygons_simplified += more.polygons_simplified;
  report.polygons_split += more.polygons_split;
  report.degenerate_polygons_removed += more.degenerate_polygons_removed;
  report.duplicated_polygons_removed += more.duplicated_polygons_removed;
  report.internal_walls_removed += more.internal_walls_removed;
  report.internal_wall_polygons_removed += more.internal_wall_polygons_removed;
  report.zero_volume_walls_removed += more.zero_volume_walls_removed;
  report.isolated_points_removed += more.isolated_points_removed;
  report.non_manifold_edges += more.non_manifold_edges;
  report.non_manifold_vertices += more.non_manifold_vertices;
  report.vertices_duplicated += more.vertices_duplicated;
  report.polygons_reversed += more.polygons_reversed;
  report.orientable = report.orientable && more.orientable;
}

namespace internal {

/// False when face `f` of `pm` (more than 3 sides) is not simple seen along the normal CGAL's
/// `triangulate_face` projects it on (`compute_face_normal`, so that both decide on the same
/// projection), or when that normal is zero or not finite (internal/polygon_projection.h).
/// CGAL's triangulation would insert every crossing of two sides as a vertex (O(n^2) time and
/// memory: about a million for a {1500/601} star) and then fail; on a small polygon whose
/// projection crosses itself only by a rounding (corners 1e-60 apart beside one at 4.44, or one
/// coordinate of 4e91: found by fuzzing) CGAL 5.5's constrained triangulation dereferences a
/// null face, and on a normal that is not finite (coordinates of 1e99) its exact predicates
/// raise SIGFPE. Such a polygon goes to the fan directly.
template <class PolygonMesh>
bool worth_triangulating_with_cgal(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                                   const PolygonMesh& pm) {
  if (degree(f, pm) <= 3) return true;
  const auto vpm = get(CGAL::vertex_point, pm);
  using Point = typename boost::property_traits<decltype(vpm)>::value_type;
  std::vector<Point> corners;
  for (auto v : vertices_around_face(halfedge(f, pm), pm)) corners.push_back(get(vpm, v));
  return projection_is_simple(corners, CGAL::Polygon_mesh_processing::compute_face_normal(f, pm));
}

/// Appends to `triangles` the triangles of one polygon of `points` (indices into `points`):
/// CGAL's triangulation of the polygon on its own (a constrained Delaunay triangulation in its
/// plane) when it succeeds, else a fan from its first point. CGAL fails on polygons whose
/// points are all collinear and on polygons whose projection is not simple (both are found in
/// real OBJ files); their fans' degenerate or overlapping triangles are left to the repair.
template <class PolygonMesh, class Point, class Polygon, class Triangles>
void triangulate_polygon(const std::vector<Point>& points, const Polygon& polygon,
                         Triangles& triangles) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  auto fan = [&] {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
  };
  PolygonMesh one;
  auto vpm = get(CGAL::vertex_point, one);
  std::unordered_map<vertex_descriptor, std::size_t> index;
  std::vector<vertex_descriptor> corners;
  for (std::size_t i : polygon) {
    const vertex_descriptor v = add_vertex(one);
    put(vpm, v, points[i]);
    index.emplace(v, i);
    corners.push_back(v);
  }
  const auto f = CGAL::Euler::add_face(corners, one);
  if (f == boost::graph_traits<PolygonMesh>::null_face() ||
      !worth_triangulating_with_cgal(f, one) ||
      !CGAL::Polygon_mesh_processing::triangulate_face(f, one) ||
      !CGAL::is_valid_polygon_mesh(one) || num_faces(one) + 2 != polygon.size())
    return fan();
  for (auto g : faces(one)) {
    std::array<std::size_t, 3> triangle;
    std::size_t k = 0;
    for (vertex_descriptor v : vertices_around_face(halfedge(g, one), one))
      if (k < 3) triangle[k++] = index.at(v);
    triangles.push_back({triangle[0], triangle[1], triangle[2]});
  }
}

}  // namespace internal

namespace internal {

/// True when two triangles of `pm` have the same three vertices, in either orientation.
template <class PolygonMesh>
bool has_repeated_triangles(const PolygonMesh& pm) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::vector<std::array<vertex_descriptor, 3>> triangles;
  triangles.reserve(num_faces(pm));
  for (auto f : faces(pm)) {
    if (degree(f, pm) != 3) continue;
    const auto h = halfedge(f, pm);
    std::array<vertex_descriptor, 3> t = {target(h, pm), target(next(h, pm), pm), source(h, pm)};
    std::sort(t.begin(), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  return std::adjacent_find(triangles.begin(), triangles.end()) != triangles.end();
}

}  // namespace internal

/// Builds `pm` from `soup` with every polygon of more than three sides triangulated on its own
/// (`internal::triangulate_polygon`: CGAL's triangulation, or a fan where CGAL fails), the
/// triangle soup repaired again (a fan's diagonals may meet other faces); the triangulation and
/// the second repair are counted in `report`. The fallback of `soup_to_mesh` when CGAL cannot
/// triangulate the faces of the whole mesh.
template <class PolygonMesh, class Point>
std::string triangulate_soup_to_mesh(const Polygon_soup<Point>& soup, PolygonMesh& pm,
                                     Soup_repair_report& report) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Polygon_soup<Point> triangles;
  triangles.points = soup.points;
  std::size_t polygons = 0;
  for (const auto& polygon : soup.polygons) {
    if (polygon.size() <= 3) {
      triangles.polygons.push_back(polygon);
      continue;
    }
    ++polygons;
    internal::triangulate_polygon<PolygonMesh>(soup.points, polygon, triangles.polygons);
  }
  report.polygons_triangulated = polygons;
  report.triangles_from_polygons = triangles.polygons.size() - (soup.polygons.size() - polygons);
  add_soup_changes(report, repair_polygon_soup(triangles));
  clear(pm);
  if (triangles.polygons.empty()) return "no face is left after triangulating the polygons";
  if (!PMP::is_polygon_soup_a_polygon_mesh(triangles.polygons))
    return "the triangulated polygon soup is not a valid polygon mesh even after repair";
  internal::polygon_mesh_soup_to_mesh(triangles.points, triangles.polygons, pm);
  return {};
}

/// Builds `pm` from a soup that `repair_polygon_soup` made manifold. Faces with more than three
/// sides are triangulated when `triangulate` is set (counted in `report`).
template <class PolygonMesh, class Point>
std::string soup_to_mesh(const Polygon_soup<Point>& soup, PolygonMesh& pm, bool triangulate,
                         Soup_repair_report& report) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons))
    return "the polygon soup is not a valid polygon mesh even after repair";
  internal::polygon_mesh_soup_to_mesh(soup.points, soup.polygons, pm);
  if (triangulate) {
    std::size_t non_triangles = 0;
    bool large_crossing_polygon = false;
    for (auto f : faces(pm)) {
      non_triangles += degree(f, pm) > 3 ? 1 : 0;
      large_crossing_polygon =
          large_crossing_polygon || !internal::worth_triangulating_with_cgal(f, pm);
    }
    // CGAL would fail on it after quadratic work; the fallback fans it (internal::
    // triangulate_polygon) and triangulates the other polygons as CGAL does.
    if (large_crossing_polygon) return triangulate_soup_to_mesh(soup, pm, report);
    if (non_triangles > 0) {
      const std::size_t before = num_faces(pm);
      // In an order fixed by the polygons (internal/face_triangulation.h): with CGAL's, the
      // halfedge indices, and every later choice made in index order, change from run to run.
      if (!internal::triangulate_faces_in_fixed_order(pm))
        return triangulate_soup_to_mesh(soup, pm, report);
      report.polygons_triangulated = non_triangles;
      report.triangles_from_polygons = num_faces(pm) - before + non_triangles;
      // CGAL 5.5's triangulate_faces can return a corrupt halfedge structure for a non-planar
      // polygon whose projection is not simple (found by fuzzing: the next CGAL call on the
      // mesh never returns). Then the soup's polygons are split into fans and repaired again.
      if (!CGAL::is_valid_polygon_mesh(pm)) return triangulate_soup_to_mesh(soup, pm, report);
      // A polygon and triangles covering it (a double-sided face written once as a polygon,
      // once as triangles) become repeated triangles only now, past the soup's duplicate
      // removal and orientation: repaired again as triangles.
      if (internal::has_repeated_triangles(pm)) return triangulate_soup_to_mesh(soup, pm, report);
    }
  }
  return {};
}

/// The steps of `read_mesh` after reading: repairs and orients a validated `soup` (consumed)
/// and converts it into `pm`, counting every change in `report`. Also for soups that come from
/// elsewhere than a file (the Python module's arrays); `name` starts the messages. Returns an
/// empty string on success, else one line describing the problem (then `pm` is left empty).
template <class PolygonMesh, class Point>
std::string repaired_soup_to_mesh(Polygon_soup<Point>& soup, PolygonMesh& pm,
                                  Soup_repair_report& report, const Read_options& options,
                                  const std::string& name) {
  report = Soup_repair_report();
  report.input_points = soup.points.size();
  report.input_polygons = soup.polygons.size();
  if (options.repair_soup) report = repair_polygon_soup(soup, options.remove_zero_volume_walls);
  report.input_polygons += soup.short_polygons_skipped;
  report.degenerate_polygons_removed += soup.short_polygons_skipped;
  report.header_lines_skipped = soup.header_lines_skipped;
  if (soup.polygons.empty()) return name + ": no valid face left after soup repair";
  const std::string error = soup_to_mesh(soup, pm, options.triangulate, report);
  if (!error.empty()) {
    clear(pm);
    return name + ": " + error;
  }
  return {};
}

/// Reads, validates, repairs and converts `filename` into `pm`. Returns an empty string on
/// success, else one line describing the problem (then `pm` is left empty).
template <class PolygonMesh>
std::string read_mesh(const std::string& filename, PolygonMesh& pm, Soup_repair_report& report,
                      const Read_options& options = Read_options()) {
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  Polygon_soup<Point> soup;
  const std::string error = read_polygon_soup(filename, soup);
  if (!error.empty()) return error;
  return repaired_soup_to_mesh(soup, pm, report, options, filename);
}

/// Writes `pm` to `filename` (format by extension; `binary` selects binary STL/PLY) through a
/// temporary file in the same folder, renamed over the target only once it is complete.
/// Returns an empty string on success, else one line describing the problem.
template <class PolygonMesh>
std::string write_mesh(const std::string& filename, const PolygonMesh& pm, bool binary = false) {
  const std::string format = internal::format_name(filename);
  if (format.empty()) return filename + ": unknown output format (use .off, .obj, .stl or .ply)";
  std::string error = internal::check_writable(filename);
  if (!error.empty()) return error;
  internal::remove_stale_temporaries(filename);
  const std::string temporary = internal::temporary_name_for(filename);
  internal::register_temporary_file(temporary);
  bool ok = false;
  try {
    // CGAL prints its own complaints on std::cerr; ours is the only message.
    internal::Silence_cerr quiet;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    CGAL::IO::set_mode(out, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
    if (out) {
      const auto np = CGAL::parameters::stream_precision(17).use_binary_mode(binary);
      if (format == "OFF")
        ok = CGAL::IO::write_OFF(out, pm, np);
      else if (format == "OBJ")
        ok = CGAL::IO::write_OBJ(out, pm, np);
      else if (format == "STL")
        ok = CGAL::IO::write_STL(out, pm, np);
      else
        ok = CGAL::IO::write_PLY(out, pm, np);
      out.close();
      ok = ok && !out.fail();
    }
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok) {
    std::remove(temporary.c_str());
    internal::register_temporary_file({});
    return filename + ": cannot be written (" + internal::folder_of(filename) +
           " not writable or full)";
  }
  const bool renamed = std::rename(temporary.c_str(), filename.c_str()) == 0;
  if (!renamed) std::remove(temporary.c_str());
  internal::register_temporary_file({});
  return renamed ? std::string() : filename + ": cannot be renamed into place";
}

}  // namespace Mesh_repair
}  // namespace CGAL

// Compiled once in the core library (internal/compiled_core.h): every command, test and benchmark
// reads and writes Surface_mesh<Epick>, and the readers, CGAL's soup repair and orientation and
// the face triangulation are the heaviest templates a file that only reads a mesh would compile.
#ifdef CGAL_MESH_REPAIR_COMPILED_CORE
#include <CGAL/Mesh_repair/internal/compiled_core.h>
#ifdef CGAL_MESH_REPAIR_INSTANTIATE_IO
#define CGAL_MESH_REPAIR_IO_EXTERN
#else
#define CGAL_MESH_REPAIR_IO_EXTERN extern
#endif
namespace CGAL {
namespace Mesh_repair {
CGAL_MESH_REPAIR_IO_EXTERN template struct Polygon_soup<internal::Core_traits::Point_3>;
CGAL_MESH_REPAIR_IO_EXTERN template std::string read_polygon_soup_from_memory(
    const char*, std::size_t, const std::string&, const std::string&,
    Polygon_soup<internal::Core_traits::Point_3>&);
CGAL_MESH_REPAIR_IO_EXTERN template std::string read_polygon_soup(
    const std::string&, Polygon_soup<internal::Core_traits::Point_3>&);
CGAL_MESH_REPAIR_IO_EXTERN template Soup_repair_report repair_polygon_soup(
    Polygon_soup<internal::Core_traits::Point_3>&, bool);
CGAL_MESH_REPAIR_IO_EXTERN template std::string soup_to_mesh(
    const Polygon_soup<internal::Core_traits::Point_3>&, internal::Core_mesh&, bool,
    Soup_repair_report&);
CGAL_MESH_REPAIR_IO_EXTERN template std::string repaired_soup_to_mesh(
    Polygon_soup<internal::Core_traits::Point_3>&, internal::Core_mesh&, Soup_repair_report&,
    const Read_options&, const std::string&);
CGAL_MESH_REPAIR_IO_EXTERN template std::string read_mesh(const std::string&, internal::Core_mesh&,
                                                          Soup_repair_report&, const Read_options&);
CGAL_MESH_REPAIR_IO_EXTERN template std::string write_mesh(const std::string&,
                                                           const internal::Core_mesh&, bool);
}  // namespace Mesh_repair
// CGAL's face triangulation, which soup_to_mesh calls, and so do the commands and the smoother
// on a mesh with polygons: one constrained Delaunay triangulation instantiated for all of them.
namespace Polygon_mesh_processing {
CGAL_MESH_REPAIR_IO_EXTERN template bool
triangulate_faces<Mesh_repair::internal::Core_mesh, parameters::Default_named_parameters>(
    Mesh_repair::internal::Core_mesh&, const parameters::Default_named_parameters&);
}  // namespace Polygon_mesh_processing
}  // namespace CGAL
#undef CGAL_MESH_REPAIR_IO_EXTERN
#endif

#endif  // CGAL_MESH_REPAIR_IO_H
