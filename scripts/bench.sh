#!/usr/bin/env bash
# Everything docs/performance.md shows, from one run: build Release (no sanitizers) with the peers,
# run every benchmark one after another, write the CSVs into bench/results/<machine>/, redraw the
# charts (gnuplot, PNG) into docs/, and write the page's tables back into docs/performance.md
# between its <!-- NAME --> and <!-- /NAME --> markers.
#
#   scripts/bench.sh                        the catalogue's step counts, 3 rounds
#   BENCH_STEPS=100 BENCH_REPEAT=1 scripts/bench.sh    a quicker run (fewer steps, one round)
#   CHARTS_ONLY=1 MACHINE=NAME scripts/bench.sh        redraw charts and tables from committed CSVs
#
# Environment: BUILD_DIR (default /tmp/tumble-bench-build), MACHINE (default from lscpu),
# BENCH_STEPS (default: each scene's own), BENCH_REPEAT (rounds, default 3), BENCH_PEER_BUDGET
# (seconds Box2D 2.4.1 or Chipmunk may spend on one scene's round before it is stopped there,
# default 30: Box2D 2.4.1 takes seconds a step on the spinners; Tumble and v3 always finish), TUMBLE_BOX2D3_DIR (install prefix of Box2D v3) or
# TUMBLE_BOX2D3_SOURCE_DIR (its source tree) for the Box2D v3 peer; without either, the v3 columns
# stay empty. The build uses two jobs (the machines this runs on are shared).
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
PAGE="$DOCS/performance.md"
STEPS_ARGS=()
[[ -n "${BENCH_STEPS:-}" ]] && STEPS_ARGS=(--steps "$BENCH_STEPS")
REPEAT="${BENCH_REPEAT:-3}"
BUDGET="${BENCH_PEER_BUDGET:-30}"
PEER_ARGS=()
[[ -n "${TUMBLE_BOX2D3_DIR:-}" ]] && PEER_ARGS+=(-DTUMBLE_BOX2D3_DIR="$TUMBLE_BOX2D3_DIR")
[[ -n "${TUMBLE_BOX2D3_SOURCE_DIR:-}" ]] && PEER_ARGS+=(-DTUMBLE_BOX2D3_SOURCE_DIR="$TUMBLE_BOX2D3_SOURCE_DIR")

# Box2D v3's ten benchmark scenes as v3 builds them, then the variants every peer can build
# (kinematic drum and blade instead of motorised joints, rigid humans, ragdolls all at once).
SCENES=(large_pyramid many_pyramids tumbler_motor smash spinner_motor washer junkyard compounds joint_grid rain
	tumbler spinner rain_rigid rain_ragdolls)
JOINTED="tumbler_motor spinner_motor joint_grid rain rain_ragdolls" # drawn apart in perf_joints.png
WORKER_SCENES=(large_pyramid many_pyramids tumbler_motor smash junkyard compounds joint_grid)
PROFILE_SCENES=(large_pyramid junkyard)
mkdir -p "$RESULTS" "$DOCS"

