#!/usr/bin/env bash
# Compile cost of a user's translation unit (issue 17's goals): one unit that calls
# `fill_holes(Surface_mesh<Epick>&)`, one that calls `automatic_repair` on it, each compiled at
# -O1 under /usr/bin/time, in the two ways the library is used:
#   - with the compiled core (CGAL_MESH_REPAIR_COMPILED_CORE, what the tool, the tests and the
#     examples built in this tree get from linking mesh_repair_core: the operators are extern
#     templates, instantiated once in the core);
#   - header-only (what a project gets from an installed package: every operator instantiated
#     in the unit).
# Prints "mode unit CPU-s peak-MB" per unit. Usage: scripts/consumer_compile_cost.sh [CXX]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cxx=${1:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/fill_unit.cpp" <<'EOF'
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/fill_holes.h>
#include <CGAL/Surface_mesh.h>
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
std::size_t fill(Mesh& mesh) { return CGAL::Mesh_repair::fill_holes(mesh).filled; }
EOF
cat >"$work/repair_unit.cpp" <<'EOF'
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_repair/automatic_repair.h>
#include <CGAL/Surface_mesh.h>
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
bool repair(Mesh& mesh) { return CGAL::Mesh_repair::automatic_repair(mesh).complete(); }
EOF
flags=(-std=c++17 -O1 -DNDEBUG -frounding-math -DCGAL_EIGEN3_ENABLED -DCGAL_USE_GMPXX=1
  -I"$root/Mesh_repair/include" -isystem /usr/include/eigen3)
echo "| mode | unit | CPU s | peak MB |"
echo "|---|---|---|---|"
for mode in compiled_core header_only; do
  extra=()
  [[ $mode == compiled_core ]] && extra=(-DCGAL_MESH_REPAIR_COMPILED_CORE)
  for unit in fill_unit repair_unit; do
    /usr/bin/time -o "$work/time" -f "%U %M" "$cxx" "${flags[@]}" "${extra[@]}" \
      -c "$work/$unit.cpp" -o "$work/$unit.o"
    read -r cpu rss <"$work/time"
    printf "| %s | %s | %.1f | %.0f |\n" "$mode" "$unit" "$cpu" "$((rss / 1024))"
  done
done
