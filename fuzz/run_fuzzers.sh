#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan + coverage) and runs each for RUNS
# executions, seeded with the shared real scenes and fuzz/seeds_settings. Prints libFuzzer's final
# stats (the exact execution counts); any crash, leak, timeout (> 1 s) or allocation over
# 256 MB (-malloc_limit_mb: the fuzz targets' budgets allow far less) stops the run and leaves the
# input in BUILD/fuzz-artifacts/ — add it under tests/ as a regression fixture.
# Usage: fuzz/run_fuzzers.sh [RUNS=1000000] [BUILD=build-fuzz] [JOBS=1]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-1000000}
build=${2:-build-fuzz}
jobs=${3:-1}
scenes=${SHADOWLAB_SHARED_SCENES:-$(pwd)/../shared/scenes}

CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_FUZZ=ON \
  -DSHADOWLAB_SANITIZE=address,undefined,fuzzer-no-link -DSHADOWLAB_SANITIZED_TWINS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target fuzz_scene fuzz_settings

mkdir -p "$build/corpus/scene" "$build/corpus/settings" "$build/fuzz-artifacts"
if [[ -d $scenes ]]; then
  find "$scenes" \( -name '*.glb' -o -name '*.gltf' \) -size -2M -exec cp -n {} "$build/corpus/scene/" \; 2>/dev/null || true
fi
cp -n fuzz/seeds_settings/* "$build/corpus/settings/"

status=0
for target in scene settings; do
  echo "== fuzz_$target: $runs executions"
  "$build/fuzz/fuzz_$target" "$build/corpus/$target" -runs="$runs" -jobs="$jobs" -workers="$jobs" -timeout=1 \
    -rss_limit_mb=2048 -malloc_limit_mb=256 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$build/fuzz-artifacts/${target}-" 2>&1 | grep -E "^stat::|ERROR|SUMMARY|Done|DONE" || status=1
done
exit $status
