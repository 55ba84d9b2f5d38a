// stitch_gaps: two patches of a plane with a small gap and non-matching nodes between them are
// joined into one surface (node merging, T-junction splits, gluing); then repair_t_junctions on
// a seam whose nodes do not match but whose gap is zero.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/repair_t_junctions.h>
#include <CGAL/Mesh_repair/stitch_gaps.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace MR = CGAL::Mesh_repair;

// A strip [0,1] x [y0,y1] with `cells` cells along x, appended to the soup.
void add_strip(std::vector<Point>& points, std::vector<std::vector<std::size_t>>& faces, double y0,
               double y1, int cells) {
  const std::size_t base = points.size();
  for (int i = 0; i <= cells; ++i) {
    points.emplace_back(double(i) / cells, y0, 0);
    points.emplace_back(double(i) / cells, y1, 0);
  }
  for (int i = 0; i < cells; ++i) {
    const std::size_t a = base + 2 * i, b = a + 2, c = a + 3, d = a + 1;
    faces.push_back({a, b, c});
    faces.push_back({a, c, d});
  }
}

std::size_t border_cycles(const Mesh& mesh) {
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  return cycles.size();
}

int main() {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  add_strip(points, faces, -1.0, -0.005, 4);  // lower patch, 4 cells
  add_strip(points, faces, 0.005, 1.0, 7);    // upper patch, 7 cells, 0.01 above
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  std::cout << "before: " << border_cycles(mesh) << " border cycles\n";

  const MR::Stitch_result result = MR::stitch_gaps(mesh, MR::parameters::merge_tolerance(0.02));
  std::cout << "stitch_gaps: " << result.node_merges << " node merges, " << result.t_junctions_split
            << " T-junction splits, " << result.edges_stitched << " edges glued, max move "
            << result.max_displacement << "; now " << border_cycles(mesh) << " border cycle(s), "
            << (result.valid ? "valid" : "INVALID") << "\n";

  // The default tolerance is derived from the local border edge lengths and reported.
  points.clear();
  faces.clear();
  add_strip(points, faces, -1.0, 0.0, 3);
  add_strip(points, faces, 0.0, 1.0, 5);
  Mesh seam;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, seam);
  const MR::Stitch_result t = MR::repair_t_junctions(seam);
  std::cout << "repair_t_junctions: " << t.t_junctions_split
            << " splits with derived tolerance up to " << t.merge_tolerance << "; now "
            << border_cycles(seam) << " border cycle(s)\n";
  return border_cycles(mesh) == 1 && border_cycles(seam) == 1 ? 0 : 1;
}
