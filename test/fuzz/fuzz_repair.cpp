// libFuzzer target of read -> soup repair -> mesh -> automatic_repair, the path of
// `mesh_repair repair` (stitching, slivers, hole filling with every fallback; fuzz_input.h:
// the first byte chooses the format). The result must be a valid mesh, and what the report
// says must be true of the mesh.
#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/boost/graph/helpers.h>

#include "fuzz_input.h"

#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace MR = CGAL::Mesh_repair;
  fuzz_input::Mesh mesh;
  MR::Soup_repair_report report;
  if (!fuzz_input::read_mesh(data, size, mesh, report)) return 0;
  // Meshes of up to `max_faces` faces: the repair's cost grows with the intersecting pairs, up
  // to quadratically in the faces on a self-overlapping fan (the 998 triangles of the 1000-gon
  // star1000_7.off: 1.5 s in the release tool, 15 s under the fuzzer's ASan at -O1, past its
  // 10 s hang timeout). Larger inputs are repaired by the release tool in ctest
  // (test_cli_robustness runs every file of the regression corpus, a hang killed at 60 s).
  constexpr std::size_t max_faces = 500;
  if (num_faces(mesh) > max_faces) return 0;
  const MR::Repair_result result = MR::automatic_repair(mesh, MR::parameters::number_of_threads(1));
  if (result.valid != CGAL::is_valid_polygon_mesh(mesh)) std::abort();
  if (result.closed != CGAL::is_closed(mesh)) std::abort();
  std::vector<fuzz_input::Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  if (result.border_cycles_left != cycles.size()) std::abort();
  return 0;
}
