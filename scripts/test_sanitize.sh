#!/usr/bin/env bash
# The sanitizer configuration CI runs: builds rpu and the test executables with
# -fsanitize=address,undefined (RPU_SANITIZE=ON, RelWithDebInfo, no benchmarks) into build-asan/
# and runs the unit and CLI tests under CTest. Any sanitizer finding aborts the process that
# made it, so the test fails; the script's exit status is CTest's.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache: hash paths relative to the checkout, so every clone of the project shares one cache.
export CCACHE_BASEDIR="$PWD"
start=$(date +%s)
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DRPU_SANITIZE=ON -DRPU_BENCH=OFF -DRPU_SIM=OFF >/dev/null
# With RPU_BENCH=OFF and RPU_SIM=OFF the default target is exactly rpu, its library and the
# C++ test executables (the verilated testbenches run in the main build).
cmake --build build-asan -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
ctest --test-dir build-asan -L "unit|cli" --output-on-failure -j2 || status=$?
echo "sanitizer run (build + tests): $(($(date +%s) - start)) s, ctest exit status ${status}"
exit "${status}"
