#!/usr/bin/env bash
# Configures and builds Mesh_repair into build/ (Release by default). Extra arguments go to cmake.
# Usage: scripts/build.sh [--target T] [cmake -D options...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${MESH_REPAIR_BUILD_DIR:-$root/build}
target_args=()
cmake_args=()
while (($#)); do
  case "$1" in
    --target) target_args+=(--target "$2"); shift 2 ;;
    *) cmake_args+=("$1"); shift ;;
  esac
done
# Ninja for a new build folder when it is installed (scripts/setup.sh installs it): unlike make, it
# compiles a target's units without waiting for the libraries the target links, so both
# processors stay busy to the end (a clean -j2 build of the tool and the suites: 852 s with make,
# one processor idle for about 200 s of it; doc/benchmarks.md, "Compile cost"). A folder already
# configured keeps its generator (CMake refuses to change it), and a -G of the caller wins.
generator_args=()
if [[ ! -f "$build_dir/CMakeCache.txt" && " ${cmake_args[*]} " != *" -G"* ]] &&
   command -v ninja >/dev/null; then
  generator_args=(-G Ninja)
fi
cmake -S "$root" -B "$build_dir" "${generator_args[@]}" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} \
  "${cmake_args[@]}" >/dev/null
jobs=${MESH_REPAIR_JOBS:-$(nproc)}
cmake --build "$build_dir" -j "$jobs" "${target_args[@]}"
