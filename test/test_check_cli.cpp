// mesh_repair check, run as a user would: exit statuses, the summary, the JSON report's
// top-level keys, counts that include the soup stage, and real meshes against CGAL's count.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "scratch_folder.h"
#include "support/cgal_calls.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return mesh_repair_test::scratch_folder("mesh_repair_test_check_") / name;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Check_run {
  int status;
  std::string out, err;
};

Check_run check(const std::string& arguments) {
  const fs::path out = scratch("stdout.txt"), err = scratch("stderr.txt");
  const std::string command = std::string("timeout 120 ") + MESH_REPAIR_CLI + " check " +
                              arguments + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
}

/// The integer value of a top-level key of the (pretty-printed) JSON report, -1 if absent.
long long json_integer(const std::string& json, const std::string& key) {
  const std::regex pattern("\n  \"" + key + "\": (-?[0-9]+)");
  std::smatch match;
  return std::regex_search(json, match, pattern) ? std::stoll(match[1]) : -1;
}

std::string json_boolean(const std::string& json, const std::string& key) {
  const std::regex pattern("\n  \"" + key + "\": (true|false)");
  std::smatch match;
  return std::regex_search(json, match, pattern) ? std::string(match[1]) : std::string();
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

const char* const closed_tetrahedron =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

TEST(CheckCli, CleanClosedMeshExitsZeroWithEveryTopLevelKey) {
  const fs::path input = scratch("tetra.off"), json = scratch("tetra.json");
  write_file(input, closed_tetrahedron);
  const Check_run run = check(input.string() + " --json " + json.string() + " --quiet");
  EXPECT_EQ(run.status, 0) << run.out << run.err;
  const std::string report = read_text(json);
  for (const char* key :
       {"vertices", "faces", "border_cycles", "non_manifold_edges", "non_manifold_vertices",
        "duplicated_faces", "degenerate_faces", "needles", "caps", "slivers", "small_gaps",
        "t_junctions", "overlaps", "self_intersections", "connected_components"})
    EXPECT_GE(json_integer(report, key), 0) << key;
  EXPECT_EQ(json_integer(report, "vertices"), 4);
  EXPECT_EQ(json_integer(report, "faces"), 4);
  EXPECT_EQ(json_integer(report, "border_cycles"), 0);
  EXPECT_EQ(json_boolean(report, "closed"), "true");
  EXPECT_NE(report.find("\"soup_repair\""), std::string::npos);
  EXPECT_NE(run.out.find("closed"), std::string::npos);
}

TEST(CheckCli, OpenMeshExitsOneAndCountsTheHole) {
  const fs::path input = scratch("open.off"), json = scratch("open.json");
  write_file(input, "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n");
  const Check_run run = check(input.string() + " --json " + json.string());
  EXPECT_EQ(run.status, 1);
  const std::string report = read_text(json);
  EXPECT_EQ(json_integer(report, "border_cycles"), 1);
  EXPECT_EQ(json_boolean(report, "closed"), "false");
}

TEST(CheckCli, SoupStageRepairsAreCountedAsDefects) {
  // The tetrahedron with one face twice and one face reversed.
  const fs::path input = scratch("dirty.off"), json = scratch("dirty.json");
  write_file(input,
             "OFF\n4 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 3 2 1\n3 0 3 2\n"
             "3 0 3 2\n");
  const Check_run run = check(input.string() + " --json " + json.string());
  EXPECT_EQ(run.status, 1);
  const std::string report = read_text(json);
  EXPECT_EQ(json_integer(report, "duplicated_faces"), 1);
  EXPECT_EQ(json_integer(report, "inconsistent_orientation"), 1);
  EXPECT_EQ(json_integer(report, "border_cycles"), 0);
}

TEST(CheckCli, EdgeSharedByThreeTrianglesIsOneNonManifoldEdge) {
  const fs::path input = scratch("fin.off"), json = scratch("fin.json");
  write_file(input,
             "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  const Check_run run = check(input.string() + " --json " + json.string());
  EXPECT_EQ(run.status, 1);
  const std::string report = read_text(json);
  EXPECT_EQ(json_integer(report, "non_manifold_edges"), 1);
  EXPECT_EQ(json_integer(report, "non_manifold_vertices"), 2);
}

TEST(CheckCli, SelfIntersectionsCanBeSkipped) {
  const fs::path input = scratch("cross.off"), json = scratch("cross.json");
  write_file(input,
             "OFF\n6 2 0\n0 0 0\n2 0 0\n0 2 0\n0.5 0.5 -1\n0.5 0.5 1\n1.5 0.5 0.2\n"
             "3 0 1 2\n3 3 4 5\n");
  check(input.string() + " --json " + json.string());
  EXPECT_EQ(json_integer(read_text(json), "self_intersections"), 1);
  check(input.string() + " --json " + json.string() + " --no-self-intersections");
  EXPECT_EQ(json_integer(read_text(json), "self_intersections"), 0);
  EXPECT_EQ(json_boolean(read_text(json), "self_intersections_checked"), "false");
}

TEST(CheckCli, AbsoluteAndRelativeTolerancesReachTheGapTest) {
  // Two unit squares 0.01 apart.
  const fs::path input = scratch("gap.off"), json = scratch("gap.json");
  write_file(input,
             "OFF\n8 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1.01 0 0\n2.01 0 0\n2.01 1 0\n1.01 1 0\n"
             "3 0 1 2\n3 0 2 3\n3 4 5 6\n3 4 6 7\n");
  check(input.string() + " --json " + json.string() + " --tolerance 0.02");
  EXPECT_EQ(json_integer(read_text(json), "small_gaps"), 2);
  check(input.string() + " --json " + json.string() + " --tolerance 0.001");
  EXPECT_EQ(json_integer(read_text(json), "small_gaps"), 0);
  check(input.string() + " --json " + json.string() + " --tolerance-rel 0.01");
  EXPECT_EQ(json_integer(read_text(json), "small_gaps"), 2);
}

TEST(CheckCli, BadUsageExitsTwo) {
  EXPECT_EQ(check("").status, 2);
  EXPECT_EQ(check("a.off b.off").status, 2);
  EXPECT_EQ(check("--tolerance").status, 2);
  const fs::path input = scratch("t.off");
  write_file(input, closed_tetrahedron);
  EXPECT_EQ(check(input.string() + " --tolerance 1 --tolerance-rel 0.1").status, 2);
  EXPECT_EQ(check(input.string() + " --tolerance -1").status, 2);
  EXPECT_EQ(check(input.string() + " --bogus").status, 2);
  EXPECT_EQ(check(scratch("missing.off").string()).status, 2);
  const Check_run unwritable = check(input.string() + " --json /nonexistent-dir/r.json");
  EXPECT_EQ(unwritable.status, 2);
  EXPECT_FALSE(unwritable.err.empty());
}

// Independent count: CGAL reads the file itself (no soup repair) and counts its boundary cycles.
class CheckRealMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(CheckRealMesh, BorderCyclesEqualCgalOnTheFileAsCgalReadsIt) {
  const std::string path = std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/" + GetParam();
  if (!fs::exists(path)) GTEST_SKIP() << path << " absent (scripts/fetch_demo_data.sh)";
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  ASSERT_TRUE(mesh_repair_test::read_polygon_mesh(path, mesh));
  const std::vector<decltype(mesh)::Halfedge_index> cycles =
      mesh_repair_test::boundary_cycles(mesh);
  const fs::path json = scratch("real.json");
  check(path + " --json " + json.string() + " --no-self-intersections --quiet");
  const std::string report = read_text(json);
  EXPECT_EQ(json_integer(report, "border_cycles"), (long long)cycles.size());
  EXPECT_EQ(json_integer(report, "faces"), (long long)mesh.number_of_faces());
  EXPECT_EQ(json_boolean(report, "closed"), cycles.empty() ? "true" : "false");
}

INSTANTIATE_TEST_SUITE_P(DemoMeshes, CheckRealMesh,
                         ::testing::Values("elephant-with-holes.off", "mech-holes-shark.off",
                                           "holes.off", "mesh_with_border.off", "elephant.off",
                                           "bunny00.off", "fandisk.off"));

}  // namespace
