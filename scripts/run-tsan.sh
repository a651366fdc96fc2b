#!/usr/bin/env bash
# ThreadSanitizer over the step on workers: builds the `tumble` program with -fsanitize=thread and
# runs every catalogue scene for 120 steps on 4 workers (tumble run --workers 4), checking that
# its trajectory (CSV, floats written exactly) equals the one on 1 worker. Any data race or any
# difference fails the run. (Criterion's test runner cannot start under ThreadSanitizer, so the
# scenes run through `tumble`; tests/test_determinism.c checks 1, 2, 4, 8 workers in the suite.)
# Needs what the README's test command installs. About 30 minutes on 2 cores; pass scene names to
# run only those.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTUMBLE_TSAN=ON -DTUMBLE_BUILD_BENCH=OFF \
	-DTUMBLE_BUILD_TESTS=OFF >/dev/null
cmake --build build/tsan -j2 --target tumble_cli >/dev/null
export TSAN_OPTIONS="halt_on_error=1 exitcode=66"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=($(build/tsan/samples/tumble list | awk '{print $1}'))
for scene in "${scenes[@]}"; do
	build/tsan/samples/tumble run "$scene" --steps 120 --csv "$out/one.csv" >/dev/null
	build/tsan/samples/tumble run "$scene" --steps 120 --workers 4 --csv "$out/four.csv" >/dev/null
	cmp -s "$out/one.csv" "$out/four.csv" || { echo "tsan: $scene differs on 4 workers"; exit 1; }
	echo "tsan: $scene on 4 workers: no race, same trajectory as on 1"
done
