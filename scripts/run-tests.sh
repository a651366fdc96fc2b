#!/usr/bin/env bash
# Build Tumble with AddressSanitizer, UndefinedBehaviorSanitizer and warnings as errors, then run
# every test under ctest; then run each fuzz harness for 60 s (scripts/fuzz.sh, clang libFuzzer),
# so that a change that makes a harness crash fails here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh test
cmake -S . -B build/test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTUMBLE_SANITIZE=ON -DTUMBLE_WERROR=ON -DTUMBLE_BUILD_BENCH=OFF >/dev/null
cmake --build build/test -j"$(nproc)"
(cd build/test && ctest --output-on-failure -j"$(nproc)" --timeout 600)
FUZZ_SEED=1 scripts/fuzz.sh 60
