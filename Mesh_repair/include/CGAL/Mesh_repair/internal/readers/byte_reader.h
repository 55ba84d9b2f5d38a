// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_BYTE_READER_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_BYTE_READER_H

// What the strict mesh readers share: a byte source (a file read in fixed chunks, or a buffer in
// memory for the fuzz targets) that knows its byte offset and line, the parse error they throw,
// number parsing and the limits that bound their memory and the work after them.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace readers {

/// Polygons with more vertices than this are refused: CGAL's soup repair, orientation and face
/// triangulation are not linear in a polygon's size (measured on one polygon of n distinct
/// points: 0.03 s at n = 3000, 0.8 s + 3.3 s to triangulate at n = 30000; n = 10^6 ran for
/// hours). Real meshes stay far below it (a CAD cap of a cylinder has a few hundred sides).
constexpr std::size_t max_polygon_vertices = 10000;

/// Longest text line accepted (a face of `max_polygon_vertices` indices takes under 200 KB).
constexpr std::size_t max_line_bytes = std::size_t(64) << 20;

/// A file whose never-written regions (holes of the file system, read back as zeros) are more
/// than half of it, and at least 1 MB, is refused before it is read: a preallocated, truncated or
/// sparse file is no mesh, and its zeros would be read as millions of vertices at the origin.
/// The zero-chunk rule of `Byte_reader` catches a whole megabyte of zeros; a file with one
/// written byte every half megabyte passed it and took 2.4 GB and 15 s to refuse.
constexpr std::uintmax_t min_unwritten_bytes = std::uintmax_t(1) << 20;

/// The bytes of the open file `fd` (of `size` bytes) that lie in holes of the file system, and
/// the offset of the first hole (`size` when none). 0 where the system cannot tell (no
/// `SEEK_HOLE`): the file is then read as before. Leaves the file offset at 0.
inline std::uintmax_t unwritten_bytes(int fd, std::uintmax_t size, std::uintmax_t& first_hole) {
  std::uintmax_t holes = 0;
  first_hole = size;
#if defined(SEEK_HOLE) && defined(SEEK_DATA)
  // One step per written region; each step moves forwards by at least one block.
  for (off_t at = 0; std::uintmax_t(at) < size;) {
    const off_t hole = ::lseek(fd, at, SEEK_HOLE);
    if (hole < 0 || std::uintmax_t(hole) >= size) break;
    off_t data = ::lseek(fd, hole, SEEK_DATA);
    if (data < 0 || std::uintmax_t(data) > size) data = off_t(size);  // a hole to the end
    if (data <= hole) break;
    holes += std::uintmax_t(data - hole);
    first_hole = std::min(first_hole, std::uintmax_t(hole));
    at = data;
  }
  ::lseek(fd, 0, SEEK_SET);
#else
  (void)fd;
#endif
  return holes;
}

/// A malformed file: the reason, and where (a line for text formats, else a byte offset).
struct Parse_error {
  std::string reason;
  std::uintmax_t line = 0;    ///< 1-based line of text formats; 0 when unknown
  std::uintmax_t offset = 0;  ///< byte offset, used when `line` is 0
};

[[noreturn]] inline void fail_at_line(std::uintmax_t line, const std::string& reason) {
  Parse_error e;
  e.reason = reason;
  e.line = line;
  throw e;
}

[[noreturn]] inline void fail_at_offset(std::uintmax_t offset, const std::string& reason) {
  Parse_error e;
  e.reason = reason;
  e.offset = offset;
  throw e;
}

/// Bytes of a file or of a memory buffer, read forwards.
class Byte_reader {
 public:
  /// Reads `file` (opened in binary mode) in chunks of 1 MB; `size` is its size in bytes.
  Byte_reader(std::FILE* file, std::uintmax_t size) : file_(file), size_(size), buffer_(1 << 20) {}
  /// Reads a buffer in memory (not copied).
  Byte_reader(const char* data, std::size_t size)
      : size_(size), begin_(data), current_(data), end_(data + size) {}

  std::uintmax_t size() const { return size_; }

  /// Binary readers call this: from then on a whole chunk (1 MB) of zero bytes is an error. No
  /// mesh holds 87000 vertices at the origin in a row; a sparse, preallocated or zero-filled
  /// file does, and is refused after its first megabyte instead of being read to the end.
  void refuse_zero_chunks() { refuse_zero_chunks_ = true; }
  std::uintmax_t offset() const { return consumed_ + std::uintmax_t(current_ - begin_); }
  std::uintmax_t line() const { return line_; }

