#!/usr/bin/env bash
# Checks that every tracked *.h and *.cpp file is formatted as the repository's .clang-format says
# (clang-format --dry-run -Werror). Prints the files that are not, and exits 1 when there are any.
# Usage: scripts/check_format.sh [--verbose]   (--verbose also prints clang-format's diagnostics)
#   CLANG_FORMAT=clang-format-14   the binary to use (default: clang-format)
# To fix a file: clang-format -i FILE (the style file is found from the file's folder upwards).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
clang_format=${CLANG_FORMAT:-clang-format}
if ! command -v "$clang_format" >/dev/null; then
  echo "check_format: $clang_format not found (Debian: apt-get install clang-format)" >&2
  exit 2
fi
verbose=0
[[ "${1:-}" == "--verbose" ]] && verbose=1

bad=()
checked=0
while IFS= read -r -d '' file; do
  checked=$((checked + 1))
  if ! diagnostics=$("$clang_format" --style=file --dry-run -Werror "$file" 2>&1); then
    bad+=("$file")
    ((verbose)) && printf '%s\n' "$diagnostics" >&2
  fi
done < <(git ls-files -z -- '*.h' '*.cpp')

if ((${#bad[@]})); then
  echo "check_format: ${#bad[@]} of $checked files are not formatted ($("$clang_format" --version)):"
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "check_format: all $checked files formatted"
