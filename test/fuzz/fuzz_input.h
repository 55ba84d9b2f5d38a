// The shared first steps of the whole-pipeline fuzz targets: the first byte chooses the format
// (0 OFF, 1 OBJ, 2 STL, 3 PLY), the rest is the file, read from memory, its soup repaired and
// turned into a mesh, as the tool does.
#ifndef MESH_REPAIR_FUZZ_INPUT_H
#define MESH_REPAIR_FUZZ_INPUT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace fuzz_input {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

/// False when the bytes are not a readable mesh (a result, not a finding).
inline bool read_mesh(const std::uint8_t* data, std::size_t size, Mesh& mesh,
                      CGAL::Mesh_repair::Soup_repair_report& report) {
  namespace MR = CGAL::Mesh_repair;
  if (size < 1) return false;
  static const char* const formats[] = {"OFF", "OBJ", "STL", "PLY"};
  MR::Polygon_soup<Point> soup;
  if (!MR::read_polygon_soup_from_memory(reinterpret_cast<const char*>(data + 1), size - 1,
                                         formats[data[0] % 4], "input", soup)
           .empty())
    return false;
  report = MR::repair_polygon_soup(soup);
  if (soup.polygons.empty()) return false;
  return MR::soup_to_mesh(soup, mesh, true, report).empty();
}

}  // namespace fuzz_input

#endif  // MESH_REPAIR_FUZZ_INPUT_H
