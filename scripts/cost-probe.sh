#!/usr/bin/env bash
# The instructions one in-place frame of the library executes on llvmpipe, counted by callgrind:
# the JIT-compiled shaders and the rasteriser included (LP_NUM_THREADS=0 runs them in the calling
# thread), the frame before it (program builds, allocations) and everything around it excluded.
# Unlike llvmpipe's wall-clock times, which move by tens of per cent on a shared machine, the count
# repeats to the instruction; it measures work, not time (no cache or memory effects).
#
#   scripts/cost-probe.sh [PROBE] [-- sss_cost_probe arguments]
#
# PROBE defaults to build/release/tests/bench/sss_cost_probe (build it first: it is part of the
# test build). Another build's probe compares the two on the same frame, e.g. an older checkout's.
# Prints "<arguments>: <instructions>".
set -euo pipefail
cd "$(dirname "$0")/.."

probe=build/release/tests/bench/sss_cost_probe
if [[ $# -gt 0 && $1 != "--" ]]; then
  probe=$1
  shift
fi
[[ ${1:-} == "--" ]] && shift
if [[ ! -x $probe ]]; then
  echo "cost-probe.sh: $probe not built (cmake --build build/release --target sss_cost_probe)" >&2
  exit 2
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
LP_NUM_THREADS=0 valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=/dev/null \
  "$probe" "$@" > "$log" 2>&1 || { cat "$log" >&2; exit 1; }
count=$(sed -n 's/^==[0-9]*== Collected : \([0-9]*\)$/\1/p' "$log")
echo "${*:-defaults}: $count"
