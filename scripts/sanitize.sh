#!/usr/bin/env bash
# Builds with AddressSanitizer + UndefinedBehaviorSanitizer into build-asan/ and runs the suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
export MESH_REPAIR_BUILD_DIR="$root/build-asan"
export BUILD_TYPE=RelWithDebInfo
# -O1 with line tables only: what the ASan documentation recommends, and it halves the build time
# of our template-heavy translation units against -O2 -g while stack traces keep file:line.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$root/scripts/test.sh" -DMESH_REPAIR_SANITIZE=ON -DMESH_REPAIR_BUILD_BENCHMARKS=OFF \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "$@"
