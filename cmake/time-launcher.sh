#!/usr/bin/env bash
# Compiler/linker launcher that records each step's CPU time (user + sys, seconds) and wall time:
#   cmake -S . -B build -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/cmake/time-launcher.sh \
#         -DCMAKE_CXX_LINKER_LAUNCHER=$PWD/cmake/time-launcher.sh
#   SHADOWLAB_TIME_LOG=/tmp/steps.tsv cmake --build build
# Each line of the log: user  sys  wall  output-file. CPU time is what the numbers in
# docs/build-times.md compare: on a shared machine, wall time mostly measures the neighbours.
log=${SHADOWLAB_TIME_LOG:-/tmp/shadowlab-build-steps.tsv}
out=unknown
prev=
for arg in "$@"; do
  [[ $prev == -o ]] && out=$arg
  prev=$arg
done
times_file=$(mktemp)
/usr/bin/time -f "%U	%S	%e" -o "$times_file" "$@"
status=$?
printf '%s\t%s\n' "$(tail -n 1 "$times_file")" "$PWD/$out" >>"$log"
rm -f "$times_file"
exit $status
