#!/usr/bin/env bash
# Build Tumble with AddressSanitizer, UndefinedBehaviorSanitizer and warnings as errors, then run
# every test under ctest; then the large-world build (double-precision positions) and its tests;
# then run each fuzz harness for 60 s (scripts/fuzz.sh, clang libFuzzer), so that a change that
# makes a harness crash fails here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh test
cmake -S . -B build/test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTUMBLE_SANITIZE=ON -DTUMBLE_WERROR=ON -DTUMBLE_BUILD_BENCH=OFF >/dev/null
cmake --build build/test -j"$(nproc)"
(cd build/test && ctest --output-on-failure -j"$(nproc)" --timeout 600)
cmake -S . -B build/large-world -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTUMBLE_SANITIZE=ON -DTUMBLE_WERROR=ON \
	-DTUMBLE_DOUBLE_PRECISION=ON -DTUMBLE_BUILD_SAMPLES=OFF -DTUMBLE_BUILD_BENCH=OFF -DTUMBLE_BUILD_TOOLS=OFF >/dev/null
cmake --build build/large-world -j"$(nproc)"
(cd build/large-world && ctest --output-on-failure -j"$(nproc)" --timeout 600)
FUZZ_SEED=1 scripts/fuzz.sh 60
