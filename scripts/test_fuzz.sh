#!/usr/bin/env bash
# The fuzzing step of CI (issue 14, item 3; docs/verification.md "Fuzzing"): builds the libFuzzer
# targets with clang (ASan, UBSan, RPU_FUZZ=ON, RelWithDebInfo) into build-fuzz/ — only the fuzz
# targets and what they link — and runs the CTests labelled `fuzz`: for each target a smoke run
# of a fixed libFuzzer seed and run count (about 60 s; RPU_FUZZ_SEED / RPU_FUZZ_RUNS override) on
# a copy of its corpus, and a run of its corpus and fuzz/regressions/<target>/ once.
# Prints the time taken; the exit status is CTest's.
set -euo pipefail
if [[ $# -ne 0 ]]; then
  echo "usage: $0   (no arguments; longer runs: scripts/fuzz.sh SECONDS [target...])" >&2
  exit 2
fi
cd "$(dirname "$0")/.."
# ccache: hash paths relative to the checkout, so every clone of the project shares one cache.
export CCACHE_BASEDIR="$PWD"
start=$(date +%s)
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DRPU_FUZZ=ON -DRPU_SIM=OFF -DRPU_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_scene fuzz_sweep fuzz_render fuzz_params
status=0
ctest --test-dir build-fuzz -L fuzz --output-on-failure -j2 || status=$?
echo "fuzz run (build + tests): $(($(date +%s) - start)) s, ctest exit status ${status}"
exit "${status}"
