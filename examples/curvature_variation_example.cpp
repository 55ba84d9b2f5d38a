// Fills two holes of a sphere with Pernot's curvature-variation method, cleaning their contours
// first, in one deformation step, with a point constraint pulling the first patch outwards.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/clean_hole_contour.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/hole_filling/curvature_variation.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using halfedge_descriptor = boost::graph_traits<Mesh>::halfedge_descriptor;
namespace MR = CGAL::Mesh_repair;

int main() {
  Mesh mesh;
  MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  // Two holes: the faces around the poles.
  std::vector<boost::graph_traits<Mesh>::face_descriptor> doomed;
  for (auto f : faces(mesh)) {
    bool near_pole = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      near_pole = near_pole && std::abs(CGAL::to_double(mesh.point(v).z())) > 0.8;
    if (near_pole) doomed.push_back(f);
  }
  for (auto f : doomed) CGAL::Euler::remove_face(halfedge(f, mesh), mesh);

  std::vector<halfedge_descriptor> holes;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(holes));
  for (auto& h : holes) {
    const auto cleaning = MR::clean_hole_contour(mesh, h);
    std::cout << "contour: " << cleaning.border_edges_before << " -> "
              << cleaning.border_edges_after << " border edges, " << cleaning.badly_oriented_removed
              << " badly oriented triangles removed, " << cleaning.edges_split << " split, "
              << cleaning.edges_collapsed << " collapsed\n";
    h = cleaning.border_halfedge;  // the given halfedge may have been removed
  }

  MR::Fill_constraints<Point> constraints;
  constraints.points.push_back(Point(0, 0, 1.1));
  std::vector<MR::Fill_patch<Mesh>> patches;
  MR::Curvature_deformation_report deformation;
  const MR::Fill_result result = MR::fill_holes_curvature_variation(
      mesh, holes, patches,
      MR::parameters::curvature_objective(MR::Curvature_objective::force_variation)
          .objective_nodes(MR::Objective_nodes::free_and_contour_nodes)
          .fill_constraints(constraints)
          .deformation_report(&deformation));
  std::cout << result.filled << " of " << holes.size() << " holes filled; "
            << deformation.free_vertices << " free vertices, " << deformation.factorizations
            << " factorisation, constraint residual " << deformation.max_constraint_residual
            << "\n";
  return result.all_filled() && CGAL::is_closed(mesh) ? 0 : 1;
}
