// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_OBJ_READER_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_OBJ_READER_H

// A strict Wavefront OBJ reader for the geometry of polygonal faces: `v x y z [w | r g b]`,
// `f` (and the old `fo`) with indices `i`, `i/t`, `i//n` or `i/t/n`, negative (relative)
// indices, '\' line continuations and '#' comments. Every other statement (vt, vn, g, o, s,
// usemtl, mtllib, l, p, curves) is skipped; a line that is no statement is an error.

#include <CGAL/Mesh_repair/internal/readers/byte_reader.h>

#include <cctype>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace readers {

// The next logical line: comments removed, '\' continuations joined. Returns the line number
// where it starts, 0 at the end.
inline std::uintmax_t obj_line(Byte_reader& in, std::string& line, std::string& piece) {
  line.clear();
  std::uintmax_t start = 0;
  while (in.read_line(piece)) {
    if (start == 0) start = in.line();
    const std::size_t hash = piece.find('#');
    if (hash != std::string::npos) piece.erase(hash);
    while (!piece.empty() && Tokens::is_space(piece.back())) piece.pop_back();
    const bool continued = !piece.empty() && piece.back() == '\\';
    if (continued) piece.back() = ' ';
    if (line.size() + piece.size() > max_line_bytes)
      fail_at_line(start, "statement longer than " + std::to_string(max_line_bytes) + " bytes");
    line += piece;
    if (!continued) return start;
  }
  return start;
}

inline bool obj_keyword(std::string_view word) {
  if (word.empty() || !std::isalpha(static_cast<unsigned char>(word[0]))) return false;
  for (char c : word)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// One face corner: the vertex index before any '/', made 0-based (negative = relative).
inline std::size_t obj_index(std::string_view word, std::size_t vertices_so_far,
                             std::uintmax_t line) {
  const std::string_view number = word.substr(0, word.find('/'));
  long long index = 0;
  if (!parse_integer(number, index) || index == 0)
    fail_at_line(line, "expected a vertex index (1-based or negative), found " + quoted(word));
  if (index < 0) {
    if (std::uintmax_t(-(index + 1)) >= vertices_so_far)
      fail_at_line(line, "relative vertex index " + std::to_string(index) + " but only " +
                             std::to_string(vertices_so_far) + " vertices before it");
    return std::size_t(std::intmax_t(vertices_so_far) + index);
  }
  // Forward references are checked once every vertex is read.
  if (std::uintmax_t(index) > (std::uintmax_t(1) << 48))
    fail_at_line(line, "vertex index " + std::to_string(index) + " out of range");
  return std::size_t(index - 1);
}

/// Reads an OBJ file into a soup; throws Parse_error.
template <class Point>
void read_obj(Byte_reader& in, std::vector<Point>& points,
              std::vector<std::vector<std::size_t>>& polygons, Read_counts& counts) {
  std::string line, piece;
  std::vector<std::size_t> polygon;
  std::uintmax_t largest_index_line = 0;
  std::size_t largest_index = 0;
  while (const std::uintmax_t at = obj_line(in, line, piece)) {
    Tokens words(line);
    const std::string_view keyword = words.next();
    if (keyword.empty()) continue;
    if (keyword == "v") {
      double c[3];
      for (int i = 0; i < 3; ++i) {
        const std::string_view word = words.next();
        if (word.empty()) fail_at_line(at, "a vertex needs three coordinates");
        c[i] = coordinate(word, at, "vertex coordinate");
      }
      points.emplace_back(c[0], c[1], c[2]);
    } else if (keyword == "f" || keyword == "fo") {
      polygon.clear();
      for (std::string_view word = words.next(); !word.empty(); word = words.next()) {
        polygon.push_back(obj_index(word, points.size(), at));
        if (polygon.back() >= largest_index) {
          largest_index = polygon.back();
          largest_index_line = at;
        }
        check_polygon_size(polygon.size(), at, 0);
      }
      if (polygon.size() < 3)
        ++counts.short_polygons;
      else
        polygons.push_back(polygon);
    } else if (keyword == "l") {
      ++counts.line_statements;
    } else if (!obj_keyword(keyword)) {
      fail_at_line(at, "not an OBJ statement: " + quoted(keyword));
    }
  }
  if (largest_index_line > 0 && largest_index >= points.size())
    fail_at_line(largest_index_line, "a face refers to vertex " +
                                         std::to_string(largest_index + 1) + " but the file has " +
                                         std::to_string(points.size()) + " vertices");
}

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_OBJ_READER_H
