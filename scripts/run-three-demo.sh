#!/usr/bin/env bash
# The three.js package's example page (docs/three.md): installs what is missing (the "web" set),
# builds and packs the package (scripts/build-three-package.sh), installs the tarball into a fresh
# folder beside three and lil-gui (npm ci from web/three/dev/package-lock.json), puts the head scan
# at /head.glb and serves that folder on the loopback address:
#
#   scripts/run-three-demo.sh [PORT]     (default 8001; Ctrl-C stops the server)
set -euo pipefail
cd "$(dirname "$0")/.."
port=${1:-8001}
scripts/install-deps.sh web
scripts/build-three-package.sh build/three
site=build/three/demo-site
rm -rf "$site"
mkdir -p "$site"
cp web/three/dev/package.json web/three/dev/package-lock.json "$site/"
(cd "$site" && npm ci --prefer-offline --no-audit --no-fund && npm install --no-save --prefer-offline --no-audit --no-fund ../sss-three-*.tgz)
# The scan and its licence's attribution (the page shows it too).
cp assets/lee-perry-smith-head/head.glb assets/lee-perry-smith-head/README.md "$site/"
echo "run-three-demo.sh: open http://127.0.0.1:$port/node_modules/sss-three/example/index.html"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site"
