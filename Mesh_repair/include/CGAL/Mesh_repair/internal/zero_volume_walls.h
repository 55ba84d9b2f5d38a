// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_ZERO_VOLUME_WALLS_H
#define CGAL_MESH_REPAIR_INTERNAL_ZERO_VOLUME_WALLS_H

// Duplicated polygons (the same points, either orientation) are either a surface given twice,
// of which one copy stays, or a zero-volume wall between two shells (two solids sharing a
// face, each written whole), which goes entirely: the shells' faces then meet along the wall's
// outline, two per edge. The choice is made per wall, not per polygon: along the outline, keeping
// one copy leaves edges with three polygons and removing all leaves two, but inside the wall both
// choices leave two, and a choice per polygon kept the inner polygons of a wall larger than one
// polygon as a sheet inside the joined shells. One rule for the soup read from a file (io.h)
// and for the mesh written (automatic_repair's coincident elements).

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
/// keeping one copy does, and keeping when the reverse holds. A group with no preference (all
/// its edges as crowded either way) is removed with the preferring groups it meets along edges
/// that only the two groups use: it lies inside their wall.
inline Zero_volume_walls choose_zero_volume_walls(const std::vector<Classes_along_edges>& groups) {
  enum Choice { keep_one, remove_all, tie };
  const std::size_t n = groups.size();
  std::vector<Choice> choice(n, tie);
  std::vector<std::vector<std::size_t>> inside_neighbours(n);
  for (std::size_t g = 0; g < n; ++g) {
    std::size_t excess_keep_one = 0, excess_remove_all = 0;
    for (const auto& along : groups[g]) {
      const std::size_t others = along.empty() ? 0 : along.size() - 1;
      excess_keep_one += others + 1 > 2 ? others - 1 : 0;
      excess_remove_all += others > 2 ? others - 2 : 0;
      if (along.size() == 2 && along[0] < n && along[1] < n)
        inside_neighbours[g].push_back(along[0] == g ? along[1] : along[0]);
    }
    if (excess_remove_all != excess_keep_one)
      choice[g] = excess_remove_all < excess_keep_one ? remove_all : keep_one;
  }
  Zero_volume_walls result;
  result.removed.assign(n, false);
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (choice[seed] != remove_all || result.removed[seed]) continue;
    std::vector<std::size_t> stack{seed};
    result.removed[seed] = true;
    while (!stack.empty()) {
      const std::size_t g = stack.back();
      stack.pop_back();
      for (std::size_t next : inside_neighbours[g])
        if (choice[next] != keep_one && !result.removed[next]) {
          result.removed[next] = true;
          stack.push_back(next);
        }
    }
    ++result.walls;
  }
  return result;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_ZERO_VOLUME_WALLS_H
