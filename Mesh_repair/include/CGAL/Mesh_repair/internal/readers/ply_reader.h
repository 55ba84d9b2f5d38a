// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_PLY_READER_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_PLY_READER_H

// A strict PLY reader: ASCII, binary little- and big-endian. The header is checked completely
// before any record is read (a property outside an element, an unknown type, a list where a
// coordinate must be a number, counts the file cannot hold). Vertices need scalar x, y, z of
// any type; faces a list `vertex_indices` (or `vertex_index`) of an integer type; `tristrips`
// (lists with -1 between strips) become triangles. Every other element and property is read
// by its declared type and skipped. ASCII records are one per line; fields after the declared
// ones are ignored (several exporters write them).

#include <CGAL/Mesh_repair/internal/readers/byte_reader.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace readers {

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline bool ply_type(std::string_view name, Ply_type& type) {
  static const struct {
    const char* name;
    Ply_type type;
  } types[] = {
      {"char", Ply_type::int8},      {"int8", Ply_type::int8},       {"uchar", Ply_type::uint8},
      {"uint8", Ply_type::uint8},    {"short", Ply_type::int16},     {"int16", Ply_type::int16},
      {"ushort", Ply_type::uint16},  {"uint16", Ply_type::uint16},   {"int", Ply_type::int32},
      {"int32", Ply_type::int32},    {"uint", Ply_type::uint32},     {"uint32", Ply_type::uint32},
      {"float", Ply_type::float32},  {"float32", Ply_type::float32}, {"double", Ply_type::float64},
      {"float64", Ply_type::float64}};
  for (const auto& t : types)
    if (name == t.name) {
      type = t.type;
      return true;
    }
  return false;
}

inline std::size_t ply_size(Ply_type t) {
  switch (t) {
    case Ply_type::int8:
    case Ply_type::uint8:
      return 1;
    case Ply_type::int16:
    case Ply_type::uint16:
      return 2;
    case Ply_type::int32:
    case Ply_type::uint32:
    case Ply_type::float32:
      return 4;
    case Ply_type::float64:
      return 8;
  }
  return 1;
}

inline bool ply_integer(Ply_type t) {
  return t != Ply_type::float32 && t != Ply_type::float64;
}

struct Ply_property {
  std::string name;
  bool list = false;
  Ply_type count_type = Ply_type::uint8;
  Ply_type type = Ply_type::float32;
};

struct Ply_element {
  std::string name;
  std::uintmax_t count = 0;
  std::uintmax_t header_line = 0;
  std::vector<Ply_property> properties;
  /// Index of a property by name, or -1.
  int find(const char* wanted) const {
    for (std::size_t i = 0; i < properties.size(); ++i)
      if (properties[i].name == wanted) return int(i);
    return -1;
  }
};

enum class Ply_format { ascii, little_endian, big_endian };

struct Ply_header {
  Ply_format format = Ply_format::ascii;
  std::vector<Ply_element> elements;
  std::uintmax_t vertices = 0;
  std::uintmax_t data_offset = 0;
};

inline void parse_ply_property(Tokens& words, Ply_header& h, std::uintmax_t line) {
  if (h.elements.empty()) fail_at_line(line, "'property' before any 'element'");
  Ply_property p;
  std::string_view word = words.next();
  if (word == "list") {
    p.list = true;
    const std::string_view count = words.next();
    if (!ply_type(count, p.count_type))
      fail_at_line(line, "unknown list count type " + quoted(count));
    if (!ply_integer(p.count_type)) fail_at_line(line, "a list count type must be an integer type");
    word = words.next();
  }
  if (!ply_type(word, p.type)) fail_at_line(line, "unknown property type " + quoted(word));
  const std::string_view name = words.next();
  if (name.empty()) fail_at_line(line, "a property without a name");
  p.name = std::string(name);
  h.elements.back().properties.push_back(p);
}

