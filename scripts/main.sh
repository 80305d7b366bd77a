#!/usr/bin/env bash
# Sets up everything (system packages), builds, and runs the main job: every built-in demo
# scene through every backend, images and the agreement summary under out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
./build/rpu demo --out out/demo "$@"
echo "Open out/demo/summary.md (images beside it)."
