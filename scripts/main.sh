#!/usr/bin/env bash
# Sets up everything (system packages), builds, and runs the main job: `rpu compare` on every
# built-in demo scene (float, float-ip, the bit-accurate model and the Verilated RTL, every RTL
# pixel checked against the model), reports under out/demo/. Extra arguments go to `rpu demo`
# (e.g. --size 256x256, --max-side 128).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
status=0
./build/rpu demo --out out/demo "$@" || status=$?
echo "Report: out/demo/index.html (per scene: out/demo/<scene>/report.html; summary.md)"
exit $status
