// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair mesh-points: surface meshing of unorganised points (Chen et al. 2.1): CGAL's
// advancing-front surface reconstruction builds the primary triangulation, quality edge flips
// clean it, optional conversion to quads, then micro-GA smoothing on the rebuilt G1 surface.
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/internal/json.h>
#include <CGAL/Mesh_repair/mga_smooth.h>
#include <CGAL/Mesh_repair/triangles_to_quads.h>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <iostream>
#include <sstream>

namespace mesh_repair_cli {

const char* const mesh_points_help =
    "usage: mesh_repair mesh-points IN.xyz|IN.ply -o OUT [--quads] [--no-smooth] [--iterations N]\n"
    "                              [--seed S] [--threads N] [--feature-angle DEG]\n"
    "                              [--report R.json] [--quiet]\n"
    "  Triangulates unorganised points with CGAL's advancing-front reconstruction, flips edges\n"
    "  to raise quality, optionally converts to quads, and smooths with the micro-GA, nodes on\n"
    "  the G1 surface through the points (the paper's mapping).\n";

int run_mesh_points(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  namespace PMP = CGAL::Polygon_mesh_processing;
  Arguments arguments(args, {"--quads", "--no-smooth", "--quiet"},
                      {"-o", "--iterations", "--seed", "--threads", "--feature-angle", "--report"});
  const std::string input = arguments.single_input(mesh_points_help);
  const std::string output = arguments.get("-o");
  if (output.empty()) throw Input_error("mesh-points: -o OUT is required");
  const int iterations = int(arguments.get_int("--iterations", 3));
  const int threads = int(arguments.get_int("--threads", 1));
  const unsigned seed = unsigned(arguments.get_int("--seed", 0));
  const double feature_angle = arguments.get_double("--feature-angle", 120.0);
  if (iterations < 0 || threads < 1) throw Input_error("mesh-points: bad --iterations/--threads");

  std::vector<Point> points;
  if (!CGAL::IO::read_points(input, std::back_inserter(points)) || points.size() < 3)
    throw Input_error("mesh-points: cannot read at least three points from " + input);

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(),
                                               std::back_inserter(facets));
  if (facets.empty()) throw Input_error("mesh-points: the reconstruction produced no triangle");
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& f : facets) polygons.push_back({f[0], f[1], f[2]});
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const double reconstruction_seconds = seconds_since(start);

  const auto flips =
      MR::flip_edges_for_quality(mesh, MR::parameters::feature_angle_deg(feature_angle));
  MR::Quad_conversion_result conversion;
  if (arguments.has("--quads"))
    conversion = MR::triangles_to_quads(mesh, MR::parameters::feature_angle_deg(feature_angle));
  MR::Mga_smooth_result smoothing;
  Progress_bar bar(progress_wanted(arguments));
  if (!arguments.has("--no-smooth"))
    smoothing = MR::mga_smooth(mesh, MR::parameters::feature_angle_deg(feature_angle)
                                         .number_of_threads(threads)
                                         .random_seed(seed)
                                         .number_of_iterations(iterations)
                                         .surface_tangent_scale(1.0)
                                         .visitor(std::ref(bar)));
  const double seconds = seconds_since(start);
  save_mesh(output, mesh);

  std::cout << input << ": " << points.size() << " points -> " << mesh.number_of_vertices()
            << " vertices, " << mesh.number_of_faces() << " faces (" << conversion.quads
            << " quads); " << flips.flips << " flips; quality mean "
            << smoothing.mean_quality_before << " -> " << smoothing.mean_quality_after << ", worst "
            << smoothing.worst_quality_before << " -> " << smoothing.worst_quality_after << "; "
            << seconds << " s\n";
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::internal::Json_writer json(text);
    json.begin_object();
    json.field("input", input).field("output", output).field("points", points.size());
    json.field("vertices", mesh.number_of_vertices()).field("faces", mesh.number_of_faces());
    json.field("reconstruction_seconds", reconstruction_seconds).field("seconds", seconds);
    json.field("edge_flips", flips.flips).field("quads", conversion.quads);
    json.field("remaining_triangles", conversion.remaining_triangles);
    json.field("worst_quality_before", smoothing.worst_quality_before);
    json.field("mean_quality_before", smoothing.mean_quality_before);
    json.field("worst_quality_after", smoothing.worst_quality_after);
    json.field("mean_quality_after", smoothing.mean_quality_after);
    json.field("sweeps", smoothing.sweeps).field("moves", smoothing.moves);
    json.end_object();
    save_text(arguments.get("--report"), text.str());
  }
  return smoothing.cancelled ? exit_incomplete : exit_success;
}

}  // namespace mesh_repair_cli
