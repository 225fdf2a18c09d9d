#!/usr/bin/env bash
# ctest web.browser: builds the page with Emscripten (scripts/build-web.sh, into build/web of the
# source tree, shared with scripts/run-web-demo.sh) and runs web/test/browser_test.py against the
# native twin. Exit 77 (a skip) when Emscripten or Chromium is not installed.
#
#   run_browser_test.sh SSS_WEB_FRAME OUT_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
frame_bin=$1
out_dir=$2
for tool in emcmake chromium; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIP: $tool not found (Debian: emscripten, chromium; scripts/install-deps.sh test installs both)"
    exit 77
  fi
done
"$root/scripts/build-web.sh" "$root/build/web"
exec python3 "$root/web/test/browser_test.py" --page "$root/build/web/web-page" --frame-bin "$frame_bin" --out "$out_dir"