// Checks what the soup needs from the vertex, face and tristrips elements.
inline void check_ply_elements(Ply_header& h) {
  bool vertex = false;
  for (const Ply_element& e : h.elements) {
    if (e.name == "vertex") {
      if (vertex) fail_at_line(e.header_line, "a second 'vertex' element");
      vertex = true;
      h.vertices = e.count;
      for (const char* axis : {"x", "y", "z"}) {
        const int i = e.find(axis);
        if (i < 0)
          fail_at_line(e.header_line,
                       std::string("the vertex element has no '") + axis + "' property");
        if (e.properties[i].list)
          fail_at_line(e.header_line,
                       std::string("vertex property '") + axis + "' is a list, not a number");
      }
    } else if (e.name == "face" || e.name == "tristrips") {
      int i = e.find("vertex_indices");
      if (i < 0 && e.name == "face") i = e.find("vertex_index");
      if (i < 0) {
        if (e.count == 0) continue;
        fail_at_line(e.header_line, "the " + e.name + " element has no 'vertex_indices' list");
      }
      if (!e.properties[i].list)
        fail_at_line(e.header_line,
                     "'" + e.properties[i].name + "' of " + e.name + " is not a list");
      if (!ply_integer(e.properties[i].type))
        fail_at_line(e.header_line,
                     "'" + e.properties[i].name + "' of " + e.name + " is not of an integer type");
    }
  }
}

// The fewest bytes a record of `e` takes.
inline std::uintmax_t ply_min_record_bytes(const Ply_element& e, Ply_format format) {
  std::uintmax_t bytes = 0;
  for (const Ply_property& p : e.properties)
    bytes += format == Ply_format::ascii ? 2 : ply_size(p.list ? p.count_type : p.type);
  return std::max<std::uintmax_t>(bytes, 1);
}

inline Ply_header read_ply_header(Byte_reader& in, Read_counts& counts) {
  Ply_header h;
  std::string line;
  if (!in.read_line(line) || Tokens(line).next() != "ply" || !Tokens(line).rest().substr(3).empty())
    fail_at_line(1, "not a PLY file (no 'ply' magic line)");
  bool format = false;
  while (true) {
    if (!in.read_line(line)) fail_at_line(in.line(), "the header has no 'end_header'");
    const std::uintmax_t at = in.line();
    Tokens words(line);
    const std::string_view keyword = words.next();
    if (keyword == "end_header") break;
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
    if (keyword == "format") {
      if (format) fail_at_line(at, "a second 'format' line");
      const std::string_view name = words.next();
      if (name == "ascii")
        h.format = Ply_format::ascii;
      else if (name == "binary_little_endian")
        h.format = Ply_format::little_endian;
      else if (name == "binary_big_endian")
        h.format = Ply_format::big_endian;
      else
        fail_at_line(at, "unknown format " + quoted(name));
      format = true;
    } else if (keyword == "element") {
      if (!format) fail_at_line(at, "'element' before 'format'");
      Ply_element e;
      e.name = std::string(words.next());
      const std::string_view count = words.next();
      long long n = 0;
      if (e.name.empty() || !parse_integer(count, n) || n < 0 || n > (1ll << 40))
        fail_at_line(at, "invalid element count " + quoted(count));
      e.count = std::uintmax_t(n);
      e.header_line = at;
      h.elements.push_back(e);
    } else if (keyword == "property") {
      parse_ply_property(words, h, at);
    } else if (h.elements.empty()) {
      // Free text before the elements, like a comment: Blender 2.4x wrote "Created by ..."
      // there. Within the elements an unknown line may be a misspelt declaration: refused.
      ++counts.header_lines_skipped;
    } else {
      fail_at_line(at, "unknown header line " + quoted(keyword));
    }
  }
  if (!format) fail_at_line(in.line(), "the header has no 'format' line");
  h.data_offset = in.offset();
  check_ply_elements(h);
  std::uintmax_t needed = 0;
  const std::uintmax_t available = in.size() - h.data_offset;
  for (const Ply_element& e : h.elements) {
    const std::uintmax_t bytes = ply_min_record_bytes(e, h.format);
    // Saturating: a count times a record size beyond the file is enough to refuse it.
    needed =
        e.count > 0 && bytes > (available + 1) / e.count ? available + 1 : needed + e.count * bytes;
    if (needed > available) break;
  }
  if (needed > available)
    fail_at_line(in.line(), "the header declares more records than the " +
                                std::to_string(available) +
                                " bytes after it can hold (truncated or corrupt)");
  return h;
}

