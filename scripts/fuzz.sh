#!/usr/bin/env bash
# Build the libFuzzer harnesses (clang, ASan + UBSan) and run each for a bounded time.
#   scripts/fuzz.sh [SECONDS_PER_HARNESS] [HARNESS...]
# FUZZ_SEED=N fixes libFuzzer's random seed (the test command uses 1): the order of the inputs is
# fixed, how many run in the time depends on the machine, so a longer run replays a red one.
# FUZZ_JOBS=N runs N harnesses at a time (default 2: the CI machine has two cores, and each
# harness is one process on one core).
# Defaults: 60 s each for fuzz_collision, fuzz_world, fuzz_scene, fuzz_api, fuzz_decompose and
# fuzz_snapshot.
# New inputs go to build/fuzz/corpus/<harness>; the committed seeds in fuzz/corpus/<harness> are
# read, never written. Each harness writes its log to build/fuzz/<harness>.log, printed whole once
# the harness is done (so the logs of harnesses running side by side do not interleave). A finding
# stops its harness with the crashing input saved as build/fuzz/<harness>-crash-*, and this script
# exits non-zero once every harness has run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
	harnesses=(fuzz_collision fuzz_world fuzz_scene fuzz_api fuzz_decompose fuzz_snapshot)
fi
jobs="${FUZZ_JOBS:-2}"
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

# Options a harness needs beyond the common ones.
extra_options() {
	case "$1" in
		# A call sequence needs length to reach deep states: mutate at full length from the start
		# rather than growing inputs slowly from a few bytes.
		fuzz_api) echo "-max_len=4096 -len_control=0" ;;
		*) echo "" ;;
	esac
}

# Start one harness in the background; its pid goes to pids[], its name to names[].
pids=()
names=()
start() {
	local harness="$1"
	mkdir -p "build/fuzz/corpus/$harness"
	local seed=()
	[ -n "${FUZZ_SEED:-}" ] && seed=(-seed="$FUZZ_SEED")
	local options
	read -r -a options <<<"$(extra_options "$harness")"
	# The committed seeds, where the harness has any (libFuzzer stops on a missing directory).
	local seeds=()
	[ -d "fuzz/corpus/$harness" ] && seeds=("../../fuzz/corpus/$harness")
	echo "== $harness: started for ${seconds} s (log: build/fuzz/$harness.log)"
	(cd build/fuzz && exec "./fuzz/$harness" -max_total_time="$seconds" "${seed[@]}" "${options[@]}" \
		-print_final_stats=1 -artifact_prefix="$harness-" "corpus/$harness" "${seeds[@]}") \
		>"build/fuzz/$harness.log" 2>&1 &
	pids+=($!)
	names+=("$harness")
}

# Wait for any running harness to end, print its log and status, and drop it from the lists.
status=0
finish_one() {
	while true; do
		for i in "${!pids[@]}"; do
			if ! kill -0 "${pids[$i]}" 2>/dev/null; then
				local code=0
				wait "${pids[$i]}" || code=$?
				local harness="${names[$i]}"
				echo "== $harness: log"
				cat "build/fuzz/$harness.log"
				if [ "$code" -eq 0 ]; then
					echo "== $harness: passed"
				else
					echo "== $harness: FAILED (exit status $code; the input is build/fuzz/$harness-crash-* or -timeout-*)"
					status=1
				fi
				unset 'pids[i]' 'names[i]'
				pids=("${pids[@]}")
				names=("${names[@]}")
				return
			fi
		done
		sleep 1
	done
}

for harness in "${harnesses[@]}"; do
	while [ ${#pids[@]} -ge "$jobs" ]; do
		finish_one
	done
	start "$harness"
done
while [ ${#pids[@]} -gt 0 ]; do
	finish_one
done
exit $status
