// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_READ_SOUP_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_READ_SOUP_H

// The strict readers behind io.h's read_polygon_soup, one per format, from a file or from
// memory (the fuzz targets). No CGAL reader sees the bytes: CGAL's readers trust their input.
//
// Resources: a file of S bytes is read in 1 MB chunks; what is kept is the soup itself, at
// most about 14 bytes per input byte for faces (a triangle is 56 bytes in memory and takes at
// least 4 bytes of binary PLY or 8 of ASCII OFF/OBJ) and 24 bytes per point; every count a
// header declares is checked against the file size before anything is allocated for it, so a
// truncated or sparse file claiming 10^9 elements is refused at once.

#include <CGAL/Mesh_repair/internal/readers/byte_reader.h>
#include <CGAL/Mesh_repair/internal/readers/obj_reader.h>
#include <CGAL/Mesh_repair/internal/readers/off_reader.h>
#include <CGAL/Mesh_repair/internal/readers/ply_reader.h>
#include <CGAL/Mesh_repair/internal/readers/stl_reader.h>
#include <CGAL/Mesh_repair/internal/readers/xyz_reader.h>

#include <algorithm>
#include <cctype>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace readers {

// The keyword of an ASCII STL, after white space, in any case.
inline bool starts_with_solid(const std::string& text) {
  const std::size_t start = std::min(text.find_first_not_of(" \t\r\n\f\v"), text.size());
  std::string word = text.substr(start, 5);
  for (char& c : word) c = char(std::tolower(static_cast<unsigned char>(c)));
  return word == "solid";
}

/// Reads `in` as `format` ("OFF", "OBJ", "STL", "PLY", or "XYZ": points only) into a soup. Returns
/// an empty string, or one line "NAME: line L: reason" / "NAME: byte B: reason"; the soup is then
/// empty.
template <class Point>
std::string read_soup(Byte_reader& in, const std::string& format, const std::string& name,
                      std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons,
                      Read_counts& counts) {
  points.clear();
  polygons.clear();
  counts = Read_counts();
  std::string error;
  try {
    // A UTF-16 text file is read as its UTF-8 text; a binary STL may start with the same two
    // bytes, so an STL is decoded only when its text starts with "solid".
    std::string utf16_text;
    if (format != "XYZ" && starts_with_utf16_mark(in)) {
      utf16_text = utf16_to_utf8(in);
      if (format == "STL" && !starts_with_solid(utf16_text)) {
        utf16_text.clear();
        in.rewind();
      }
    }
    Byte_reader decoded(utf16_text.data(), utf16_text.size());
    Byte_reader& text = utf16_text.empty() ? in : decoded;
    if (format == "OFF")
      read_off(text, points, polygons, counts);
    else if (format == "OBJ")
      read_obj(text, points, polygons, counts);
    else if (format == "STL")
      read_stl(text, points, polygons, counts);
    else if (format == "PLY")
      read_ply(text, points, polygons, counts);
    else if (format == "XYZ")
      read_xyz(in, points);  // points only
    else
      error = name + ": unknown format '" + format + "'";
  } catch (const Parse_error& e) {
    error = name + ": " +
            (e.line > 0 ? "line " + std::to_string(e.line) : "byte " + std::to_string(e.offset)) +
            ": " + e.reason;
  } catch (const std::bad_alloc&) {
    error = name + ": out of memory while reading";
  } catch (const std::length_error&) {
    error = name + ": out of memory while reading";
  }
  if (!error.empty()) {
    std::vector<Point>().swap(points);
    std::vector<std::vector<std::size_t>>().swap(polygons);
  }
  return error;
}

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_READ_SOUP_H
