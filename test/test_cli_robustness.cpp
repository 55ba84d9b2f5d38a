// The command-line tool on malformed input: exit status 2, one line on stderr, within seconds,
// input untouched.
#include <gtest/gtest.h>

#include "scratch_folder.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <tuple>
#include <unistd.h>

namespace {
namespace fs = std::filesystem;

struct Cli_run {
  int status;
  std::string stderr_text;
  double seconds;
};

fs::path scratch(const std::string& name) {
  return mesh_repair_test::scratch_folder("mesh_repair_test_cli_") / name;
}

const fs::path corpus_dir =
    fs::path(MESH_REPAIR_SOURCE_DIR) / "test" / "fuzz" / "corpus-regression";
const fs::path readers_dir = fs::path(MESH_REPAIR_TEST_DATA_DIR) / "readers";

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Cli_run run_cli(const std::string& arguments, int timeout_seconds = 20) {
  const fs::path err = scratch("stderr.txt");
  // --signal=KILL: a hang shows as a signal (status -1), never as an exit status.
  const std::string command = "timeout --signal=KILL " + std::to_string(timeout_seconds) + " " +
                              MESH_REPAIR_CLI + " " + arguments + " >/dev/null 2>" + err.string();
  const auto start = std::chrono::steady_clock::now();
  const int raw = std::system(command.c_str());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str(), seconds};
}

void write_bytes(const fs::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
}

std::size_t count_lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(CliRobustness, MalformedInputsExitTwoWithOneLine) {
  std::string noise(4096, '\0');
  unsigned state = 12345;
  for (char& c : noise) {
    state = state * 1103515245u + 12345u;
    c = char(state >> 16);
  }
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"empty.off", ""},
      {"truncated.stl",
       std::string(80, 's') + std::string("\xe8\x03\x00\x00", 4) + std::string(120, '\0')},
      {"nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"},
      {"inf.off", "OFF\n3 1 0\n0 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n"},
      {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
      {"huge.off", "OFF\n1000000000 1000000000 0\n0 0 0\n"},
      {"huge.ply",
       "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\n"
       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
       "0 0 0\n"},
      {"negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"},
      {"no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"},
      {"only_degenerate.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 0\n"},
      {"truncated_ascii.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n"},
      {"noise.off", noise},
      {"noise.stl", noise},
      {"noise.ply", noise},
      {"noise.obj", noise},
  };
  for (const auto& c : cases) {
    const fs::path path = scratch(c.first);
    write_bytes(path, c.second);
    const auto before = fs::file_size(path);
    const Cli_run run = run_cli("check " + path.string());
    EXPECT_EQ(run.status, 2) << c.first << ": " << run.stderr_text;
    EXPECT_EQ(count_lines(run.stderr_text), 1u) << c.first << ": " << run.stderr_text;
    EXPECT_LT(run.seconds, 10.0) << c.first;
    EXPECT_EQ(fs::file_size(path), before) << c.first;
  }
}

// Inputs that parse but leave nothing a repair can work on: faces that are all collinear (every
// one removed as degenerate, where the tool used to write a file with no face and exit 1), and
// a mesh spanning less than 1e-60 (its volumes underflow; the repair decided otherwise than on
// the same mesh at scale 1). Both exit 2 with one line and write nothing.
TEST(CliRobustness, InputsWithNothingToRepairExitTwoWithOneLine) {
  const std::string tetrahedron = "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n";
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"collinear.off", "OFF\n4 4 0\n0 0 0\n1 2 3\n2 4 6\n3 6 9\n" + tetrahedron,
       "no face left after repair (faces removed: degenerate faces 4)"},
      {"tiny.off", "OFF\n4 4 0\n0 0 0\n1e-120 0 0\n0 1e-120 0\n0 0 1e-120\n" + tetrahedron,
       "the points span only 1e-120"},
  };
  for (const auto& [name, text, reason] : cases) {
    const fs::path path = scratch(name), out = scratch("out_" + name);
    write_bytes(path, text);
    std::vector<std::string> commands{"repair " + path.string() + " -o " + out.string()};
    if (name == "tiny.off") commands.push_back("check " + path.string());  // refused on reading
    for (const std::string& command : commands) {
      const Cli_run run = run_cli(command);
      EXPECT_EQ(run.status, 2) << command << ": " << run.stderr_text;
      EXPECT_EQ(count_lines(run.stderr_text), 1u) << run.stderr_text;
      EXPECT_NE(run.stderr_text.find(path.string() + ": "), std::string::npos) << run.stderr_text;
      EXPECT_NE(run.stderr_text.find(reason), std::string::npos) << run.stderr_text;
    }
    EXPECT_FALSE(fs::exists(out)) << name;
  }
}

