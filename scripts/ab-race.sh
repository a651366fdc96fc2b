#!/usr/bin/env bash
# Race two builds of Tumble in one process, step by step (bench/ab/ab_driver.c): for a change
# whose effect is a few per cent on a machine whose speed wanders by more between runs.
#
#   scripts/ab-race.sh OLD_BUILD NEW_BUILD STEPS WORKERS SCENE...
#
# SCENE is a catalogue scene (samples/tumble list) or, when both builds have built tumble-bench-games,
# game:NAME for a scene of bench/game_scenes.c (tumble-bench-games --list).
# OLD_BUILD and NEW_BUILD are build directories of this tree (e.g. a Release build of the commit
# before, from a second worktree, and one of the change) in which the targets `tumble` and
# `tumble_scenes` are built. A is OLD_BUILD, B is NEW_BUILD: B/A < 1 means the change is faster.
# Each build's libraries are linked with bench/ab/runner.c into one object whose symbols are all
# hidden but four, renamed A_* or B_*, so the two copies of the library do not clash. Needs gcc,
# ld and objcopy (binutils) and what the README's build installs.
set -euo pipefail
if [ $# -lt 5 ]; then
	sed -n '4,6p' "$0" >&2
	exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
old="$(cd "$1" && pwd)"; new="$(cd "$2" && pwd)"; shift 2
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# Game scenes (SCENE "game:NAME", bench/game_scenes.c) when both builds have tumble-bench-games' library.
games=()
gamesFlag=()
if [ -f "$old/bench/libtumble_games_tumble.a" ] && [ -f "$new/bench/libtumble_games_tumble.a" ]; then
	gamesFlag=(-DAB_GAMES -I"$root/bench")
fi
gcc -O2 -c -I"$root/samples" -I"$root/include" "${gamesFlag[@]}" "$root/bench/ab/runner.c" -o "$work/runner.o"
side() { # side LETTER BUILD_DIR
	if [ ${#gamesFlag[@]} -gt 0 ]; then games=("$2/bench/libtumble_games_tumble.a"); fi
	ld -r -o "$work/$1.raw.o" "$work/runner.o" --whole-archive "${games[@]}" "$2/samples/libtumble_scenes.a" \
		"$2/libtumble.a" --no-whole-archive
	objcopy --keep-global-symbol=R_create --keep-global-symbol=R_step --keep-global-symbol=R_hash \
		--keep-global-symbol=R_destroy "$work/$1.raw.o" "$work/$1.kept.o"
	objcopy --redefine-sym R_create="$1_create" --redefine-sym R_step="$1_step" --redefine-sym R_hash="$1_hash" \
		--redefine-sym R_destroy="$1_destroy" "$work/$1.kept.o" "$work/$1.o"
}
side A "$old"
side B "$new"
gcc -O2 "$root/bench/ab/ab_driver.c" "$work/A.o" "$work/B.o" -lcjson -lm -lpthread -o "$work/ab-race"
"$work/ab-race" "$@"
