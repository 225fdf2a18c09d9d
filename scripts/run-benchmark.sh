#!/usr/bin/env bash
# Regenerates docs/benchmarks.md (and its plots and pictures in docs/benchmarks/, with preintegrated.md and
# burley.md there, and the README's headline table): the full
# benchmark sweep on this machine's GL (headless; on Mesa that is llvmpipe). Installs what is
# missing first. Extra arguments go to sss_bench (e.g. --size 1920x1080 --scenes head-close,head-mid
# for a shorter run; see `sss_bench --help`).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh test
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --parallel "$(nproc)" --target sss_bench sss_bench_preintegrated sss_bench_burley
rm -rf docs/benchmarks
mkdir -p docs/benchmarks
build/release/tests/bench/sss_bench --full --out docs/benchmarks --doc docs/benchmarks.md "$@"
# The pre-integrated path: LUT generation time and its error against the same exact reference.
build/release/tests/bench/sss_bench_preintegrated --size 320x180 --repetitions 5 --out docs/benchmarks \
  --doc docs/benchmarks/preintegrated.md
# Burley's normalized diffusion on the footprint sweep: the kernel families' miss against its exact
# plane reference.
build/release/tests/bench/sss_bench_burley --doc docs/benchmarks/burley.md
# The gnuplot inputs are intermediate files; the PNGs and tables stay.
rm -f docs/benchmarks/*.dat docs/benchmarks/*.gp
# The README's headline table from the new results.
scripts/update-readme-numbers.sh
