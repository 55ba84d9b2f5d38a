// The kinds of file real users bring (ctest label `realworld`), each made here: two quads sharing
// three vertices, closed shells touching at coincident but distinct corners (a face, an edge, a
// point), a cube whose faces use a duplicated vertex, open meshes with holes, an open sheet, a
// part open where another reaches in.
// Each goes through `mesh_repair repair` as a user runs it; the output is read back with CGAL's
// own reader (coincident points merged) and the report must say what that reading shows, with
// the exit status of its status (written_file_check.h).
#include <gtest/gtest.h>

#include "scratch_folder.h"
#include "support/written_file_check.h"

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <tuple>
#include <vector>

namespace {
namespace fs = std::filesystem;
using mesh_repair_test::Cgal_reading;

fs::path scratch(const std::string& name) {
  return mesh_repair_test::scratch_folder("mesh_repair_test_realworld_") / name;
}

struct Soup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;

  void add(const Soup& other) {
    const std::size_t offset = points.size();
    points.insert(points.end(), other.points.begin(), other.points.end());
    for (auto f : other.faces) {
      for (auto& i : f) i += offset;
      faces.push_back(f);
    }
  }
  void write_off(const fs::path& path) const {
    std::ofstream out(path);
    out << "OFF\n" << points.size() << ' ' << faces.size() << " 0\n";
    for (const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for (const auto& f : faces) {
      out << f.size();
      for (std::size_t i : f) out << ' ' << i;
      out << '\n';
    }
  }
};

/// A closed axis-aligned cube of side `s` at `o`, outward triangles, with its own eight points.
/// `flip`: the other diagonal on every side.
Soup cube(double x, double y, double z, double s = 1, bool flip = false) {
  Soup c;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) c.points.push_back({x + i * s, y + j * s, z + k * s});
  const std::size_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    if (flip) {
      c.faces.push_back({q[0], q[1], q[3]});
      c.faces.push_back({q[1], q[2], q[3]});
    } else {
      c.faces.push_back({q[0], q[1], q[2]});
      c.faces.push_back({q[0], q[2], q[3]});
    }
  }
  return c;
}

/// An n x n grid of unit squares in the plane z = 0, two triangles each.
Soup sheet(int n) {
  Soup s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.points.push_back({double(i), double(j), 0.05 * (i % 2)});
  auto at = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return s;
}

struct Repair_run {
  int status = -1;
  std::string out;
  Cgal_reading reading;
  std::string report;
};

/// `mesh_repair repair IN -o OUT --report R [options]`, then CGAL's reading of OUT checked
/// against R.
Repair_run repair(const std::string& name, const Soup& input, const std::string& options = "",
                  const std::string& extension = ".off") {
  const fs::path in = scratch(name + ".in.off"), out = scratch(name + ".out" + extension),
                 report = scratch(name + ".report.json"), log = scratch(name + ".log");
  input.write_off(in);
  const std::string command = std::string("timeout 120 ") + MESH_REPAIR_CLI + " repair " +
                              in.string() + " -o " + out.string() + " --report " + report.string() +
                              " --quiet " + options + " >" + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  Repair_run run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = mesh_repair_test::file_text(log.string());
  run.reading = mesh_repair_test::read_like_cgal(out.string());
  run.report = mesh_repair_test::file_text(report.string());
  mesh_repair_test::expect_report_is_the_reading(report.string(), run.reading, run.status, name);
  return run;
}

std::string repair_member(const Repair_run& run, const std::string& key) {
  return mesh_repair_test::member_value(mesh_repair_test::member_object(run.report, "repair"), key);
}

// Two quads on the points 0, 1, 2 and one more each: triangulated, both hold the triangle
// (0, 1, 2), once in each orientation; written as such, a merging reader drops one copy.
TEST(RealWorld, TwoQuadsSharingThreeVertices) {
  Soup quads;
  quads.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-0.33, 0.31, 0.49}, {-0.35, 0.27, -0.91}};
  quads.faces = {{0, 1, 2, 3}, {4, 0, 2, 1}};
  const Repair_run run = repair("two_quads", quads);
  EXPECT_EQ(run.reading.duplicated_polygons, 0u) << run.out;
  Soup other;
  other.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 1, 1}};
  other.faces = {{0, 1, 2, 3}, {0, 1, 2, 4}};
  repair("two_quads_b", other);
}

