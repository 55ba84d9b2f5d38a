// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_CHECK_WRITTEN_MESH_H
#define CGAL_MESH_REPAIR_CHECK_WRITTEN_MESH_H

/// \file check_written_mesh.h
/// `check_written_mesh`: reads a mesh file back the way CGAL's
/// `Polygon_mesh_processing::IO::read_polygon_mesh` does (the polygon soup repaired: coincident
/// points merged, duplicated and degenerate polygons removed; then oriented, non-manifold edges
/// and vertices split apart; then built) and says what that reading shows. A file stores
/// positions, not vertices: a mesh that keeps distinct vertices at one position, or two faces on
/// the same three positions, is another mesh once read. `apply_written_check` makes a
/// `Repair_result` say what the written file holds. See doc/automatic_repair.md, "The written
/// file".

#include <CGAL/Mesh_repair/internal/mesh_counts.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/repair_result.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/helpers.h>

#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// What a mesh file shows when read back as CGAL's `read_polygon_mesh` reads it.
struct Written_mesh_check {
  std::string file;
  bool readable = false;  ///< the reading built a mesh
  std::string error;      ///< why not, one line
  /// What the reading changed, step by step (`points_merged`: coincident distinct vertices of
  /// the file; `duplicated_polygons_removed`, `non_manifold_edges`, `non_manifold_vertices`,
  /// `polygons_reversed`, ...). `input_points` and `input_polygons` are the file's counts.
  Soup_repair_report reading;
  std::size_t vertices = 0, faces = 0;  ///< of the mesh the reading built
  bool valid = false;                   ///< `CGAL::is_valid_polygon_mesh` of that mesh
  bool closed = false;                  ///< at least one face and no border edge
  std::size_t border_cycles = 0;
  /// Non-manifold vertices and edges the reading found (and split apart).
  std::size_t non_manifold_vertices = 0, non_manifold_edges = 0;

  bool manifold() const { return readable && non_manifold_vertices + non_manifold_edges == 0; }
  /// True when the reading merged, removed, split and reversed nothing: a reader that merges
  /// coincident points and one that does not see the same mesh. (An STL file stores every
  /// triangle's own corners, so its points are always merged; the other changes still count.)
  bool read_as_written() const {
    return readable &&
           reading.polygons_simplified + reading.polygons_split +
                   reading.degenerate_polygons_removed + reading.duplicated_polygons_removed +
                   reading.isolated_points_removed + reading.vertices_duplicated +
                   reading.polygons_reversed + non_manifold_vertices + non_manifold_edges ==
               0;
  }
};

inline void write_json(Json_writer& json, const Written_mesh_check& w) {
  json.begin_object()
      .field("file", w.file)
      .field("readable", w.readable)
      .field("error", w.error)
      .field("points_in_file", w.reading.input_points)
      .field("faces_in_file", w.reading.input_polygons)
      .field("coincident_points_merged", w.reading.points_merged)
      .field("duplicated_faces_removed", w.reading.duplicated_polygons_removed)
      .field("degenerate_faces_removed", w.reading.degenerate_polygons_removed)
      .field("faces_reversed", w.reading.polygons_reversed)
      .field("vertices", w.vertices)
      .field("faces", w.faces)
      .field("valid", w.valid)
      .field("closed", w.closed)
      .field("manifold", w.manifold())
      .field("border_cycles", w.border_cycles)
      .field("non_manifold_vertices", w.non_manifold_vertices)
      .field("non_manifold_edges", w.non_manifold_edges)
      .field("read_as_written", w.read_as_written());
  json.key("reading");
  write_json(json, w.reading);
  json.end_object();
}

/// \ingroup PkgMeshRepair
/// Reads `filename` (OFF, OBJ, STL or PLY) as CGAL's
/// `Polygon_mesh_processing::IO::read_polygon_mesh` does, into `pm`, and returns what that reading
/// shows: whether it builds a valid mesh, its size, closedness and border cycles, the non-manifold
/// vertices and edges it had to split, and every change of the soup stage (merged points, removed
/// duplicated or degenerate faces, reversed faces). The steps are those of `read_mesh` (the same
/// CGAL soup repair and orientation, our validating readers), so `detect_defects` on `pm` combined
/// with `add_soup_repair_report(report, check.reading, pm)` is what `mesh_repair check` reports for
/// the file.
/// @tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph`
template <class PolygonMesh>
Written_mesh_check check_written_mesh(const std::string& filename, PolygonMesh& pm) {
  Written_mesh_check check;
  check.file = filename;
  check.error = read_mesh(filename, pm, check.reading);
  check.readable = check.error.empty();
  if (!check.readable) return check;
  check.vertices = internal::count_vertices(pm);
  check.faces = internal::count_faces(pm);
  check.valid = CGAL::is_valid_polygon_mesh(pm);
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> cycles, pinched;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(pm, std::back_inserter(cycles));
  check.border_cycles = cycles.size();
  check.closed = check.faces > 0 && cycles.empty();
  CGAL::Polygon_mesh_processing::non_manifold_vertices(pm, std::back_inserter(pinched));
  check.non_manifold_vertices = check.reading.non_manifold_vertices + pinched.size();
  check.non_manifold_edges = check.reading.non_manifold_edges;
  return check;
}

/// Makes `result` say what the written file holds: `valid`, `closed`, `manifold` and
/// `border_cycles_left` become those of the reading, and whatever the reading shows that the
/// repaired mesh did not (a file that cannot be read back, non-manifold elements, more border
/// cycles, faces the reading drops) is added to `remaining`, so the status is `incomplete`.
inline void apply_written_check(Repair_result& result, const Written_mesh_check& written) {
  auto add = [&](const std::string& line) { result.remaining.push_back(line); };
  if (!written.readable) {
    add("the written file cannot be read back: " + written.error);
    result.valid = result.closed = result.manifold = false;
    return;
  }
  const std::string read = "the written file, read back with coincident points merged, ";
  if (!written.valid && result.valid) add(read + "is not a valid polygon mesh");
  if (!written.manifold() && result.manifold)
    add(read + "has " + std::to_string(written.non_manifold_vertices) +
        " non-manifold vertex(es) and " + std::to_string(written.non_manifold_edges) +
        " non-manifold edge(s)");
  if (written.border_cycles > result.border_cycles_left)
    add(read + "has " + std::to_string(written.border_cycles) +
        " border cycle(s), the repaired mesh " + std::to_string(result.border_cycles_left));
  const auto& r = written.reading;
  if (r.duplicated_polygons_removed + r.degenerate_polygons_removed > 0)
    add(read + "loses " + std::to_string(r.duplicated_polygons_removed) + " duplicated and " +
        std::to_string(r.degenerate_polygons_removed) + " degenerate face(s)");
  result.valid = written.valid;
  result.manifold = written.manifold();
  result.border_cycles_left = written.border_cycles;
  result.closed = written.closed;
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_CHECK_WRITTEN_MESH_H
