#!/usr/bin/env bash
# Regenerates docs/benchmarks-passes.md (and docs/benchmarks-passes/): the rows issue 24 ("Faster
# passes") is measured by, alone, on this machine's GL: the default kernel written back in place at
# 1920x1080 on the head shots and the empty frame, on the plain and masked fragment paths, with and
# without the host's region, on the compute path (with and without the region), and on the
# half-resolution path, each beside the two-pass copy of the same run (`x copy`). A full
# scripts/run-benchmark.sh run has the same rows in docs/benchmarks.md ("Skipping what a frame does
# not need (1920x1080)"); this shorter run is for a loaded machine, where the full sweep takes hours.
# Installs what is missing first. Extra arguments go to sss_bench. Then the before-and-after table
# (scripts/pass-before-after.py).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/bench-rows.sh benchmarks-passes --full \
  --methods copy,separable-in-place,separable-region,separable-masked,separable-compute,separable-compute-region,separable-half,separable-auto-region \
  --size 1920x1080:head-close,head-mid,head-far,empty --footprints "" --no-exact \
  --no-msaa --no-heat-maps "$@"
# The same rows against the last full run before issue 24: docs/benchmarks-passes-before-after.md.
python3 scripts/pass-before-after.py
