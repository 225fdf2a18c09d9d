#!/usr/bin/env bash
# Regenerates docs/benchmarks/whole-surface.md (and whole-surface.csv beside it): the head scored
# against the exact convolution over its whole mesh, hidden surface included (issue 49;
# tests/bench/whole_surface.hpp), at 960x540 for the close-up, the three-quarter view and the
# close-up under the hard key, per region and channel, with the input's floor and the hidden-light
# rows beside every method, the reference's checks on the head (--check), and heat maps in
# docs/benchmarks/whole-surface/ (sss_whole_surface, tests/bench/whole_surface_study.cpp); then
# docs/benchmarks/whole-surface-1080p.md: the close-up and the three-quarter view at 1920x1080 on a
# 1-in-16 grid, no pictures. About fifteen minutes on two cores, and 12 GB of memory at the peak
# (the --check frame: the 0.22 mm term sampled 0.06 mm apart over the face). Installs what is
# missing and builds it in build/release (or SSS_BUILD_DIR) first. Extra arguments go to both runs
# of sss_whole_surface (see its --help).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SSS_BUILD_DIR:-build/release}

scripts/install-deps.sh test
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" --parallel "$(nproc)" --target sss_whole_surface
mkdir -p docs/benchmarks
rm -rf docs/benchmarks/whole-surface
"$build/tests/bench/sss_whole_surface" --doc docs/benchmarks/whole-surface.md --csv docs/benchmarks/whole-surface.csv \
  --pictures docs/benchmarks/whole-surface --check "$@"
"$build/tests/bench/sss_whole_surface" --shots close-up,three-quarter --size 1920x1080 --stride 4 \
  --doc docs/benchmarks/whole-surface-1080p.md --csv docs/benchmarks/whole-surface-1080p.csv "$@"
