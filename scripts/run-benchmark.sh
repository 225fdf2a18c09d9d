#!/usr/bin/env bash
# Regenerates docs/benchmarks.md (and its plots and pictures in docs/benchmarks/, with preintegrated.md,
# burley.md, turn-sweep.md and surface-study.md there, and the README's headline table): the full
# benchmark sweep on this machine's GL (headless; on Mesa that is llvmpipe). Installs what is
# missing first. Extra arguments go to sss_bench (e.g. --size 1920x1080 --scenes head-close,head-mid
# for a shorter run; see `sss_bench --help`).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh test
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --parallel "$(nproc)" --target sss_bench sss_bench_preintegrated sss_bench_burley
# What the programs below write goes first (pictures of scenes and methods, plots, tables; a scene
# or method that is gone must not leave its pictures). The other generators' files in
# docs/benchmarks/ stay: cost-probe.md and profile-cost.md (scripts/cost-table.sh and friends),
# half-resolution*.md and half-resolution-miss.png (scripts/fit-half-threshold.sh, half-cost.sh).
mkdir -p docs/benchmarks
find docs/benchmarks -maxdepth 1 -type f \( -name '*-[0-9]*x[0-9]*-*.png' -o -name '*-[0-9]*x[0-9]*.png' \
  -o -name 'pareto-*' -o -name 'footprint-*' -o -name 'results.*' -o -name 'miss.csv' -o -name 'msaa.*' \
  -o -name 'preintegrated*' -o -name 'burley.md' -o -name 'surface-study*' -o -name 'turn-sweep.md' \) -delete
rm -rf docs/benchmarks/preintegrated-* docs/benchmarks/turn-sweep docs/benchmarks/surface-study
build/release/tests/bench/sss_bench --full --out docs/benchmarks --doc docs/benchmarks.md "$@"
# The pre-integrated path: LUT generation time and its error against the same exact reference.
build/release/tests/bench/sss_bench_preintegrated --size 320x180 --repetitions 5 --out docs/benchmarks \
  --doc docs/benchmarks/preintegrated.md
# Burley's normalized diffusion on the footprint sweep: the kernel families' miss against its exact
# plane reference.
build/release/tests/bench/sss_bench_burley --doc docs/benchmarks/burley.md
# The gnuplot inputs are intermediate files; the PNGs and tables stay.
rm -f docs/benchmarks/*.dat docs/benchmarks/*.gp
# Surfaces turned away from the camera: the turn sweep (GL) and the walk's choices (CPU model).
scripts/run-turn-sweep.sh
scripts/run-surface-study.sh
# The README's headline table from the new results.
scripts/update-readme-numbers.sh
