// Reads each file given with our strict readers only (no soup repair) and prints points,
// polygons and the error line, for scripts/measure_readers.sh (memory and time per input byte).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/internal/readers/read_soup.h>
#include <CGAL/Mesh_repair/internal/soup_validation.h>

#include <cstdio>
#include <iostream>
#include <sys/stat.h>

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

int main(int argc, char** argv) {
  namespace R = CGAL::Mesh_repair::internal::readers;
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string name = argv[i];
    std::FILE* file = std::fopen(name.c_str(), "rb");
    struct stat info;
    if (!file || ::fstat(::fileno(file), &info) != 0) {
      std::cout << name << ": cannot be opened\n";
      status = 2;
      continue;
    }
    R::Byte_reader in(file, std::uintmax_t(info.st_size));
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    R::Read_counts counts;
    const std::string error = R::read_soup(in, CGAL::Mesh_repair::internal::format_name(name), name,
                                           points, polygons, counts);
    std::fclose(file);
    std::cout << name << ": " << info.st_size << " bytes, " << points.size() << " points, "
              << polygons.size() << " polygons" << (error.empty() ? "" : "; " + error) << '\n';
    if (!error.empty()) status = 2;
  }
  return status;
}
