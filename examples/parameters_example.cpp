// Mesh_repair's named parameters chain with CGAL's: our own options (merge_tolerance,
// fill_method, ...) and CGAL's (random_seed, geom_traits, vertex_point_map, ...) in one pack.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/parameters.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace MR = CGAL::Mesh_repair;

template <class NamedParameters>
void show(const Mesh& mesh, const NamedParameters& np) {
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double tolerance =
      choose_parameter(get_parameter(np, MR::internal_np::merge_tolerance_t{}), -1.0);
  const unsigned seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, mesh));
  std::cout << "merge_tolerance=" << tolerance << " random_seed=" << seed
            << " first point=" << get(vpm, *vertices(mesh).begin()) << '\n';
}

int main() {
  Mesh sphere;
  MR::make_sphere(sphere, Kernel::Point_3(0, 0, 0), 1.0, 2);
  std::cout << "sphere: " << num_vertices(sphere) << " vertices, " << num_faces(sphere)
            << " faces\n";
  show(sphere, MR::parameters::merge_tolerance(0.01).random_seed(7u));
  show(sphere, MR::parameters::extend(CGAL::parameters::vertex_point_map(sphere.points()))
                   .merge_tolerance(0.5));
  return num_faces(sphere) == 320 ? 0 : 1;
}