// Two closed cubes on a common face: the wall between them is a zero-volume pair of faces,
// removed whole, and the cubes become one closed box. With the other diagonal on the second cube
// the wall's triangles are not duplicates: whatever is left, the report says it.
TEST(RealWorld, TwoCubesTouchingAlongAFace) {
  Soup cubes = cube(0, 0, 0);
  cubes.add(cube(0, 0, 1));
  const Repair_run run = repair("cubes_face", cubes);
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_TRUE(run.reading.closed);
  EXPECT_TRUE(run.reading.manifold);
  EXPECT_EQ(run.reading.vertices, 12u);
  EXPECT_EQ(run.reading.faces, 20u);
  EXPECT_NE(run.out.find("zero-volume walls removed"), std::string::npos) << run.out;
  Soup flipped = cube(0, 0, 0);
  flipped.add(cube(0, 0, 1, 1, true));
  const Repair_run other = repair("cubes_face_flipped", flipped);
  EXPECT_EQ(other.reading.duplicated_polygons, 0u) << other.out;
}

// Two closed cubes on a common edge and on a common corner: a merging reader would see a
// non-manifold edge or vertex, and faces of the two cubes meeting there. The copies of the edge
// and of the corner are moved apart, each into its own cube: two closed solids, manifold and free
// of intersections as CGAL reads the file back, and the report counts the moves.
TEST(RealWorld, TwoCubesTouchingAlongAnEdgeOrAtACorner) {
  Soup edge = cube(0, 0, 0);
  edge.add(cube(1, 0, 1));
  Soup corner = cube(0, 0, 0);
  corner.add(cube(1, 1, 1));
  for (const auto& [name, input, moved] :
       {std::make_tuple("cubes_edge", edge, 4), std::make_tuple("cubes_corner", corner, 2)}) {
    const Repair_run run = repair(name, input);
    EXPECT_EQ(run.status, 0) << run.out;
    EXPECT_TRUE(run.reading.closed) << name;
    EXPECT_TRUE(run.reading.manifold) << name;
    EXPECT_EQ(run.reading.self_intersections, 0u) << name;
    EXPECT_EQ(run.reading.vertices, 16u) << name;
    EXPECT_NE(run.out.find("contact_vertices_moved_apart " + std::to_string(moved)),
              std::string::npos)
        << run.out;
  }
}

// A cube whose faces use two distinct vertices at one corner.
TEST(RealWorld, CubeWithADuplicatedVertex) {
  Soup c = cube(0, 0, 0);
  c.points.push_back(c.points[7]);
  for (std::size_t f = 0; f < c.faces.size(); f += 2)
    for (auto& i : c.faces[f])
      if (i == 7) i = 8;
  const Repair_run run = repair("cube_duplicated_vertex", c);
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_TRUE(run.reading.closed);
  EXPECT_EQ(run.reading.coincident_points, 0u);
  EXPECT_EQ(run.reading.vertices, 8u);
}

// Open meshes: a cube without two opposite sides is closed; with a hole-size limit the holes
// are kept (status complete_except_kept, exit 3); an open sheet's outline is kept by the default
// sheet_border_ratio.
TEST(RealWorld, OpenMeshesWithHoles) {
  Soup open = cube(0, 0, 0);
  open.faces.erase(open.faces.begin(), open.faces.begin() + 4);  // bottom and top
  const Repair_run filled = repair("cube_two_holes", open);
  EXPECT_EQ(filled.status, 0) << filled.out;
  EXPECT_TRUE(filled.reading.closed);
  const Repair_run limited = repair("cube_two_holes_limited", open, "--max-hole-edges 3");
  EXPECT_EQ(limited.status, 3) << limited.out;
  EXPECT_EQ(limited.reading.border_cycles, 2u);
  EXPECT_EQ(repair_member(limited, "status"), "complete_except_kept");
  const Repair_run flat = repair("open_sheet", sheet(6));
  EXPECT_EQ(flat.status, 3) << flat.out;
  EXPECT_EQ(flat.reading.border_cycles, 1u);
}

