#!/usr/bin/env bash
# The debug views' pictures in the guide (docs/integration.md §12 "Debug views"): the demo's
# headless close-up with every view of the library (sss_frame.debug_view), and the far shot's tiles
# view, where the masked path's culling shows best, in the demo's false colours (its legend for
# each view is in docs/demo/views/README.txt, beside the head scan's attribution).
#
#   scripts/update-debug-view-pictures.sh        writes docs/demo/views/*.png, README.txt, ATTRIBUTION.txt
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh demo
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSS_BUILD_TESTS=OFF >/dev/null
cmake --build build/demo --parallel "$(nproc)" --target sss_demo
demo=build/demo/demo/sss_demo
work=build/debug-view-pictures
rm -rf "$work"
"$demo" --headless --size 640x360 --repeat 1 --preset close --debug-view all --out "$work/close"
"$demo" --headless --size 640x360 --repeat 1 --preset far --debug-view tiles --out "$work/far"
out=docs/demo/views
rm -rf "$out"
mkdir -p "$out"
cp "$work"/close/close-view-*.png "$work/far/far-view-tiles.png" "$work/close/ATTRIBUTION.txt" "$out/"
cp "$work/close/README.txt" "$out/README.txt"
echo "update-debug-view-pictures.sh: wrote $(ls "$out" | wc -l) files into $out"
