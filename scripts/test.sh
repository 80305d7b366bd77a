#!/usr/bin/env bash
# Sets up everything (system packages), builds, and runs the default test suite under CTest,
# then the unit and CLI tests again under ASan/UBSan (scripts/test_sanitize.sh, build-asan/), then
# the libFuzzer smoke runs (scripts/test_fuzz.sh, clang, build-fuzz/).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
./scripts/test_sanitize.sh
./scripts/test_fuzz.sh
