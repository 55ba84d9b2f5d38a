// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SOUP_VALIDATION_H
#define CGAL_MESH_REPAIR_INTERNAL_SOUP_VALIDATION_H

// Checks on mesh files before and after our readers (internal/readers/) parse them: the file
// must be a readable, non-empty regular file of a known format, and the soup must have finite
// coordinates, indices in range and at least one face. The readers check every header and
// record themselves; these checks are what holds for every format.

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

inline std::string lower_extension(const std::string& filename) {
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = filename.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

/// "OFF", "OBJ", "STL", "PLY", or empty for an extension we do not handle.
inline std::string format_name(const std::string& filename) {
  const std::string ext = lower_extension(filename);
  if (ext == "off" || ext == "obj" || ext == "stl" || ext == "ply") {
    std::string upper = ext;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return char(std::toupper(c)); });
    return upper;
  }
  return {};
}

/// Checks that `filename` is a readable, non-empty regular file. Returns an empty string when it
/// may be opened, else the one-line reason.
inline std::string precheck_file(const std::string& filename) {
  struct stat info;
  if (::stat(filename.c_str(), &info) != 0) return filename + ": no such file";
  if (S_ISDIR(info.st_mode)) return filename + ": is a directory, not a mesh file";
  if (!S_ISREG(info.st_mode)) return filename + ": not a regular file";
  if (::access(filename.c_str(), R_OK) != 0) return filename + ": cannot be opened for reading";
  if (info.st_size == 0) return filename + ": empty file";
  return {};
}

/// `precheck_file`, and a known mesh format (by extension). Returns an empty string when the
/// file may be handed to a reader.
inline std::string precheck_mesh_file(const std::string& filename) {
  struct stat info;
  if (::stat(filename.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
      format_name(filename).empty())
    return filename + ": unknown format '" + lower_extension(filename) +
           "' (expected .off, .obj, .stl or .ply)";
  return precheck_file(filename);
}

/// The largest coordinate magnitude read: products of two squared lengths (CGAL's closest
/// point on a triangle, squared areas of quality measures) must stay finite in double precision,
/// with room for features smaller than the mesh. Real files stay far below (single-precision STL
/// cannot exceed 3.4e38).
constexpr double max_coordinate_magnitude = 1e60;

/// The smallest extent (largest side of the bounding box) of points that are not all one point,
/// for the same reason: on meshes spanning 1e-90 to 1e-98 those products underflow to zero,
/// CGAL's closest points on triangles become NaN and the exact predicates that compare them
/// raise SIGFPE (found by fuzzing); at 1e-120 the repair decided otherwise than at scale 1.
constexpr double min_extent = 1e-60;

/// Every coordinate finite and at most `max_coordinate_magnitude`, and the points spanning zero or
/// at least `min_extent` (a soup's vertices, or a point set's points); the reason when not.
template <class Point>
std::string validate_points(const std::string& filename, const std::vector<Point>& points) {
  std::array<double, 3> lo{}, hi{};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const std::array<double, 3> c{CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                  CGAL::to_double(p.z())};
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
      std::ostringstream out;
      out << filename << ": vertex " << i << " has a non-finite coordinate (NaN or inf)";
      return out.str();
    }
    const double largest = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
    if (largest > max_coordinate_magnitude) {
      std::ostringstream out;
      out << filename << ": vertex " << i << " has a coordinate of magnitude " << largest
          << ", above 1e60: products of squared lengths would overflow";
      return out.str();
    }
    for (int k = 0; k < 3; ++k) {
      lo[k] = i == 0 ? c[k] : (std::min)(lo[k], c[k]);
      hi[k] = i == 0 ? c[k] : (std::max)(hi[k], c[k]);
    }
  }
  const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if (extent > 0 && extent < min_extent) {
    std::ostringstream out;
    out << filename << ": the points span only " << extent
        << " (the largest side of their bounding box), below 1e-60: products of squared "
           "lengths would underflow; scale the mesh up";
    return out.str();
  }
  return {};
}

/// What a file without faces holds, for its message: lines (OBJ `l`), faces of fewer than
/// three vertices, or points only.
inline std::string what_a_faceless_file_holds(std::size_t points, std::size_t line_statements,
                                              std::size_t short_polygons) {
  std::string held = "only " + std::to_string(points) + " points";
  if (line_statements > 0)
    return held + " and " + std::to_string(line_statements) +
           " line statement(s) (`l`): curves, not a surface";
  if (short_polygons > 0)
    return held + " and " + std::to_string(short_polygons) +
           " face(s) of one or two vertices: points and segments, not a surface";
  return held + ": a point cloud (`mesh_repair mesh-points` meshes one)";
}

/// After reading: every coordinate finite and at most `max_coordinate_magnitude`, every index in
/// range, at least one face. `line_statements` and `short_polygons` (skipped by the reader) say
/// what a file without faces holds.
template <class Point>
std::string validate_soup(const std::string& filename, const std::vector<Point>& points,
                          const std::vector<std::vector<std::size_t>>& polygons,
                          std::size_t line_statements = 0, std::size_t short_polygons = 0) {
  if (polygons.empty() && !points.empty())
    return filename + ": contains no faces (no face with three or more vertices), " +
           what_a_faceless_file_holds(points.size(), line_statements, short_polygons);
  if (polygons.empty())
    return filename + ": contains no faces (no face with three or more vertices)";
  if (points.empty()) return filename + ": contains no vertices";
  const std::string error = validate_points(filename, points);
  if (!error.empty()) return error;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    for (std::size_t index : polygons[f]) {
      if (index >= points.size()) {
        std::ostringstream out;
        out << filename << ": face " << f << " refers to vertex " << index << " but there are only "
            << points.size() << " vertices";
        return out.str();
      }
    }
  }
  return {};
}

/// The temporary file `write_mesh` writes before renaming: same folder, same extension.
inline std::string temporary_name_for(const std::string& filename) {
  const std::size_t slash = filename.find_last_of('/');
  const std::string folder =
      slash == std::string::npos ? std::string() : filename.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? filename : filename.substr(slash + 1);
  return folder + ".tmp-" + std::to_string(::getpid()) + "-" + base;
}

/// The temporary file being written, if any, for a signal handler to remove (async-safe read).
inline char* pending_temporary_file() {
  static char path[4096] = {0};
  return path;
}

inline void register_temporary_file(const std::string& path) {
  char* slot = pending_temporary_file();
  slot[0] = '\0';
  if (path.size() < 4095) std::memcpy(slot, path.c_str(), path.size() + 1);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_SOUP_VALIDATION_H