if [[ -z "${CHARTS_ONLY:-}" ]]; then
	started=$(date +%s)
	cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DTUMBLE_SANITIZE=OFF \
		-DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_TOOLS=OFF -DTUMBLE_BUILD_SAMPLES=OFF -DTUMBLE_BUILD_BENCH=ON \
		"${PEER_ARGS[@]}" >/dev/null
	cmake --build "$BUILD_DIR" -j 2 --target tumble-bench tumble-bench-broadphase tumble-bench-games >/dev/null
	BENCH="$BUILD_DIR/bench/tumble-bench"
	quiet() { grep --line-buffered -v '^Initializing cpSpace\|^Compile with' || true; }

	{
		lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|L2|L3)'
		echo "date: $(date -u +%Y-%m-%dT%H:%MZ)  commit: $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo none)$(git -C "$ROOT" diff --quiet HEAD -- src include bench ':!bench/results' 2>/dev/null || echo ' (with uncommitted changes)')"
		echo "command: ${BENCH_STEPS:+BENCH_STEPS=$BENCH_STEPS }BENCH_REPEAT=$REPEAT BENCH_PEER_BUDGET=$BUDGET scripts/bench.sh"
		echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)"
	} >"$RESULTS/machine.txt"

	echo "== scenes: Tumble, Box2D v3, Box2D 2.4.1, Chipmunk 7 stepped in turn in one process"
	"$BENCH" "${SCENES[@]}" --peers --interleave --repeat "$REPEAT" --peer-budget "$BUDGET" "${STEPS_ARGS[@]}" \
		--csv "$RESULTS/scenes.csv" 2>&1 | quiet | tee "$RESULTS/scenes.txt"
	for w in 1 2; do
		echo "== workers: Tumble and Box2D v3 on $w worker(s)"
		"$BENCH" "${WORKER_SCENES[@]}" --peer box2d-3 --interleave --repeat "$REPEAT" --workers "$w" "${STEPS_ARGS[@]}" \
			--csv "$RESULTS/workers_$w.csv" | tee "$RESULTS/workers_$w.txt"
	done
	echo "== stage profile: Tumble and Box2D v3 stepped in turn"
	"$BENCH" profile "${PROFILE_SCENES[@]}" "${STEPS_ARGS[@]}" --csv "$RESULTS/profile.csv" | tee "$RESULTS/profile.txt"
	echo "== sleeping bodies"
	"$BENCH" sleep --repeat "$REPEAT" --csv "$RESULTS/sleep.csv"
	echo "== solver chart"
	"$BENCH" solver-chart --csv "$RESULTS/solver.csv" 2>&1 | quiet >/dev/null
	echo "== narrow-phase chart"
	"$BENCH" narrowphase-chart --csv "$RESULTS/narrowphase.csv"
	echo "== time-of-impact chart"
	"$BENCH" toi-chart --csv "$RESULTS/toi.csv"
	"$BENCH" tunnel-chart --csv "$RESULTS/tunnel.csv" 2>&1 | quiet >/dev/null
	echo "== broad-phase chart"
	"$BUILD_DIR/bench/tumble-bench-broadphase" | awk '/^method,bodies,sizes,ms_per_step/{on=1} on && NF' >"$RESULTS/broadphase.csv"
	echo "== game-scale scenes: Tumble and Box2D v3.2, one source compiled twice, in one process"
	"$BUILD_DIR/bench/tumble-bench-games" --rounds "$REPEAT" "${STEPS_ARGS[@]}" --csv "$RESULTS/games.csv" \
		--memory-csv "$RESULTS/games_memory.csv" | tee "$RESULTS/games.txt"
	"$BUILD_DIR/bench/tumble-bench-games" --sweep --rounds "$REPEAT" --csv "$RESULTS/games_sweep.csv"
	{
		echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)"
		echo "duration: $(( ($(date +%s) - started) / 60 )) min"
	} >>"$RESULTS/machine.txt"
fi

# ---------------------------------------------------------------------------------------------
# Derived CSVs for the charts

# scenes.csv (one row per scene and engine) -> scene,tumble,box2d,box2d3,chipmunk (median ms a
# step). A peer that stopped short of Tumble's steps (its budget) or refused the scene is NaN.
# $1: the CSV; $2: "jointed" or "jointless" (which scenes to keep).
wide() {
	awk -F, -v keep="$2" -v jointed="$JOINTED" 'function or_nan(v) { return v == "" ? "NaN" : v }
	BEGIN { n = split(jointed, j, " "); for (i = 1; i <= n; ++i) isJointed[j[i]] = 1 }
	NR > 1 && (keep == "jointed") == ($1 in isJointed) {
		if (!($1 in seen)) { seen[$1] = 1; order[++count] = $1 }
		if ($2 == "tumble") steps[$1] = $3
		ms[$1, $2] = $5; taken[$1, $2] = $3 }
	END { print "scene,tumble,box2d,box2d3,chipmunk"
		for (i = 1; i <= count; ++i) { s = order[i]
			for (e in taken) { split(e, k, SUBSEP); if (k[1] == s && taken[e] < steps[s]) ms[e] = "" }
			printf "%s,%s,%s,%s,%s\n", s, ms[s, "tumble"], or_nan(ms[s, "box2d-2.4.1"]), or_nan(ms[s, "box2d-3"]),
				or_nan(ms[s, "chipmunk-7"]) } }' "$1"
}
wide "$RESULTS/scenes.csv" jointless >"$RESULTS/scenes_wide.csv"
wide "$RESULTS/scenes.csv" jointed >"$RESULTS/joints_wide.csv"
# workers_1.csv + workers_2.csv -> scene,tumble_1,tumble_2,box2d3_1,box2d3_2
awk -F, 'FNR > 1 { w = FILENAME ~ /workers_2/ ? 2 : 1; if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 }
		ms[$1, $2, w] = $5 }
	END { print "scene,tumble_1,tumble_2,box2d3_1,box2d3_2"
		for (i = 1; i <= n; ++i) { s = order[i]
			printf "%s,%s,%s,%s,%s\n", s, ms[s, "tumble", 1], ms[s, "tumble", 2], ms[s, "box2d-3", 1], ms[s, "box2d-3", 2] } }' \
	"$RESULTS/workers_1.csv" "$RESULTS/workers_2.csv" >"$RESULTS/workers.csv"

