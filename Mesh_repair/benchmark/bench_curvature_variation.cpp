// Pernot 7 / Fig. 13: curvature-variation filling (phi_F, phi_DeltaF over free or free + contour
// nodes) against CGAL's Liepa fairing at continuity 1 and 2, on the SAME refined Liepa patches.
// Prints a markdown table (medians over holes) and writes one CSV row per hole and method.
//   bench_curvature_variation [--csv FILE] [--holes N] [--radius R] [mesh.off ...]
//   bench_curvature_variation --scaling N [--scaling N2 ...]   (speed against CGAL's fair)
// Without meshes: analytic sphere and torus; with meshes: those (closed meshes are best: the
// truth is the mesh before punching).
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/hole_filling/curvature_variation.h>
#include <CGAL/Mesh_repair/internal/curvature_variation/measures.h>
#include <CGAL/Mesh_repair/internal/hole_benchmark/punch.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using halfedge_descriptor = boost::graph_traits<Mesh>::halfedge_descriptor;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Tree =
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
namespace MR = CGAL::Mesh_repair;
namespace cv = CGAL::Mesh_repair::internal::curvature_variation;
namespace PMP = CGAL::Polygon_mesh_processing;
using CGAL::Mesh_repair::internal::hole_benchmark::punch_ball_hole;

struct Method {
  std::string name;
  int cgal_continuity;  // 1 or 2 for CGAL's fair, 0 for ours
  MR::Curvature_objective objective;
  MR::Objective_nodes nodes;
  MR::Force_density density = MR::Force_density::uniform;
  bool area_normalized = false;
};

