#!/usr/bin/env bash
# The texturing modes on planes with an albedo at pore scale, facing and turned, and on the head close-up
# with its albedo map (tests/bench/texturing_bench.cpp, texturing_head.cpp):
# writes docs/benchmarks/texturing.md and bench-out/texturing/results.csv. Needs the test build
# (scripts/run-tests.sh, or cmake --build build/release --target sss_bench_texturing).
#
#   scripts/run-texturing-bench.sh [sss_bench_texturing arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
bench=build/release/tests/bench/sss_bench_texturing
if [[ ! -x $bench ]]; then
  echo "run-texturing-bench.sh: $bench not built (cmake --build build/release --target sss_bench_texturing)" >&2
  exit 2
fi
"$bench" --backend egl --out bench-out/texturing --doc docs/benchmarks/texturing.md "$@"
