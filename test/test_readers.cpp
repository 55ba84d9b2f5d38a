// Our strict OFF/OBJ/STL/PLY readers (internal/readers/, behind io.h's read_polygon_soup): the
// variants real files contain (test/data/readers/, written by scripts/make_reader_test_files.py)
// are read with the right counts and points; every malformed file gives one line naming the
// file, the line or byte offset and the reason; huge declared counts and sparse files are
// refused at once.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;
namespace fs = std::filesystem;

const fs::path readers_dir = fs::path(MESH_REPAIR_TEST_DATA_DIR) / "readers";
const fs::path corpus_dir =
    fs::path(MESH_REPAIR_SOURCE_DIR) / "test" / "fuzz" / "corpus-regression";

// A scratch folder removed when the test ends.
struct Scratch {
  fs::path dir;
  Scratch() {
    dir = fs::temp_directory_path() /
          ("mesh_repair_test_readers_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  fs::path write(const std::string& name, const std::string& bytes) const {
    std::ofstream out(dir / name, std::ios::binary);
    out << bytes;
    return dir / name;
  }
};

std::string read_soup(const fs::path& path, MR::Polygon_soup<Point>& soup) {
  return MR::read_polygon_soup(path.string(), soup);
}

// The unit tetrahedron of the generator script.
const std::vector<Point> tetrahedron = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0),
                                        Point(0, 0, 1)};

TEST(Readers, EveryVariantOfTheTetrahedronReadsAsFourPointsAndFourClosedFaces) {
  for (const char* name : {"counts_on_header.off",
                           "comments.off",
                           "coff.off",
                           "noff.off",
                           "stoff.off",
                           "ndim.off",
                           "homogeneous.off",
                           "crlf_tabs.off",
                           "binary.off",
                           "cr_only_bom.off",
                           "no_keyword.off",
                           "utf16le.off",
                           "continuation.obj",
                           "cr_only.obj",
                           "bom.obj",
                           "utf16be.obj",
                           "negative.obj",
                           "texture_normal.obj",
                           "binary_solid.stl",
                           "ascii_whitespace.stl",
                           "ascii_one_line.stl",
                           "ascii_bom_cr_only.stl",
                           "ascii_utf16le.stl",
                           "binary_header_utf16_mark.stl",
                           "binary_little.ply",
                           "binary_big.ply",
                           "extra_properties.ply",
                           "extra_fields.ply",
                           "tristrips.ply",
                           "free_text_header.ply",
                           "vertex_index.ply"}) {
    MR::Polygon_soup<Point> soup;
    ASSERT_EQ(read_soup(readers_dir / name, soup), "") << name;
    EXPECT_EQ(soup.points.size(), 4u) << name;
    EXPECT_EQ(soup.polygons.size(), 4u) << name;
    for (const Point& p : soup.points)
      EXPECT_NE(std::find(tetrahedron.begin(), tetrahedron.end(), p), tetrahedron.end())
          << name << ": " << p;
    Mesh mesh;
    MR::Soup_repair_report report;
    ASSERT_EQ(MR::read_mesh((readers_dir / name).string(), mesh, report), "") << name;
    EXPECT_EQ(num_faces(mesh), 4u) << name;
    EXPECT_TRUE(CGAL::is_closed(mesh)) << name;
    EXPECT_EQ(report.polygons_reversed, 0u) << name;  // strips alternate their orientation
  }
}

TEST(Readers, ObjPolygonsAndShortOffFacesAreCounted) {
  MR::Polygon_soup<Point> soup;
  ASSERT_EQ(read_soup(readers_dir / "polygon.obj", soup), "");
  ASSERT_EQ(soup.polygons.size(), 1u);
  EXPECT_EQ(soup.polygons[0].size(), 5u);
  EXPECT_EQ(soup.points[2], Point(3, 1, 0));  // the colour after the coordinates is ignored
  ASSERT_EQ(read_soup(readers_dir / "quad_and_short.off", soup), "");
  EXPECT_EQ(soup.polygons.size(), 1u);
  EXPECT_EQ(soup.short_polygons_skipped, 2u);
  Mesh mesh;
  MR::Soup_repair_report report;
  ASSERT_EQ(MR::read_mesh((readers_dir / "quad_and_short.off").string(), mesh, report), "");
  EXPECT_EQ(report.input_polygons, 3u);
  EXPECT_EQ(report.degenerate_polygons_removed, 2u);
  EXPECT_EQ(num_faces(mesh), 2u);  // the quad, triangulated
}

