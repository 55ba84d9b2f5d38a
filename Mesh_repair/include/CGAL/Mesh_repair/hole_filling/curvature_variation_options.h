// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_HOLE_FILLING_CURVATURE_VARIATION_OPTIONS_H
#define CGAL_MESH_REPAIR_HOLE_FILLING_CURVATURE_VARIATION_OPTIONS_H

/// \file curvature_variation_options.h
/// The choices and the report of Pernot's curvature-variation filling (curvature_variation.h),
/// in a light header so that command-line parsers and reports need not include the solver.

#include <cmath>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

/// Pernot eq. 8 (`forces`: sum of squared external forces, a membrane) or eq. 9
/// (`force_variation`: sum of squared differences of the forces of connected nodes, which
/// simulates the curvature variation).
enum class Curvature_objective { forces, force_variation };

/// The nodes whose forces are summed in the objective (Pernot Fig. 9-10): the free nodes only, or
/// the free nodes and the hole-contour nodes (reaches one more ring of the surrounding mesh:
/// tangency for `forces`, curvature continuity for `force_variation`). Contour nodes are blocked
/// in both cases (Pernot 6.2): they enter the sum, they never move.
enum class Objective_nodes { free_nodes, free_and_contour_nodes };

/// The topology of the inner mesh (Pernot 5): the stretched unit disc with Delaunay-connected
/// interior vertices, or Liepa's triangulation refined to the surrounding density.
enum class Topological_grid { disc, refined_liepa };

/// Force densities q of the bars (Pernot 6.1): all 1; the inverse of the bar length (bars with
/// a free end, whose length is unknown, take the inverse of the mean contour edge length); or
/// the cotangent weight (cot a + cot b) / 2 of the bar measured on the initial positions (the
/// stretched grid or Liepa's refined triangulation), clamped below at 1/20 of the mean, with
/// which the equilibrium force is the area-weighted mean-curvature normal.
enum class Force_density { uniform, inverse_length, cotangent };

inline const char* to_string(Curvature_objective o) {
  return o == Curvature_objective::forces ? "forces" : "force_variation";
}
inline const char* to_string(Objective_nodes n) {
  return n == Objective_nodes::free_nodes ? "free" : "free_and_contour";
}
inline const char* to_string(Topological_grid g) {
  return g == Topological_grid::disc ? "disc" : "refined_liepa";
}
inline const char* to_string(Force_density d) {
  switch (d) {
    case Force_density::uniform:
      return "uniform";
    case Force_density::inverse_length:
      return "inverse_length";
    case Force_density::cotangent:
      return "cotangent";
  }
  return "unknown";
}

inline bool curvature_objective_from_string(const std::string& s, Curvature_objective& o) {
  if (s == "forces")
    o = Curvature_objective::forces;
  else if (s == "force_variation")
    o = Curvature_objective::force_variation;
  else
    return false;
  return true;
}
inline bool objective_nodes_from_string(const std::string& s, Objective_nodes& n) {
  if (s == "free")
    n = Objective_nodes::free_nodes;
  else if (s == "free_and_contour")
    n = Objective_nodes::free_and_contour_nodes;
  else
    return false;
  return true;
}
inline bool topological_grid_from_string(const std::string& s, Topological_grid& g) {
  if (s == "disc")
    g = Topological_grid::disc;
  else if (s == "refined_liepa" || s == "liepa")
    g = Topological_grid::refined_liepa;
  else
    return false;
  return true;
}
inline bool force_density_from_string(const std::string& s, Force_density& d) {
  if (s == "uniform")
    d = Force_density::uniform;
  else if (s == "inverse_length")
    d = Force_density::inverse_length;
  else if (s == "cotangent")
    d = Force_density::cotangent;
  else
    return false;
  return true;
}

/// Shape constraints of Pernot 6.4: 3D points the inner mesh must pass through, and polylines
/// the inner mesh must follow (discretised into point constraints every `polyline_spacing`; 0
/// means the mean contour edge length). Each point is attached to the closest point of the
/// unconstrained inner mesh and pulled to its target with a Lagrange multiplier.
template <class Point>
struct Fill_constraints {
  std::vector<Point> points;
  std::vector<std::vector<Point>> polylines;
  double polyline_spacing = 0;
  bool empty() const { return points.empty() && polylines.empty(); }
};

/// Reads constraints in the text format of `mesh_repair fill --constraints FILE`, one per line:
/// \code
/// # a comment; blank lines are ignored
/// point X Y Z                      a point the inner mesh must pass through
/// polyline X1 Y1 Z1 X2 Y2 Z2 ...   a polyline it must follow (at least two points)
/// spacing S                        sample polylines every S model units (default: mean edge)
/// \endcode
/// Returns an empty string on success, else "line N: what is wrong".
template <class Point>
std::string read_fill_constraints(std::istream& in, Fill_constraints<Point>& constraints) {
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword) || keyword[0] == '#') continue;
    std::vector<double> values;
    std::string word;
    while (words >> word) {
      std::size_t used = 0;
      double value = 0;
      try {
        value = std::stod(word, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != word.size() || !std::isfinite(value))
        return "line " + std::to_string(number) + ": '" + word + "' is not a number";
      values.push_back(value);
    }
    auto error = [&](const char* what) { return "line " + std::to_string(number) + ": " + what; };
    if (keyword == "point") {
      if (values.size() != 3) return error("point needs 3 coordinates");
      constraints.points.emplace_back(values[0], values[1], values[2]);
    } else if (keyword == "polyline") {
      if (values.size() < 6 || values.size() % 3 != 0)
        return error("polyline needs at least 2 points of 3 coordinates");
      std::vector<Point> polyline;
      for (std::size_t k = 0; k < values.size(); k += 3)
        polyline.emplace_back(values[k], values[k + 1], values[k + 2]);
      constraints.polylines.push_back(polyline);
    } else if (keyword == "spacing") {
      if (values.size() != 1 || values[0] <= 0) return error("spacing needs one positive length");
      constraints.polyline_spacing = values[0];
    } else {
      return error("expected 'point', 'polyline' or 'spacing'");
    }
  }
  return {};
}

/// What the single deformation step (Pernot 6) did, for all holes together.
struct Curvature_deformation_report {
  bool solved = false;
  bool cancelled = false;
  std::string failure;               ///< why the system could not be solved (empty when solved)
  std::size_t free_vertices = 0;     ///< unknown positions (3 coordinates each)
  std::size_t contour_vertices = 0;  ///< blocked vertices of the inner meshes
  std::size_t objective_terms = 0;   ///< squared forces or force differences summed
  std::size_t system_nonzeros = 0;   ///< of the symmetric matrix factorised
  std::size_t factor_nonzeros = 0;   ///< of its LDL^T factor (nested-dissection order)
  std::size_t factorizations = 0;    ///< sparse factorisations (1 per call)
  std::size_t constraints_applied = 0;
  std::size_t constraints_dropped = 0;  ///< attached only to blocked vertices, cannot move
  double max_constraint_residual = 0;   ///< model units
  /// Times the force densities and areas were re-measured on the solved shape (1 by default).
  std::size_t weight_remeasurements = 0;
  /// Conjugate-gradient iterations of the re-measured system, preconditioned with the
  /// factorisation of the first (summed over the coordinates).
  std::size_t preconditioned_iterations = 0;
  double assembly_seconds = 0, factorization_seconds = 0, solve_seconds = 0;
};

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_HOLE_FILLING_CURVATURE_VARIATION_OPTIONS_H
