#!/usr/bin/env bash
# Downloads Debian's libcgal-demo package and unpacks its real meshes into .cache/cgal-demo/meshes
# (git-ignored). Tests that need them skip with a message when this has not run or failed.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cache="$root/.cache/cgal-demo"
if [[ -f "$cache/meshes/elephant.off" ]]; then
  echo "fetch_demo_data: meshes already in $cache/meshes"
  exit 0
fi
mkdir -p "$cache/download"
cd "$cache/download" || exit 1
if ! ls libcgal-demo_*.deb >/dev/null 2>&1; then
  if ! apt-get download libcgal-demo >/dev/null 2>&1; then
    (apt-get update -qq >/dev/null 2>&1 || sudo apt-get update -qq >/dev/null 2>&1) || true
    if ! apt-get download libcgal-demo >/dev/null 2>&1; then
      echo "fetch_demo_data: could not download libcgal-demo; real-data tests will be skipped"
      exit 0
    fi
  fi
fi
rm -rf extracted && dpkg-deb -x libcgal-demo_*.deb extracted || exit 0
archive=$(find extracted -name data.tar.gz | head -n 1)
if [[ -z "$archive" ]]; then
  echo "fetch_demo_data: no data.tar.gz in libcgal-demo; real-data tests will be skipped"
  exit 0
fi
mkdir -p "$cache/data" && tar -xzf "$archive" -C "$cache/data"
meshes=$(find "$cache/data" -type d -name meshes | head -n 1)
rm -rf "$cache/meshes" && ln -s "$meshes" "$cache/meshes"
echo "fetch_demo_data: $(ls "$cache/meshes" | wc -l) files in $cache/meshes"