// mesh-points reads point files with the project's strict readers too: CGAL's point readers
// crashed on these PLY headers (a property before any element, a coordinate declared as a list)
// and read a sparse file to its end.
TEST(CliRobustness, MalformedPointFilesExitTwoWithOneLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"property_first.ply",
       "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\nproperty float y\n"
       "end_header\n1 2\n3 4\n5 6\n"},
      {"list_x.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty list uchar float x\nproperty float y\n"
       "property float z\nend_header\n1 2 3 4\n1 2 3 4\n1 2 3 4\n"},
      {"letters.xyz", "0 0 0\n1 0 0\n0 one 0\n"},
      {"two_numbers.xyz", "0 0 0\n1 0\n0 1 0\n"},
      {"two_points.xyz", "0 0 0\n1 0 0\n"},
      {"nan.xyz", "0 0 0\n1 0 0\n0 nan 0\n"},
      {"points.las", "LASF"},
  };
  for (const auto& c : cases) {
    const fs::path path = scratch(c.first);
    write_bytes(path, c.second);
    const Cli_run run =
        run_cli("mesh-points " + path.string() + " -o " + scratch("points_out.off").string());
    EXPECT_EQ(run.status, 2) << c.first << ": " << run.stderr_text;
    EXPECT_EQ(count_lines(run.stderr_text), 1u) << c.first << ": " << run.stderr_text;
    EXPECT_NE(run.stderr_text.find(c.first), std::string::npos) << run.stderr_text;
    EXPECT_FALSE(fs::exists(scratch("points_out.off"))) << c.first;
  }
  // Points with and without normals and other columns, comments, blank lines, tabs and CRLF:
  // read and meshed.
  const Cli_run run = run_cli("mesh-points " + (readers_dir / "points_columns.xyz").string() +
                              " -o " + scratch("points_out.off").string());
  EXPECT_NE(run.status, 2) << run.stderr_text;
  EXPECT_TRUE(fs::exists(scratch("points_out.off")));
}

