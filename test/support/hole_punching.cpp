// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The hole-punching helpers (hole_punching.h), compiled once for the suites.
#include "support/hole_punching.h"

#include <CGAL/Mesh_repair/internal/hole_benchmark/punch.h>
#include <CGAL/Mesh_repair/internal/hole_filling/border_cycles.h>

namespace mesh_repair_test {

std::size_t punch_hole(Support_mesh& mesh, const Support_point& center, double radius) {
  std::size_t removed = 0;
  CGAL::Mesh_repair::internal::hole_benchmark::punch_ball_hole(mesh, center, radius, &removed);
  return removed;
}

std::size_t count_border_cycles(const Support_mesh& mesh) {
  return CGAL::Mesh_repair::internal::border_cycles(mesh).size();
}

}  // namespace mesh_repair_test