plot() { # plot SCRIPT OUTPUT VAR=FILE... [-- VAR=STRING...]
	local script="$1" output="$2"
	shift 2
	local args=(-e "OUT='$DOCS/$output'") first=""
	while [[ $# -gt 0 && "$1" != "--" ]]; do
		args+=(-e "${1%%=*}='$RESULTS/${1#*=}'")
		first="${first:-${1#*=}}"
		shift
	done
	[[ "${1:-}" == "--" ]] && shift
	for pair in "$@"; do args+=(-e "${pair%%=*}='${pair#*=}'"); done
	if [[ -s "$RESULTS/$first" ]]; then gnuplot "${args[@]}" "$CHARTS/$script" && echo "docs/$output"; fi
}
plot scenes.gp perf_scenes.png DATA=scenes_wide.csv -- "TITLE=Scenes without joints: Tumble, Box2D v3, Box2D 2.4.1, Chipmunk 7 (one process, one run)"
plot scenes.gp perf_joints.png DATA=joints_wide.csv -- "TITLE=Jointed scenes: Tumble, Box2D v3, Box2D 2.4.1, Chipmunk 7 (one process, one run)"
plot workers.gp perf_workers.png DATA=workers.csv
plot solver.gp perf_solver.png DATA=solver.csv
plot broadphase.gp perf_broadphase.png DATA=broadphase.csv
plot narrowphase.gp perf_narrowphase.png DATA=narrowphase.csv
plot continuous.gp perf_continuous.png TOI=toi.csv TUNNEL=tunnel.csv
plot games_sweep.gp perf_games_sweep.png DATA=games_sweep.csv

# ---------------------------------------------------------------------------------------------
# The page's tables, as markdown, from the same CSVs

# <!-- run -->: where and when the numbers come from.
awk -v results="bench/results/$MACHINE/" '/^Model name:/ { sub(/^Model name: */, ""); model = $0 }
	/^CPU\(s\):/ { cpus = $2 } /^date:/ { date = $2; commit = $4; dirty = ($5 != "") ? " " $5 " " $6 " " $7 : "" }
	/^command:/ { sub(/^command: /, ""); command = $0 } /^duration:/ { duration = $2 " " $3 }
	/^load average at the start:/ { l0 = $6 } /^load average at the end:/ { l1 = $6 }
	END { printf "Run of %s at commit %s%s on %s (%s vCPUs, shared with other work; load average %s at the start, %s at the end), %s:\n\n",
			date, commit, dirty, model, cpus, l0, l1, duration
		printf "```sh\nTUMBLE_BOX2D3_SOURCE_DIR=<Box2D v3 source tree> %s\n```\n\nRaw output and CSVs: `%s`.\n", command, results }' \
	"$RESULTS/machine.txt" >"$RESULTS/run.md"

# <!-- race -->: every scene, every engine that builds it.
awk -F, -v jointed="$JOINTED" 'function commas(n) { n = sprintf("%d", n); while (n ~ /[0-9][0-9][0-9][0-9]/) sub(/[0-9][0-9][0-9]$/, ",&", n); return n }
	function has(s, e) { return (s SUBSEP e) in t }
	function cell(s, e) { if (!has(s, e)) return "refuses it"
		if (n[s, e] < n[s, "tumble"]) return sprintf("stopped after %d steps (%s ms a step)", n[s, e], commas(t[s, e]))
		return sprintf("%.2f", t[s, e]) }
	BEGIN { k = split(jointed, j, " "); for (i = 1; i <= k; ++i) isJointed[j[i]] = 1 }
	NR > 1 { if (!($1 in seen)) { seen[$1] = 1; order[++count] = $1 } t[$1, $2] = $5; n[$1, $2] = $3; c[$1, $2] = $8 }
	END { print "| scene (steps) | Tumble ms | Box2D v3 ms | **Tumble ÷ v3** | Box2D 2.4.1 ms | Chipmunk 7 ms | contacts Tumble / v3 |"
		print "|---|---|---|---|---|---|---|"
		for (i = 1; i <= count; ++i) { s = order[i]
			full = has(s, "box2d-3") && n[s, "box2d-3"] == n[s, "tumble"]
			printf "| %s (%s%s) | %.2f | %s | %s | %s | %s | %s / %s |\n", s, commas(n[s, "tumble"]), s in isJointed ? "; joints" : "",
				t[s, "tumble"], cell(s, "box2d-3"), full ? sprintf("**%.2f**", t[s, "tumble"] / t[s, "box2d-3"]) : "—",
				cell(s, "box2d-2.4.1"), cell(s, "chipmunk-7"), commas(c[s, "tumble"]), has(s, "box2d-3") ? commas(c[s, "box2d-3"]) : "—" } }' \
	"$RESULTS/scenes.csv" >"$RESULTS/race.md"

# <!-- workers -->
awk -F, 'NR > 1 { printf "| %s | %.2f | %.2f | %.2f× | %.2f | %.2f | %.2f× | **%.2f** |\n", $1, $2, $3, $2 / $3, $4, $5, $4 / $5, $3 / $5 }
	NR == 1 { print "| scene | Tumble 1 | Tumble 2 | speed-up | v3 1 | v3 2 | speed-up | **Tumble 2 ÷ v3 2** |"; print "|---|---|---|---|---|---|---|---|" }' \
	"$RESULTS/workers.csv" >"$RESULTS/workers.md"

# <!-- profile -->: stage by stage, ms a step, each scene's Tumble and v3 side by side.
awk -F, 'function f(v) { return v == "nan" || v == "-nan" ? "—" : sprintf("%.3f", v) }
	NR > 1 { if (!($1 in seen)) { seen[$1] = 1; scenes[++ns] = $1 } if (!($2 in known)) { known[$2] = 1; stages[++nt] = $2 }
		t[$1, $2] = $3; v[$1, $2] = $4 }
	END { printf "| stage |"; for (i = 1; i <= ns; ++i) printf " %s Tumble | v3 |", scenes[i]; printf "\n|---|"
		for (i = 1; i <= ns; ++i) printf "---|---|"; printf "\n"
		for (k = 1; k <= nt; ++k) { shown = 0 # a stage both engines spend under 0.02 ms on is left out
			for (i = 1; i <= ns; ++i) shown = shown || t[scenes[i], stages[k]] >= 0.02 || v[scenes[i], stages[k]] >= 0.02
			if (!shown) continue
			printf "| %s |", stages[k]
			for (i = 1; i <= ns; ++i) printf " %s | %s |", f(t[scenes[i], stages[k]]), f(v[scenes[i], stages[k]]); printf "\n" } }' \
	"$RESULTS/profile.csv" >"$RESULTS/profile.md"

# <!-- solver -->: the default, the variants, and every peer point.
awk -F, 'NR == 1 { print "| configuration | ms a step (210 boxes) | stack drift (m) | deepest penetration (mm) | bounce apex error |"; print "|---|---|---|---|---|" }
	NR > 1 && ($2 == "soft" || $2 ~ /^soft-/ || $2 ~ /^box2d/ || $2 ~ /^chipmunk/ || $1 == "ngs-8") {
		printf "| %s | %.3f | %.3f | %.1f | %.1f %% |\n", $1 ($1 == "soft-4" ? " (default)" : ""), $4, $5, 1000 * $6, 100 * $7 }' \
	"$RESULTS/solver.csv" >"$RESULTS/solver.md"

# <!-- narrowphase --> and <!-- toi -->
awk -F, 'NR == 1 { print "| method | family | ns a pair | normal error mean / largest (rad) | depth error mean / largest (m) |"; print "|---|---|---|---|---|" }
	NR > 1 { printf "| %s | %s | %.0f | %.1e / %.1e | %.1e / %.1e |\n", $1, $2, $4, $5, $6, $7, $8 }' \
	"$RESULTS/narrowphase.csv" >"$RESULTS/narrowphase.md"
awk -F, 'NR == 1 { print "| method | family | queries | ns a query | error mean / largest (m) | misses |"; print "|---|---|---|---|---|---|" }
	NR > 1 { printf "| %s | %s | %d | %.0f | %.1e / %.1e | %d |\n", $1, $2, $3, $4, $5, $6, $7 }' \
	"$RESULTS/toi.csv" >"$RESULTS/toi.md"

# <!-- broadphase -->: ms a step at 16k and 64k bodies, one column per method.
awk -F, 'NR > 1 && ($2 == 16000 || $2 == 64000) { key = $3 " " $2; if (!(key in seen)) { seen[key] = 1; rows[++n] = key } t[key, $1] = $4 }
	END { split("tree sort_and_sweep spatial_hash brute_force box2d3_tree", m, " ")
		print "| mix, bodies | Tumble tree | sort-and-sweep | spatial hash | brute force | Box2D v3 tree |"; print "|---|---|---|---|---|---|"
		for (i = 1; i <= n; ++i) { printf "| %s |", rows[i]
			for (k = 1; k <= 5; ++k) printf " %s |", (rows[i] SUBSEP m[k]) in t ? sprintf("%.2f", t[rows[i], m[k]]) : "—"; printf "\n" } }' \
	"$RESULTS/broadphase.csv" >"$RESULTS/broadphase.md"

# <!-- sleep -->
awk -F, 'BEGIN { name["awake_only"] = "10 awake boxes alone"; name["with_10000_sleeping"] = "the same beside 10,000 asleep"
		name["large_pyramid_awake"] = "large_pyramid, awake"; name["large_pyramid_asleep"] = "large_pyramid, every body asleep" }
	NR == 1 { print "| case | bodies | awake | ms a step |"; print "|---|---|---|---|" }
	NR > 1 && $1 != "ratio" { printf "| %s | %s | %s | %.4f |\n", $1 in name ? name[$1] : $1, $2, $3, $5 }
	$1 == "ratio" { ratio = $5 } END { printf "\n10 awake bodies beside 10,000 asleep cost %.2f× the 10 alone.\n", ratio }' \
	"$RESULTS/sleep.csv" >"$RESULTS/sleep.md"

# <!-- games -->, <!-- games_memory -->, <!-- games_sweep -->: tumble-bench-games (µs a step, medians),
# when its CSVs are there (a results folder from before the program has none).
[[ -s "$RESULTS/games.csv" ]] && awk -F, 'function f(v) { return v == "nan" || v == "-nan" ? "—" : sprintf("%.2f", v) }
	function commas(n) { n = sprintf("%d", n); while (n ~ /[0-9][0-9][0-9][0-9]/) sub(/[0-9][0-9][0-9]$/, ",&", n); return n }
	NR == 1 { print "| scene (steps) | Tumble µs | v3.2 µs | **Tumble ÷ v3** | range over rounds | bodies | awake Tumble / v3 | touching Tumble / v3 | end-state check |"
		print "|---|---|---|---|---|---|---|---|---|" }
	NR > 1 { printf "| %s (%s) | %s | %s | **%s** | %s–%s | %s | %s / %s | %s / %s | %s |\n", $1, commas($2), f($4), f($5), f($6), f($7), f($8),
		commas($9), commas($11), commas($12), commas($13), commas($14), $23 }' "$RESULTS/games.csv" >"$RESULTS/games.md"
[[ -s "$RESULTS/games_memory.csv" ]] && awk -F, 'NR == 1 { print "| engine | body | shape (circle) | contact (touching) | joint (revolute) | joint_grid peak | many_pyramids peak |"; print "|---|---|---|---|---|---|---|" }
	NR > 1 { printf "| %s | %.0f | %.0f | %.0f | %.0f | %.1f MB | %.1f MB |\n", $1 == "tumble" ? "Tumble" : "Box2D v3.2", $3, $4, $5, $6, $8 / 1e6, $9 / 1e6 }' \
	"$RESULTS/games_memory.csv" >"$RESULTS/games_memory.md"
[[ -s "$RESULTS/games_sweep.csv" ]] && awk -F, 'function f(v) { return v == "nan" || v == "-nan" ? "—" : sprintf("%.2f", v) }
	NR == 1 { print "| bodies | awake: Tumble µs | v3.2 µs | **Tumble ÷ v3** | asleep: Tumble µs | v3.2 µs | **Tumble ÷ v3** |"
		print "|---|---|---|---|---|---|---|" }
	NR > 1 { printf "| %s | %s | %s | **%s** | %s | %s | **%s** |\n", $1, f($2), f($3), f($4), f($5), f($6), f($7) }' \
	"$RESULTS/games_sweep.csv" >"$RESULTS/games_sweep.md"
true # the guards above leave a false status when a CSV is missing

# Splice each table into the page between its markers (the markers stay, so the next run finds them).
if [[ -f "$PAGE" ]]; then
	for name in run race workers profile solver narrowphase toi broadphase sleep games games_memory games_sweep; do
		[[ -s "$RESULTS/$name.md" ]] || continue
		awk -v name="$name" -v file="$RESULTS/$name.md" '
			$0 == "<!-- " name " -->" { print; while ((getline line < file) > 0) print line; skip = 1; next }
			$0 == "<!-- /" name " -->" { skip = 0 }
			!skip { print }' "$PAGE" >"$PAGE.tmp" && mv "$PAGE.tmp" "$PAGE"
	done
	echo "docs/performance.md (tables)"
fi
