#!/usr/bin/env bash
# The demo's headless test of one preset: renders it small and checks the PNGs.
#   headless_test.sh SSS_DEMO IMAGE_CHECK OUT_DIR PRESET ATTRIBUTION [sss_demo arguments...]
# ATTRIBUTION: text the images' tEXt "Copyright" chunk must contain.
set -euo pipefail
demo=$1 check=$2 out=$3 preset=$4 attribution=$5
shift 5
rm -rf "$out"
"$demo" --headless --size 640x360 --preset "$preset" --repeat 2 --out "$out" "$@"
"$check" headless "$out" "$attribution" "$preset"
