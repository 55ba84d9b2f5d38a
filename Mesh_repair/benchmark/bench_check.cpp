// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_check: the cost of `mesh_repair check` (detect_defects) on a mesh of more than a million
// faces, against the time to only read and build that mesh, and against CGAL's
// self_intersections. Prints markdown rows for doc/benchmarks.md.
//
//   bench_check [IN.off] [--min-faces N] [--work DIR]
//
// IN (default: libcgal-demo's elephant-with-holes.off when found, else an icosphere) is Loop-
// subdivided until it has at least N faces (default 1,000,000), written as OFF to DIR, and that
// file is what is timed, so the load includes parsing and the polygon-soup stage like the CLI.

#include <CGAL/Mesh_repair/detect_defects.h>
#include <CGAL/Mesh_repair/generators.h>
#include <CGAL/Mesh_repair/io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <sys/resource.h>
#include <vector>

namespace {

namespace MR = CGAL::Mesh_repair;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Processor time of the whole process (all threads), seconds: on a shared machine the wall
/// clock also counts other users' work.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// Wall and processor seconds of one measured stretch.
struct Stopwatch {
  Clock::time_point wall = Clock::now();
  double cpu = cpu_seconds();
  std::pair<double, double> elapsed() const { return {seconds_since(wall), cpu_seconds() - cpu}; }
};

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

/// Times each step of detect_defects.
struct Step_timer : MR::Default_visitor {
  std::vector<std::pair<std::string, std::pair<double, double>>> steps;
  Stopwatch watch;
  void start_step(const char*) { watch = Stopwatch(); }
  void end_step(const char* name) { steps.emplace_back(name, watch.elapsed()); }
};

std::string make_input(const std::string& source, std::size_t min_faces,
                       const std::filesystem::path& work) {
  Mesh mesh;
  std::string name = "icosphere";
  if (!source.empty() && std::filesystem::exists(source)) {
    MR::Soup_repair_report soup;
    const std::string error = MR::read_mesh(source, mesh, soup);
    if (!error.empty()) throw std::runtime_error(error);
    name = std::filesystem::path(source).stem().string();
  } else {
    MR::make_sphere(mesh, Point(0, 0, 0), 1.0, 4);
  }
  int levels = 0;
  while (mesh.number_of_faces() < min_faces) {
    CGAL::Subdivision_method_3::Loop_subdivision(mesh);
    ++levels;
  }
  const std::filesystem::path path = work / (name + "_loop" + std::to_string(levels) + ".off");
  const std::string error = MR::write_mesh(path.string(), mesh);
  if (!error.empty()) throw std::runtime_error(error);
  return path.string();
}

}  // namespace

int main(int argc, char** argv) {
  std::string source = std::string(MESH_REPAIR_DEMO_DATA_DIR) + "/elephant-with-holes.off";
  std::size_t min_faces = 1000000;
  std::filesystem::path work = std::filesystem::temp_directory_path();
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--min-faces" && i + 1 < argc) {
      min_faces = std::stoul(argv[++i]);
    } else if (a == "--work" && i + 1 < argc) {
      work = argv[++i];
    } else {
      source = a;
    }
  }
  const std::string input = make_input(source, min_faces, work);

  Stopwatch watch;
  Mesh mesh;
  MR::Soup_repair_report soup;
  const std::string error = MR::read_mesh(input, mesh, soup);
  if (!error.empty()) {
    std::cerr << error << '\n';
    return 2;
  }
  const auto load = watch.elapsed();
  const double memory_after_load = peak_memory_mib();

  Step_timer without_timer;
  watch = Stopwatch();
  const auto without = MR::detect_defects(
      mesh, MR::parameters::detect_self_intersections(false).visitor(std::ref(without_timer)));
  const auto detect_without = watch.elapsed();
  const double memory_after_detect = peak_memory_mib();

  watch = Stopwatch();
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections<CGAL::Parallel_if_available_tag>(
      faces(mesh), mesh, std::back_inserter(pairs));
  const auto cgal_self_intersections = watch.elapsed();

  // CGAL's default is the sequential version; on few cores its box pass (no range copies) can
  // be the faster one, so both are the reference.
  watch = Stopwatch();
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> sequential_pairs;
  CGAL::Polygon_mesh_processing::self_intersections<CGAL::Sequential_tag>(
      faces(mesh), mesh, std::back_inserter(sequential_pairs));
  const auto cgal_sequential = watch.elapsed();

  Step_timer with_timer;
  watch = Stopwatch();
  const auto with = MR::detect_defects(mesh, CGAL::parameters::visitor(std::ref(with_timer)));
  const auto detect_with = watch.elapsed();

  const auto counts = MR::counts(without);
  std::printf(
      "input: %s (%zu vertices, %zu faces, %zu border cycles, %zu self-intersecting "
      "pairs)\n\n",
      input.c_str(), std::size_t(mesh.number_of_vertices()), std::size_t(mesh.number_of_faces()),
      counts.border_cycles, with.self_intersections.size());
  using Time = std::pair<double, double>;
  auto plus = [](Time a, Time b) { return Time{a.first + b.first, a.second + b.second}; };
  auto row = [](const char* what, Time t, Time reference, const char* reference_name) {
    std::printf("| %s | %.2f | %.2f | %.2fx | %.2fx | %s |\n", what, t.first, t.second,
                t.first / reference.first, t.second / reference.second, reference_name);
  };
  std::printf(
      "| measure | wall s | CPU s | wall ratio | CPU ratio | relative to |\n"
      "|---|---|---|---|---|---|\n");
  row("load (parse + soup stage + mesh)", load, load, "load");
  row("detect_defects, no self-intersections", detect_without, load, "load");
  row("**check, no self-intersections (load + detect)**", plus(load, detect_without), load,
      "load (goal <= 1.5)");
  row("CGAL self_intersections alone (Parallel_tag)", cgal_self_intersections, load, "load");
  row("CGAL self_intersections alone (Sequential_tag)", cgal_sequential, load, "load");
  // The reference is CGAL's faster configuration on this machine (by wall time).
  const Time cgal_best = cgal_sequential.first < cgal_self_intersections.first
                             ? cgal_sequential
                             : cgal_self_intersections;
  row("detect_defects with self-intersections", detect_with, cgal_best,
      "CGAL self_intersections, faster tag");
  row("**check with self-intersections (load + detect)**", plus(load, detect_with),
      plus(load, cgal_best), "load + CGAL self_intersections, faster tag (goal <= 1)");
  std::printf(
      "\nPeak resident memory: %.0f MiB after load, %.0f MiB after detection "
      "(whole run: %.0f MiB)\n\n",
      memory_after_load, memory_after_detect, peak_memory_mib());
  std::printf(
      "| step of detect_defects (with self-intersections) | wall s | CPU s |\n"
      "|---|---|---|\n");
  for (const auto& step : with_timer.steps)
    std::printf("| %s | %.2f | %.2f |\n", step.first.c_str(), step.second.first,
                step.second.second);
  std::remove(input.c_str());
  return 0;
}
