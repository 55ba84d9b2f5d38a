// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_STL_READER_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_STL_READER_H

// A strict STL reader. A file of exactly 84 + 50 n bytes, n being the count at byte 80, is
// binary even when it begins with "solid" (many exporters write that); any other file that
// begins with "solid" is ASCII, read word by word (any whitespace, keywords in any case,
// several solids, loops of three or more vertices). Identical points are merged as read, as
// CGAL's reader does, so a triangle soup becomes an indexed one.

#include <CGAL/Mesh_repair/internal/readers/byte_reader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace readers {

// Indexes points by their coordinates (0 and -0 are the same point).
template <class Point>
class Point_indexer {
 public:
  explicit Point_indexer(std::vector<Point>& points) : points_(points) {}
  std::size_t index(double x, double y, double z) {
    const Key key = {x + 0.0, y + 0.0, z + 0.0};
    const auto inserted = map_.emplace(key, points_.size());
    if (inserted.second) points_.emplace_back(x, y, z);
    return inserted.first->second;
  }

 private:
  using Key = std::array<double, 3>;
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (double d : k) {
        std::uint64_t bits;
        std::memcpy(&bits, &d, 8);
        h = (h ^ bits) * 1099511628211ull;
        h ^= h >> 29;
      }
      return std::size_t(h);
    }
  };
  std::vector<Point>& points_;
  std::unordered_map<Key, std::size_t, Hash> map_;
};

// True when the first word (after a UTF-8 byte order mark and any whitespace) is "solid", in
// any case.
inline bool stl_starts_with_solid(Byte_reader& in) {
  int c = in.get();
  if (c == 0xEF) {
    if (in.get() != 0xBB || in.get() != 0xBF) return false;
    c = in.get();
  }
  for (int skipped = 0; c == ' ' || c == '\t' || c == '\r' || c == '\n'; ++skipped) {
    if (skipped > 4096) return false;
    c = in.get();
  }
  for (const char* s = "solid"; *s; ++s, c = in.get())
    if (c < 0 || std::tolower(c) != *s) return false;
  return c < 0 || c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

template <class Point>
void read_stl_binary(Byte_reader& in, std::uint32_t triangles, std::vector<Point>& points,
                     std::vector<std::vector<std::size_t>>& polygons, Read_counts&) {
  in.refuse_zero_chunks();
  Point_indexer<Point> indexer(points);
  polygons.reserve(triangles);
  unsigned char record[50];
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const std::uintmax_t at = in.offset();
    if (!in.read(record, 50))
      fail_at_offset(at, "the file ends inside triangle " + std::to_string(t));
    std::vector<std::size_t> triangle(3);
    for (int v = 0; v < 3; ++v) {
      double c[3];
      for (int i = 0; i < 3; ++i) {
        const unsigned char* b = record + 12 + 12 * v + 4 * i;
        const std::uint32_t bits = std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8) |
                                   (std::uint32_t(b[2]) << 16) | (std::uint32_t(b[3]) << 24);
        float f;
        std::memcpy(&f, &bits, 4);
        c[i] = double(f);
        if (!std::isfinite(c[i]))
          fail_at_offset(at, "triangle " + std::to_string(t) + " has a non-finite coordinate");
      }
      triangle[v] = indexer.index(c[0], c[1], c[2]);
    }
    polygons.push_back(std::move(triangle));
  }
}

// The words of an ASCII STL file, with the line each is on.
class Stl_words {
 public:
  explicit Stl_words(Byte_reader& in) : in_(in), words_(line_) {}
  /// The next word (empty at the end of the file).
  std::string_view next() {
    while (words_.at_end()) {
      if (!in_.read_line(line_)) return {};
      words_ = Tokens(line_);
    }
    return words_.next();
  }
  /// The next word if it is on the current line, else an empty string.
  std::string_view next_on_line() { return words_.at_end() ? std::string_view() : words_.next(); }
  std::uintmax_t line() const { return in_.line(); }
  void expect(const char* keyword) {
    const std::string_view word = next();
    if (!same(word, keyword))
      fail_at_line(line(), std::string("expected '") + keyword + "', found " +
                               (word.empty() ? std::string("the end of the file") : quoted(word)));
  }
  static bool same(std::string_view word, const char* keyword) {
    const std::size_t n = std::strlen(keyword);
    if (word.size() != n) return false;
    for (std::size_t i = 0; i < n; ++i)
      if (std::tolower(static_cast<unsigned char>(word[i])) != keyword[i]) return false;
    return true;
  }

