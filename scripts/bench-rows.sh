#!/usr/bin/env bash
# The helper of scripts/update-profile-benchmark.sh and update-pass-benchmark.sh: runs some
# rows of the benchmark alone into docs/NAME.md and docs/NAME/ (the plots and tables; gnuplot's
# inputs removed), installing what is missing and building sss_bench first (in build/release, or
# SSS_BUILD_DIR).
#
#   scripts/bench-rows.sh NAME sss_bench-arguments...
set -euo pipefail
cd "$(dirname "$0")/.."
name=$1
shift
build=${SSS_BUILD_DIR:-build/release}

scripts/install-deps.sh test
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" --parallel "$(nproc)" --target sss_bench
rm -rf "docs/$name"
mkdir -p "docs/$name"
"$build/tests/bench/sss_bench" "$@" --out "docs/$name" --doc "docs/$name.md"
rm -f "docs/$name"/*.dat "docs/$name"/*.gp
