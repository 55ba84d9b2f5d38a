#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 machine: installs what is missing, fetches the real
# meshes of libcgal-demo when the package can be downloaded, builds everything and runs ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/fetch_demo_data.sh" || true
"$root/scripts/build.sh" "$@"
cd "${MESH_REPAIR_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "${MESH_REPAIR_JOBS:-$(nproc)}" --timeout 1200
