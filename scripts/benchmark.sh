#!/usr/bin/env bash
# Builds and runs the benchmark programs of Mesh_repair/benchmark/ and regenerates their blocks
# of doc/benchmarks.md: each benchmark's block, between the lines
#   <!-- benchmark.sh NAME begin -->  and  <!-- benchmark.sh NAME end -->,
# is replaced by the date, the commit, the load, the commands and their output (markdown tables).
# Anything written by hand inside a block is lost; write it around the block instead.
#
# Usage: scripts/benchmark.sh [--dry-run] [--no-doc] [NAME...]
#   NAME: check repair stitch fill mga_smooth shape_prediction curvature_variation optimize
#         (default: all of them; "holes" runs scripts/bench_holes.sh, which owns its section)
#   --dry-run  print the commands, build and run nothing
#   --no-doc   run, keep the outputs in bench-out/benchmarks/, leave doc/ alone
#   MESH_REPAIR_BUILD_DIR  build folder (default build/), MESH_REPAIR_JOBS build jobs
# Several of these take minutes and most of the machine (check and optimize build meshes of over
# a million faces); run them on a quiet machine, one at a time, and say so in the doc when not.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build_dir=${MESH_REPAIR_BUILD_DIR:-$root/build}
bin=${build_dir#"$root"/}/bin # shown relative to the repository when it is inside it
data=.cache/cgal-demo/meshes
out=bench-out/benchmarks
all=(check repair stitch fill mga_smooth shape_prediction curvature_variation optimize)

# The commands of each benchmark, one a line, run from the repository root.
commands_for() {
  case "$1" in
    check) echo "$bin/bench_check --work $out/work" ;;
    repair) echo "$bin/bench_repair" ;;
    stitch) echo "$bin/bench_stitch speed 100000 1000000" ;;
    fill)
      echo "$bin/bench_fill --benchmark_filter='BM_(advancing_front|liepa)/'" \
        "--benchmark_counters_tabular=true"
      ;;
    mga_smooth) echo "$bin/bench_mga_smooth $data 2 fandisk.off,femur.off,armadillo.off 3" ;;
    shape_prediction) echo "$bin/bench_shape_prediction" ;;
    curvature_variation)
      echo "$bin/bench_curvature_variation --holes 6 --radius 0.08 --csv $out/cv_r08.csv"
      echo "$bin/bench_curvature_variation --holes 6 --radius 0.12 --csv $out/cv_r12.csv"
      echo "$bin/bench_curvature_variation --holes 6 --radius 0.06 --csv $out/cv_real.csv" \
        "$data/elephant.off $data/fandisk.off $data/head.off"
      echo "$bin/bench_curvature_variation --scaling 1000 --scaling 5000 --scaling 20000" \
        "--scaling 50000 --scaling 100000"
      ;;
    optimize) echo "$bin/bench_optimize" ;;
    *) return 1 ;;
  esac
}

dry_run=0
update_doc=1
names=()
for arg in "$@"; do
  case "$arg" in
    --dry-run) dry_run=1 ;;
    --no-doc) update_doc=0 ;;
    -h | --help)
      sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    holes) names+=(holes) ;;
    *)
      if ! commands_for "$arg" >/dev/null; then
        echo "benchmark.sh: unknown benchmark '$arg' (known: ${all[*]} holes)" >&2
        exit 2
      fi
      names+=("$arg")
      ;;
  esac
done
((${#names[@]})) || names=("${all[@]}")

if ((dry_run)); then
  for name in "${names[@]}"; do
    if [[ $name == holes ]]; then
      echo "holes: scripts/bench_holes.sh"
      continue
    fi
    while IFS= read -r command; do echo "$name: $command"; done < <(commands_for "$name")
  done
  exit 0
fi

# Build every program asked for in one go (Release, benchmarks on).
targets=()
for name in "${names[@]}"; do
  [[ $name == holes ]] || targets+=(--target "bench_$name")
done
if ((${#targets[@]})); then
  "$root/scripts/build.sh" "${targets[@]}" -DMESH_REPAIR_BUILD_BENCHMARKS=ON
fi
[[ -f "$data/elephant.off" ]] || "$root/scripts/fetch_demo_data.sh" || true
mkdir -p "$out/work"

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- 2>/dev/null || commit="$commit with uncommitted changes"

for name in "${names[@]}"; do
  if [[ $name == holes ]]; then
    "$root/scripts/bench_holes.sh"
    continue
  fi
  result=$out/$name.md
  block=$(mktemp)
  load=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
  started=$(date -u '+%Y-%m-%d %H:%M UTC')
  start=$(date +%s)
  : >"$result"
  while IFS= read -r command; do
    echo "benchmark.sh: $command" >&2
    if [[ $name == fill ]]; then # Google Benchmark's console table, not markdown
      { echo '```'; eval "$command" </dev/null; echo '```'; } >>"$result"
    else
      eval "$command" </dev/null >>"$result"
    fi
    echo >>"$result"
  done < <(commands_for "$name")
  seconds=$(($(date +%s) - start))
  {
    echo "<!-- benchmark.sh $name begin -->"
    echo "Measured $started at commit \`$commit\`, load average $load on $(nproc) cores" \
      "at the start, $seconds s; regenerate with \`scripts/benchmark.sh $name\`:"
    echo
    echo '```'
    commands_for "$name"
    echo '```'
    echo
    cat "$result"
    echo "<!-- benchmark.sh $name end -->"
  } >"$block"
  if ((update_doc)); then
    python3 - "$root/doc/benchmarks.md" "$block" "$name" <<'EOF'
import sys
doc_path, block_path, name = sys.argv[1:4]
begin, end = f"<!-- benchmark.sh {name} begin -->", f"<!-- benchmark.sh {name} end -->"
doc = open(doc_path).read()
block = open(block_path).read().rstrip("\n")
if begin in doc and end in doc:
    start = doc.index(begin)
    stop = doc.index(end, start) + len(end)
    doc = doc[:start] + block + doc[stop:]
else:
    doc = doc.rstrip("\n") + f"\n\n## bench_{name}\n\n" + block + "\n"
open(doc_path, "w").write(doc)
EOF
    echo "benchmark.sh: $name done in $seconds s; doc/benchmarks.md updated ($result)"
  else
    cp "$block" "$result"
    echo "benchmark.sh: $name done in $seconds s; output in $result"
  fi
  rm -f "$block"
done
