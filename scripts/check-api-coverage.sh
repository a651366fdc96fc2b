#!/usr/bin/env bash
# Every public function (TB_API in include/tumble/*.h) must be called by at least one test in
# tests/. Prints the ones that are not and fails when there is any. Run by ctest (api_coverage).
set -euo pipefail
cd "$(dirname "$0")/.."
missing=0
for f in $(grep -ohE "TB_API [^;(]*\btb[A-Za-z0-9_]+\s*\(" include/tumble/*.h | grep -oE "tb[A-Za-z0-9_]+\s*\($" | tr -d '( ' | sort -u); do
	if ! grep -rqw "$f" tests/; then
		echo "untested public function: $f"
		missing=$((missing + 1))
	fi
done
echo "public functions without a test: $missing"
[ "$missing" -eq 0 ]
