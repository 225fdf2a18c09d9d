#!/usr/bin/env bash
# Regenerates docs/web/three-example.png (the example page, split view), docs/web/three-results.json
# and docs/web/three-benchmark.md by running the web.three test (web/three/test/run_three_test.sh)
# with 9 timed frames, and the numbers of docs/three.md's "Against the native frame" (the test's
# check with sss_three_native_apply, built here in NATIVE_BUILD_DIR, configured with the tests). The
# web page's and the native numbers come from docs/web/results.json (scripts/update-web-docs.sh).
#
#   scripts/update-three-docs.sh [NATIVE_BUILD_DIR]     (default build/dev)
set -euo pipefail
cd "$(dirname "$0")/.."
native=${1:-build/dev}
cmake --build "$native" --target sss_three_native_apply
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
web/three/test/run_three_test.sh "$out" --frames 9 --screenshot "$out/three-example.png" \
  --native-apply "$native/web/sss_three_native_apply"
mkdir -p docs/web
cp "$out/three-example.png" docs/web/three-example.png
cp "$out/results.json" docs/web/three-results.json
python3 web/three/test/three_docs.py docs/web/three-results.json docs/web/results.json build/three/package \
  docs/web/three-benchmark.md docs/three.md
echo "update-three-docs.sh: docs/web/three-example.png, three-results.json, three-benchmark.md and docs/three.md updated"
