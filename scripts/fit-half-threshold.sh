#!/usr/bin/env bash
# Measures the half-resolution path's threshold (tests/bench/fit_half_threshold_main.cpp) and
# rewrites what depends on it:
#   module/src/math/half_resolution_threshold.hpp   kHalfResolutionMinReachPixels
#   tests/bench/half_threshold_fit.json              the cases bench.half_threshold re-checks
#   docs/benchmarks/half-resolution.md               the report, with half-resolution-miss.png
# About two minutes on two cores. Run it after a change to the half path (its reduction or
# upsample), the kernels, the footprint taps or the instrument that moves a miss (bench.half_threshold
# fails then), and commit the files with that change. Exits 1, the header left as it was, when no
# candidate keeps the margin. SSS_BUILD_DIR picks the build folder (default build/release).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SSS_BUILD_DIR:-build/release}

scripts/install-deps.sh test
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" --parallel "$(nproc)" --target sss_fit_half_threshold
status=0
"$build/tests/bench/sss_fit_half_threshold" --header module/src/math/half_resolution_threshold.hpp \
  --expectation tests/bench/half_threshold_fit.json --doc docs/benchmarks/half-resolution.md "$@" || status=$?
rm -f docs/benchmarks/half-resolution-miss.dat docs/benchmarks/half-resolution-miss.gp
[ "$status" -eq 0 ] && echo "measured: module/src/math/half_resolution_threshold.hpp, tests/bench/half_threshold_fit.json, docs/benchmarks/half-resolution.md"
exit "$status"
