#!/usr/bin/env bash
# Installs the Debian packages Mesh_repair needs, only those that are missing.
# Usage: scripts/setup.sh [--with-plots] [--with-format] [--with-python] [--with-fuzz]
#   --with-plots   adds python3-matplotlib for the bench plots and the pictures of filled holes
#   --with-format  adds clang-format for scripts/check_format.sh (CI)
#   --with-python  adds pybind11-dev, python3-numpy, python3-pytest and python3-distributed (Dask)
#                  for python/ and its tests
#   --with-fuzz    adds clang-14 and libclang-rt-14-dev for the libFuzzer targets (scripts/fuzz.sh)
set -euo pipefail

packages=(cmake g++ make ninja-build libcgal-dev libopenmesh-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev
          libtbb-dev libgtest-dev googletest libbenchmark-dev)
for arg in "$@"; do
  case "$arg" in
    --with-plots) packages+=(python3-matplotlib) ;;
    --with-format) packages+=(clang-format) ;;
    --with-python) packages+=(pybind11-dev python3-numpy python3-pytest python3-distributed) ;;
    --with-fuzz) packages+=(clang-14 libclang-rt-14-dev) ;;
    *)
      echo "setup: unknown option $arg (use --with-plots, --with-format, --with-python, --with-fuzz)" >&2
      exit 2
      ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all required packages are installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
