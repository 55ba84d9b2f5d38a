#!/bin/sh
# Cracked copies of closed meshes (scripts/make_cracked_meshes.py: cut across by a random plane,
# the halves GAP x diagonal apart, every 3rd node of one side split into a T-junction), repaired
# by `mesh_repair repair` with its defaults and by `mesh_repair stitch --tolerance 2xGAP`; each
# output read back by `mesh_repair check`. Prints one Markdown row per case and a total.
# Usage: scripts/bench_cracks.sh [MESH.off ...]   (default: the held-out libcgal-demo meshes below)
# MESH_REPAIR (default build/bin/mesh_repair), GAPS (default "0.001 0.003"), SEEDS (default "1 2").
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
TOOL=${MESH_REPAIR:-$ROOT/build/bin/mesh_repair}
DEMO=$ROOT/.cache/cgal-demo/meshes
GAPS=${GAPS:-"0.001 0.003"}
SEEDS=${SEEDS:-"1 2"}
[ $# -gt 0 ] || set -- "$DEMO/armadillo.off" "$DEMO/bear.off" "$DEMO/cactus.off" "$DEMO/dino.off" \
  "$DEMO/eight.off" "$DEMO/joint.off" "$DEMO/knot2.off" "$DEMO/oblong.off"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/mesh_repair_cracks.XXXXXX")
trap 'rm -rf "$WORK"' EXIT INT TERM
cases=0 repaired=0 stitched=0
echo "| mesh | gap / diagonal | seed | repair: exit, border cycles, self-intersections | stitch 2x gap: border cycles, self-intersections | repair seconds |"
echo "|---|---|---|---|---|---|"
for mesh in "$@"; do
  name=$(basename "$mesh" .off)
  for gap in $GAPS; do
    for seed in $SEEDS; do
      cracked="$WORK/${name}_${gap}_$seed.off"
      summary=$(python3 "$ROOT/scripts/make_cracked_meshes.py" "$mesh" "$cracked" "$gap" "$seed")
      absolute=$(echo "$summary" | sed -n 's/.*gap \([^ ]*\) (.*/\1/p')
      start=$(date +%s.%N)
      status=0
      "$TOOL" repair "$cracked" -o "$WORK/repaired.off" --quiet >/dev/null 2>&1 || status=$?
      seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
      r=$("$TOOL" check "$WORK/repaired.off" 2>/dev/null | sed -n 's/^border cycles: *\([0-9]*\).*/\1/p;s/^self-intersections: *\([0-9]*\).*/\1/p' | tr '\n' ' ')
      "$TOOL" stitch "$cracked" -o "$WORK/stitched.off" --quiet \
        --tolerance "$(awk -v g="$absolute" 'BEGIN { print 2 * g }')" >/dev/null 2>&1 || true
      s=$("$TOOL" check "$WORK/stitched.off" 2>/dev/null | sed -n 's/^border cycles: *\([0-9]*\).*/\1/p;s/^self-intersections: *\([0-9]*\).*/\1/p' | tr '\n' ' ')
      set -- $r; rc=$1 rs=$2
      cases=$((cases + 1))
      [ "$status" = 0 ] && [ "$rc" = 0 ] && [ "$rs" = 0 ] && repaired=$((repaired + 1))
      set -- $s; sc=$1 ss=$2
      [ "$sc" = 0 ] && [ "$ss" = 0 ] && stitched=$((stitched + 1))
      printf '| %s | %s | %s | %s, %s, %s | %s, %s | %.2f |\n' "$name" "$gap" "$seed" "$status" "$rc" "$rs" "$sc" "$ss" "$seconds"
      rm -f "$WORK/repaired.off" "$WORK/stitched.off" "$cracked"
    done
  done
done
echo
echo "closed with 0 self-intersections: repair $repaired / $cases, stitch 2x gap $stitched / $cases"
