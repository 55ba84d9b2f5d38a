// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Every public operator run on one mesh type, from the same polygon soups, summarised as plain
// numbers (counts and the sorted coordinates of the output) so that the results of two mesh
// types can be compared element for element (test_face_graphs_*.cpp).
#ifndef MESH_REPAIR_TEST_FACE_GRAPH_OPERATORS_H
#define MESH_REPAIR_TEST_FACE_GRAPH_OPERATORS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Mesh_repair/clean_hole_contour.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/mga_smooth.h>
#include <CGAL/Mesh_repair/optimize_mesh.h>
#include <CGAL/Mesh_repair/remove_overlaps.h>
#include <CGAL/Mesh_repair/remove_slivers.h>
#include <CGAL/Mesh_repair/repair_t_junctions.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>
#include <CGAL/Mesh_repair/suppress_feature.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace face_graph_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface_mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

/// What an operator left: named counts, and the output mesh's faces as sorted coordinate
/// triples (independent of the mesh type's element order).
struct Outcome {
  std::map<std::string, double> counts;
  std::vector<std::vector<std::array<double, 3>>> faces;
  bool operator==(const Outcome& o) const { return counts == o.counts && faces == o.faces; }
};

/// The vertex point map the operators are given on `Mesh`: by default none (each operator uses
/// the mesh's own). A unit specialises it when the mesh's own map is not exact: CGAL 5.5.1's
/// OpenMesh map writes points as floats (properties_OpenMesh.h, `put` casts to `float`, even for
/// `OpenMesh::Vec3d` points), so every point an operator moves or creates would differ from
/// Surface_mesh's in its last bits (test_face_graphs_openmesh.cpp).
template <class Mesh>
struct Exact_point_map {
  static constexpr bool specialised = false;
};

/// `np`, with `Exact_point_map<Mesh>` as vertex point map where it is specialised.
template <class Mesh, class NamedParameters>
auto with_point_map(const Mesh& mesh, const NamedParameters& np) {
  if constexpr (Exact_point_map<Mesh>::specialised)
    return np.vertex_point_map(typename Exact_point_map<Mesh>::type(mesh));
  else
    return np;
}

template <class Mesh>
auto with_point_map(const Mesh& mesh) {
  return with_point_map(mesh, CGAL::parameters::default_values());
}

template <class Mesh>
Mesh mesh_from(const Soup& soup) {
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(
      soup.points, soup.polygons, mesh, CGAL::parameters::default_values(), with_point_map(mesh));
  return mesh;
}

template <class Mesh>
Soup soup_from(const Mesh& mesh) {
  Soup soup;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, soup.points, soup.polygons,
                                                              with_point_map(mesh));
  return soup;
}

/// The output's faces, each as its corners from the smallest one on (orientation kept), sorted.
template <class Mesh>
std::vector<std::vector<std::array<double, 3>>> sorted_faces(const Mesh& mesh) {
  const Soup soup = soup_from(mesh);
  std::vector<std::vector<std::array<double, 3>>> faces;
  for (const auto& polygon : soup.polygons) {
    std::vector<std::array<double, 3>> corners;
    for (std::size_t i : polygon) {
      const Point& p = soup.points[i];
      corners.push_back({p.x(), p.y(), p.z()});
    }
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    faces.push_back(corners);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

template <class Mesh>
Outcome outcome_of(const Mesh& mesh, std::map<std::string, double> counts) {
  counts["valid"] = CGAL::is_valid_polygon_mesh(mesh);
  counts["closed"] = CGAL::is_closed(mesh);
  return {counts, sorted_faces(mesh)};
}

/// A sphere with two polar caps removed (two holes).
inline Soup sphere_with_holes() {
  Surface_mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  std::vector<Surface_mesh::Face_index> doomed;
  for (auto f : faces(sphere)) {
    double z = 0;
    for (auto v : vertices_around_face(halfedge(f, sphere), sphere)) z += sphere.point(v).z() / 3;
    if (z > 0.85 || z < -0.9) doomed.push_back(f);
  }
  for (auto f : doomed) CGAL::Euler::remove_face(halfedge(f, sphere), sphere);
  sphere.collect_garbage();
  return soup_from(sphere);
}

/// Two grids side by side with a 0.02 gap, their nodes offset (T-junctions).
inline Soup defective_sheet() {
  Soup soup;
  auto grid = [&soup](double x0, int n, double dy) {
    const std::size_t base = soup.points.size();
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= 4; ++i)
        soup.points.emplace_back(x0 + i * 0.25, j * (1.0 / n) + (j > 0 && j < n ? dy : 0), 0);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < 4; ++i) {
        const std::size_t a = base + j * 5 + i, b = a + 1, c = a + 5, d = c + 1;
        soup.polygons.push_back({a, b, d});
        soup.polygons.push_back({a, d, c});
      }
  };
  grid(0, 4, 0);
  grid(1.02, 5, 0.01);
  return soup;
}

