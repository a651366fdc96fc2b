#!/usr/bin/env bash
# Build Release (no sanitizers) into build/release-bench, run tumble-stability (the stress scenes
# of docs/stability.md under soft / Baumgarte / NGS at 1, 2, 4, 8 sub-steps or iterations) and write
# docs/stability.md and bench/results/stability.csv. About half a minute on 2 cores.
#
# Environment: BUILD_DIR (default build/release-bench).
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build/release-bench}"
mkdir -p "$ROOT/bench/results" "$ROOT/docs"

cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DTUMBLE_SANITIZE=OFF \
	-DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_TOOLS=OFF -DTUMBLE_BUILD_SAMPLES=OFF -DTUMBLE_BUILD_BENCH=ON >/dev/null
cmake --build "$BUILD_DIR" -j "$(nproc)" --target tumble-stability >/dev/null

"$BUILD_DIR/bench/tumble-stability" --csv "$ROOT/bench/results/stability.csv" --markdown "$ROOT/docs/stability.md"
echo "wrote docs/stability.md and bench/results/stability.csv"
