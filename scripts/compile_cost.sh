#!/usr/bin/env bash
# Compile cost of every translation unit: configures a separate build folder (default
# build-compile-cost/) with a compiler launcher that records wall time, CPU time and peak memory of
# each compilation, builds everything (tool, tests, examples, benchmarks; one job by default, so
# that the figures are not inflated by a second compiler), and prints the units, heaviest first.
# Usage: scripts/compile_cost.sh [jobs]     (MESH_REPAIR_COMPILE_COST_DIR: build folder)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=${MESH_REPAIR_COMPILE_COST_DIR:-$root/build-compile-cost}
jobs=${1:-1}
mkdir -p "$dir"
launcher="$dir/time_compiler.sh"
cat >"$launcher" <<'LAUNCHER'
#!/usr/bin/env bash
# Runs the compiler under /usr/bin/time: "wall_s cpu_s max_rss_kb object" per unit.
out=""; prev=""
for a in "$@"; do [[ "$prev" == "-o" ]] && out="$a"; prev="$a"; done
/usr/bin/time -a -o "$COMPILE_COST_LOG" -f "%e %U %M $out" "$@"
LAUNCHER
chmod +x "$launcher"
export COMPILE_COST_LOG="$dir/compile_cost.log"
rm -f "$COMPILE_COST_LOG"
cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" \
  -DMESH_REPAIR_BUILD_TESTS=ON -DMESH_REPAIR_BUILD_EXAMPLES=ON -DMESH_REPAIR_BUILD_BENCHMARKS=ON \
  -DMESH_REPAIR_BUILD_CLI=ON >/dev/null
cmake --build "$dir" --clean-first -j "$jobs" >/dev/null
echo "| unit | CPU s | peak MB |"
echo "|---|---|---|"
sort -k2 -n -r "$COMPILE_COST_LOG" | awk '{ n = split($4, p, "/"); printf "| %s | %.0f | %.0f |\n", p[n], $2, $3 / 1024 }'
awk '{ cpu += $2; if ($3 > peak) peak = $3 } END { printf "\ntotal: %.0f s of CPU, largest unit %.0f MB\n", cpu, peak / 1024 }' "$COMPILE_COST_LOG"
