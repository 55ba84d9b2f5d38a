// libFuzzer target of one strict reader (MESH_REPAIR_FUZZ_FORMAT: "OFF", "OBJ", "STL", "PLY"
// or "XYZ", the point files of mesh-points): any bytes must give a soup or one error line, never a
// crash, a hang or a runaway allocation. Built by test/fuzz/CMakeLists.txt (option
// MESH_REPAIR_FUZZ), run by scripts/fuzz.sh.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/internal/readers/read_soup.h>
#include <CGAL/Mesh_repair/internal/soup_validation.h>

#include <cstdint>
#include <cstdlib>

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace R = CGAL::Mesh_repair::internal::readers;
  R::Byte_reader in(reinterpret_cast<const char*>(data), size);
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  R::Read_counts counts;
  std::string error = R::read_soup(in, MESH_REPAIR_FUZZ_FORMAT, "input", points, polygons, counts);
  if (error.empty()) error = CGAL::Mesh_repair::internal::validate_soup("input", points, polygons);
  // The contract: one line, and on success a soup of finite points and indices in range.
  if (error.find('\n') != std::string::npos) std::abort();
  if (error.empty()) {
    for (const auto& polygon : polygons) {
      if (polygon.size() < 3 || polygon.size() > R::max_polygon_vertices) std::abort();
      for (std::size_t i : polygon)
        if (i >= points.size()) std::abort();
    }
  }
  return 0;
}