// Blender 2.4x wrote "Created by ..." without `comment` before the elements: skipped as free
// text and counted in the soup stage's report; the same line among the elements is refused.
TEST(Readers, FreeTextBeforeThePlyElementsIsSkippedAndCounted) {
  MR::Polygon_soup<Point> soup;
  ASSERT_EQ(read_soup(readers_dir / "free_text_header.ply", soup), "");
  EXPECT_EQ(soup.header_lines_skipped, 1u);
  Mesh mesh;
  MR::Soup_repair_report report;
  ASSERT_EQ(MR::read_mesh((readers_dir / "free_text_header.ply").string(), mesh, report), "");
  EXPECT_EQ(report.header_lines_skipped, 1u);
  ASSERT_EQ(read_soup(readers_dir / "extra_fields.ply", soup), "");
  EXPECT_EQ(soup.header_lines_skipped, 0u);
}

TEST(Readers, NegativeObjIndicesAreRelativeToTheVerticesBefore) {
  MR::Polygon_soup<Point> soup;
  ASSERT_EQ(read_soup(readers_dir / "negative.obj", soup), "");
  const std::vector<std::size_t> first = {0, 2, 1}, last = {1, 2, 3};
  EXPECT_EQ(soup.polygons.front(), first);
  EXPECT_EQ(soup.polygons.back(), last);
}

