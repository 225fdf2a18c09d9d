#!/usr/bin/env bash
# Rewrites tests/bench/miss_baseline.csv, the accuracy regression guard's baseline (ctest
# bench.miss_baseline), from a fresh quick benchmark run in build/release. Run it after a change that
# makes a method more accurate (the guard lists such values) or that adds rows, and commit the file
# with the change. A value that got worse fails the guard: fix the change, or say in its commit why
# the new value is right.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh test
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --parallel "$(nproc)" --target sss_bench
ctest --test-dir build/release -R '^bench\.quick$' --output-on-failure
cp build/release/tests/bench/quick/miss.csv tests/bench/miss_baseline.csv
echo "tests/bench/miss_baseline.csv: $(($(wc -l < tests/bench/miss_baseline.csv) - 1)) rows"
