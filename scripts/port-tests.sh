#!/usr/bin/env bash
# Box2D v3's own public-API tests against Tumble, renamed b2 → tb and nothing else (B2_ → TB_,
# include "box2d/box2d.h" → "tumble/tumble.h"). Nothing of Box2D is kept: the files are copied to a
# temporary directory, built against Tumble's static library and run there.
# Usage: scripts/port-tests.sh /path/to/box2d [BUILD_DIR]   (BUILD_DIR default build/, built first)
# Files: test_math, test_id, test_shape, test_distance, test_dynamic_tree, test_collision,
# test_world (with the shared benchmark scenes and ragdoll it uses). test_collision includes
# Box2D's internal headers aabb.h and shape.h; it is built with Tumble's src/collision and src/world on its include path,
# where the headers of those names hold the same internals (tbAABB_RayCast, the tbShape record
# with its type and geometry fields, tbComputeFatShapeAABB), as Box2D's own test build does.
set -euo pipefail
box2d="${1:?usage: scripts/port-tests.sh /path/to/box2d [BUILD_DIR]}"
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${2:-$here/build}"
cmake --build "$build" --target tumble -j2 >/dev/null
# A large-world build of Tumble (TUMBLE_DOUBLE_PRECISION) runs the tests as Box2D's large-world
# build does: the same option under Box2D's name turns on their double-precision checks.
flags=()
if grep -q "^TUMBLE_DOUBLE_PRECISION:BOOL=ON" "$build/CMakeCache.txt"; then
	flags=(-DTUMBLE_DOUBLE_PRECISION -DBOX2D_DOUBLE_PRECISION)
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rename() { sed -e 's/\bb2/tb/g; s/\bB2_/TB_/g; s#"box2d/box2d.h"#"tumble/tumble.h"#; s#box2d/#tumble/#g' "$1" >"$2"; }
for f in test_math.c test_id.c test_shape.c test_distance.c test_dynamic_tree.c test_collision.c test_world.c test_macros.h; do
	rename "$box2d/test/$f" "$tmp/$f"
done
for f in benchmarks.c benchmarks.h human.c human.h utils.c utils.h; do
	rename "$box2d/shared/$f" "$tmp/$f"
done
cat >"$tmp/main.c" <<'MAIN'
#include "test_macros.h"
#include "tumble/tumble.h"
int MathTest(void);
int IdTest(void);
int ShapeTest(void);
int DistanceTest(void);
int DynamicTreeTest(void);
int CollisionTest(void);
int WorldTest(void);
int main(void)
{
	RUN_TEST(MathTest);
	RUN_TEST(IdTest);
	RUN_TEST(ShapeTest);
	RUN_TEST(DistanceTest);
	RUN_TEST(DynamicTreeTest);
	RUN_TEST(CollisionTest);
	RUN_TEST(WorldTest);
	printf("all ported tests passed\n");
	return 0;
}
MAIN
cc -std=c17 -O1 "${flags[@]}" -I"$here/include" -I"$tmp" -c "$tmp/test_collision.c" -I"$here/src/collision" -I"$here/src/world" -o "$tmp/test_collision.o"
rm "$tmp/test_collision.c"
cc -std=c17 -O1 "${flags[@]}" -I"$here/include" -I"$tmp" "$tmp"/*.c "$tmp/test_collision.o" "$build/libtumble.a" -lm -lpthread -o "$tmp/port-tests"
"$tmp/port-tests"