TEST(Readers, ReadingFromMemoryGivesTheSameSoup) {
  std::ifstream in(readers_dir / "binary_big.ply", std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string data = bytes.str();
  MR::Polygon_soup<Point> from_memory, from_file;
  ASSERT_EQ(
      MR::read_polygon_soup_from_memory(data.data(), data.size(), "PLY", "x.ply", from_memory), "");
  ASSERT_EQ(read_soup(readers_dir / "binary_big.ply", from_file), "");
  EXPECT_EQ(from_memory.points, from_file.points);
  EXPECT_EQ(from_memory.polygons, from_file.polygons);
}

// Each malformed input: one line with the file name, the place and the reason.
TEST(Readers, MalformedFilesGiveOneLineWithPlaceAndReason) {
  const std::vector<std::pair<const char*, const char*>> cases = {
      {"property_before_element.ply", "line 3: 'property' before any 'element'"},
      {"vertex_x_is_a_list.ply", "line 3: vertex property 'x' is a list"},
      {"face_of_a_million_indices.off", "line 6: a face of 1000000 vertices exceeds the limit"},
      {"polygon_past_the_limit.obj", "line 4: a face of 10001 vertices exceeds the limit"},
      {"huge_counts.off", "line 2: the header declares 1000000000 vertices"},
      {"huge_counts.ply",
       "line 9: the header declares more records than the 6 bytes after it can hold"},
      {"huge_counts_binary.stl", "byte 80: binary STL declares 1000000000 triangles"},
      {"zeros_after_header.off", "line 3: unexpected control byte 0x00 (byte offset 10)"},
      {"zeros.obj", "line 1: unexpected control byte 0x00"},
      {"negative_index.off", "line 6: vertex index -1 out of range"},
      {"nan.off", "line 4: non-finite vertex coordinate 'nan'"},
      {"truncated_binary.stl", "byte 80: binary STL declares 16 triangles (884 bytes)"},
      {"truncated_ascii.stl", "line 5: expected a number (vertex coordinate)"},
      {"ply_list_count_huge.ply", "byte 204: a list of 4294967295 values exceeds the limit"},
      {"obj_relative_index_out_of_range.obj", "line 2: relative vertex index -2"},
      {"ply_binary_zero_faces.ply", "contains no faces"},
      {"coordinates_1e308.off", "vertex 0 has a coordinate of magnitude 1e+308, above 1e60"},
      {"coordinates_1e308.obj", "has a coordinate of magnitude 1e+308, above 1e60"},
      {"pentagon_huge_coordinate.obj", "above 1e60: products of squared lengths would overflow"},
      {"span_1e-98_tetrahedron.off", "the points span only 9e-98"},
  };
  for (const auto& c : cases) {
    const fs::path path = corpus_dir / c.first;
    MR::Polygon_soup<Point> soup;
    const std::string error = read_soup(path, soup);
    EXPECT_EQ(error.rfind(path.string() + ": ", 0), 0u) << error;
    EXPECT_NE(error.find(c.second), std::string::npos) << c.first << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_TRUE(soup.points.empty() || soup.polygons.empty()) << c.first;
  }
}

TEST(Readers, MoreMalformedHeadersAndRecords) {
  Scratch s;
  const std::string ply = "ply\nformat ascii 1.0\n";
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"a.ply", ply + "element vertex 1\n" + xyz + "property blob w\nend_header\n",
       "line 7: unknown property type 'blob'"},
      {"b.ply", ply + "element vertex 1\nproperty float x\nend_header\n0\n",
       "line 3: the vertex element has no 'y' property"},
      {"c.ply",
       ply + "element vertex 3\n" + xyz +
           "element face 1\nproperty list uchar float vertex_indices\nend_header\n",
       "line 7: 'vertex_indices' of face is not of an integer type"},
      {"d.ply", "ply\nelement vertex 1\n", "line 2: 'element' before 'format'"},
      {"e.ply", ply + "element vertex 1\n" + xyz, "the header has no 'end_header'"},
      {"f.ply", ply + "element vertex 2\n" + xyz + "end_header\n0 0\n1 1 1 1 1 1\n",
       "line 8: the record has fewer values than its element declares"},
      {"g.ply",
       ply + "element vertex 3\n" + xyz +
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
       "line 13: vertex index 3 out of range (3 vertices)"},
      {"h.ply", ply + "element vertex 1\n" + xyz + "Created by a tool\nend_header\n",
       "line 7: unknown header line 'Created'"},
      {"f.off", std::string("\xff\xfeO\0F\0F\0\n", 9),
       "byte 8: a UTF-16 text file of an odd number of bytes"},
      {"g.off", "3 -1\n", "line 1: expected the number of faces, found '-1'"},
      {"a.off", "OFF\n3 1\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n",
       "line 4: vertex 1 has 2 coordinates, expected 3"},
      {"b.off", "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n", "the file ends after 0 of 1 faces"},
      {"c.off", "OFF\n3 x\n", "line 2: expected the number of faces, found 'x'"},
      {"d.off", "OF\n", "line 1: not an OFF file: the first word is 'OF'"},
      {"e.off", "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
       "line 6: a face declares 4 vertices but lists 3"},
      {"a.obj", "v 0 0\n", "line 1: a vertex needs three coordinates"},
      {"b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "line 4: expected a vertex index"},
      {"c.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\nf 1 2 3\n",
       "line 5: a face refers to vertex 9 but the file has 3 vertices"},
      {"d.obj", "v 0 0 0\n3.5 2\n", "line 2: not an OBJ statement: '3.5'"},
      {"polyline.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3\n",
       "contains no faces (no face with three or more vertices), only 3 points and 1 line "
       "statement(s) (`l`): curves, not a surface"},
      {"segments.off", "OFF\n3 2\n0 0 0\n1 0 0\n1 1 0\n2 0 1\n2 1 2\n",
       "only 3 points and 2 face(s) of one or two vertices: points and segments, not a surface"},
      {"points.obj", "v 0 0 0\nv 1 0 0\n", "only 2 points: a point cloud"},
      {"a.stl",
       "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendloop\nendfacet\n"
       "facet\n",
       "line 7: expected 'normal', found the end of the file"},
      {"b.stl", "solid s\nfacet normal 0 0 1\nouter lop\n", "line 3: expected 'loop'"},
  };
  for (const auto& c : cases) {
    const fs::path path = s.write(std::get<0>(c), std::get<1>(c));
    MR::Polygon_soup<Point> soup;
    const std::string error = read_soup(path, soup);
    EXPECT_NE(error.find(std::get<2>(c)), std::string::npos) << std::get<0>(c) << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

TEST(Readers, FacesUpToTheLimitAreRead) {
  Scratch s;
  std::string obj;
  const int n = 2000;
  for (int i = 0; i < n; ++i)
    obj += "v " + std::to_string(std::cos(i * 2 * M_PI / n)) + " " +
           std::to_string(std::sin(i * 2 * M_PI / n)) + " 0\n";
  obj += "f";
  for (int i = 1; i <= n; ++i) obj += " " + std::to_string(i);
  obj += "\n";
  MR::Polygon_soup<Point> soup;
  ASSERT_EQ(read_soup(s.write("disc.obj", obj), soup), "");
  ASSERT_EQ(soup.polygons.size(), 1u);
  EXPECT_EQ(soup.polygons[0].size(), std::size_t(n));
}

// A sparse file of 2 GB whose header fits its size is refused at its first zero byte, and one
// whose header claims 10^9 vertices before reading anything.
TEST(Readers, SparseMultiGigabyteFilesAreRefusedAtOnce) {
  Scratch s;
  const std::uintmax_t two_gb = std::uintmax_t(2) << 30;
  const std::string ply_head =
      "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\n"
      "property float y\nproperty float z\n";
  std::string stl_head = "solid binary";
  stl_head.resize(80, ' ');
  const std::uint32_t triangles = 40000000;  // 84 + 50 * 40000000 bytes: a valid size
  stl_head.append(reinterpret_cast<const char*>(&triangles), 4);
  for (const auto& c : std::vector<std::tuple<std::string, std::string, std::uintmax_t>>{
           {"sparse.off", "OFF\n100000000 100000000 0\n", two_gb},
           {"claims.off", "OFF\n1000000000 1000000000 0\n", two_gb},
           {"sparse.obj", "v 0 0 0\n", two_gb},
           {"claims.ply",
            ply_head + "element face 1000000000\nproperty list uchar int "
                       "vertex_indices\nend_header\n",
            two_gb},
           {"sparse.ply", ply_head + "end_header\n", two_gb},
           {"sparse.stl", stl_head, 84 + 50 * std::uintmax_t(triangles)},
           {"sparse_binary.off", "OFF BINARY\n", two_gb}}) {
    const fs::path path = s.write(std::get<0>(c), std::get<1>(c));
    fs::resize_file(path, std::get<2>(c));
    const auto start = std::chrono::steady_clock::now();
    MR::Polygon_soup<Point> soup;
    const std::string error = read_soup(path, soup);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_FALSE(error.empty()) << std::get<0>(c);
    EXPECT_LT(seconds, 2.0) << std::get<0>(c) << ": " << error;
    fs::remove(path);
  }
}

// A sparse file with one written byte every 256 KB has no whole megabyte of zeros, but most of
// it was never written: it is refused before it is read (it took 2.4 GB and 15 s), naming the
// first hole. A long file written out in full is read as before.
TEST(Readers, DottedSparseFilesAreRefusedBeforeTheyAreRead) {
  Scratch s;
  const std::uintmax_t two_gb = std::uintmax_t(2) << 30;
  std::string stl_head = "binary";
  stl_head.resize(80, ' ');
  const std::uint32_t triangles = std::uint32_t((two_gb - 84) / 50);
  stl_head.append(reinterpret_cast<const char*>(&triangles), 4);
  const std::string ply_head =
      "ply\nformat binary_little_endian 1.0\nelement vertex 70000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int "
      "vertex_indices\nend_header\n";
  for (const auto& c : std::vector<std::pair<std::string, std::string>>{{"dotted.stl", stl_head},
                                                                        {"dotted.ply", ply_head}}) {
    const fs::path path = s.write(c.first, c.second);
    fs::resize_file(path, two_gb);
    {
      std::fstream dots(path, std::ios::in | std::ios::out | std::ios::binary);
      for (std::uintmax_t at = 256 << 10; at < two_gb; at += 256 << 10) {
        dots.seekp(std::streamoff(at));
        dots.put('A');
      }
    }
    MR::Polygon_soup<Point> soup;
    const std::string error = read_soup(path, soup);
    EXPECT_NE(error.find("a sparse file"), std::string::npos) << c.first << ": " << error;
    EXPECT_NE(error.find(c.first), std::string::npos) << error;
    EXPECT_TRUE(soup.points.empty());
    fs::remove(path);
  }
  // 4 MB of blanks written out after a valid mesh: not sparse.
  std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const fs::path written = s.write("written.off", off + std::string(4 << 20, ' '));
  MR::Polygon_soup<Point> soup;
  EXPECT_EQ(read_soup(written, soup), "");
  EXPECT_EQ(soup.polygons.size(), 1u);
}

TEST(Writing, UnwritableFolderGivesOurLineOnlyAndStaleTemporariesGo) {
  Scratch s;
  Mesh mesh;
  MR::Soup_repair_report report;
  ASSERT_EQ(MR::read_mesh((readers_dir / "comments.off").string(), mesh, report), "");
  std::ostringstream captured;
  std::streambuf* saved = std::cerr.rdbuf(captured.rdbuf());
  const std::string error = MR::write_mesh((s.dir / "missing" / "out.off").string(), mesh);
  std::cerr.rdbuf(saved);
  EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
  EXPECT_EQ(captured.str(), "");
  // A temporary file of a process that no longer exists goes; one of a living process stays.
  const fs::path stale = s.write(".tmp-999999999-out.off", "half");
  const fs::path alive = s.write(".tmp-" + std::to_string(::getppid()) + "-out.off", "busy");
  ASSERT_EQ(MR::write_mesh((s.dir / "out.off").string(), mesh), "");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(alive));
  EXPECT_TRUE(fs::exists(s.dir / "out.off"));
}

}  // namespace