struct Row {
  std::string mesh, method;
  std::size_t hole, free_vertices;
  double normal_deviation_deg, truth_normal_deviation_deg, curvature_jump, truth_curvature_jump,
      einf;
  double seconds;  // for the whole mesh (all holes), same for every hole of the mesh
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Punches up to `count` ball holes at random vertices far from each other; returns their borders.
std::vector<halfedge_descriptor> punch_holes(Mesh& mesh, int count, double radius, unsigned seed) {
  CGAL::Random random(seed);
  std::vector<Point> centers;
  std::vector<halfedge_descriptor> borders;
  std::vector<vertex_descriptor> candidates(vertices(mesh).begin(), vertices(mesh).end());
  for (int attempt = 0; attempt < 50 * count && int(centers.size()) < count; ++attempt) {
    const Point c = mesh.point(candidates[std::size_t(random.get_int(0, int(candidates.size())))]);
    bool far = true;
    for (const Point& o : centers) far = far && CGAL::squared_distance(c, o) > 9 * radius * radius;
    if (!far) continue;
    Mesh trial = mesh;
    const halfedge_descriptor h = punch_ball_hole(trial, c, radius);
    if (h == boost::graph_traits<Mesh>::null_halfedge() || !CGAL::is_valid_polygon_mesh(trial))
      continue;
    std::size_t length = 0;
    for (auto b : CGAL::halfedges_around_face(h, trial)) {
      (void)b;
      ++length;
    }
    std::vector<halfedge_descriptor> cycles;
    PMP::extract_boundary_cycles(trial, std::back_inserter(cycles));
    if (cycles.size() != centers.size() + 1 || length < 8) continue;  // not a disc: skip
    mesh = trial;
    centers.push_back(c);
  }
  // Border halfedges of every hole, found again after all removals.
  PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
  return borders;
}

void run_mesh(const std::string& name, const Mesh& truth, int holes, double radius_fraction,
              std::vector<Row>& rows) {
  const auto box = PMP::bbox(truth);
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  Tree tree(faces(truth).first, faces(truth).second, truth);
  tree.accelerate_distance_queries();
  Mesh punched = truth;
  const auto borders = punch_holes(punched, holes, radius_fraction * diagonal, 7);
  // The same refined Liepa patches for every method.
  Mesh base = punched;
  std::vector<MR::Fill_patch<Mesh>> patches(borders.size());
  for (std::size_t i = 0; i < borders.size(); ++i)
    PMP::triangulate_and_refine_hole(base, borders[i], std::back_inserter(patches[i].faces),
                                     std::back_inserter(patches[i].vertices));
  // Reference values of the truth across the same contours: the vertices of `base` keep their
  // indices in a copy, so the truth's positions can be measured on the same patch connectivity
  // only for the outside; we report the truth's dihedral angle on the punched mesh borders.
  using MR::Curvature_objective;
  using MR::Force_density;
  using MR::Objective_nodes;
  const std::vector<Method> methods = {
      {"CGAL fair c=1", 1, Curvature_objective::forces, Objective_nodes::free_nodes},
      {"CGAL fair c=2", 2, Curvature_objective::forces, Objective_nodes::free_nodes},
      {"phi_F free", 0, Curvature_objective::forces, Objective_nodes::free_nodes,
       Force_density::cotangent, true},
      {"phi_F free+contour", 0, Curvature_objective::forces,
       Objective_nodes::free_and_contour_nodes, Force_density::cotangent, true},
      {"phi_DF free", 0, Curvature_objective::force_variation, Objective_nodes::free_nodes,
       Force_density::cotangent, true},
      {"phi_DF free+contour", 0, Curvature_objective::force_variation,
       Objective_nodes::free_and_contour_nodes, Force_density::cotangent, true},
      {"phi_DF free+contour paper q=1", 0, Curvature_objective::force_variation,
       Objective_nodes::free_and_contour_nodes, Force_density::uniform, false}};
  for (const Method& method : methods) {
    Mesh mesh = base;
    const auto start = std::chrono::steady_clock::now();
    bool ok = true;
    if (method.cgal_continuity > 0) {
      std::vector<vertex_descriptor> all;
      for (const auto& p : patches) all.insert(all.end(), p.vertices.begin(), p.vertices.end());
      ok = PMP::fair(mesh, all, CGAL::parameters::fairing_continuity(method.cgal_continuity));
    } else {
      ok = MR::deform_patches_curvature_variation(
               mesh, patches,
               MR::parameters::curvature_objective(method.objective)
                   .objective_nodes(method.nodes)
                   .force_density(method.density)
                   .area_normalized_forces(method.area_normalized))
               .solved;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!ok) std::cerr << name << ": " << method.name << " failed\n";
    for (std::size_t i = 0; i < patches.size(); ++i) {
      Row row;
      row.mesh = name;
      row.method = method.name;
      row.hole = i;
      row.free_vertices = patches[i].vertices.size();
      row.normal_deviation_deg =
          cv::contour_normal_deviation_deg(mesh, get(CGAL::vertex_point, mesh), patches[i]);
      row.curvature_jump =
          cv::contour_curvature_jump(mesh, get(CGAL::vertex_point, mesh), patches[i], diagonal);
      row.truth_normal_deviation_deg = 0;
      row.truth_curvature_jump = 0;
      double worst = 0;
      for (auto v : patches[i].vertices)
        worst = std::max(worst, std::sqrt(CGAL::to_double(tree.squared_distance(mesh.point(v)))));
      row.einf = worst / diagonal;
      row.seconds = seconds;
      rows.push_back(row);
    }
  }
}

// Speed against CGAL's fair on the same region: the free vertices are the N vertices of a sphere
// with the largest z (a cap), kept in place; only the solve is timed.
void run_scaling(const std::vector<std::size_t>& sizes) {
  std::cout
      << "| free vertices | CGAL fair c=1 (s) | CGAL fair c=2 (s) | phi_DF free+contour (s) | "
         "system nonzeros | ratio c=2 / ours |\n|---|---|---|---|---|---|\n";
  for (std::size_t n : sizes) {
    int subdivisions = 2;
    while (10 * std::pow(4.0, subdivisions) + 2 < 2.5 * double(n)) ++subdivisions;
    Mesh sphere;
    MR::make_sphere(sphere, Point(0, 0, 0), 1.0, subdivisions);
    std::vector<vertex_descriptor> by_height(vertices(sphere).begin(), vertices(sphere).end());
    std::sort(by_height.begin(), by_height.end(), [&](vertex_descriptor a, vertex_descriptor b) {
      return sphere.point(a).z() > sphere.point(b).z();
    });
    by_height.resize(n);
    MR::Fill_patch<Mesh> patch;
    patch.vertices = by_height;
    std::set<boost::graph_traits<Mesh>::face_descriptor> faces_of_patch;
    for (auto v : by_height)
      for (auto f : CGAL::faces_around_target(halfedge(v, sphere), sphere))
        faces_of_patch.insert(f);
    patch.faces.assign(faces_of_patch.begin(), faces_of_patch.end());
    double seconds[3];
    MR::Curvature_deformation_report report;
    for (int method = 0; method < 3; ++method) {
      Mesh mesh = sphere;
      const auto start = std::chrono::steady_clock::now();
      if (method < 2)
        PMP::fair(mesh, by_height, CGAL::parameters::fairing_continuity(method + 1));
      else
        report = MR::deform_patches_curvature_variation(mesh, {patch});
      seconds[method] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::cout << "| " << n << " | " << seconds[0] << " | " << seconds[1] << " | " << seconds[2]
              << " (assembly " << report.assembly_seconds << ", factorisation "
              << report.factorization_seconds << ", solve " << report.solve_seconds << ", "
              << report.preconditioned_iterations << " CG iterations) | " << report.system_nonzeros
              << " (factor " << report.factor_nonzeros << ") | " << seconds[1] / seconds[2]
              << " |\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv_path;
  int holes = 4;
  double radius = 0.08;
  std::vector<std::string> inputs;
  std::vector<std::size_t> scaling;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--csv" && i + 1 < argc)
      csv_path = argv[++i];
    else if (arg == "--scaling" && i + 1 < argc)
      scaling.push_back(std::stoul(argv[++i]));
    else if (arg == "--holes" && i + 1 < argc)
      holes = std::stoi(argv[++i]);
    else if (arg == "--radius" && i + 1 < argc)
      radius = std::stod(argv[++i]);
    else
      inputs.push_back(arg);
  }
  if (!scaling.empty()) {
    run_scaling(scaling);
    return 0;
  }
  std::vector<Row> rows;
  if (inputs.empty()) {
    Mesh sphere, torus;
    MR::make_sphere(sphere, Point(0, 0, 0), 1.0, 5);
    MR::make_torus<Mesh, Point>(torus, 1.0, 0.4, 160, 64);
    run_mesh("sphere", sphere, holes, radius, rows);
    run_mesh("torus", torus, holes, radius, rows);
  }
  for (const auto& path : inputs) {
    Mesh mesh;
    if (!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
      std::cerr << "cannot read " << path << "\n";
      return 2;
    }
    run_mesh(path.substr(path.find_last_of('/') + 1), mesh, holes, radius, rows);
  }
  if (!csv_path.empty()) {
    std::ofstream csv(csv_path);
    csv << "mesh,method,hole,free_vertices,normal_deviation_deg,curvature_jump,einf,seconds\n";
    for (const Row& r : rows)
      csv << r.mesh << ',' << r.method << ',' << r.hole << ',' << r.free_vertices << ','
          << r.normal_deviation_deg << ',' << r.curvature_jump << ',' << r.einf << ',' << r.seconds
          << '\n';
  }
  std::map<std::string, std::vector<const Row*>> by_method;
  std::vector<std::string> order;
  for (const Row& r : rows) {
    if (!by_method.count(r.method)) order.push_back(r.method);
    by_method[r.method].push_back(&r);
  }
  std::cout << "| method | holes | median normal deviation (deg) | median curvature jump x diag | "
               "median Einf / diag | total seconds |\n|---|---|---|---|---|---|\n";
  for (const auto& name : order) {
    std::vector<double> nd, cj, ei;
    std::map<std::string, double> seconds_per_mesh;
    for (const Row* r : by_method[name]) {
      nd.push_back(r->normal_deviation_deg);
      cj.push_back(r->curvature_jump);
      ei.push_back(r->einf);
      seconds_per_mesh[r->mesh] = r->seconds;
    }
    double seconds = 0;
    for (const auto& [mesh, s] : seconds_per_mesh) seconds += s;
    std::cout << "| " << name << " | " << nd.size() << " | " << std::setprecision(4) << median(nd)
              << " | " << median(cj) << " | " << median(ei) << " | " << seconds << " |\n";
  }
  return 0;
}