/// A bumpy height field: input of the optimiser, the smoother and the sliver remover.
inline Soup bumpy_plate() {
  Surface_mesh plate;
  MR::make_height_field<Surface_mesh, Point>(plate, 0, 1, 0, 1, 12, 12, [](double x, double y) {
    return 0.1 * std::sin(6 * x) * std::cos(5 * y);
  });
  return soup_from(plate);
}

/// Every operator on `Mesh`; the keys name the operator and what is counted.
template <class Mesh>
std::map<std::string, Outcome> run_every_operator() {
  std::map<std::string, Outcome> out;
  {
    const Mesh mesh = mesh_from<Mesh>(defective_sheet());
    const MR::Defect_report r = MR::detect_defects(mesh, with_point_map(mesh));
    const auto c = MR::counts(r);
    out["detect_defects"] = outcome_of(mesh, {{"border_cycles", double(c.border_cycles)},
                                              {"degenerate_faces", double(c.degenerate_faces)},
                                              {"duplicated_faces", double(c.duplicated_faces)},
                                              {"small_gaps", double(c.small_gaps)},
                                              {"t_junctions", double(c.t_junctions)},
                                              {"components", double(c.connected_components)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(defective_sheet());
    const MR::Stitch_result r =
        MR::stitch_gaps(mesh, with_point_map(mesh, MR::parameters::merge_tolerance(0.05)));
    out["stitch_gaps"] = outcome_of(mesh, {{"node_merges", double(r.node_merges)},
                                           {"t_junctions_split", double(r.t_junctions_split)},
                                           {"edges_stitched", double(r.edges_stitched)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(defective_sheet());
    const MR::Stitch_result r =
        MR::repair_t_junctions(mesh, with_point_map(mesh, MR::parameters::merge_tolerance(0.05)));
    out["repair_t_junctions"] =
        outcome_of(mesh, {{"t_junctions_split", double(r.t_junctions_split)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(bumpy_plate());
    const MR::Sliver_result r =
        MR::remove_slivers(mesh, with_point_map(mesh, MR::parameters::shape_factor_threshold(0.9)));
    out["remove_slivers"] =
        outcome_of(mesh, {{"collapsed", double(r.collapsed)}, {"flipped", double(r.flipped)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(defective_sheet());
    const MR::Overlap_result r = MR::remove_overlaps(mesh, with_point_map(mesh));
    out["remove_overlaps"] =
        outcome_of(mesh, {{"duplicated", double(r.duplicated_faces_removed)},
                          {"overlapping", double(r.overlapping_faces_removed)}});
  }
  for (MR::Fill_method method :
       {MR::Fill_method::advancing_front, MR::Fill_method::liepa, MR::Fill_method::shape_prediction,
        MR::Fill_method::curvature_variation, MR::Fill_method::automatic}) {
    Mesh mesh = mesh_from<Mesh>(sphere_with_holes());
    const MR::Fill_result r = MR::fill_holes(
        mesh, with_point_map(mesh, MR::parameters::fill_method(method).number_of_threads(1)));
    out[std::string("fill_holes ") + MR::to_string(method)] =
        outcome_of(mesh, {{"filled", double(r.filled)}, {"failed", double(r.failed)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(sphere_with_holes());
    // The border halfedge with the smallest (source, target) points: the same hole and the same
    // starting edge on every mesh type, whatever order halfedges(mesh) visits them in.
    typename boost::graph_traits<Mesh>::halfedge_descriptor border;
    std::pair<Point, Point> smallest;
    bool found = false;
    for (auto h : halfedges(mesh)) {
      if (!CGAL::is_border(h, mesh)) continue;
      const std::pair<Point, Point> ends(get(CGAL::vertex_point, mesh, source(h, mesh)),
                                         get(CGAL::vertex_point, mesh, target(h, mesh)));
      if (!found || ends < smallest) border = h, smallest = ends, found = true;
    }
    const auto r = MR::clean_hole_contour(mesh, border, with_point_map(mesh));
    out["clean_hole_contour"] = outcome_of(mesh, {{"edges_split", double(r.edges_split)},
                                                  {"edges_after", double(r.border_edges_after)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(defective_sheet());
    const MR::Repair_result r =
        MR::automatic_repair(mesh, with_point_map(mesh, MR::parameters::number_of_threads(1)));
    out["automatic_repair"] = outcome_of(mesh, {{"complete", double(r.complete())},
                                                {"holes_filled", double(r.holes.filled)},
                                                {"steps", double(r.steps.size())}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(bumpy_plate());
    const MR::Optimization_result r = MR::optimize_mesh(
        mesh, with_point_map(mesh, MR::parameters::target_face_ratio(0.5).random_seed(1u)));
    out["optimize_mesh"] = outcome_of(mesh, {{"regions", double(r.regions_replaced)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(bumpy_plate());
    const MR::Mga_smooth_result r =
        MR::mga_smooth(mesh, with_point_map(mesh, MR::parameters::random_seed(1u)));
    out["mga_smooth"] = outcome_of(mesh, {{"moves", double(r.moves)}});
  }
  {
    Mesh mesh = mesh_from<Mesh>(bumpy_plate());
    std::vector<typename boost::graph_traits<Mesh>::face_descriptor> feature;
    for (auto f : faces(mesh)) {
      double x = 0, y = 0;
      for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
        x += get(CGAL::vertex_point, mesh, v).x() / 3;
        y += get(CGAL::vertex_point, mesh, v).y() / 3;
      }
      if (std::hypot(x - 0.5, y - 0.5) < 0.2) feature.push_back(f);
    }
    const auto r =
        MR::suppress_feature(mesh, feature, with_point_map(mesh, MR::parameters::random_seed(1u)));
    out["suppress_feature"] =
        outcome_of(mesh, {{"opened", double(r.holes_opened)}, {"filled", double(r.holes_filled)}});
  }
  return out;
}

/// Runs every operator on `Mesh` and on Surface_mesh and expects the same counts and meshes.
template <class Mesh>
void expect_results_of_surface_mesh() {
  const auto reference = run_every_operator<Surface_mesh>();
  const auto results = run_every_operator<Mesh>();
  ASSERT_EQ(results.size(), reference.size());
  for (const auto& [name, expected] : reference) {
    const auto& got = results.at(name);
    EXPECT_EQ(got.counts, expected.counts) << name;
    EXPECT_EQ(got.faces.size(), expected.faces.size()) << name;
    EXPECT_TRUE(got.faces == expected.faces) << name << ": the output meshes differ";
    EXPECT_EQ(expected.counts.at("valid"), 1.0) << name;
    // What was compared, so that a run shows that each operator did something.
    std::cout << "[ compared ] " << name << ": faces " << expected.faces.size();
    for (const auto& [key, value] : expected.counts) std::cout << ", " << key << " " << value;
    std::cout << '\n';
  }
}

/// A sphere whose north pole was pushed through to beyond the south pole: its faces pierce
/// the far side.
inline Soup sphere_with_spike() {
  Surface_mesh sphere;
  MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 3);
  auto top = *sphere.vertices().begin();
  for (auto v : sphere.vertices())
    if (sphere.point(v).z() > sphere.point(top).z()) top = v;
  sphere.point(top) = Point(0.01, 0.02, -1.1);
  return soup_from(sphere);
}

/// `automatic_repair` replaces the self-intersecting faces on every mesh type (it only needs
/// Euler operations and the hole filling), with the same result as on `Surface_mesh`.
template <class Mesh>
void expect_self_intersections_removed_as_on_surface_mesh() {
  Mesh mesh = mesh_from<Mesh>(sphere_with_spike());
  const MR::Repair_result r =
      MR::automatic_repair(mesh, with_point_map(mesh, MR::parameters::number_of_threads(1)));
  Surface_mesh reference = mesh_from<Surface_mesh>(sphere_with_spike());
  const MR::Repair_result expected =
      MR::automatic_repair(reference, MR::parameters::number_of_threads(1));
  EXPECT_TRUE(r.unavailable_steps.empty());
  EXPECT_GT(r.self_intersections_input, 0u);
  EXPECT_EQ(r.self_intersections_input, expected.self_intersections_input);
  EXPECT_EQ(r.self_intersections_output, 0u);
  EXPECT_EQ(expected.self_intersections_output, 0u);
  EXPECT_TRUE(r.closed && r.valid);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(sorted_faces(mesh) == sorted_faces(reference)) << "the output meshes differ";
}

}  // namespace face_graph_test

#endif  // MESH_REPAIR_TEST_FACE_GRAPH_OPERATORS_H
