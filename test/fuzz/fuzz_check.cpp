// libFuzzer target of read -> soup repair -> mesh -> detect_defects, the path of
// `mesh_repair check` (fuzz_input.h: the first byte chooses the format).
#include <CGAL/Mesh_repair/detect_defects.h>

#include "fuzz_input.h"

#include <cstdint>
#include <cstdlib>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace MR = CGAL::Mesh_repair;
  fuzz_input::Mesh mesh;
  MR::Soup_repair_report report;
  if (!fuzz_input::read_mesh(data, size, mesh, report)) return 0;
  MR::Defect_report defects = MR::detect_defects(mesh);
  MR::add_soup_repair_report(defects, report, mesh);
  const std::string text = MR::summary(defects);
  if (text.find("nan") != std::string::npos) std::abort();  // no NaN printed in the report
  std::ostringstream json_text;
  MR::Json_writer json(json_text);
  MR::write_json(json, defects);
  return 0;
}