// One record's values, ASCII or binary, read in order.
class Ply_record_reader {
 public:
  Ply_record_reader(Byte_reader& in, Ply_format format) : in_(in), format_(format) {}

  /// Starts a record (for ASCII: reads its line).
  void start() {
    record_offset_ = in_.offset();
    if (format_ != Ply_format::ascii) return;
    do {
      if (!in_.read_line(line_))
        fail_at_line(in_.line() + 1, "the file ends before all records are read");
      words_ = Tokens(line_);
    } while (words_.at_end());
  }
  double number(Ply_type type) {
    if (format_ == Ply_format::ascii) {
      const std::string_view word = words_.next();
      double value = 0;
      if (word.empty()) fail("the record has fewer values than its element declares");
      if (!parse_double(word, value)) fail("expected a number, found " + quoted(word));
      return value;
    }
    return binary(type);
  }
  long long integer(Ply_type type) {
    if (format_ == Ply_format::ascii) {
      const std::string_view word = words_.next();
      long long value = 0;
      if (word.empty()) fail("the record has fewer values than its element declares");
      if (!parse_integer(word, value)) fail("expected an integer, found " + quoted(word));
      return value;
    }
    return (long long)binary(type);
  }
  [[noreturn]] void fail(const std::string& reason) {
    if (format_ == Ply_format::ascii) fail_at_line(in_.line(), reason);
    fail_at_offset(record_offset_, reason);
  }

 private:
  double binary(Ply_type type) {
    // Zeroed for GCC's -Wmaybe-uninitialized, which cannot see that read() fills the first n.
    unsigned char b[8] = {};
    const std::size_t n = ply_size(type);
    if (!in_.read(b, n)) fail("the file ends inside a record");
    if (format_ == Ply_format::big_endian) std::reverse(b, b + n);  // to little-endian
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < n; ++i) bits |= std::uint64_t(b[i]) << (8 * i);
    switch (type) {
      case Ply_type::int8:
        return double(std::int8_t(bits));
      case Ply_type::uint8:
        return double(std::uint8_t(bits));
      case Ply_type::int16:
        return double(std::int16_t(bits));
      case Ply_type::uint16:
        return double(std::uint16_t(bits));
      case Ply_type::int32:
        return double(std::int32_t(bits));
      case Ply_type::uint32:
        return double(std::uint32_t(bits));
      case Ply_type::float32: {
        const std::uint32_t b32 = std::uint32_t(bits);
        float f;
        std::memcpy(&f, &b32, 4);
        return double(f);
      }
      case Ply_type::float64: {
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
      }
    }
    return 0;
  }

  Byte_reader& in_;
  Ply_format format_;
  std::string line_;
  Tokens words_{line_};
  std::uintmax_t record_offset_ = 0;
};

// The length of a list, checked: not negative, and within `limit`.
inline std::size_t ply_list_length(Ply_record_reader& r, const Ply_property& p,
                                   std::uintmax_t limit) {
  const long long n = r.integer(p.count_type);
  if (n < 0) r.fail("negative list length " + std::to_string(n));
  if (std::uintmax_t(n) > limit)
    r.fail("a list of " + std::to_string(n) + " values exceeds the limit of " +
           std::to_string(limit));
  return std::size_t(n);
}

