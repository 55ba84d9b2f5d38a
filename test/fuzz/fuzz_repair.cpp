// libFuzzer target of read -> soup repair -> mesh -> automatic_repair, the path of
// `mesh_repair repair` (stitching, slivers, hole filling with every fallback). The first byte
// chooses the format; the rest is the file. The result must be a valid mesh, and a report that
// says closed must be true of the mesh.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstdint>
#include <cstdlib>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace MR = CGAL::Mesh_repair;
  if (size < 1) return 0;
  static const char* const formats[] = {"OFF", "OBJ", "STL", "PLY"};
  const std::string format = formats[data[0] % 4];
  MR::Polygon_soup<Point> soup;
  const std::string error = MR::read_polygon_soup_from_memory(
      reinterpret_cast<const char*>(data + 1), size - 1, format, "input", soup);
  if (!error.empty()) return 0;
  MR::Soup_repair_report report = MR::repair_polygon_soup(soup);
  if (soup.polygons.empty()) return 0;
  Mesh mesh;
  if (!MR::soup_to_mesh(soup, mesh, true, report).empty()) return 0;
  const MR::Repair_result result = MR::automatic_repair(mesh, MR::parameters::number_of_threads(1));
  // What the report says must be true of the mesh.
  if (result.valid != CGAL::is_valid_polygon_mesh(mesh)) std::abort();
  if (result.closed != CGAL::is_closed(mesh)) std::abort();
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  if (result.border_cycles_left != cycles.size()) std::abort();
  return 0;
}
