#!/usr/bin/env bash
# Regenerates docs/benchmarks/turn-sweep.md (and docs/benchmarks/turn-sweep/: results.csv and the plot):
# the turn sweep (sss_bench_turns, tests/bench/turn_sweep.cpp) on this machine's GL: the library's
# interior miss on planes turned away from the camera (orthographic and perspective), a cylinder and a
# sphere, at four footprints, against the exact references. Minutes on llvmpipe. Installs what is
# missing and builds sss_bench_turns in build/release (or SSS_BUILD_DIR) first. Extra arguments go to
# sss_bench_turns (e.g. --footprints 0.2,1 --methods separable,sum-of-gaussians for a shorter run;
# see `sss_bench_turns --help`).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SSS_BUILD_DIR:-build/release}

scripts/install-deps.sh test
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" --parallel "$(nproc)" --target sss_bench_turns
rm -rf docs/benchmarks/turn-sweep
mkdir -p docs/benchmarks/turn-sweep
"$build/tests/bench/sss_bench_turns" --out docs/benchmarks/turn-sweep --doc docs/benchmarks/turn-sweep.md "$@"
# The gnuplot inputs are intermediate files; the PNG and the CSV stay.
rm -f docs/benchmarks/turn-sweep/*.dat docs/benchmarks/turn-sweep/*.gp
