#!/usr/bin/env bash
# Installs the missing Debian packages (the "demo" set), builds the demo into build/demo and runs
# it: in a window with the control panel when there is an X display (DISPLAY set), else headless
# (EGL, falling back to OSMesa), writing before/after/split/heat-map PNGs of each camera preset and
# a README.txt with the pass times into ./demo-out. Arguments are passed on to sss_demo (see
# `sss_demo --help`); --headless renders headless even with a display.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh demo
# Without the test suites, so that the demo needs only its own packages.
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSS_BUILD_TESTS=OFF
cmake --build build/demo --parallel "$(nproc)" --target sss_demo
if [[ -n ${DISPLAY:-} ]]; then
  exec build/demo/demo/sss_demo --out demo-out "$@"
fi
echo "run-demo.sh: no DISPLAY: rendering headless into ./demo-out"
exec build/demo/demo/sss_demo --headless --out demo-out "$@"
