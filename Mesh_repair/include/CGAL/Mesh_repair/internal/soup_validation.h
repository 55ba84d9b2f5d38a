// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_SOUP_VALIDATION_H
#define CGAL_MESH_REPAIR_INTERNAL_SOUP_VALIDATION_H

// Checks on mesh files before and after CGAL reads them. CGAL's readers trust header counts
// (an OFF header declaring 10^9 vertices makes them allocate for it) and accept NaN
// coordinates and out-of-range indices; a repair tool must refuse such files with one clear line.

#include <algorithm>
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

// Smallest number of bytes a vertex / face record can take in the file, to reject headers that
// declare more elements than the file can hold before any reader allocates for them.
constexpr std::uintmax_t min_vertex_bytes = 6;  // "0 0 0\n" in ASCII; binary needs 12
constexpr std::uintmax_t min_face_bytes = 4;    // "3 0 1 2" needs more; keep the bound loose

inline std::string check_declared_counts(const std::string& filename, std::uintmax_t file_size,
                                         std::uintmax_t vertices, std::uintmax_t faces) {
  if (vertices > file_size / min_vertex_bytes || faces > file_size / min_face_bytes) {
    std::ostringstream out;
    out << filename << ": header declares " << vertices << " vertices and " << faces
        << " faces but the file has only " << file_size << " bytes (truncated or corrupt)";
    return out.str();
  }
  return {};
}

// OFF headers: a keyword containing "OFF" ([ST][C][N][4][n]OFF, optionally "BINARY"), then the
// vertex and face counts; '#' starts a comment.
inline std::string precheck_off(const std::string& filename, std::ifstream& in,
                                std::uintmax_t size) {
  auto is_number = [](const std::string& t) {
    return !t.empty() &&
           std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); });
  };
  std::string token;
  std::vector<std::uintmax_t> counts;
  bool seen_keyword = false;
  while (counts.size() < 2 && in >> token) {
    if (token[0] == '#') {
      std::string rest;
      std::getline(in, rest);
    } else if (!seen_keyword) {
      if (token.find("OFF") == std::string::npos)
        return filename + ": not an OFF file (no OFF keyword)";
      seen_keyword = true;
    } else if (token == "BINARY") {
      return {};  // binary counts follow; CGAL's reader checks them
    } else if (!is_number(token) || token.size() > 18) {
      return filename + ": OFF header expected vertex and face counts, found '" +
             token.substr(0, 40) + "'";
    } else {
      counts.push_back(std::stoull(token));
    }
  }
  if (counts.size() < 2) return filename + ": OFF header is incomplete";
  return check_declared_counts(filename, size, counts[0], counts[1]);
}

// PLY headers: "element vertex N" and "element face N" lines up to "end_header".
inline std::string precheck_ply(const std::string& filename, std::ifstream& in,
                                std::uintmax_t size) {
  std::string line;
  std::getline(in, line);
  if (line.rfind("ply", 0) != 0) return filename + ": not a PLY file (no 'ply' magic)";
  std::uintmax_t vertices = 0, faces = 0;
  for (int lines = 0; std::getline(in, line) && lines < 10000; ++lines) {
    if (line.rfind("end_header", 0) == 0)
      return check_declared_counts(filename, size, vertices, faces);
    std::istringstream words(line);
    std::string keyword, element, count;
    words >> keyword >> element >> count;
    if (keyword != "element") continue;
    if (count.empty() || count.size() > 18 ||
        !std::all_of(count.begin(), count.end(), [](unsigned char c) { return std::isdigit(c); }))
      return filename + ": PLY header has an invalid element count";
    if (element == "vertex") vertices = std::stoull(count);
    if (element == "face") faces = std::stoull(count);
  }
  return filename + ": PLY header has no end_header";
}

// STL: a binary file is 84 bytes plus 50 per triangle; an ASCII one starts with "solid".
inline std::string precheck_stl(const std::string& filename, std::ifstream& in,
                                std::uintmax_t size) {
  char head[84] = {0};
  in.read(head, 84);
  const std::streamsize got = in.gcount();
  std::string start(head, std::size_t(std::min<std::streamsize>(got, 5)));
  bool ascii_candidate = start == "solid";
  if (ascii_candidate) {
    // Binary files may also begin with "solid"; ASCII ones contain "facet" or "endsolid" soon.
    std::string text(head, std::size_t(got));
    std::string more(4096, '\0');
    in.read(&more[0], std::streamsize(more.size()));
    text += more.substr(0, std::size_t(in.gcount()));
    if (text.find("facet") != std::string::npos || text.find("endsolid") != std::string::npos)
      return {};
  }
  if (got < 84) return filename + ": truncated binary STL (shorter than its 84-byte header)";
  std::uint32_t triangles = 0;
  std::memcpy(&triangles, head + 80, 4);
  if (std::uintmax_t(84) + std::uintmax_t(50) * triangles != size) {
    std::ostringstream out;
    out << filename << ": binary STL declares " << triangles << " triangles ("
        << 84 + 50 * std::uintmax_t(triangles) << " bytes) but the file has " << size
        << " bytes (truncated or corrupt)";
    return out.str();
  }
  return {};
}

/// Checks that `filename` is a readable, non-empty regular file of a known format whose header
/// counts fit its size. Returns an empty string when it may be handed to CGAL's reader.
inline std::string precheck_mesh_file(const std::string& filename) {
  struct stat info;
  if (::stat(filename.c_str(), &info) != 0) return filename + ": no such file";
  if (S_ISDIR(info.st_mode)) return filename + ": is a directory, not a mesh file";
  if (!S_ISREG(info.st_mode)) return filename + ": not a regular file";
  const std::string format = format_name(filename);
  if (format.empty())
    return filename + ": unknown format '" + lower_extension(filename) +
           "' (expected .off, .obj, .stl or .ply)";
  std::ifstream in(filename, std::ios::binary);
  if (!in) return filename + ": cannot be opened for reading";
  const std::uintmax_t size = std::uintmax_t(info.st_size);
  if (size == 0) return filename + ": empty file";
  if (format == "OFF") return precheck_off(filename, in, size);
  if (format == "PLY") return precheck_ply(filename, in, size);
  if (format == "STL") return precheck_stl(filename, in, size);
  return {};
}

/// After reading: every coordinate finite, every index in range, at least one face.
template <class Point>
std::string validate_soup(const std::string& filename, const std::vector<Point>& points,
                          const std::vector<std::vector<std::size_t>>& polygons) {
  if (points.empty() || polygons.empty()) return filename + ": contains no faces";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if (!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
        !std::isfinite(CGAL::to_double(p.z()))) {
      std::ostringstream out;
      out << filename << ": vertex " << i << " has a non-finite coordinate (NaN or inf)";
      return out.str();
    }
  }
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
