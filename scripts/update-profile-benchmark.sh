#!/usr/bin/env bash
# Regenerates docs/benchmarks-profiles.md (and docs/benchmarks-profiles/): the per-pixel profile rows
# of the benchmark alone (one profile against per-pixel profiles, issue 23) on this machine's GL, the
# head shots at 640x360 and 1080p and the mixed-material scene at 640x360, in one run. A full
# scripts/run-benchmark.sh run has the same rows in docs/benchmarks.md ("Several materials in one pass
# pair"); this shorter run is for a loaded machine, where the full sweep takes hours. Installs what is
# missing first. Extra arguments go to sss_bench.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh test
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --parallel "$(nproc)" --target sss_bench
rm -rf docs/benchmarks-profiles
mkdir -p docs/benchmarks-profiles
build/release/tests/bench/sss_bench --full --methods separable-one-profile,separable-profiles \
  --size 640x360:head-close,head-mid,head-far,head-mixed --size 1920x1080:head-close,head-mid,head-far \
  --no-msaa --no-heat-maps --warmup 3 --reps 15 \
  --out docs/benchmarks-profiles --doc docs/benchmarks-profiles.md "$@"
rm -f docs/benchmarks-profiles/*.dat docs/benchmarks-profiles/*.gp
