// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_OFF_READER_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_OFF_READER_H

// A strict OFF reader: the keyword [ST][C][N][4][n]OFF (optional, as in Geomview: then the
// file starts with the counts), optionally BINARY; the counts on the
// keyword's line or after it; '#' comments anywhere; one vertex or face per line (what follows
// the coordinates or the indices, colours or normals, is ignored). Binary OFF is big-endian.

#include <CGAL/Mesh_repair/internal/readers/byte_reader.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace readers {

struct Off_header {
  bool texture = false, colour = false, normals = false, homogeneous = false, binary = false;
  std::size_t dimension = 3;
  std::uintmax_t vertices = 0, faces = 0;
};

// One line without its comment.
inline bool off_line(Byte_reader& in, std::string& line) {
  if (!in.read_line(line)) return false;
  const std::size_t hash = line.find('#');
  if (hash != std::string::npos) line.erase(hash);
  return true;
}

// The keyword: [ST][C][N][4][n]OFF.
inline bool parse_off_keyword(std::string_view word, Off_header& h) {
  std::size_t i = 0;
  auto take = [&](const char* prefix) {
    const std::size_t n = std::strlen(prefix);
    if (word.substr(i, n) != prefix) return false;
    i += n;
    return true;
  };
  h.texture = take("ST");
  h.colour = take("C");
  h.normals = take("N");
  h.homogeneous = take("4");
  const bool dimension_given = take("n");
  if (word.substr(i) != "OFF") return false;
  h.dimension = dimension_given ? 0 : 3;
  return true;
}

inline std::uintmax_t off_count(std::string_view word, std::uintmax_t line, const char* what) {
  long long n = 0;
  if (!parse_integer(word, n) || n < 0)
    fail_at_line(line, std::string("expected the number of ") + what + ", found " + quoted(word));
  return std::uintmax_t(n);
}

// Reads the keyword and the counts; leaves `in` at the first vertex.
inline Off_header read_off_header(Byte_reader& in) {
  Off_header h;
  std::string line;
  bool keyword = false;
  std::vector<std::uintmax_t> numbers;  // [dimension], vertices, faces
  std::size_t wanted = 2;
  while (numbers.size() < wanted) {
    if (!off_line(in, line))
      fail_at_line(in.line(), keyword ? "the OFF header ends before its vertex and face counts"
                                      : "no OFF keyword");
    Tokens words(line);
    if (!keyword) {
      if (words.at_end()) continue;
      const std::string_view word = words.next();
      long long count = 0;
      if (parse_integer(word, count) && count >= 0)
        numbers.push_back(std::uintmax_t(count));  // Geomview's OFF: the keyword is optional
      else if (!parse_off_keyword(word, h))
        fail_at_line(in.line(), "not an OFF file: the first word is " + quoted(word));
      keyword = true;
      wanted = h.dimension == 0 ? 3 : 2;
      if (!words.at_end() && words.rest().substr(0, 6) == "BINARY") {
        words.next();
        h.binary = true;
        if (!words.at_end())
          fail_at_line(in.line(), "unexpected " + quoted(words.next()) + " after OFF BINARY");
        return h;  // the counts are binary too
      }
    }
    while (!words.at_end() && numbers.size() < wanted) {
      const char* what = numbers.size() + 2 == wanted ? "vertices" : "faces";
      if (numbers.size() + 3 == wanted) what = "dimensions";
      numbers.push_back(off_count(words.next(), in.line(), what));
    }
    // The edge count (and anything else) after the face count on its line is ignored.
  }
  if (wanted == 3) {
    if (numbers[0] < 2 || numbers[0] > 16)
      fail_at_line(in.line(),
                   "nOFF dimension " + std::to_string(numbers[0]) + " is not supported (2 to 16)");
    h.dimension = std::size_t(numbers[0]);
  }
  h.vertices = numbers[wanted - 2];
  h.faces = numbers[wanted - 1];
  return h;
}

