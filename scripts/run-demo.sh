#!/usr/bin/env bash
# Installs the missing Debian packages, builds the demo and runs it. Without a display it renders
# headless (EGL, falling back to OSMesa) and writes PNGs to ./demo-out; arguments are passed on to
# sss_demo (see `sss_demo --help`).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh demo
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --parallel "$(nproc)" --target sss_demo
build/release/demo/sss_demo --out demo-out "$@"
