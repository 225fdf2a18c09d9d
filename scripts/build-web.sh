#!/usr/bin/env bash
# Builds the library and the web demo page with Debian's Emscripten (docs/web.md):
#
#   scripts/build-web.sh [BUILD_DIR]     (default build/web)
#
# BUILD_DIR/web-page/ then holds all the page loads: index.html, sss_page.js, sss_web.js,
# sss_web.wasm and sss_web.data (the head scan). Installs nothing: scripts/install-deps.sh web does.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build/web}
if ! command -v emcmake >/dev/null 2>&1; then
  echo "build-web.sh: emcmake not found (Debian: emscripten; scripts/install-deps.sh web)" >&2
  exit 1
fi
# Debian's Emscripten runs its JavaScript optimiser with node, which finds its modules (acorn) here.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
emcmake cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=MinSizeRel ${launcher[@]+"${launcher[@]}"} >/dev/null
cmake --build "$dir" --target sss_web
echo "build-web.sh: the page is in $dir/web-page"