// Refuses counts the file cannot hold before anything is allocated for them.
inline void check_off_counts(const Off_header& h, std::uintmax_t size, std::uintmax_t line,
                             std::uintmax_t vertex_bytes, std::uintmax_t face_bytes) {
  const std::uintmax_t limit = std::uintmax_t(1) << 40;
  if (h.vertices > limit || h.faces > limit ||
      h.vertices * vertex_bytes + h.faces * face_bytes > size)
    fail_at_line(line, "the header declares " + std::to_string(h.vertices) + " vertices and " +
                           std::to_string(h.faces) + " faces, more than the " +
                           std::to_string(size) +
                           " bytes of the file can hold (truncated or "
                           "corrupt)");
}

template <class Point>
void read_off_ascii(Byte_reader& in, const Off_header& h, std::vector<Point>& points,
                    std::vector<std::vector<std::size_t>>& polygons, Read_counts& counts) {
  const std::size_t coordinates = h.dimension + (h.homogeneous ? 1 : 0);
  check_off_counts(h, in.size(), in.line(), 2 * coordinates, 2);
  points.reserve(std::size_t(h.vertices));
  polygons.reserve(std::size_t(std::min<std::uintmax_t>(h.faces, in.size() / 8)));
  std::string line;
  double c[17];
  while (points.size() < h.vertices) {
    if (!off_line(in, line))
      fail_at_line(in.line(), "the file ends after " + std::to_string(points.size()) + " of " +
                                  std::to_string(h.vertices) + " vertices");
    Tokens words(line);
    if (words.at_end()) continue;
    for (std::size_t i = 0; i < coordinates; ++i) {
      const std::string_view word = words.next();
      if (word.empty())
        fail_at_line(in.line(), "vertex " + std::to_string(points.size()) + " has " +
                                    std::to_string(i) + " coordinates, expected " +
                                    std::to_string(coordinates));
      c[i] = coordinate(word, in.line(), "vertex coordinate");
    }
    if (h.dimension == 2) c[2] = 0;
    if (h.homogeneous) {
      const double w = c[coordinates - 1];
      if (w == 0) fail_at_line(in.line(), "homogeneous vertex coordinate w is 0");
      for (int i = 0; i < 3; ++i) c[i] /= w;
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
        fail_at_line(in.line(), "vertex coordinates overflow once divided by w");
    }
    points.emplace_back(c[0], c[1], c[2]);
  }
  std::uintmax_t faces = 0;
  std::vector<std::size_t> polygon;
  while (faces < h.faces) {
    if (!off_line(in, line))
      fail_at_line(in.line(), "the file ends after " + std::to_string(faces) + " of " +
                                  std::to_string(h.faces) + " faces");
    Tokens words(line);
    if (words.at_end()) continue;
    ++faces;
    const std::string_view first = words.next();
    long long n = 0;
    if (!parse_integer(first, n) || n < 0)
      fail_at_line(in.line(), "expected a face's vertex count, found " + quoted(first));
    check_polygon_size(std::uintmax_t(n), in.line(), 0);
    polygon.clear();
    for (long long i = 0; i < n; ++i) {
      const std::string_view word = words.next();
      long long index = 0;
      if (word.empty())
        fail_at_line(in.line(), "a face declares " + std::to_string(n) + " vertices but lists " +
                                    std::to_string(i));
      if (!parse_integer(word, index))
        fail_at_line(in.line(), "expected a vertex index, found " + quoted(word));
      if (index < 0 || std::uintmax_t(index) >= h.vertices)
        fail_at_line(in.line(), "vertex index " + std::to_string(index) + " out of range (" +
                                    std::to_string(h.vertices) + " vertices)");
      polygon.push_back(std::size_t(index));
    }
    if (n < 3)
      ++counts.short_polygons;
    else
      polygons.push_back(polygon);
  }
}