// The files that options name (--faces of suppress, --constraints of fill) follow the mesh
// readers' rules: a sparse 2 GB file was read to its end (it hung), a bad word gave no file nor
// line.
TEST(CliRobustness, OptionFilesAreCheckedLikeMeshFiles) {
  const std::string mesh = (readers_dir / "comments.off").string();
  const fs::path out = scratch("option_out.off");
  const fs::path sparse = scratch("sparse.txt");
  write_bytes(sparse, "");
  fs::resize_file(sparse, std::uintmax_t(2) << 30);
  struct Case {
    std::string name, content, option, expected;
  };
  for (const Case& c : std::vector<Case>{
           {"letters.txt", "0 1\n2 x\n", "suppress --faces", "line 2: expected a face index"},
           {"range.txt", "0\n\n99999999999999999999999\n", "suppress --faces", "line 3:"},
           {"nul.txt", std::string("0 1\n2\0 3\n", 9), "suppress --faces", "line 2:"},
           {"sparse.txt", "", "suppress --faces", "a sparse file"},
           {"bad_constraint.txt", "# c\npoint 0 0\n", "fill --constraints", "line 2:"},
           {"sparse.txt", "", "fill --constraints", "a sparse file"}}) {
    const fs::path file = scratch(c.name);
    if (c.name != "sparse.txt") write_bytes(file, c.content);
    const std::string command = c.option.substr(0, c.option.find(' '));
    const std::string option = c.option.substr(c.option.find(' ') + 1);
    const Cli_run run =
        run_cli(command + " " + mesh + " -o " + out.string() + " " + option + " " + file.string());
    EXPECT_EQ(run.status, 2) << c.name << ": " << run.stderr_text;
    EXPECT_EQ(count_lines(run.stderr_text), 1u) << run.stderr_text;
    EXPECT_NE(run.stderr_text.find(file.string() + ": "), std::string::npos) << run.stderr_text;
    EXPECT_NE(run.stderr_text.find(c.expected), std::string::npos) << run.stderr_text;
    EXPECT_LT(run.seconds, 10.0) << c.name;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
  fs::remove(sparse);
}

TEST(CliRobustness, DirectoryAndMissingFileExitTwo) {
  EXPECT_EQ(run_cli("check " + fs::temp_directory_path().string()).status, 2);
  EXPECT_EQ(run_cli("check /nonexistent/mesh.off").status, 2);
}

TEST(CliRobustness, BadUsageExitsTwo) {
  EXPECT_EQ(run_cli("").status, 2);
  EXPECT_EQ(run_cli("no-such-command").status, 2);
  EXPECT_EQ(run_cli("check").status, 2);
  EXPECT_EQ(run_cli("check a.off b.off").status, 2);
  EXPECT_EQ(run_cli("check a.off --no-such-option").status, 2);
  EXPECT_EQ(run_cli("check a.off --tolerance abc").status, 2);
}

// Every input that ever crashed, hung or ran away (test/fuzz/corpus-regression/) through the
// release tool: exit 0, 1 or 2 (and 3, complete except what was kept, for repair), never a
// signal, within the timeout, input untouched.
TEST(CliRobustness, RegressionCorpusNeverCrashesOrHangs) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(corpus_dir)) files.push_back(entry.path());
  ASSERT_GE(files.size(), 20u);
  for (const fs::path& file : files) {
    const std::string before = file_text(file);
    const Cli_run check = run_cli("check " + file.string(), 30);
    EXPECT_TRUE(check.status >= 0 && check.status <= 2) << file << ": " << check.stderr_text;
    if (check.status == 2) {
      EXPECT_EQ(count_lines(check.stderr_text), 1u) << file;
    }
    const fs::path out = scratch("out" + file.extension().string());
    const Cli_run repair =
        run_cli("repair " + file.string() + " -o " + out.string() + " --quiet", 60);
    EXPECT_TRUE(repair.status >= 0 && repair.status <= 3) << file << ": " << repair.stderr_text;
    EXPECT_EQ(file_text(file), before) << file;
    fs::remove(out);
  }
}

// The mesh reader variants of test/data/readers all read through the tool.
TEST(CliRobustness, ReaderVariantsAreCheckedWithoutError) {
  for (const auto& entry : fs::directory_iterator(readers_dir)) {
    if (entry.path().extension() == ".xyz") continue;  // a point file (mesh-points)
    const Cli_run run = run_cli("check " + entry.path().string());
    EXPECT_TRUE(run.status == 0 || run.status == 1) << entry.path() << ": " << run.stderr_text;
  }
}

TEST(CliRobustness, NoCommandWritesItsInputEvenThroughALink) {
  const fs::path input = scratch("input.off");
  fs::copy_file(readers_dir / "comments.off", input, fs::copy_options::overwrite_existing);
  const fs::path link = scratch("link.off");
  fs::remove(link);
  fs::create_symlink(input, link);
  const std::string before = file_text(input);
  for (const std::string& command : {"fill " + input.string() + " -o " + input.string(),
                                     "repair " + input.string() + " -o " + link.string(),
                                     "stitch " + link.string() + " -o " + input.string(),
                                     "repair " + input.string() + " -o " +
                                         scratch("ok.off").string() + " --report " + input.string(),
                                     "check " + input.string() + " --json " + link.string()}) {
    const Cli_run run = run_cli(command);
    EXPECT_EQ(run.status, 2) << command << ": " << run.stderr_text;
    EXPECT_NE(run.stderr_text.find("is the input file"), std::string::npos) << run.stderr_text;
    EXPECT_EQ(file_text(input), before) << command;
  }
  EXPECT_FALSE(fs::exists(scratch("ok.off")));
}

