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
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} "${cmake_args[@]}" >/dev/null
jobs=${MESH_REPAIR_JOBS:-$(nproc)}
cmake --build "$build_dir" -j "$jobs" "${target_args[@]}"
