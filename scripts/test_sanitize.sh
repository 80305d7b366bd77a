#!/usr/bin/env bash
# The sanitizer configuration CI runs: builds rpu and the test executables with ASan and UBSan
# (clang, -fsanitize=address,undefined, plus the fuzz targets' coverage instrumentation) into
# build-fuzz/ (scripts/asan_build.sh; the fuzz smoke runs reuse it) and runs the unit and CLI
# tests under CTest. Any sanitizer finding aborts the process that made it, so the test fails;
# the script's exit status is CTest's.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/asan_build.sh
start=$(date +%s)
configure_asan_build
# With RPU_BENCH=OFF and RPU_SIM=OFF the default target is exactly rpu, its library, the C++
# test executables and the fuzz targets (the verilated testbenches run in the main build).
cmake --build build-fuzz -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
ctest --test-dir build-fuzz -L "unit|cli" --output-on-failure -j"$(nproc)" || status=$?
echo "sanitizer run (build + tests): $(($(date +%s) - start)) s, ctest exit status ${status}"
exit "${status}"