inline std::size_t ply_index(Ply_record_reader& r, Ply_type type, std::uintmax_t vertices,
                             bool strip) {
  const long long index = r.integer(type);
  if (strip && index == -1) return std::size_t(-1);
  if (index < 0 || std::uintmax_t(index) >= vertices)
    r.fail("vertex index " + std::to_string(index) + " out of range (" + std::to_string(vertices) +
           " vertices)");
  return std::size_t(index);
}

// Triangles of one strip (orientation alternating); joining triangles with a repeated
// vertex are strip encoding, not faces, and are skipped.
inline void ply_strip_triangles(const std::vector<std::size_t>& strip,
                                std::vector<std::vector<std::size_t>>& polygons) {
  for (std::size_t i = 0; i + 2 < strip.size(); ++i) {
    std::size_t a = strip[i], b = strip[i + 1];
    const std::size_t c = strip[i + 2];
    if (a == b || b == c || a == c) continue;
    if (i % 2 == 1) std::swap(a, b);
    polygons.push_back({a, b, c});
  }
}

template <class Point>
void read_ply_element(Ply_record_reader& r, const Ply_header& h, const Ply_element& e,
                      std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons,
                      Read_counts& counts, std::uintmax_t bytes_left) {
  const bool vertex = e.name == "vertex", strip = e.name == "tristrips";
  int axes[3] = {-1, -1, -1}, indices = -1;
  if (vertex) {
    axes[0] = e.find("x"), axes[1] = e.find("y"), axes[2] = e.find("z");
    points.reserve(std::size_t(e.count));
  } else if (e.name == "face" || strip) {
    indices = e.find("vertex_indices");
    if (indices < 0 && !strip) indices = e.find("vertex_index");
    if (!strip && indices >= 0) {
      const Ply_property& p = e.properties[std::size_t(indices)];
      const std::uintmax_t triangle_bytes =
          ply_min_record_bytes(e, h.format) +
          (h.format == Ply_format::ascii ? 6 : 3 * ply_size(p.type));
      polygons.reserve(polygons.size() +
                       std::size_t(std::min(e.count, bytes_left / triangle_bytes)));
    }
  }
  std::vector<std::size_t> polygon;
  for (std::uintmax_t k = 0; k < e.count; ++k) {
    r.start();
    double c[3] = {0, 0, 0};
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const Ply_property& p = e.properties[i];
      if (!p.list) {
        const double value = r.number(p.type);
        for (int a = 0; a < 3; ++a)
          if (int(i) == axes[a]) c[a] = value;
        continue;
      }
      if (int(i) == indices) {
        const std::size_t n = ply_list_length(r, p, strip ? bytes_left : max_polygon_vertices);
        polygon.clear();
        for (std::size_t j = 0; j < n; ++j) {
          const std::size_t index = ply_index(r, p.type, h.vertices, strip);
          if (index != std::size_t(-1)) {
            polygon.push_back(index);
          } else {
            ply_strip_triangles(polygon, polygons);
            polygon.clear();
          }
        }
        if (strip)
          ply_strip_triangles(polygon, polygons);
        else if (n < 3)
          ++counts.short_polygons;
        else
          polygons.push_back(polygon);
        continue;
      }
      const std::size_t n = ply_list_length(r, p, bytes_left);
      for (std::size_t j = 0; j < n; ++j) r.number(p.type);
    }
    if (vertex) {
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
        r.fail("vertex " + std::to_string(k) + " has a non-finite coordinate");
      points.emplace_back(c[0], c[1], c[2]);
    }
  }
}

/// Reads a PLY file into a soup; throws Parse_error.
template <class Point>
void read_ply(Byte_reader& in, std::vector<Point>& points,
              std::vector<std::vector<std::size_t>>& polygons, Read_counts& counts) {
  const Ply_header h = read_ply_header(in, counts);
  Ply_record_reader records(in, h.format);
  if (h.format != Ply_format::ascii) in.refuse_zero_chunks();
  for (const Ply_element& e : h.elements)
    read_ply_element(records, h, e, points, polygons, counts, in.size() - in.offset());
}

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_PLY_READER_H
