#!/usr/bin/env bash
# Refits the default kernel (tests/bench/fit_default_main.cpp) and rewrites what depends on it:
#   module/src/math/default_kernel_fit.hpp   the constants the library's defaults use
#   tests/bench/default_kernel_fit.json      the expectation bench.default_kernel_fit checks
#   docs/kernel-fits.md                       its "calibrated default" section (sss_kernel_report)
# then rebuilds. About 10-30 minutes on two cores (three BOBYQA fits, a second or two per
# evaluation). Run it after a change to the kernels, the footprint taps or the instrument that moves
# bench.default_kernel_fit's objective, and commit the three files with that change; regenerate the
# miss baseline afterwards (scripts/update-miss-baseline.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh test
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --parallel "$(nproc)" --target sss_fit_default
build/release/tests/bench/sss_fit_default --header module/src/math/default_kernel_fit.hpp \
  --expectation tests/bench/default_kernel_fit.json "$@"
cmake --build build/release --parallel "$(nproc)" --target sss_kernel_report sss_bench
build/release/tools/sss_kernel_report --out docs/kernel-fits.md
echo "refitted: module/src/math/default_kernel_fit.hpp, tests/bench/default_kernel_fit.json, docs/kernel-fits.md"
