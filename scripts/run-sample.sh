#!/usr/bin/env bash
# The main job: build Tumble and run a headless sample that writes PNG frames.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh build
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF -DTUMBLE_BUILD_TOOLS=OFF >/dev/null
# The `tumble` program and the platformer sample (build/release/samples/tumble-platformer), both
# of which the README shows.
cmake --build build/release --target tumble_cli tumble-platformer -j"$(nproc)"
scene="${1:-pyramid}"
out="out/$scene"
rm -rf "$out"
mkdir -p "$out"
build/release/samples/tumble run "$scene" --steps 300 --every 10 --png "$out" --size 640x480
echo "Frames written to $(pwd)/$out/ (frame_00000.png ...)"