  /// The next byte without consuming it, or -1 at the end.
  int peek() {
    if (current_ == end_ && !refill()) return -1;
    return static_cast<unsigned char>(*current_);
  }
  int get() {
    if (current_ == end_ && !refill()) return -1;
    const char c = *current_++;
    if (c == '\n') ++line_;
    return static_cast<unsigned char>(c);
  }
  /// Reads `n` bytes; false when the data ends before.
  bool read(void* out, std::size_t n) {
    char* target = static_cast<char*>(out);
    while (n > 0) {
      if (current_ == end_ && !refill()) return false;
      const std::size_t take = std::min<std::size_t>(n, std::size_t(end_ - current_));
      std::memcpy(target, current_, take);
      current_ += take;
      target += take;
      n -= take;
    }
    return true;
  }

  /// Reads one text line into `line`; false at the end of data. A line ends at "\n", "\r\n" or a
  /// lone "\r" (classic Mac files), which is not part of it; a UTF-8 byte order mark at the
  /// start of the file is dropped. A NUL byte or another control character is an error (text
  /// formats never contain one), and so is a line longer than `max_line_bytes`; both are found
  /// before the line is complete, so a sparse file of zeros is refused at its first zero byte.
  bool read_line(std::string& line) {
    line.clear();
    if (peek() < 0) return false;
    while (true) {
      if (current_ == end_ && !refill()) break;
      const char* until = current_;
      for (; until != end_ && *until != '\n' && *until != '\r'; ++until) {
        const unsigned char u = static_cast<unsigned char>(*until);
        if (u < 32 && u != '\t' && u != '\f' && u != '\v')
          fail_at_line(line_ + 1, "unexpected control byte 0x" + hex(u) + " (byte offset " +
                                      std::to_string(consumed_ + std::uintmax_t(until - begin_)) +
                                      ") in a text file");
      }
      if (line.size() + std::size_t(until - current_) > max_line_bytes)
        fail_at_line(line_ + 1, "line longer than " + std::to_string(max_line_bytes) + " bytes");
      line.append(current_, until);
      current_ = until;
      if (until != end_) {
        const char line_end = *current_++;
        if (line_end == '\r' && peek() == '\n') ++current_;  // peek refilled if needed
        break;
      }
    }
    if (line_ == 0 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    ++line_;
    return true;
  }

  /// Starts again from the first byte (files and buffers alike).
  bool rewind() {
    line_ = 0;
    if (!file_) {
      current_ = begin_;
      return true;
    }
    if (std::fseek(file_, 0, SEEK_SET) != 0) return false;
    consumed_ = 0;
    begin_ = current_ = end_ = nullptr;
    return true;
  }

  static std::string hex(unsigned c) {
    const char digits[] = "0123456789abcdef";
    return std::string{digits[(c >> 4) & 15], digits[c & 15]};
  }

 private:
  bool refill() {
    if (!file_) return false;
    consumed_ += std::uintmax_t(end_ - begin_);
    const std::size_t got = std::fread(buffer_.data(), 1, buffer_.size(), file_);
    begin_ = current_ = buffer_.data();
    end_ = begin_ + got;
    if (refuse_zero_chunks_ && got == buffer_.size() &&
        std::all_of(begin_, end_, [](char c) { return c == 0; }))
      fail_at_offset(consumed_,
                     "1 MB of zero bytes (a sparse, preallocated or truncated file, "
                     "not mesh data)");
    return got > 0;
  }

  std::FILE* file_ = nullptr;
  std::uintmax_t size_ = 0;
  std::vector<char> buffer_;
  const char* begin_ = nullptr;
  const char* current_ = nullptr;
  const char* end_ = nullptr;
  std::uintmax_t consumed_ = 0;
  std::uintmax_t line_ = 0;  // lines completed so far
  bool refuse_zero_chunks_ = false;
};

/// Whitespace-separated words of one line, read in order.
class Tokens {
 public:
  explicit Tokens(const std::string& line) : p_(line.data()), end_(line.data() + line.size()) {}
  /// The next word, or an empty string at the end of the line.
  std::string_view next() {
    skip_space();
    const char* start = p_;
    while (p_ != end_ && !is_space(*p_)) ++p_;
    return std::string_view(start, std::size_t(p_ - start));
  }
  bool at_end() {
    skip_space();
    return p_ == end_;
  }
  /// What is left of the line, leading spaces skipped.
  std::string_view rest() {
    skip_space();
    return std::string_view(p_, std::size_t(end_ - p_));
  }
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
  }