inline std::uint32_t off_big_endian_u32(Byte_reader& in, const char* what) {
  unsigned char b[4];
  const std::uintmax_t at = in.offset();
  if (!in.read(b, 4)) fail_at_offset(at, std::string("the file ends inside ") + what);
  return (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) |
         std::uint32_t(b[3]);
}

inline double off_big_endian_float(Byte_reader& in, const char* what) {
  const std::uint32_t bits = off_big_endian_u32(in, what);
  float f;
  std::memcpy(&f, &bits, 4);
  return double(f);
}

template <class Point>
void read_off_binary(Byte_reader& in, Off_header h, std::vector<Point>& points,
                     std::vector<std::vector<std::size_t>>& polygons, Read_counts& counts) {
  in.refuse_zero_chunks();
  if (h.dimension == 0) h.dimension = off_big_endian_u32(in, "the dimension");
  if (h.dimension < 2 || h.dimension > 16)
    fail_at_offset(in.offset(), "binary nOFF dimension " + std::to_string(h.dimension) +
                                    " is not supported (2 to 16)");
  h.vertices = off_big_endian_u32(in, "the header");
  h.faces = off_big_endian_u32(in, "the header");
  off_big_endian_u32(in, "the header");  // edges
  const std::size_t coordinates = h.dimension + (h.homogeneous ? 1 : 0);
  const std::size_t extra = (h.normals ? 3 : 0) + (h.colour ? 4 : 0) + (h.texture ? 2 : 0);
  check_off_counts(h, in.size(), 0, 4 * (coordinates + extra), 8);
  points.reserve(std::size_t(h.vertices));
  polygons.reserve(std::size_t(std::min<std::uintmax_t>(h.faces, in.size() / 16)));
  double c[17];
  for (std::uintmax_t v = 0; v < h.vertices; ++v) {
    const std::uintmax_t at = in.offset();
    for (std::size_t i = 0; i < coordinates; ++i) c[i] = off_big_endian_float(in, "a vertex");
    for (std::size_t i = 0; i < extra; ++i) off_big_endian_float(in, "a vertex");
    if (h.dimension == 2) c[2] = 0;
    if (h.homogeneous) {
      const double w = c[coordinates - 1];
      if (w == 0) fail_at_offset(at, "homogeneous vertex coordinate w is 0");
      for (int i = 0; i < 3; ++i) c[i] /= w;
    }
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
      fail_at_offset(at, "vertex " + std::to_string(v) + " has a non-finite coordinate");
    points.emplace_back(c[0], c[1], c[2]);
  }
  std::vector<std::size_t> polygon;
  for (std::uintmax_t f = 0; f < h.faces; ++f) {
    const std::uintmax_t at = in.offset();
    const std::uint32_t n = off_big_endian_u32(in, "a face");
    check_polygon_size(n, 0, at);
    polygon.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t index = off_big_endian_u32(in, "a face");
      if (index >= h.vertices)
        fail_at_offset(at, "face " + std::to_string(f) + ": vertex index " +
                               std::to_string(std::int32_t(index)) + " out of range");
      polygon.push_back(index);
    }
    const std::uint32_t colours = off_big_endian_u32(in, "a face");
    if (colours > 4) fail_at_offset(at, "face colour of " + std::to_string(colours) + " values");
    for (std::uint32_t i = 0; i < colours; ++i) off_big_endian_float(in, "a face");
    if (n < 3)
      ++counts.short_polygons;
    else
      polygons.push_back(polygon);
  }
}

/// Reads an OFF file into a soup; throws Parse_error.
template <class Point>
void read_off(Byte_reader& in, std::vector<Point>& points,
              std::vector<std::vector<std::size_t>>& polygons, Read_counts& counts) {
  const Off_header h = read_off_header(in);
  if (h.binary)
    read_off_binary(in, h, points, polygons, counts);
  else
    read_off_ascii(in, h, points, polygons, counts);
}

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_OFF_READER_H
