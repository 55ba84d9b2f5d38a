#!/usr/bin/env bash
# Regenerates the "Hole filling fidelity" section of doc/benchmarks.md and its plots in
# doc/images/ with `mesh_repair bench holes` (doc/bench_holes.md).
# Usage: scripts/bench_holes.sh [--quick | --held-out | --self-validation]
#   MESH_REPAIR=path/to/mesh_repair  (default: build/bin/mesh_repair, built if missing)
#   BENCH_METHODS=a,b,...            (default: all; --held-out: shape_prediction,liepa_c1,liepa_c2)
# --quick: sphere and torus only, one seed (a smoke run; doc/ is not touched).
# --self-validation: the tuning and held-out suites of doc/fill_holes.md ("Self-validated
#   choice") into bench-out/self-validation-*, with scripts/compare_fills.py; doc/ is not touched.
# --held-out: holes the methods were not tuned on (eight meshes, seeds 4-6, and jagged borders
#   with seeds 1-3) into bench-out/held-out-{disc,jagged}; prints the medians over the holes
#   every method closed and the time growth (doc/shape_prediction.md); doc/ is not touched.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tool=${MESH_REPAIR:-$root/build/bin/mesh_repair}
if [[ ! -x "$tool" ]]; then
  "$root/scripts/build.sh" --target mesh_repair
fi
meshes_dir=$root/.cache/cgal-demo/meshes
[[ -f "$meshes_dir/elephant.off" ]] || "$root/scripts/fetch_demo_data.sh"

if [[ "${1:-}" == "--self-validation" ]]; then
  # The two suites of doc/fill_holes.md, "Self-validated choice": the five meshes the methods were
  # tuned on (seeds 1-3) and eight they never saw (seeds 7-8), per-case ratios by compare_fills.py.
  methods=${BENCH_METHODS:-liepa_c1,liepa_c2,shape_prediction,curvature_variation,self_validated,auto}
  for suite in tuning held-out; do
    if [[ $suite == tuning ]]; then
      names="elephant bunny00 head femur fandisk"; seeds=1,2,3
    else
      names="armadillo dino homer knot1 bear man triceratops blobby"; seeds=7,8
    fi
    meshes=()
    for name in $names; do
      [[ -f "$meshes_dir/$name.off" ]] && meshes+=(--mesh "$meshes_dir/$name.off")
    done
    out=$root/bench-out/self-validation-$suite
    "$tool" bench holes --holes 3 --radius 0.05,0.12 --seeds "$seeds" --methods "$methods" \
      --out "$out" --no-plots --no-pictures --quiet "${meshes[@]}"
    echo "### $suite suite ($names; seeds $seeds)"
    /usr/bin/env python3 "$root/scripts/compare_fills.py" "$out/results.jsonl"
    sed -n '/^Medians over the/,/^Holes not closed/p' "$out/table.md" | sed '$d'
    echo
  done
  exit 0
fi

if [[ "${1:-}" == "--held-out" ]]; then
  methods=${BENCH_METHODS:-shape_prediction,liepa_c1,liepa_c2}
  meshes=()
  for name in elephant bunny00 head femur fandisk camel bull cow; do
    [[ -f "$meshes_dir/$name.off" ]] && meshes+=(--mesh "$meshes_dir/$name.off")
  done
  for shape in disc jagged; do
    seeds=4,5,6
    [[ $shape == jagged ]] && seeds=1,2,3
    out=$root/bench-out/held-out-$shape
    "$tool" bench holes --shape "$shape" --holes 3 --radius 0.05,0.12 --seeds "$seeds" \
      --methods "$methods" --out "$out" --no-plots --no-pictures --quiet "${meshes[@]}"
    echo "### held-out, $shape holes, seeds $seeds"
    sed -n '/^Medians over the/,/^Holes not closed/p' "$out/table.md" | sed '$d'
    /usr/bin/env python3 "$root/scripts/bench_growth.py" "$out/results.jsonl"
    echo
  done
  exit 0
