#!/usr/bin/env bash
# Scan-like defects (scripts/make_scan_defects.py: spikes, jagged holes holding fragments,
# reversed and duplicated faces) on closed libcgal-demo meshes, two sets: 16 meshes x seeds 1, 2
# (1% spikes, holes up to 60 faces) and 10 other meshes x seeds 11 (2%, 100 faces) and 12 (0.5%,
# 30 faces). Runs `mesh_repair repair --batch` on each set and prints the count of each outcome.
# Usage: scripts/bench_scan_defects.sh [TOOL] [repair options] (default build/bin/mesh_repair).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tool=${1:-$root/build/bin/mesh_repair}
[[ $# -gt 0 ]] && shift
meshes=$root/.cache/cgal-demo/meshes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/set1" "$work/set2"
for m in armadillo camel cow dino elephant elk femur hand homer lion man mushroom pig \
  triceratops bull cactus; do
  for seed in 1 2; do
    python3 "$root/scripts/make_scan_defects.py" "$meshes/$m.off" "$work/set1/${m}_$seed.off" "$seed"
  done
done
for m in bear dragknob knot1 rotor sphere966 turbine couplingdown bones eight blobby; do
  python3 "$root/scripts/make_scan_defects.py" "$meshes/$m.off" "$work/set2/${m}_11.off" 11 0.02 100
  python3 "$root/scripts/make_scan_defects.py" "$meshes/$m.off" "$work/set2/${m}_12.off" 12 0.005 30
done
for set in set1 set2; do
  "$tool" repair --batch "$work/$set" --out-dir "$work/out-$set" --jobs 1 --timeout 120 "$@" \
    >/dev/null 2>&1 || true
  echo "$set: $(ls "$work/$set" | wc -l) files"
  tail -n +2 "$work/out-$set/summary.csv" | cut -d, -f2 | sort | uniq -c
  echo "  not repaired completely:"
  tail -n +2 "$work/out-$set/summary.csv" | awk -F, '$2 != "repaired" { print "   ", $1, $2 }'
done
