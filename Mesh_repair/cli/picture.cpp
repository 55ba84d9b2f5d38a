// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "picture.h"

#include <CGAL/Mesh_repair/json_writer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

void Panel_builder::add_face(const Mesh& mesh, Mesh::Face_index f, double value) {
  for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    panel_.faces.push_back(index(mesh, v));
  panel_.values.push_back(value);
}

void Panel_builder::add_border(const Mesh& mesh, const std::vector<Mesh::Vertex_index>& loop) {
  std::vector<std::size_t> indices;
  for (Mesh::Vertex_index v : loop) indices.push_back(index(mesh, v));
  panel_.borders.push_back(indices);
}

std::size_t Panel_builder::index(const Mesh& mesh, Mesh::Vertex_index v) {
  const auto [it, added] = indices_.emplace(std::make_pair(&mesh, v), indices_.size());
  if (added) {
    const Point& p = mesh.point(v);
    panel_.vertices.insert(panel_.vertices.end(), {p.x(), p.y(), p.z()});
  }
  return it->second;
}

std::size_t surrounding_rings(std::size_t border_edges) {
  // A disc of n border edges of length e has radius n e / (2 pi): n / 12 rings is about half.
  return std::clamp<std::size_t>(border_edges / 12, 2, 8);
}

std::vector<Mesh::Face_index> surrounding_faces(const Mesh& mesh,
                                                const std::vector<Mesh::Vertex_index>& seeds,
                                                std::size_t rings,
                                                const std::set<Mesh::Face_index>& excluded) {
  std::set<Mesh::Vertex_index> reached(seeds.begin(), seeds.end());
  std::vector<Mesh::Vertex_index> frontier = seeds;
  std::set<Mesh::Face_index> faces;
  for (std::size_t ring = 0; ring < rings; ++ring) {
    std::vector<Mesh::Vertex_index> next;
    for (Mesh::Vertex_index v : frontier) {
      if (mesh.halfedge(v) == Mesh::null_halfedge()) continue;
      for (Mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
        if (f == Mesh::null_face() || excluded.count(f) || !faces.insert(f).second) continue;
        for (Mesh::Vertex_index w : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
          if (reached.insert(w).second) next.push_back(w);
      }
    }
    frontier.swap(next);
  }
  return {faces.begin(), faces.end()};
}

std::vector<std::vector<Mesh::Vertex_index>> region_borders(
    const Mesh& mesh, const std::set<Mesh::Face_index>& faces) {
  const auto inside = [&](Mesh::Halfedge_index h) { return faces.count(mesh.face(h)) > 0; };
  std::set<Mesh::Halfedge_index> done;
  std::vector<std::vector<Mesh::Vertex_index>> loops;
  for (Mesh::Face_index f : faces) {
    for (Mesh::Halfedge_index start : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      if (inside(mesh.opposite(start)) || done.count(start)) continue;
      std::vector<Mesh::Vertex_index> loop;
      // Walk the region's boundary: turn around each target vertex inside the region.
      for (Mesh::Halfedge_index h = start; done.insert(h).second;) {
        loop.push_back(mesh.source(h));
        h = mesh.next(h);
        for (std::size_t turns = 0; inside(mesh.opposite(h)) && turns < 1000; ++turns)
          h = mesh.next(mesh.opposite(h));
      }
      loops.push_back(loop);
    }
  }
  return loops;
}

std::vector<Mesh::Vertex_index> border_loop(const Mesh& mesh,
                                            Mesh::Halfedge_index border_halfedge) {
  std::vector<Mesh::Vertex_index> loop;
  for (Mesh::Halfedge_index h : CGAL::halfedges_around_face(border_halfedge, mesh))
    loop.push_back(mesh.source(h));
  return loop;
}

namespace {

// Coordinates with 6 digits and distances with 4: a picture needs no more, and a scene of a
// large hole stays a few hundred kilobytes.
std::string numbers(const std::vector<double>& values, const char* format) {
  std::string text = "[";
  char buffer[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) text += ',';
    if (!std::isfinite(values[i])) {
      text += "null";
      continue;
    }
    std::snprintf(buffer, sizeof buffer, format, values[i]);
    text += buffer;
  }
  return text + "]";
}

std::string indices(const std::vector<std::size_t>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i ? "," : "") + std::to_string(values[i]);
  return text + "]";
}

void write_panel(CGAL::Mesh_repair::Json_writer& json, const Picture_panel& panel) {
  json.begin_object();
  json.field("title", panel.title).field("subtitle", panel.subtitle);
  json.key("vertices").raw(numbers(panel.vertices, "%.6g"));
  json.key("faces").raw(indices(panel.faces));
  json.key("values").raw(numbers(panel.values, "%.4g"));
  json.key("borders").begin_array();
  for (const auto& loop : panel.borders) json.raw(indices(loop));
  json.end_array();
  if (panel.normal != std::array<double, 3>{0, 0, 0})
    json.key("normal").raw(numbers({panel.normal.begin(), panel.normal.end()}, "%.6g"));
  json.end_object();
}

}  // namespace

std::string scene_json(const Picture_scene& scene) {
  std::ostringstream text;
  CGAL::Mesh_repair::Json_writer json(text, false);
  json.begin_object();
  json.field("title", scene.title);
  json.key("normal").raw(numbers({scene.normal.begin(), scene.normal.end()}, "%.6g"));
  json.field("mode", scene.by_category ? "category" : "distance");
  if (!scene.by_category) {
    json.field("scale_label", scene.scale_label).field("scale_max", scene.scale_max);
    json.field("scale_clipped", scene.scale_clipped);
  } else {
    json.array("legend", scene.legend);
  }
  json.key("panels").begin_array();
  for (const Picture_panel& panel : scene.panels) write_panel(json, panel);
  json.end_array();
  json.end_object();
  text << '\n';
  return text.str();
}

bool render_pictures(const std::vector<std::pair<std::string, std::string>>& jobs,
                     const std::string& command) {
  if (jobs.empty()) return true;
  const std::string unavailable = plotting_unavailable();
  if (!unavailable.empty()) {
    std::cerr << command << ": no pictures: " << unavailable << '\n';
    return false;
  }
  const std::string script = script_path("render_patches.py");
  if (!std::filesystem::exists(script)) {
    std::cerr << command << ": no pictures: " << script << " not found\n";
    return false;
  }
  std::vector<std::string> args;
  for (const auto& [scene, picture] : jobs) args.insert(args.end(), {scene, picture});
  if (run_python_script(script, args) != 0) {
    std::cerr << command << ": " << script << " failed; some pictures are missing\n";
    return false;
  }
  return true;
}

}  // namespace mesh_repair_cli
