#!/usr/bin/env bash
# Record what Box2D v3 prints for the programs of tests/v3_programs/ (written against v3.2's API):
# builds v3 from its source tree (Release) in a temporary directory, compiles each program against
# it and writes tests/v3_programs/expected/<program>.txt, which ctest compares with the same
# program renamed b2 → tb and built against Tumble.
# Usage: scripts/v3-programs.sh /path/to/box2d   (a checkout of github.com/erincatto/box2d)
set -euo pipefail
box2d="${1:?usage: scripts/v3-programs.sh /path/to/box2d}"
here="$(cd "$(dirname "$0")/.." && pwd)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake -S "$box2d" -B "$tmp/box2d" -DCMAKE_BUILD_TYPE=Release -DBOX2D_SAMPLES=OFF -DBOX2D_UNIT_TESTS=OFF \
	-DBOX2D_BENCHMARKS=OFF >/dev/null
cmake --build "$tmp/box2d" --target box2d -j2 >/dev/null
lib=$(find "$tmp/box2d" -name libbox2d.a | head -n 1)
programs="$here/tests/v3_programs"
for source in "$programs"/*.c; do
	name=$(basename "$source" .c)
	cc -std=c17 -O2 -I"$box2d/include" -I"$programs" "$source" "$lib" -lm -lpthread -o "$tmp/$name"
	"$tmp/$name" >"$programs/expected/$name.txt"
	echo "$name: $(wc -l <"$programs/expected/$name.txt") lines"
done
echo "Box2D at $(git -C "$box2d" rev-parse --short HEAD 2>/dev/null || echo "an unknown commit")"