/// Appends an nu x nv grid of triangles over origin + s * u + t * v (s, t in [0, 1]).
void add_grid(Soup& soup, std::array<double, 3> origin, std::array<double, 3> u,
              std::array<double, 3> v, int nu, int nv) {
  const std::size_t first = soup.points.size();
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double s = double(i) / nu, t = double(j) / nv;
      soup.points.push_back({origin[0] + s * u[0] + t * v[0], origin[1] + s * u[1] + t * v[1],
                             origin[2] + s * u[2] + t * v[2]});
    }
  auto at = [&](int i, int j) { return first + std::size_t(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      soup.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      soup.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

/// The four side walls of the box [0, 1]^2 x [z0, z1], `n` cells along each side.
void add_walls(Soup& soup, double z0, double z1, int n) {
  const double h = z1 - z0;
  add_grid(soup, {0, 0, z0}, {1, 0, 0}, {0, 0, h}, n, 2);
  add_grid(soup, {1, 0, z0}, {0, 1, 0}, {0, 0, h}, n, 2);
  add_grid(soup, {1, 1, z0}, {-1, 0, 0}, {0, 0, h}, n, 2);
  add_grid(soup, {0, 1, z0}, {0, -1, 0}, {0, 0, h}, n, 2);
}

// A closed box cracked across: the two halves 0.003 apart, meshed with 7 and 11 cells per side
// so that no node of one side meets a node of the other (T-junctions all along the crack).
TEST(RealWorld, CrackWithTJunctionsAcrossAClosedPart) {
  const double gap = 0.003;
  Soup box;
  add_grid(box, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 7, 7);  // bottom
  add_walls(box, 0, 0.5, 7);
  add_walls(box, 0.5 + gap, 1 + gap, 11);
  add_grid(box, {0, 0, 1 + gap}, {1, 0, 0}, {0, 1, 0}, 11, 11);  // top
  const Repair_run run = repair("cracked_box", box);
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_TRUE(run.reading.closed && run.reading.valid && run.reading.manifold) << run.out;
  EXPECT_EQ(repair_member(run, "self_intersections_output"), "0") << run.report;
}

// Two closed cubes passing through each other (an assembly): both are kept as solids, their
// intersections counted as kept between components, exit 3; nothing of either is removed.
TEST(RealWorld, OverlappingSolidsAreKeptAsSeparateSolids) {
  Soup solids = cube(0, 0, 0);
  solids.add(cube(0.5, 0.4, 0.3));
  const Repair_run run = repair("overlapping_cubes", solids);
  EXPECT_EQ(run.status, 3) << run.out;
  EXPECT_EQ(run.reading.faces, 24u);
  EXPECT_TRUE(run.reading.closed && run.reading.valid);
  EXPECT_EQ(repair_member(run, "status"), "complete_except_kept");
  EXPECT_NE(repair_member(run, "self_intersections_between_components"), "0") << run.report;
}

// A table top modelled without its underside, a leg reaching in through the opening without
// touching the top (sweethome3d's furniture has such parts): every patch of the opening crosses
// the leg. The opening is closed flat, the leg's crossing kept as a contact between separate
// solids (exit 3); with --merge-intersecting-solids the two are one solid (exit 0).
TEST(RealWorld, AnOpeningThatAnotherPartReachesThroughIsClosed) {
  Soup table = cube(0, 0, 0, 2);
  for (auto& p : table.points) p[2] *= 0.2;                         // the top: [0, 2]^2 x [0, 0.4]
  table.faces.erase(table.faces.begin(), table.faces.begin() + 2);  // its underside
  Soup leg = cube(0.8, 0.8, 0, 0.4);
  for (auto& p : leg.points) p[2] = -1 + 3 * p[2];  // [0.8, 1.2]^2 x [-1, 0.2]
  table.add(leg);

  const Repair_run kept = repair("table_open_underneath", table);
  EXPECT_EQ(kept.status, 3) << kept.out;
  EXPECT_TRUE(kept.reading.closed && kept.reading.valid);
  EXPECT_EQ(repair_member(kept, "status"), "complete_except_kept");
  EXPECT_EQ(repair_member(kept, "holes_filled"), "1") << kept.report;
  EXPECT_NE(repair_member(kept, "self_intersections_between_components"), "0") << kept.report;

  const Repair_run merged =
      repair("table_open_underneath_merged", table, "--merge-intersecting-solids");
  EXPECT_EQ(merged.status, 0) << merged.out;
  EXPECT_TRUE(merged.reading.closed && merged.reading.valid);
  EXPECT_EQ(repair_member(merged, "status"), "complete");
  EXPECT_EQ(repair_member(merged, "self_intersections_output"), "0") << merged.report;
}

/// The outer surface of a union of unit cells (integer corners), two outward triangles per
/// square; the cells' corners are shared points, as a voxel or CAD export writes them.
Soup voxels(const std::vector<std::array<int, 3>>& cells) {
  Soup s;
  std::map<std::array<int, 3>, std::size_t> index;
  auto point = [&](std::array<int, 3> p) {
    const auto found = index.emplace(p, s.points.size());
    if (found.second) s.points.push_back({double(p[0]), double(p[1]), double(p[2])});
    return found.first->second;
  };
  const std::set<std::array<int, 3>> filled(cells.begin(), cells.end());
  for (const auto& c : cells)
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        std::array<int, 3> next = c;
        next[axis] += side ? 1 : -1;
        if (filled.count(next)) continue;
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        std::array<int, 3> base = c;
        base[axis] += side;
        std::vector<std::size_t> q;
        for (const auto& d : {std::array<int, 2>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
          std::array<int, 3> p = base;
          p[a] += d[0];
          p[b] += d[1];
          q.push_back(point(p));
        }
        if (!side) std::swap(q[1], q[3]);  // outward: -axis
        s.faces.push_back({q[0], q[1], q[2]});
        s.faces.push_back({q[0], q[2], q[3]});
      }
  return s;
}

// One solid pinched along an edge: two cells meet only along it, a layer of cells above joins
// them. The corners at the pinch are not spikes (nothing may move them far), and the two copies
// of the pinch edge are moved apart by about 1e-6 of the diagonal, each into its own cell: the
// file read back is closed, manifold and free of intersections, with every face kept.
TEST(RealWorld, ASolidPinchedAlongAnEdgeIsMovedApartThere) {
  const Repair_run run =
      repair("pinched", voxels({{0, 0, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}));
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_EQ(run.report.find("spike_vertices_moved"), std::string::npos) << run.out;
  EXPECT_EQ(run.reading.faces, 48u);
  EXPECT_TRUE(run.reading.closed);
  EXPECT_TRUE(run.reading.manifold);
  EXPECT_EQ(run.reading.self_intersections, 0u);
  EXPECT_NE(run.out.find("contact_vertices_moved_apart 2"), std::string::npos) << run.out;
}

// The same checks on the other formats: binary STL stores every triangle's corners as floats,
// OBJ and PLY as the OFF.
TEST(RealWorld, EveryOutputFormatIsReadBackAsReported) {
  Soup cubes = cube(0, 0, 0);
  cubes.add(cube(1, 1, 1));
  for (const char* extension : {".stl", ".obj", ".ply"}) {
    repair(std::string("cubes_corner_") + (extension + 1), cubes, "", extension);
    repair(std::string("cube_binary_") + (extension + 1), cube(0.1, 0.2, 0.3, 0.7), "--binary",
           extension);
  }
}

}  // namespace
