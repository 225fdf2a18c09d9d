#!/usr/bin/env bash
# The demo's window test under Xvfb: opens the window (640x360) on the close-up, renders frames
# with the panel, saves a screenshot at frame 5 (the F12 path) and compares the frame with the
# headless render of the same preset and size. Exit 77 (skipped) without xvfb-run or xauth.
#   window_test.sh SSS_DEMO IMAGE_CHECK HEADLESS_DIR OUT_DIR
set -euo pipefail
demo=$1 check=$2 headless=$3 out=$4
for tool in xvfb-run xauth; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIP: $tool not found (Debian: apt-get install xvfb xauth, or scripts/install-deps.sh demo)"
    exit 77
  fi
done
rm -rf "$out"
# -a: the first free display number, so that tests can run side by side.
xvfb-run -a -s "-screen 0 1024x768x24" \
  "$demo" --size 640x360 --preset close --frames 8 --screenshot-frame 5 --out "$out"
"$check" window "$out/screenshot-001.png" "$out/screenshot-001-window.png" "$headless/close-after.png"
