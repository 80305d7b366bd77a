#!/usr/bin/env bash
# Sets up everything (system packages), builds, and runs the default test suite under CTest,
# then the unit and CLI tests again under ASan/UBSan (scripts/test_sanitize.sh, build-asan/), then
# the libFuzzer smoke runs (scripts/test_fuzz.sh, clang, build-fuzz/).
# Prints how long each phase took (the CI budget, README "Tests").
set -euo pipefail
cd "$(dirname "$0")/.."
phases=""
t0=$(date +%s)
phase() {  # phase NAME COMMAND...: runs it and records its wall time
  local name=$1 s
  shift
  s=$(date +%s)
  "$@"
  phases+="${name} $(($(date +%s) - s)) s; "
}
phase setup ./scripts/setup.sh
phase build ./scripts/build.sh
phase ctest ctest --test-dir build --output-on-failure -j"$(nproc)"
phase sanitize ./scripts/test_sanitize.sh
phase fuzz ./scripts/test_fuzz.sh
echo "test.sh: ${phases}total $(($(date +%s) - t0)) s"
