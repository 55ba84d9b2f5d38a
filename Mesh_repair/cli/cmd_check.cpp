// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair check: interim version (reads and reports the soup stage); detect_defects lands next.
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/io.h>

#include <iostream>

namespace mesh_repair_cli {

const char* const check_help =
    "usage: mesh_repair check IN [--json OUT.json] [--tolerance X | --tolerance-rel F]\n"
    "                        [--no-self-intersections] [--quiet]\n";

int run_check(const std::vector<std::string>& args) {
  Arguments arguments(args, {"--no-self-intersections", "--quiet"},
                      {"--json", "--tolerance", "--tolerance-rel"});
  const std::string input = arguments.single_input(check_help);
  Mesh mesh;
  CGAL::Mesh_repair::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  std::cout << input << ": " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " faces\n"
            << describe_soup_repair(soup);
  return soup.clean() ? exit_success : exit_incomplete;
}

}  // namespace mesh_repair_cli
