#!/usr/bin/env bash
# Regenerates docs/benchmarks-profiles.md (and docs/benchmarks-profiles/): the per-pixel profile rows
# of the benchmark alone (one profile against per-pixel profiles, issue 23) on this machine's GL, the
# head shots at 640x360 and 1080p and the mixed-material scene at 640x360, in one run. A full
# scripts/run-benchmark.sh run has the same rows in docs/benchmarks.md ("Several materials in one pass
# pair"); this shorter run is for a loaded machine, where the full sweep takes hours. Installs what is
# missing first. Extra arguments go to sss_bench.
set -euo pipefail
cd "$(dirname "$0")/.."

exec scripts/bench-rows.sh benchmarks-profiles --full --methods separable-one-profile,separable-profiles \
  --size 640x360:head-close,head-mid,head-far,head-mixed --size 1920x1080:head-close,head-mid,head-far \
  --no-msaa --no-heat-maps --warmup 3 --reps 15 "$@"
