// The command-line tool on malformed input: exit status 2, one line on stderr, within seconds,
// input untouched.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace {
namespace fs = std::filesystem;

struct Cli_run {
  int status;
  std::string stderr_text;
  double seconds;
};

fs::path scratch(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("mesh_repair_test_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

Cli_run run_cli(const std::string& arguments) {
  const fs::path err = scratch("stderr.txt");
  const std::string command = std::string("timeout 20 ") + MESH_REPAIR_CLI + " " + arguments +
                              " >/dev/null 2>" + err.string();
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

}  // namespace
