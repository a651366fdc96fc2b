#!/usr/bin/env bash
# Build the libFuzzer harnesses (clang, ASan + UBSan) and run each for a bounded time.
#   scripts/fuzz.sh [SECONDS_PER_HARNESS] [HARNESS...]
# FUZZ_SEED=N fixes libFuzzer's random seed (the test command uses 1, so a CI run explores the
# same inputs as the last one did, and a red run can be reproduced).
# Defaults: 60 s each for fuzz_collision, fuzz_world and fuzz_scene, one process at a time (one
# core). New inputs go to build/fuzz/corpus/<harness>; the committed seeds in
# fuzz/corpus/<harness> are read, never written. A finding stops the harness with the crashing
# input saved as build/fuzz/<harness>-crash-* and this script exits non-zero.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
	harnesses=(fuzz_collision fuzz_world fuzz_scene)
fi
if ! command -v clang >/dev/null; then
	if [ "$(id -u)" = 0 ]; then
		apt-get install -y clang
	else
		echo "clang is missing: sudo apt-get install -y clang" >&2
		exit 1
	fi
fi
scripts/install-deps.sh test
CC=clang CXX=clang++ cmake -S . -B build/fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTUMBLE_FUZZ=ON \
	-DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF -DTUMBLE_BUILD_TOOLS=OFF -DTUMBLE_BUILD_SAMPLES=OFF >/dev/null
cmake --build build/fuzz -j"$(nproc)" --target "${harnesses[@]}"
status=0
for harness in "${harnesses[@]}"; do
	mkdir -p "build/fuzz/corpus/$harness"
	echo "== $harness for ${seconds} s"
	seed=()
	[ -n "${FUZZ_SEED:-}" ] && seed=(-seed="$FUZZ_SEED")
	(cd build/fuzz && "./fuzz/$harness" -max_total_time="$seconds" "${seed[@]}" -print_final_stats=1 -artifact_prefix="$harness-" \
		"corpus/$harness" "../../fuzz/corpus/$harness") || status=1
done
exit $status
