#!/usr/bin/env bash
# Installs what is missing (the "web" set), builds the web demo (scripts/build-web.sh) and serves it
# on the loopback address, printing the URL to open in a browser with WebGL2 (docs/web.md):
#
#   scripts/run-web-demo.sh [PORT]     (default 8000; Ctrl-C stops the server)
set -euo pipefail
cd "$(dirname "$0")/.."
port=${1:-8000}
scripts/install-deps.sh web
scripts/build-web.sh build/web
echo "run-web-demo.sh: open http://127.0.0.1:$port/index.html"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory build/web/web-page
