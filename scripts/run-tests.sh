#!/usr/bin/env bash
# Build Tumble with AddressSanitizer, UndefinedBehaviorSanitizer and warnings as errors, then run
# every test under ctest; then the large-world build (double-precision positions) and its tests;
# then the AVX2 build's bit-identity tests (where the processor has AVX2); then the browser page
# (samples/web) in headless Chromium against the native build (tests/web/test_page.py); then run each
# fuzz harness for 60 s (scripts/fuzz.sh, clang libFuzzer), so that a change that makes a harness
# crash fails here.
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
# The eight-lane AVX2 solver (TUMBLE_AVX2) gives the SSE2 build's results bit for bit: its build runs
# the tests that hold golden state hashes and those of the wide solver's layout, where the
# processor has AVX2.
if grep -qw avx2 /proc/cpuinfo 2>/dev/null; then
	cmake -S . -B build/avx2 -DCMAKE_BUILD_TYPE=Release -DTUMBLE_WERROR=ON -DTUMBLE_AVX2=ON \
		-DTUMBLE_BUILD_SAMPLES=OFF -DTUMBLE_BUILD_BENCH=OFF -DTUMBLE_BUILD_TOOLS=OFF >/dev/null
	cmake --build build/avx2 -j"$(nproc)" --target test_determinism test_solver test_constraint_graph test_contact_solver
	(cd build/avx2 && ctest --output-on-failure -j"$(nproc)" --timeout 600 -R '^(determinism|solver|constraint_graph|contact_solver)\.')
else
	echo "run-tests: no AVX2 on this processor: the TUMBLE_AVX2 build is not tested"
fi
# The WebAssembly build and its page in a real browser: the same state hashes as the native tumble
# program (the sanitizer build's, run by the test), a mouse drag, memory returned, a screenshot.
scripts/install-deps.sh web-test
scripts/run-web.sh --build-only
/usr/bin/python3 tests/web/test_page.py --page build/web/web --tumble build/test/samples/tumble \
	--screenshot build/web/page.png
FUZZ_SEED=1 scripts/fuzz.sh 60
