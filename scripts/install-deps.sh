#!/usr/bin/env bash
# Install the Debian packages Tumble needs, when they are missing.
# Usage: scripts/install-deps.sh build|test|bench|web|web-test
# As root it runs apt-get; otherwise it prints the exact apt-get line to run and fails.
set -euo pipefail

base=(cmake make gcc g++ pkg-config libcjson-dev libstb-dev)
case "${1:-build}" in
	build) packages=("${base[@]}") ;;
	test) packages=("${base[@]}" libcriterion-dev libbox2d-dev clang libclang-rt-dev) ;; # clang and its runtimes: libFuzzer (scripts/fuzz.sh)
	bench) packages=("${base[@]}" libbox2d-dev libchipmunk-dev gnuplot-nox) ;;
	# The WebAssembly build (scripts/run-web.sh): clang's wasm32 target, wasi-libc, lld's wasm-ld and
	# the compiler's wasm32 builtins; python3 serves the page.
	web) packages=(cmake make clang-14 wasi-libc lld-14 libclang-rt-14-dev-wasm32 python3) ;;
	# The browser test (tests/web): Debian's Chromium, headless, driven by Selenium and chromedriver.
	web-test) packages=(cmake make clang-14 wasi-libc lld-14 libclang-rt-14-dev-wasm32 python3 chromium chromium-driver python3-selenium) ;;
	*) echo "usage: $0 build|test|bench|web|web-test" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing+=("$p")
	fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
	echo "Installing: ${missing[*]}"
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -qq
	apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
	echo "Missing Debian packages. Run as root:" >&2
	echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
	exit 1
fi