fi

methods=${BENCH_METHODS:-all}
out=$root/bench-out/holes
args=(holes --analytic sphere --analytic torus --holes 3 --radius 0.05,0.12 --seeds 1,2,3
      --methods "$methods" --out "$out")
quick=0
if [[ "${1:-}" == "--quick" ]]; then
  quick=1
  args=(holes --analytic sphere --analytic torus --holes 2 --radius 0.05,0.12 --seeds 1
        --methods "$methods" --out "$out")
else
  for name in elephant bunny00 head femur fandisk; do
    if [[ -f "$meshes_dir/$name.off" ]]; then
      args+=(--mesh "$meshes_dir/$name.off")
    else
      echo "bench_holes: $name.off not found in $meshes_dir; skipped" >&2
    fi
  done
fi

start=$(date +%s)
started=$(date -u '+%Y-%m-%d %H:%M UTC')
load=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$root" diff --quiet HEAD -- 2>/dev/null || commit="$commit with uncommitted changes"
"$tool" bench "${args[@]}"
seconds=$(($(date +%s) - start))
((quick)) && exit 0

# Plots: a few small ones are kept in doc/images.
mkdir -p "$root/doc/images"
for plot in bar_einf_rel bar_e2_rel bar_hausdorff_rel bar_normal_deviation_max_deg bar_min_alpha \
            bar_seconds error_vs_size error_vs_radius; do
  [[ -f "$out/$plot.png" ]] && cp "$out/$plot.png" "$root/doc/images/bench_holes_$plot.png"
done

# Replace only our own section of doc/benchmarks.md (from its heading to the next "## ").
section=$(mktemp)
command_line="mesh_repair bench ${args[*]}"
command_line=${command_line//$root\//}
{
  echo "## Hole filling fidelity (mesh_repair bench holes)"
  echo
  echo "Measured $started at commit \`$commit\`. Regenerate with \`scripts/bench_holes.sh\`"
  echo "($seconds s wall-clock on the 2-core machine, load average $load at the start). Command"
  echo "(paths relative to the repository):"
  echo
  echo '```'
  echo "$command_line"
  echo '```'
  echo
  echo "Definitions of every measure: [bench_holes.md](bench_holes.md). Distances are divided by"
  echo "the bounding-box diagonal; on sphere and torus the E norms use the exact surface."
  echo
  sed -n '/^| method |/,$p' "$out/table.md"
  echo
  echo "Time of each method against CGAL's continuity 1 and 2, per hole, over the holes both"
  echo "closed, and its growth with the border size (\`scripts/bench_growth.py\`: the ratio grows"
  echo "when the 95% interval of its slope lies above 0; \"own fill\": the holes a method with"
  echo "fallbacks filled itself):"
  echo
  /usr/bin/env python3 "$root/scripts/bench_growth.py" "$out/results.jsonl"
  echo
  for plot in bar_einf_rel bar_normal_deviation_max_deg bar_min_alpha bar_seconds error_vs_size \
              error_vs_radius; do
    [[ -f "$root/doc/images/bench_holes_$plot.png" ]] &&
      echo "![$plot](images/bench_holes_$plot.png)"
  done
  echo
} >"$section"
/usr/bin/env python3 - "$root/doc/benchmarks.md" "$section" <<'EOF'
import sys
doc_path, section_path = sys.argv[1], sys.argv[2]
heading = "## Hole filling fidelity (mesh_repair bench holes)"
doc = open(doc_path).read()
section = open(section_path).read()
if heading in doc:
    start = doc.index(heading)
    end = doc.find("\n## ", start + len(heading))
    doc = doc[:start] + section.rstrip("\n") + "\n" + (doc[end:] if end >= 0 else "")
else:
    doc = doc.rstrip("\n") + "\n\n" + section
open(doc_path, "w").write(doc)
EOF
rm -f "$section"
echo "bench_holes: doc/benchmarks.md and doc/images/bench_holes_*.png updated ($seconds s)"