 private:
  void skip_space() {
    while (p_ != end_ && is_space(*p_)) ++p_;
  }
  const char* p_;
  const char* end_;
};

/// Shortens a word for an error message.
inline std::string quoted(std::string_view word) {
  std::string text(word.substr(0, 40));
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return "'" + text + (word.size() > 40 ? "...'" : "'");
}

/// A decimal number (strtod syntax without hexadecimal; a leading '+' allowed). False when the
/// word is not entirely a number; non-finite values are parsed and left to the caller.
inline bool parse_double(std::string_view word, double& value) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  if (word.empty()) return false;
  const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
  if (result.ec == std::errc::result_out_of_range && result.ptr == word.data() + word.size()) {
    // Beyond double's range: strtod says whether it overflows (inf, refused later) or
    // underflows (0 or a denormal).
    value = std::strtod(std::string(word).c_str(), nullptr);
    return true;
  }
  return result.ec == std::errc() && result.ptr == word.data() + word.size();
}

/// A signed decimal integer that fits in 64 bits.
inline bool parse_integer(std::string_view word, long long& value) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  if (word.empty()) return false;
  const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
  return result.ec == std::errc() && result.ptr == word.data() + word.size();
}

/// A finite coordinate, else a parse error at `line`.
inline double coordinate(std::string_view word, std::uintmax_t line, const char* what) {
  double value = 0;
  if (!parse_double(word, value))
    fail_at_line(line, std::string("expected a number (") + what + "), found " + quoted(word));
  if (!std::isfinite(value))
    fail_at_line(line, std::string("non-finite ") + what + " " + quoted(word) + " (NaN or inf)");
  return value;
}

/// A polygon's vertex count checked against the limit.
inline void check_polygon_size(std::uintmax_t n, std::uintmax_t line, std::uintmax_t offset) {
  if (n <= max_polygon_vertices) return;
  const std::string reason = "a face of " + std::to_string(n) + " vertices exceeds the limit of " +
                             std::to_string(max_polygon_vertices) + " vertices per face";
  if (line > 0) fail_at_line(line, reason);
  fail_at_offset(offset, reason);
}

/// What a reader produces besides the soup: faces with fewer than three vertices, which are
/// left out of the soup (counted, so the soup report stays complete).
/// True when `in` starts with a UTF-16 byte order mark (FF FE or FE FF: Windows editors save
/// "Unicode" text so); leaves `in` at its first byte.
inline bool starts_with_utf16_mark(Byte_reader& in) {
  unsigned char mark[2];
  const bool read = in.size() >= 2 && in.read(mark, 2);
  if (!in.rewind()) fail_at_offset(0, "cannot seek back to the start of the file");
  return read && ((mark[0] == 0xFF && mark[1] == 0xFE) || (mark[0] == 0xFE && mark[1] == 0xFF));
}

/// The UTF-16 text of `in` (after its byte order mark) as UTF-8, which the text readers read like
/// any other file; 3 bytes of memory per code unit at most. An odd number of bytes is an error.
inline std::string utf16_to_utf8(Byte_reader& in) {
  unsigned char unit[2];
  in.read(unit, 2);
  const bool little_endian = unit[0] == 0xFF;
  if (in.size() % 2 != 0)
    fail_at_offset(in.size() - 1, "a UTF-16 text file of an odd number of bytes (truncated)");
  std::string text;
  text.reserve(std::size_t(in.size() / 2));
  while (in.read(unit, 2)) {
    const unsigned c =
        little_endian ? unit[0] | unsigned(unit[1]) << 8 : unit[1] | unsigned(unit[0]) << 8;
    if (c < 0x80) {
      text += char(c);
    } else if (c < 0x800) {
      text += char(0xC0 | c >> 6);
      text += char(0x80 | (c & 0x3F));
    } else {  // a surrogate half is written as its own 3 bytes: only comments hold such text
      text += char(0xE0 | c >> 12);
      text += char(0x80 | (c >> 6 & 0x3F));
      text += char(0x80 | (c & 0x3F));
    }
  }
  return text;
}

struct Read_counts {
  std::size_t short_polygons = 0;
  /// OBJ line statements (`l`), skipped: a file of curves only is no surface, and says so.
  std::size_t line_statements = 0;
  /// PLY header lines of no known keyword (old Blender exporters wrote "Created by ..."
  /// without `comment`), skipped.
  std::size_t header_lines_skipped = 0;
};

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_BYTE_READER_H
