#!/bin/sh
# Does `mesh_repair repair` grow in proportion to its input? Each kind of defect of
# scripts/make_scaling_inputs.py is made at N and 4N parts and repaired on one thread; the row
# gives both times and their ratio (about 4 when the time is proportional to the input, 16 when
# it is quadratic). The kinds are those where a quadratic pass was found and removed
# (doc/benchmarks.md, "Scaling").
# Usage: scripts/bench_scaling.sh [N]   (default 10000)
# MESH_REPAIR (default build/bin/mesh_repair).
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
TOOL=${MESH_REPAIR:-$ROOT/build/bin/mesh_repair}
N=${1:-10000}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/mesh_repair_scaling.XXXXXX")
trap 'rm -rf "$WORK"' EXIT INT TERM
seconds() { # runs the tool, prints its wall time
  start=$(date +%s.%N)
  "$TOOL" repair "$@" --threads 1 --quiet >/dev/null 2>&1 || true
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }'
}
echo "| kind | options | N | seconds | 4N | seconds | ratio |"
echo "|---|---|---|---|---|---|---|"
for row in "separate_faces:$N:" "intersecting_spheres:$((N / 25)):--merge-intersecting-solids" \
  "small_holes:$((N / 5)):" "separate_cubes:$((N / 5)):" "duplicated_faces:$((N * 2)):" \
  "overlapping_sheets:$((N * 2)):"; do
  kind=${row%%:*}
  rest=${row#*:}
  n=${rest%%:*}
  options=${rest#*:}
  python3 "$ROOT/scripts/make_scaling_inputs.py" "$kind" "$n" "$WORK/a.off" >/dev/null
  python3 "$ROOT/scripts/make_scaling_inputs.py" "$kind" $((4 * n)) "$WORK/b.off" >/dev/null
  # shellcheck disable=SC2086
  a=$(seconds "$WORK/a.off" -o "$WORK/a_out.off" $options)
  # shellcheck disable=SC2086
  b=$(seconds "$WORK/b.off" -o "$WORK/b_out.off" $options)
  ratio=$(awk -v a="$a" -v b="$b" 'BEGIN { r = (a > 0) ? b / a : 0; printf "%.1f", r }')
  echo "| $kind | ${options:--} | $n | $a | $((4 * n)) | $b | $ratio |"
done
