// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures of filled holes, run as a user would: `fill --picture` and `bench holes` write valid
// PNG files (and bench its page) when python3-matplotlib is present, and say so in one line and
// still succeed when it is not.
#include <gtest/gtest.h>

#include "scratch_folder.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return mesh_repair_test::scratch_folder("mesh_repair_test_pictures_") / name;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Tool_run {
  int status;
  std::string out, err;
};

Tool_run run_tool(const std::string& arguments, const std::string& environment = "") {
  const fs::path out = scratch("stdout.txt"), err = scratch("stderr.txt");
  const std::string command = environment + " timeout 600 " + MESH_REPAIR_CLI + " " + arguments +
                              " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
}

// The tool's interpreter (Debian's) can import matplotlib.
bool matplotlib_present() {
  const char* python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = std::string(python) + " -c 'import matplotlib' >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

// A PNG file: its 8-byte signature, then at least a header chunk.
bool is_png(const fs::path& path) {
  const std::string bytes = read_text(path);
  return bytes.size() > 32 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

// A UV sphere of radius 1 whose faces above z = 0.8 are missing: one hole of 24 border edges.
fs::path sphere_with_hole() {
  const fs::path path = scratch("sphere_with_hole.off");
  const int rings = 16, sectors = 24;
  const double pi = std::acos(-1.0);
  std::ostringstream vertices, faces;
  int face_count = 0;
  vertices << "0 0 -1\n";
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double theta = pi * i / rings, phi = 2 * pi * j / sectors;
      vertices << std::sin(theta) * std::cos(phi) << ' ' << std::sin(theta) * std::sin(phi) << ' '
               << -std::cos(theta) << '\n';
    }
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * sectors + (j % sectors); };
  for (int j = 0; j < sectors; ++j, ++face_count)
    faces << "3 0 " << at(1, j + 1) << ' ' << at(1, j) << '\n';
  for (int i = 1; i + 1 < rings && -std::cos(pi * (i + 1) / rings) < 0.8; ++i)
    for (int j = 0; j < sectors; ++j, face_count += 2) {
      faces << "3 " << at(i, j) << ' ' << at(i, j + 1) << ' ' << at(i + 1, j + 1) << '\n';
      faces << "3 " << at(i, j) << ' ' << at(i + 1, j + 1) << ' ' << at(i + 1, j) << '\n';
    }
  std::ofstream out(path);
  out << "OFF\n"
      << 1 + (rings - 1) * sectors << ' ' << face_count << " 0\n"
      << vertices.str() << faces.str();
  return path;
}

std::size_t files_ending_in(const fs::path& folder, const std::string& suffix) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    count += name.size() >= suffix.size() &&
             name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  }
  return count;
}

TEST(PicturesCli, FillPictureIsAPngAndLeavesNoSceneFile) {
  const fs::path input = sphere_with_hole(), output = scratch("filled.off");
  const fs::path picture = scratch("fill.png");
  const Tool_run run = run_tool("fill " + input.string() + " -o " + output.string() +
                                " --method liepa --picture " + picture.string() + " --quiet");
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_TRUE(fs::exists(output));
  EXPECT_EQ(files_ending_in(scratch(""), ".json"), 0u) << "the scene file is removed";
  if (!matplotlib_present()) GTEST_SKIP() << "python3-matplotlib is missing: " << run.err;
  EXPECT_TRUE(is_png(picture)) << run.err;
  fs::remove(picture);
}

TEST(PicturesCli, BenchWritesOnePngPerHoleAndAPageShowingThem) {
  const fs::path out = scratch("bench");
  const Tool_run run = run_tool(
      "bench holes --analytic sphere --holes 2 --radius 0.06 --seeds 1 "
      "--methods liepa_c1,advancing_front --no-plots --quiet --out " +
      out.string());
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  const std::string page = read_text(out / "index.html");
  EXPECT_NE(page.find("liepa_c1"), std::string::npos);
  if (!matplotlib_present()) GTEST_SKIP() << "python3-matplotlib is missing: " << run.err;
  for (const char* name : {"sphere-r0.06-s1-h0.png", "sphere-r0.06-s1-h1.png"}) {
    EXPECT_TRUE(is_png(out / "pictures" / name)) << name << '\n' << run.err;
    EXPECT_NE(page.find(std::string("pictures/") + name), std::string::npos) << name;
  }
  EXPECT_EQ(files_ending_in(out / "pictures", ".json"), 0u) << "scenes removed once drawn";
  fs::remove_all(out);
}

TEST(PicturesCli, WithoutMatplotlibOneLineSaysSoAndTheFillSucceeds) {
  const fs::path input = sphere_with_hole(), output = scratch("filled_no_python.off");
  const fs::path picture = scratch("no_python.png");
  const Tool_run run = run_tool("fill " + input.string() + " -o " + output.string() +
                                    " --method liepa --picture " + picture.string() + " --quiet",
                                "MESH_REPAIR_PYTHON=/nonexistent/python3");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(fs::exists(output));
  EXPECT_FALSE(fs::exists(picture));
  EXPECT_NE(run.err.find("no pictures"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

TEST(PicturesCli, WithoutMatplotlibBenchKeepsTheScenesToDrawLater) {
  const fs::path out = scratch("bench_no_python");
  const Tool_run run = run_tool(
      "bench holes --analytic sphere --holes 1 --radius 0.06 --seeds 1 "
      "--methods liepa_c1 --quiet --out " +
          out.string(),
      "MESH_REPAIR_PYTHON=/nonexistent/python3");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(fs::exists(out / "table.md"));
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find("no plots and no pictures"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::exists(out / "pictures" / "sphere-r0.06-s1-h0.json"));
  EXPECT_EQ(files_ending_in(out / "pictures", ".png"), 0u);
  EXPECT_NE(read_text(out / "index.html").find("no picture"), std::string::npos);
  fs::remove_all(out);
}

TEST(PicturesCli, PictureThatIsNotPngIsBadUsage) {
  const fs::path input = sphere_with_hole();
  const Tool_run run = run_tool("fill " + input.string() + " -o " + scratch("x.off").string() +
                                " --picture " + scratch("x.jpg").string());
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_FALSE(fs::exists(scratch("x.off")));
}

}  // namespace
