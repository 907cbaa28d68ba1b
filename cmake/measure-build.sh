#!/usr/bin/env bash
# Measures a clean build the way docs/build-times.md reports it: configure, then `--target shadowlab`
# (the README's run command), then everything else (the README's test command builds both), each
# with its CPU time (user + sys of every process it starts) and wall time, ccache off, and every
# compile and link step's CPU time (cmake/time-launcher.sh) for the per-target table.
#   cmake/measure-build.sh BUILD_DIR OUT_DIR [cmake options...]
# OUT_DIR gets configure.time, shadowlab.time, all.time ("user sys wall" in seconds), steps.tsv
# and summary.txt. BUILD_DIR is deleted first.
set -euo pipefail
if (($# < 2)); then
  echo "usage: $0 BUILD_DIR OUT_DIR [cmake options...]" >&2
  exit 2
fi
src=$(cd "$(dirname "$0")/.." && pwd)
build=$1
out=$2
shift 2
mkdir -p "$out"
out=$(cd "$out" && pwd)
launcher=$src/cmake/time-launcher.sh
export CCACHE_DISABLE=1 SHADOWLAB_TIME_LOG=$out/steps.tsv
rm -rf "$build" "$SHADOWLAB_TIME_LOG"
timed() {
  local name=$1
  shift
  /usr/bin/time -f "%U %S %e" -o "$out/$name.time" "$@" >"$out/$name.log" 2>&1
}
timed configure cmake -S "$src" -B "$build" -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" \
  -DCMAKE_CXX_LINKER_LAUNCHER="$launcher" "$@"
timed shadowlab cmake --build "$build" -j"$(nproc)" --target shadowlab
timed all cmake --build "$build" -j"$(nproc)"
python3 "$src/cmake/summarize-steps.py" "$out" | tee "$out/summary.txt"
