// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_ZERO_VOLUME_WALLS_H
#define CGAL_MESH_REPAIR_INTERNAL_ZERO_VOLUME_WALLS_H

// Duplicated polygons (the same points, either orientation) are either a surface given twice,
// of which one copy stays, or a zero-volume wall between two shells (two solids sharing a
// face, each written whole), which goes entirely: the shells' faces then meet along the wall's
// outline, two per edge. Along the outline, keeping one copy leaves edges with three polygons
// and removing all leaves two, so the outline's groups choose removal; inside the wall both
// choices leave two per edge, and a choice per group kept the inner polygons of a wall larger
// than one polygon as a sheet inside the joined shells. Such groups go with the wall when the
// wall is enclosed: every edge of its outline carries at least two other polygons, so that
// nothing is left open. A surface given twice does not pass: where it ends, its edges are
// borders or meet one other surface (OpenFOAM's motorbike gives 67,000 polygons twice; taken
// for walls from the 1,061 groups where the copies meet other parts, they would all have gone).
// One rule for the soup read from a file (io.h) and for the mesh written (automatic_repair's
// coincident elements).

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// For each edge of a group's polygon, the distinct classes of polygons along it: a group of
/// duplicates counts once and has its group index as class; other polygons have classes from the
/// number of groups up.
using Classes_along_edges = std::vector<std::vector<std::size_t>>;

/// Which groups are removed whole, and how many walls (connected sets of such groups) that makes.
struct Zero_volume_walls {
  std::vector<bool> removed;  ///< by group
  std::size_t walls = 0;
};

/// A group prefers removal when that leaves fewer polygons beyond two along its edges than
/// keeping one copy does, and keeping when the reverse holds; those that prefer removal are
/// removed. A group with no preference (all its edges as crowded either way) is removed with the
/// groups it meets along edges that only the two groups carry, when that set holds a group
/// that prefers removal and is enclosed (above).
inline Zero_volume_walls choose_zero_volume_walls(const std::vector<Classes_along_edges>& groups) {
  enum Choice { keep_one, remove_all, tie };
  const std::size_t n = groups.size();
  std::vector<Choice> choice(n, tie);
  std::vector<std::vector<std::size_t>> inside_neighbours(n);
  std::vector<bool> enclosed(n, true);
  for (std::size_t g = 0; g < n; ++g) {
    std::size_t excess_keep_one = 0, excess_remove_all = 0;
    for (const auto& along : groups[g]) {
      const std::size_t others = along.empty() ? 0 : along.size() - 1;
      excess_keep_one += others + 1 > 2 ? others - 1 : 0;
      excess_remove_all += others > 2 ? others - 2 : 0;
      if (along.size() == 2 && along[0] < n && along[1] < n)
        inside_neighbours[g].push_back(along[0] == g ? along[1] : along[0]);
      else if (others < 2)
        enclosed[g] = false;
    }
    if (excess_remove_all != excess_keep_one)
      choice[g] = excess_remove_all < excess_keep_one ? remove_all : keep_one;
  }
  Zero_volume_walls result;
  result.removed.assign(n, false);
  std::vector<bool> seen(n, false);
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (choice[seed] != remove_all || seen[seed]) continue;
    // The set of groups reached through inner edges, and whether all of it is enclosed.
    std::vector<std::size_t> wall{seed}, stack{seed};
    seen[seed] = true;
    bool wall_enclosed = enclosed[seed];
    while (!stack.empty()) {
      const std::size_t g = stack.back();
      stack.pop_back();
      for (std::size_t next : inside_neighbours[g]) {
        // A neighbour that keeps one copy would be left with a bare edge.
        if (choice[next] == keep_one) wall_enclosed = false;
        if (choice[next] == keep_one || seen[next]) continue;
        seen[next] = true;
        wall_enclosed = wall_enclosed && enclosed[next];
        wall.push_back(next);
        stack.push_back(next);
      }
    }
    // Not enclosed: each group that prefers removal is a wall of its own, and the ties stay.
    for (std::size_t g : wall) {
      result.removed[g] = wall_enclosed || choice[g] == remove_all;
      result.walls += !wall_enclosed && choice[g] == remove_all ? 1 : 0;
    }
    result.walls += wall_enclosed ? 1 : 0;
  }
  return result;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_ZERO_VOLUME_WALLS_H
