#!/usr/bin/env bash
# ctest web.three (docs/three.md): builds and packs the three.js package
# (scripts/build-three-package.sh, into build/three of the source tree, shared with
# scripts/run-three-demo.sh), installs it from its tarball into a fresh folder beside three and
# lil-gui at the versions of web/three/dev/package-lock.json (npm ci), type-checks its declarations
# and runs web/three/test/three_test.py on the example page served from that folder. Exit 77 (a
# skip) when Emscripten, Chromium or npm is not installed or the npm packages cannot be had.
#
#   run_three_test.sh OUT_DIR [three_test.py options...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
out=$1
shift
for tool in emcmake chromium npm; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIP: $tool not found (Debian: emscripten, chromium, npm; scripts/install-deps.sh test installs them)"
    exit 77
  fi
done
"$root/scripts/build-three-package.sh" "$root/build/three"
tarball=$(ls "$root"/build/three/sss-three-*.tgz)

site=$out/site
rm -rf "$site"
mkdir -p "$site/test"
cp "$root/web/three/dev/package.json" "$root/web/three/dev/package-lock.json" "$site/"
if ! (cd "$site" && npm ci --prefer-offline --no-audit --no-fund); then
  echo "SKIP: npm ci could not get three, lil-gui and TypeScript (no registry and no npm cache)"
  exit 77
fi
(cd "$site" && npm install --no-save --prefer-offline --no-audit --no-fund "$tarball")
# The example's model and its licence's attribution, where the example looks for them.
cp "$root/assets/lee-perry-smith-head/head.glb" "$root/assets/lee-perry-smith-head/README.md" "$site/"
cp "$root/web/three/test/checks.js" "$site/test/"
cp "$root/web/three/test/types_check.ts" "$root/web/three/test/tsconfig.json" "$site/"
(cd "$site" && node_modules/.bin/tsc -p tsconfig.json)
echo "ok   the package's declarations type-check against @types/three (types_check.ts)"
exec python3 "$root/web/three/test/three_test.py" --site "$site" --out "$out" "$@"
