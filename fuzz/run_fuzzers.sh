#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan + coverage) and runs each for RUNS
# executions, seeded with the shared real scenes (files < 2 MB), the shared fuzz finds, the scene
# regression fixtures and fuzz/seeds_settings. Prints libFuzzer's final stats for each target (stat::number_of_executed_units,
# stat::peak_rss_mb, ...) and the wall time; the whole log is in BUILD/fuzz-TARGET.log. Any crash,
# leak, timeout (> 1 s) or allocation over 256 MB (-malloc_limit_mb: the targets' budgets allow far
# less) stops that target's run, leaves the input in BUILD/fuzz-artifacts/ and makes the script
# exit 1 — copy the input into tests/fuzz_regressions/TARGET/ so CTest replays it from then on.
# Usage: fuzz/run_fuzzers.sh [RUNS=1000000] [BUILD=build-fuzz] [TARGETS="scene settings"]
# Environment: BUILD_JOBS (default nproc), SHADOWLAB_FUZZ_FINDS (default: fuzz-finds beside the
# scenes folder), TIMEOUT_SECONDS (libFuzzer's -timeout, wall clock; default 1: raise it on a
# machine so loaded that a 20 ms input is descheduled for a second), MAX_SECONDS (stop a target after that long even short
# of RUNS; default 0 = no limit), SHADOWLAB_SHARED_SCENES, CMAKE_CXX_COMPILER_LAUNCHER (ccache).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-1000000}
build=${2:-build-fuzz}
targets=${3:-scene settings}
scenes=${SHADOWLAB_SHARED_SCENES:-$(pwd)/../shared/scenes}
finds=${SHADOWLAB_FUZZ_FINDS:-$(dirname "$scenes")/fuzz-finds}

CXX=${CXX:-clang++} cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_FUZZ=ON \
  -DSHADOWLAB_SANITIZE=address,undefined,fuzzer-no-link -DSHADOWLAB_SANITIZED_TWINS=OFF >/dev/null
cmake --build "$build" -j"${BUILD_JOBS:-$(nproc)}" --target fuzz_scene fuzz_settings

mkdir -p "$build/corpus/scene" "$build/corpus/settings" "$build/fuzz-artifacts"
if [[ -d $scenes ]]; then
  # Named by their path below $scenes: Box/glTF/Box.gltf and Box/glTF-Embedded/Box.gltf are both seeds.
  find "$scenes" \( -name '*.glb' -o -name '*.gltf' \) -size -2M -print0 |
    while IFS= read -r -d '' file; do
      relative=${file#"$scenes"/}
      cp -n "$file" "$build/corpus/scene/${relative//\//_}"
    done
else
  echo "note: no shared scenes at $scenes (set SHADOWLAB_SHARED_SCENES); seeding with the fixtures only"
fi
# Inputs that failed before, found with other seeds: kept as seeds so their neighbourhood is searched.
if [[ -d $finds ]]; then
  find "$finds" \( -name '*.glb' -o -name '*.gltf' \) -size -2M -exec cp -n {} "$build/corpus/scene/" \;
fi
cp -n tests/fuzz_regressions/scene/* "$build/corpus/scene/"
cp -n fuzz/seeds_settings/* tests/fuzz_regressions/settings/* "$build/corpus/settings/"

status=0
for target in $targets; do
  log="$build/fuzz-$target.log"
  echo "== fuzz_$target: $runs executions (log: $log)"
  start=$(date +%s)
  # One process (no -jobs: with -jobs libFuzzer moves the output into fuzz-N.log files).
  rc=0
  "$build/fuzz/fuzz_$target" "$build/corpus/$target" -runs="$runs" -max_total_time="${MAX_SECONDS:-0}" -timeout="${TIMEOUT_SECONDS:-1}" -rss_limit_mb=2048 \
    -malloc_limit_mb=256 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$build/fuzz-artifacts/${target}-" >"$log" 2>&1 || rc=$?
  grep -E "^stat::|^Done|ERROR:|SUMMARY:|^artifact_prefix|Test unit written" "$log" || true
  echo "fuzz_$target: exit $rc, $(($(date +%s) - start)) s wall"
  [[ $rc -eq 0 ]] || status=1
done
if [[ $status -ne 0 ]]; then
  echo "FAILED: inputs in $build/fuzz-artifacts/ -> add them to tests/fuzz_regressions/<target>/"
fi
exit $status
