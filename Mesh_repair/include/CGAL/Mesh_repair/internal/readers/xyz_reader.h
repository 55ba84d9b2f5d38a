// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_XYZ_READER_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_XYZ_READER_H

// XYZ point files (CGAL's .xyz and .pwn): one point per line, its three coordinates and
// optionally a normal (three more numbers, read and left out); blank lines and lines starting
// with '#' are skipped. Strict like the mesh readers: any other line is an error with its number.

#include <CGAL/Mesh_repair/internal/readers/byte_reader.h>

#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace readers {

template <class Point>
void read_xyz(Byte_reader& in, std::vector<Point>& points) {
  std::string line;
  while (in.read_line(line)) {
    Tokens words(line);
    if (words.at_end() || words.rest().front() == '#') continue;
    double values[6];
    int count = 0;
    for (std::string_view word = words.next(); !word.empty(); word = words.next()) {
      if (count == 6) fail_at_line(in.line(), "more than 6 numbers (a point and its normal)");
      if (!parse_double(word, values[count]))
        fail_at_line(in.line(), "expected a number, found " + quoted(word));
      ++count;
    }
    if (count != 3 && count != 6)
      fail_at_line(in.line(), "expected 3 numbers (a point) or 6 (a point and its normal), found " +
                                  std::to_string(count));
    points.emplace_back(values[0], values[1], values[2]);
  }
}

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_XYZ_READER_H
