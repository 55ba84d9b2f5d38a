// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_READERS_XYZ_READER_H
#define CGAL_MESH_REPAIR_INTERNAL_READERS_XYZ_READER_H

// XYZ point files (CGAL's .xyz and .pwn): one point per line, its three coordinates and
// whatever numbers follow (a normal, a colour, an intensity: read and left out); blank lines
// and lines starting with '#' are skipped. Strict like the mesh readers: a line with fewer than
// three numbers, or a word that is not a number, is an error with its line number.

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
    double xyz[3];
    std::size_t count = 0;
    for (std::string_view word = words.next(); !word.empty(); word = words.next(), ++count) {
      double value;
      if (!parse_double(word, value))
        fail_at_line(in.line(), "expected a number, found " + quoted(word));
      if (count < 3) xyz[count] = value;
    }
    if (count < 3)
      fail_at_line(in.line(), "a point needs 3 coordinates, found " + std::to_string(count));
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
}

}  // namespace readers
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_READERS_XYZ_READER_H
