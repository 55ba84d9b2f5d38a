// libFuzzer target of read -> soup repair -> mesh -> detect_defects, the path of
// `mesh_repair check`. The first byte chooses the format; the rest is the file.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <cstdlib>
#include <sstream>

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
  MR::Defect_report defects = MR::detect_defects(mesh);
  MR::add_soup_repair_report(defects, report, mesh);
  const std::string text = MR::summary(defects);
  if (text.find("nan") != std::string::npos) std::abort();  // no NaN printed in the report
  std::ostringstream json_text;
  MR::Json_writer json(json_text);
  MR::write_json(json, defects);
  return 0;
}
