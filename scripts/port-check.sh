#!/usr/bin/env bash
# Port check: which functions of a Box2D v3 source tree's public headers Tumble has under the
# tb prefix (b2Foo → tbFoo), and which it lacks. Usage: scripts/port-check.sh /path/to/box2d
# (a checkout of github.com/erincatto/box2d). Prints counts and the missing names.
set -euo pipefail
box2d="${1:?usage: scripts/port-check.sh /path/to/box2d}"
here="$(cd "$(dirname "$0")/.." && pwd)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -ohE "B2_(API|INLINE) [^;(]*\bb2[A-Za-z0-9_]+\s*\(" "$box2d"/include/box2d/*.h |
	grep -oE "b2[A-Za-z0-9_]+\s*\($" | tr -d '( ' | sed 's/^b2/tb/' | sort -u >"$tmp/v3"
grep -ohE "TB_(API|INLINE) [^;(]*\btb[A-Za-z0-9_]+\s*\(" "$here"/include/tumble/*.h |
	grep -oE "tb[A-Za-z0-9_]+\s*\($" | tr -d '( ' | sort -u >"$tmp/tb"
echo "Box2D v3 functions: $(wc -l <"$tmp/v3"); in Tumble as tb*: $(comm -12 "$tmp/v3" "$tmp/tb" | wc -l)"
echo "missing:"
comm -23 "$tmp/v3" "$tmp/tb" | sed 's/^/  /'
