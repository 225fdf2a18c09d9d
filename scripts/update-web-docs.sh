#!/usr/bin/env bash
# Regenerates docs/web/ (the page's screenshot, the native and web frames, their difference images,
# results.json) and the numbers in docs/web.md, by running the browser test
# (web/test/browser_test.py) against a fresh page build (scripts/build-web.sh) and sss_web_frame:
#
#   scripts/update-web-docs.sh [NATIVE_BUILD_DIR]     (default build/dev, configured with the tests)
set -euo pipefail
cd "$(dirname "$0")/.."
native=${1:-build/dev}
scripts/build-web.sh build/web
cmake --build "$native" --target sss_web_frame
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 web/test/browser_test.py --page build/web/web-page --frame-bin "$native/web/sss_web_frame" --out "$out" \
  --screenshot "$out/page.png"
mkdir -p docs/web
cp "$out"/page.png "$out"/results.json "$out"/web-on.png "$out"/native-on.png "$out"/diff-on-x8.png docs/web/
python3 web/test/web_docs.py docs/web/results.json docs/web.md
echo "update-web-docs.sh: docs/web/ and docs/web.md updated"
