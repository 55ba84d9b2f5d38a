#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: installs what is missing, builds Release, then runs
# mesh_repair on the bundled defective CAD part (data/demo/defective_part.off): prints the defect
# report and writes the repaired mesh to build/demo/ (the build folder is $MESH_REPAIR_BUILD_DIR
# when set, as for scripts/build.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${MESH_REPAIR_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh"
# Only the tool is built. On a fresh build/ the tests, examples and benchmarks are configured off
# (a quicker configure, and no GoogleTest needed); an existing build/ keeps its options (after
# scripts/test.sh, they stay on), so neither script undoes the other.
options=(-DMESH_REPAIR_BUILD_CLI=ON)
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  options+=(-DMESH_REPAIR_BUILD_TESTS=OFF -DMESH_REPAIR_BUILD_EXAMPLES=OFF
            -DMESH_REPAIR_BUILD_BENCHMARKS=OFF)
fi
"$root/scripts/build.sh" --target mesh_repair "${options[@]}"
tool="$build_dir/bin/mesh_repair"
input="$root/data/demo/defective_part.off"
out="$build_dir/demo"
mkdir -p "$out"
echo
echo "== mesh_repair check $input"
"$tool" check "$input" --json "$out/defects_before.json" || true
if "$tool" --help | grep -q "^  repair "; then
  echo
  echo "== mesh_repair repair $input -o $out/repaired_part.off"
  status=0
  "$tool" repair "$input" -o "$out/repaired_part.off" --report "$out/repair_report.json" || status=$?
  echo
  echo "== mesh_repair check $out/repaired_part.off"
  "$tool" check "$out/repaired_part.off" --json "$out/defects_after.json" || true
  echo
  echo "repaired mesh: $out/repaired_part.off (repair exit status $status; reports in $out)"
fi