TEST(CliRobustness, UnwritableOutputsAreFoundBeforeAnyWork) {
  const fs::path input = readers_dir / "comments.off";
  const fs::path out = scratch("written.off");
  fs::remove(out);
  for (const std::string& command :
       {"repair " + input.string() + " -o /nonexistent/folder/out.off",
        "repair " + input.string() + " -o " + out.string() + " --report /nonexistent/r.json",
        "fill " + input.string() + " -o " + scratch("").string()}) {
    const Cli_run run = run_cli(command);
    EXPECT_EQ(run.status, 2) << command;
    EXPECT_EQ(count_lines(run.stderr_text), 1u) << run.stderr_text;
    EXPECT_EQ(run.stderr_text.find("Could not create"), std::string::npos) << run.stderr_text;
    EXPECT_FALSE(fs::exists(out)) << command;  // the mesh is not written when the report cannot be
  }
}

TEST(CliRobustness, RepairWithTwoFilesSuggestsDashO) {
  const Cli_run run = run_cli("repair " + (readers_dir / "comments.off").string() + " out.off");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.stderr_text.find("did you mean -o out.off"), std::string::npos) << run.stderr_text;
}

TEST(CliRobustness, StaleTemporaryOfADeadProcessIsRemovedByTheNextWrite) {
  const fs::path folder = scratch("stale");
  fs::create_directories(folder);
  const fs::path stale = folder / ".tmp-999999999-out.off";
  std::ofstream(stale) << "half written";
  const Cli_run run = run_cli("repair " + (readers_dir / "comments.off").string() + " -o " +
                              (folder / "out.off").string() + " --quiet");
  EXPECT_TRUE(run.status == 0 || run.status == 1) << run.stderr_text;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(folder / "out.off"));
  fs::remove_all(folder);
}

// A sparse 2 GB file is refused in under 2 s (the header claims what the file cannot hold, or
// its first zero byte stops the text reader).
TEST(CliRobustness, SparseTwoGigabyteFilesAreRefusedAtOnce) {
  for (const auto& c : std::vector<std::pair<std::string, std::string>>{
           {"sparse.off", "OFF\n1000000000 1000000000 0\n"},
           {"sparse_fits.off", "OFF\n100000000 10 0\n"},
           {"sparse.obj", "v 0 0 0\n"}}) {
    const fs::path path = scratch(c.first);
    write_bytes(path, c.second);
    fs::resize_file(path, std::uintmax_t(2) << 30);
    const Cli_run run = run_cli("check " + path.string());
    EXPECT_EQ(run.status, 2) << c.first << ": " << run.stderr_text;
    EXPECT_LT(run.seconds, 2.0) << c.first;
    fs::remove(path);
  }
}

// Every entry of the batch folder is in the summary: a .off link to /dev/zero is a failed row.
TEST(CliRobustness, BatchListsEveryEntryOfTheFolder) {
  const fs::path in = scratch("batch_in"), out = scratch("batch_out");
  fs::remove_all(in);
  fs::remove_all(out);
  fs::create_directories(in);
  fs::copy_file(readers_dir / "comments.off", in / "good.off");
  fs::create_symlink("/dev/zero", in / "zero.off");
  fs::create_symlink(in / "missing.off", in / "dangling.obj");
  std::ofstream(in / "notes.txt") << "not a mesh";
  const Cli_run run = run_cli("repair --batch " + in.string() + " --out-dir " + out.string(), 60);
  EXPECT_EQ(run.status, 1) << run.stderr_text;
  const std::string summary = file_text(out / "summary.csv");
  for (const char* row :
       {"good.off,repaired", "zero.off,failed,2", "dangling.obj,failed,2", "notes.txt,skipped"})
    EXPECT_NE(summary.find(row), std::string::npos) << row << "\n" << summary;
  EXPECT_NE(summary.find("not a regular file"), std::string::npos) << summary;
  fs::remove_all(in);
  fs::remove_all(out);
}

}  // namespace
