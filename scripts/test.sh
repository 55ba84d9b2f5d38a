#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 machine: installs what is missing, fetches the real
# meshes of libcgal-demo when the package can be downloaded, builds everything and runs ctest,
# then the Python tests when python/ holds any.
# Usage: scripts/test.sh [--target T] [cmake -D options...]   (passed on to scripts/build.sh)
#
# Whatever build/ (or $MESH_REPAIR_BUILD_DIR) already holds, the tests, examples and the tool are
# switched on here: scripts/demo.sh configures build/ with them off, and a cached OFF would
# otherwise leave ctest with nothing to run. The benchmarks are not tests and are not built here
# (scripts/benchmark.sh builds and runs them; .ci/run compiles them after the suite); a build/ that
# has them on keeps them. The caller's options come after ours, so they win. ctest fails when it
# finds no test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${MESH_REPAIR_BUILD_DIR:-$root/build}
# Python tests: only when python/ exists and holds pytest files.
python_tests=0
if [[ -d "$root/python" &&
      -n $(find "$root/python" \( -name 'test_*.py' -o -name '*_test.py' \) -print -quit) ]]; then
  python_tests=1
fi
if ((python_tests)); then
  "$root/scripts/setup.sh" --with-python
else
  "$root/scripts/setup.sh"
fi
"$root/scripts/fetch_demo_data.sh" || true
# The Python module is built with the rest when there are Python tests to run it.
python_option=()
((python_tests)) && python_option=(-DMESH_REPAIR_PYTHON=ON)
"$root/scripts/build.sh" -DMESH_REPAIR_BUILD_TESTS=ON -DMESH_REPAIR_BUILD_EXAMPLES=ON \
  -DMESH_REPAIR_BUILD_CLI=ON "${python_option[@]}" "$@"
cd "$build_dir"
ctest --output-on-failure --no-tests=error -j "${MESH_REPAIR_JOBS:-$(nproc)}" --timeout 1200

# Exit status 5 is pytest's "no tests collected": with test files present that means they define
# no test, a failure here as it is for ctest.
if ((python_tests)); then
  cd "$root"
  # Debian's interpreter, the one scripts/setup.sh installs python3-pytest for (a python3 earlier
  # in PATH, e.g. a pyenv one, may lack it); $PYTHON overrides.
  python=${PYTHON:-python3}
  [[ -z ${PYTHON:-} && -x /usr/bin/python3 ]] && python=/usr/bin/python3
  status=0
  # The package as built (module and Python files together in <build>/python), and the real
  # meshes where fetch_demo_data.sh put them.
  PYTHONPATH="$build_dir/python${PYTHONPATH:+:$PYTHONPATH}" \
    MESH_REPAIR_BUILD_DIR="$build_dir" \
    "$python" -m pytest -q "$root/python" || status=$?
  if ((status == 5)); then
    echo "test.sh: pytest collected no test in python/" >&2
    exit 1
  fi
  exit "$status"
fi