 private:
  Byte_reader& in_;
  std::string line_;
  Tokens words_;
};

template <class Point>
void read_stl_ascii(Byte_reader& in, std::vector<Point>& points,
                    std::vector<std::vector<std::size_t>>& polygons, Read_counts& counts) {
  Point_indexer<Point> indexer(points);
  Stl_words words(in);
  std::vector<std::size_t> polygon;
  std::string_view word = words.next();
  bool solid = false;
  while (true) {
    if (word.empty()) {
      if (!solid) fail_at_line(words.line(), "no 'solid' in an ASCII STL file");
      return;  // a missing endsolid after a complete facet is tolerated
    }
    if (Stl_words::same(word, "solid") || Stl_words::same(word, "endsolid")) {
      solid = solid || Stl_words::same(word, "solid");
      // The solid's name: the rest of its line, unless the facets follow on the same line.
      for (word = words.next_on_line(); !word.empty(); word = words.next_on_line())
        if (Stl_words::same(word, "facet") || Stl_words::same(word, "endsolid") ||
            Stl_words::same(word, "solid"))
          break;
      if (!word.empty()) continue;
    } else if (Stl_words::same(word, "facet")) {
      if (!solid) fail_at_line(words.line(), "'facet' before 'solid'");
      words.expect("normal");
      for (int i = 0; i < 3; ++i) {
        const std::string_view n = words.next();
        double value;
        if (!parse_double(n, value))
          fail_at_line(words.line(), "expected a normal coordinate, found " + quoted(n));
      }
      words.expect("outer");
      words.expect("loop");
      polygon.clear();
      for (word = words.next(); Stl_words::same(word, "vertex"); word = words.next()) {
        double c[3];
        for (int i = 0; i < 3; ++i)
          c[i] = coordinate(words.next(), words.line(), "vertex coordinate");
        polygon.push_back(indexer.index(c[0], c[1], c[2]));
        check_polygon_size(polygon.size(), words.line(), 0);
      }
      if (!Stl_words::same(word, "endloop"))
        fail_at_line(words.line(),
                     "expected 'vertex' or 'endloop', found " +
                         (word.empty() ? std::string("the end of the file") : quoted(word)));
      words.expect("endfacet");
      if (polygon.size() < 3)
        ++counts.short_polygons;
      else
        polygons.push_back(polygon);
    } else {
      fail_at_line(words.line(), "expected 'facet' or 'endsolid', found " + quoted(word));
    }
    word = words.next();
  }
}

/// Reads an STL file into a soup; throws Parse_error.
template <class Point>
void read_stl(Byte_reader& in, std::vector<Point>& points,
              std::vector<std::vector<std::size_t>>& polygons, Read_counts& counts) {
  const std::uintmax_t size = in.size();
  unsigned char head[84];
  const bool solid = stl_starts_with_solid(in);
  in.rewind();
  std::uint32_t triangles = 0;
  bool have_count = false;
  if (size >= 84 && in.read(head, 84)) {
    triangles = std::uint32_t(head[80]) | (std::uint32_t(head[81]) << 8) |
                (std::uint32_t(head[82]) << 16) | (std::uint32_t(head[83]) << 24);
    have_count = true;
  }
  const std::uintmax_t binary_size = 84 + 50 * std::uintmax_t(triangles);
  if (have_count && (binary_size == size || (!solid && binary_size < size))) {
    read_stl_binary(in, triangles, points, polygons, counts);
    return;
  }
  // "solid" followed by zero bytes is a binary file whose count is wrong.
  const bool zero_byte = have_count && std::find(head, head + 84, 0) != head + 84;
  if (!solid || zero_byte) {
    if (!have_count)
      fail_at_offset(0,
                     "not an ASCII STL (no 'solid') and shorter than a binary STL's 84-byte "
                     "header");
    fail_at_offset(80, "binary STL declares " + std::to_string(triangles) + " triangles (" +
                           std::to_string(binary_size) + " bytes) but the file has " +
                           std::to_string(size) + " bytes (truncated or corrupt)");
  }
  in.rewind();
  read_stl_ascii(in, points, polygons, counts);
}

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_STL_READER_H
