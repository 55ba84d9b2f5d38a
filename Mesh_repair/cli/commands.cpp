// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"

namespace mesh_repair_cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"check", "report every defect of a mesh (text and JSON)", check_help, run_check},
      {"repair", "repair a mesh (or a folder) into a valid watertight one", repair_help,
       run_repair},
      {"fill", "fill holes (advancing front, Liepa, ...) with exact patch checks", fill_help,
       run_fill},
      {"smooth", "micro-GA, conjugate-gradient or CGAL smoothing, triangles or quads", smooth_help,
       run_smooth},
      {"mesh-points", "mesh unorganised points (advancing front), clean and smooth",
       mesh_points_help, run_mesh_points},
      {"bench", "hole-filling fidelity benchmark against the truth (bench holes)", bench_help,
       run_bench},
      {"suppress", "remove a feature (faces, ball or box) and fill the hole; implant patches",
       suppress_help, run_suppress},
      {"stitch", "close gaps, small overlaps and T-junctions within a tolerance", stitch_help,
       run_stitch},
      {"slivers", "remove sliver triangles by node merging and edge swapping", slivers_help,
       run_slivers},
      {"optimize", "GA mesh reduction or triangle-quality improvement keeping features",
       optimize_help, run_optimize},
  };
  return table;
}

}  // namespace mesh_repair_cli
