#!/usr/bin/env bash
# Builds the three.js package (docs/three.md): the library's WebAssembly for three's context
# (web/three/wasm, Debian's Emscripten, in the web build folder that scripts/build-web.sh shares),
# the package folder and its tarball:
#
#   scripts/build-three-package.sh [OUT_DIR]     (default build/three)
#
# OUT_DIR/package/ is the package as it installs; OUT_DIR/sss-three-VERSION.tgz is what `npm pack`
# makes of it (offline: the package bundles nothing from the registry). Installs nothing:
# scripts/install-deps.sh web does.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/three}
web_build=${SSS_WEB_BUILD_DIR:-build/web}
for tool in emcmake npm; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "build-three-package.sh: $tool not found (Debian: emscripten, npm; scripts/install-deps.sh web)" >&2
    exit 1
  fi
done
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}  # Emscripten's optimiser finds acorn here (build-web.sh)
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
emcmake cmake -S . -B "$web_build" -G Ninja -DCMAKE_BUILD_TYPE=MinSizeRel ${launcher[@]+"${launcher[@]}"} >/dev/null
cmake --build "$web_build" --target sss_three

package=$out/package
rm -rf "$package"
mkdir -p "$package/wasm" "$package/example"
cp web/three/package.json web/three/README.md web/three/src/sss-three.js web/three/src/split-lighting.js web/three/src/sss-three.d.ts "$package/"
cp LICENSE "$package/"  # the project's MIT licence (npm ships a LICENSE at the package's root)
cp "$web_build/three-wasm/sss_three.js" "$web_build/three-wasm/sss_three.wasm" "$package/wasm/"
cp web/three/example/index.html web/three/example/example.js "$package/example/"
rm -f "$out"/sss-three-*.tgz
tarball=$(cd "$package" && npm pack --silent --pack-destination "$(cd .. && pwd)")
echo "build-three-package.sh: $out/$tarball (from $package)"
