#!/usr/bin/env bash
# Scan-like holes on held-out closed meshes of libcgal-demo: 3 holes of radius 0.06 x diagonal
# punched by scripts/fold_hole_borders.py, every third border vertex pushed outwards by 1.5 mean
# edge lengths so its faces fold over the surface. Prints, per case, the holes plain `fill`
# leaves open and what `repair` (which grows failed holes and replaces self-intersecting faces)
# leaves. Usage: scripts/bench_folded_holes.sh [TOOL] (default build/bin/mesh_repair).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tool=${1:-$root/build/bin/mesh_repair}
meshes=$root/.cache/cgal-demo/meshes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-24s %12s %14s %7s %6s %s\n' case fill_failed repair_failed closed valid self_intersections
for m in fandisk femur bunny00 elephant armadillo ChineseDragon-10kv; do
  for seed in 1 2; do
    case=$work/$m-$seed
    python3 "$root/scripts/fold_hole_borders.py" "$meshes/$m.off" "$case.off" 0.06 "$seed" >/dev/null
    "$tool" fill "$case.off" -o "$case.fill.off" --quiet --report "$case.fill.json" >/dev/null || true
    "$tool" repair "$case.off" -o "$case.rep.off" --quiet --report "$case.rep.json" >/dev/null || true
    python3 - "$case" "$m-$seed" <<'PY'
import json, sys
case, name = sys.argv[1:3]
fill = json.load(open(case + ".fill.json"))["result"]
rep = json.load(open(case + ".rep.json"))["repair"]
print(f"{name:24s} {fill['failed']:12d} {rep['holes_failed']:14d} {str(rep['closed']):>7s} "
      f"{str(rep['valid']):>6s} {rep['self_intersections_input']} -> {rep['self_intersections_output']}")
PY
  done
done
