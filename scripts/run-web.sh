#!/usr/bin/env bash
# Build the WebAssembly module of the library and the scene catalogue (samples/web) and serve the
# samples page on 127.0.0.1, printing its address. Ctrl-C stops the server.
# Usage: scripts/run-web.sh [PORT]      (default 8642)
#        scripts/run-web.sh --build-only (build into build/web/web and stop)
# The page is static files and tumble.wasm: any static server will do, with no special headers.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh web
# The wide contact solver on WebAssembly's 128-bit SIMD (TUMBLE_SIMD=ON, src/core/simd.h): the same
# results as the native SSE2 build, bit for bit, as its plain floats (TUMBLE_SIMD=OFF) are.
cmake -S . -B build/web -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/wasm32-wasi.cmake" -DCMAKE_BUILD_TYPE=Release \
	-DTUMBLE_BUILD_WEB=ON -DTUMBLE_SIMD=ON -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_SAMPLES=OFF \
	-DTUMBLE_BUILD_BENCH=OFF -DTUMBLE_BUILD_TOOLS=OFF >/dev/null
cmake --build build/web -j"$(nproc)"
if [ "${1:-}" = "--build-only" ]; then
	exit 0
fi
port="${1:-8642}"
echo "Tumble in the browser: http://127.0.0.1:$port/ (Ctrl-C stops the server)"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory build/web/web
