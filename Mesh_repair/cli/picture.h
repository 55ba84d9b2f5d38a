// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_CLI_PICTURE_H
#define MESH_REPAIR_CLI_PICTURE_H

// Pictures of filled holes (`bench holes`, `fill --picture`). The tool writes a small scene per
// picture, the region of a hole and a few rings of its surroundings with one value per face, and
// scripts/render_patches.py draws it with matplotlib (the format is described there).

#include "common.h"

#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace mesh_repair_cli {

/// One view of a scene: faces with one value each (NaN: surroundings, drawn grey) and the hole's
/// border loops (drawn black).
struct Picture_panel {
  std::string title, subtitle;
  std::vector<double> vertices;    ///< x, y, z per vertex
  std::vector<std::size_t> faces;  ///< three vertex indices per face
  std::vector<double> values;      ///< per face: a distance, or a legend index
  std::vector<std::vector<std::size_t>> borders;
  std::array<double, 3> normal{};  ///< own camera direction when not zero (else the scene's)
};

/// One picture: panels side by side. Values are distances drawn on one colour scale up to
/// `scale_max` (larger ones in its top colour), or, `by_category`, indices into `legend`.
struct Picture_scene {
  std::string title;
  std::array<double, 3> normal{0, 0, 1};
  bool by_category = false;
  std::string scale_label;
  double scale_max = 0;
  bool scale_clipped = false;  ///< some value is above `scale_max`
  std::vector<std::string> legend;
  std::vector<Picture_panel> panels;
};

/// Adds faces of one or more meshes to a panel, sharing the vertices of each mesh.
class Panel_builder {
 public:
  explicit Panel_builder(Picture_panel& panel) : panel_(panel) {}
  void add_face(const Mesh& mesh, Mesh::Face_index f, double value);
  /// A closed loop of vertices of `mesh`, drawn as a border.
  void add_border(const Mesh& mesh, const std::vector<Mesh::Vertex_index>& loop);

 private:
  std::size_t index(const Mesh& mesh, Mesh::Vertex_index v);
  Picture_panel& panel_;
  std::map<std::pair<const Mesh*, Mesh::Vertex_index>, std::size_t> indices_;
};

/// How many vertex rings of surroundings a picture shows around a hole of `border_edges`
/// edges: about half the hole's radius, so the surface around it is seen, at least two rings.
std::size_t surrounding_rings(std::size_t border_edges);

/// The faces within `rings` vertex rings of `seeds`, except `excluded`, in index order.
std::vector<Mesh::Face_index> surrounding_faces(const Mesh& mesh,
                                                const std::vector<Mesh::Vertex_index>& seeds,
                                                std::size_t rings,
                                                const std::set<Mesh::Face_index>& excluded);

/// The vertex loops bounding the face set `faces` (where a face of the set meets one outside it
/// or a border).
std::vector<std::vector<Mesh::Vertex_index>> region_borders(
    const Mesh& mesh, const std::set<Mesh::Face_index>& faces);

/// The vertex loop of the border cycle of `border_halfedge` (a halfedge without face).
std::vector<Mesh::Vertex_index> border_loop(const Mesh& mesh, Mesh::Halfedge_index border_halfedge);

/// Area-weighted mean normal of `faces`: the direction a camera looks at them from.
template <class FaceRange>
std::array<double, 3> mean_normal(const Mesh& mesh, const FaceRange& faces) {
  std::array<double, 3> sum{0, 0, 0};
  for (Mesh::Face_index f : faces) {
    const auto h = mesh.halfedge(f);
    const Point &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
                &c = mesh.point(mesh.target(mesh.next(h)));
    const auto n = CGAL::cross_product(b - a, c - a);  // twice the area, along the normal
    sum = {sum[0] + n.x(), sum[1] + n.y(), sum[2] + n.z()};
  }
  return sum;
}

/// The scene as the JSON scripts/render_patches.py reads.
std::string scene_json(const Picture_scene& scene);

/// Renders `jobs` (scene file, picture file) with one run of scripts/render_patches.py. When
/// python3 or matplotlib is missing, or the script fails, prints one line naming `command` and
/// returns false; the command itself goes on.
bool render_pictures(const std::vector<std::pair<std::string, std::string>>& jobs,
                     const std::string& command);

}  // namespace mesh_repair_cli

#endif  // MESH_REPAIR_CLI_PICTURE_H
