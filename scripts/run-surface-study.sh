#!/usr/bin/env bash
# Regenerates docs/benchmarks/surface-study.md (and surface-study.csv beside it): the choices behind
# the passes' walk over the surface (module/src/math/pass_surface.hpp: the tangent rule, the ramp's
# slack, and the previous phase's facing walk) measured on the CPU model against the exact 2D
# reference, raw and energy-conserving, on the head scan and on curved and turned analytic surfaces,
# with heat maps of the grazing view before and after in docs/benchmarks/surface-study/
# (sss_surface_study, tests/bench/surface_study.cpp). About half an hour on two cores. Installs what
# is missing and builds it in build/release (or SSS_BUILD_DIR) first. Extra arguments go to
# sss_surface_study (e.g. --scenes head-close --stride 12 for a shorter run; see its --help).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SSS_BUILD_DIR:-build/release}

scripts/install-deps.sh test
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" --parallel "$(nproc)" --target sss_surface_study
mkdir -p docs/benchmarks
rm -rf docs/benchmarks/surface-study
"$build/tests/bench/sss_surface_study" --doc docs/benchmarks/surface-study.md --csv docs/benchmarks/surface-study.csv \
  --pictures docs/benchmarks/surface-study "$@"
