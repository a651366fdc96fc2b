#!/usr/bin/env bash
# Build Release (no sanitizers), run every benchmark one after another, write the CSVs into
# bench/results/<machine>/ and regenerate the charts (gnuplot, PNG) into docs/.
#
#   scripts/bench.sh                       full run: catalogue step counts, 3 repeats
#   BENCH_STEPS=100 BENCH_REPEAT=1 scripts/bench.sh   quicker run (what docs/performance.md quotes)
#   CHARTS_ONLY=1 scripts/bench.sh         redraw the charts from the committed CSVs
#
# Environment: BUILD_DIR (default /tmp/tumble-bench-build), MACHINE (default from lscpu),
# BENCH_STEPS (default: each scene's own), BENCH_REPEAT (default 3), TUMBLE_BOX2D3_DIR (install
# prefix of Box2D v3) or TUMBLE_BOX2D3_SOURCE_DIR (its source tree) for the Box2D v3 peer.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-/tmp/tumble-bench-build}"
if [[ -z "${MACHINE:-}" ]]; then
	model="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1)"
	short="$(echo "$model" | tr 'A-Z' 'a-z' | sed -e 's/([a-z]*)//g' -e 's/intel\|amd\|processor\|cpu.*\|@.*//g' | xargs | tr ' ' '-')"
	MACHINE="${short:-unknown}-$(nproc)vcpu"
fi
RESULTS="$ROOT/bench/results/$MACHINE"
DOCS="$ROOT/docs"
CHARTS="$ROOT/bench/charts"
STEPS_ARGS=()
[[ -n "${BENCH_STEPS:-}" ]] && STEPS_ARGS=(--steps "$BENCH_STEPS")
REPEAT="${BENCH_REPEAT:-3}"
PEER_ARGS=()
[[ -n "${TUMBLE_BOX2D3_DIR:-}" ]] && PEER_ARGS+=(-DTUMBLE_BOX2D3_DIR="$TUMBLE_BOX2D3_DIR")
[[ -n "${TUMBLE_BOX2D3_SOURCE_DIR:-}" ]] && PEER_ARGS+=(-DTUMBLE_BOX2D3_SOURCE_DIR="$TUMBLE_BOX2D3_SOURCE_DIR")
mkdir -p "$RESULTS" "$DOCS"

if [[ -z "${CHARTS_ONLY:-}" ]]; then
	cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DTUMBLE_SANITIZE=OFF \
		-DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_TOOLS=OFF -DTUMBLE_BUILD_SAMPLES=OFF -DTUMBLE_BUILD_BENCH=ON \
		"${PEER_ARGS[@]}" >/dev/null
	cmake --build "$BUILD_DIR" -j "$(nproc)" --target tumble-bench tumble-bench-broadphase >/dev/null
	BENCH="$BUILD_DIR/bench/tumble-bench"

	lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|L2|L3)' >"$RESULTS/machine.txt"
	echo "date: $(date -u +%Y-%m-%dT%H:%MZ)  commit: $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo none)" >>"$RESULTS/machine.txt"

	echo "== scenes (Tumble, Box2D 2.4.1, Box2D v3, Chipmunk 7 in one process)"
	"$BENCH" --peers --interleave --repeat "$REPEAT" "${STEPS_ARGS[@]}" --csv "$RESULTS/scenes.csv" | grep -v '^Initializing cpSpace\|^Compile with' \
		| tee "$RESULTS/scenes.txt"
	echo "== jointed scenes (every peer builds the joints; 120 steps)"
	"$BENCH" joint_grid rain_ragdolls --peers --interleave --repeat "$REPEAT" --steps 120 --csv "$RESULTS/joints.csv" \
		| grep -v '^Initializing cpSpace\|^Compile with' | tee "$RESULTS/joints.txt"
	echo "== exact rain (Box2D v3's rain benchmark: humans spawned every 8 steps; 2.4.1 and Chipmunk refuse it)"
	"$BENCH" rain --peer box2d-3 --interleave --repeat "$REPEAT" --steps 600 --csv "$RESULTS/rain.csv" \
		| tee "$RESULTS/rain.txt"
	echo "== sleeping bodies"
	"$BENCH" sleep --repeat "$REPEAT" --csv "$RESULTS/sleep.csv"
	echo "== solver chart"
	"$BENCH" solver-chart --csv "$RESULTS/solver.csv" >/dev/null
	echo "== narrow-phase chart"
	"$BENCH" narrowphase-chart --csv "$RESULTS/narrowphase.csv"
	echo "== time-of-impact chart"
	"$BENCH" toi-chart --csv "$RESULTS/toi.csv"
	"$BENCH" tunnel-chart --csv "$RESULTS/tunnel.csv" >/dev/null
	echo "== broad-phase chart"
	"$BUILD_DIR/bench/tumble-bench-broadphase" | awk '/^method,bodies,sizes,ms_per_step/{on=1} on && NF' >"$RESULTS/broadphase.csv"
fi

# scenes.csv (long) -> scenes_wide.csv: scene,tumble,box2d,box2d3,chipmunk (median ms per step)
wide() {
awk -F, 'function or_nan(v) { return v == "" ? "NaN" : v }
	NR > 1 { if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 } ms[$1, $2] = $5 }
	END { print "scene,tumble,box2d,box2d3,chipmunk"
		for (i = 1; i <= n; ++i) { s = order[i]
			printf "%s,%s,%s,%s,%s\n", s, ms[s, "tumble"], or_nan(ms[s, "box2d-2.4.1"]), or_nan(ms[s, "box2d-3"]),
				or_nan(ms[s, "chipmunk-7"]) } }' "$1"
}
wide "$RESULTS/scenes.csv" >"$RESULTS/scenes_wide.csv"
[[ -s "$RESULTS/joints.csv" ]] && wide "$RESULTS/joints.csv" >"$RESULTS/joints_wide.csv"

plot() { # plot SCRIPT OUTPUT VAR=FILE...
	local script="$1" output="$2"
	shift 2
	local args=(-e "OUT='$DOCS/$output'")
	for pair in "$@"; do args+=(-e "${pair%%=*}='$RESULTS/${pair#*=}'"); done
	if [[ -s "$RESULTS/${1#*=}" ]]; then gnuplot "${args[@]}" "$CHARTS/$script" && echo "docs/$output"; fi
}
plot scenes.gp perf_scenes.png DATA=scenes_wide.csv
plot scenes.gp perf_joints.png DATA=joints_wide.csv
plot solver.gp perf_solver.png DATA=solver.csv
plot broadphase.gp perf_broadphase.png DATA=broadphase.csv
plot narrowphase.gp perf_narrowphase.png DATA=narrowphase.csv
plot continuous.gp perf_continuous.png TOI=toi.csv TUNNEL=tunnel.csv
