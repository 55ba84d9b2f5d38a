#!/bin/sh
# Builds the libFuzzer targets of test/fuzz with clang-14 (ASan + UBSan) into build-fuzz/ and
# runs each for SECONDS (default 60) with -rss_limit_mb=2048 -timeout=10. Working corpora go to
# build-fuzz/corpus/TARGET (seeded from test/data/readers and test/fuzz/corpus-regression),
# crashes, timeouts and out-of-memory inputs to build-fuzz/artifacts/TARGET/; copy each finding
# into test/fuzz/corpus-regression/ once it is fixed. Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
# FUZZ_SEED=N fixes libFuzzer's seed (CI: the same run every time); exit 1 when a target found
# something.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD="$ROOT/build-fuzz"
SECONDS_EACH=${1:-60}
[ $# -gt 0 ] && shift
TARGETS=${*:-"fuzz_read_off fuzz_read_obj fuzz_read_stl fuzz_read_ply fuzz_read_xyz fuzz_check fuzz_repair"}
JOBS=${FUZZ_BUILD_JOBS:-1}
SEED_OPTION=""
[ -n "${FUZZ_SEED:-}" ] && SEED_OPTION="-seed=$FUZZ_SEED"
FOUND=0

cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DMESH_REPAIR_FUZZ=ON \
  -DMESH_REPAIR_BUILD_CLI=OFF -DMESH_REPAIR_BUILD_TESTS=OFF -DMESH_REPAIR_BUILD_EXAMPLES=OFF \
  -DMESH_REPAIR_BUILD_BENCHMARKS=OFF -DMESH_REPAIR_USE_TBB=OFF >/dev/null
for target in $TARGETS; do
  cmake --build "$BUILD" -j"$JOBS" --target "$target"
done

for target in $TARGETS; do
  corpus="$BUILD/corpus/$target"
  artifacts="$BUILD/artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  case $target in
    fuzz_read_off) ext=off ;;
    fuzz_read_obj) ext=obj ;;
    fuzz_read_stl) ext=stl ;;
    fuzz_read_ply) ext=ply ;;
    fuzz_read_xyz) ext=xyz ;;
    *) ext="" ;;
  esac
  for f in "$ROOT"/test/data/readers/* "$ROOT"/test/fuzz/corpus-regression/*; do
    [ -f "$f" ] || continue
    # slow_*: inputs that once ran away and now take seconds in the sanitizer build (under the
    # timeout, but not by a margin a loaded CI machine keeps); the release tool replays them in
    # ctest (test_cli_robustness).
    case $(basename "$f") in slow_*) continue ;; esac
    case $f in
      *."$ext") cp "$f" "$corpus/" ;;
    esac
    if [ -z "$ext" ]; then
      # fuzz_check, fuzz_repair: the first byte chooses the format (0 OFF, 1 OBJ, 2 STL, 3 PLY).
      case $f in
        *.off) b='\000' ;; *.obj) b='\001' ;; *.stl) b='\002' ;; *.ply) b='\003' ;; *) continue ;;
      esac
      { printf "$b"; cat "$f"; } >"$corpus/$(basename "$f")"
    fi
  done
  echo "== $target: $SECONDS_EACH s"
  "$BUILD/bin/$target" "$corpus" -max_total_time="$SECONDS_EACH" -rss_limit_mb=2048 \
    -timeout=10 -max_len=65536 -artifact_prefix="$artifacts/" -print_final_stats=1 $SEED_OPTION \
    2>"$BUILD/$target.log" || { echo "$target stopped: see $BUILD/$target.log and $artifacts"; FOUND=1; }
  grep -E "^#[0-9]+.*(DONE|pulse)|stat::|ERROR|SUMMARY" "$BUILD/$target.log" | tail -8
  echo "corpus: $(ls "$corpus" | wc -l) files; findings: $(ls "$artifacts" | wc -l)"
done
exit $FOUND
