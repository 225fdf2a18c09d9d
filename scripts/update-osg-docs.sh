#!/usr/bin/env bash
# The OpenSceneGraph host's documents (examples/osg): the time the library adds to its frame at
# 1280x720 on this machine, beside the demo's own figure for its sss pass at the same size
# (docs/benchmarks/osg-host.md; timing, so a benchmark and never a test), and its frame with and
# without the module and the standard-materials scene after it (docs/osg/*.png, 960x540).
#
#   scripts/update-osg-docs.sh [FRAMES]      (default 30)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-30}
scripts/install-deps.sh test demo
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build/release --parallel "$(nproc)" --target sss_osg_host sss_demo
host=build/release/examples/osg/sss_osg_host
osg_out=$(examples/osg/run_with_display.sh "$(command -v xvfb-run || true)" "$host" --bench "$frames" --width 1280 --height 720)
demo_out=$(build/release/demo/sss_demo --headless --size 1280x720 --preset close --repeat "$frames" --out build/osg-bench-demo 2>/dev/null)
read -r _ size skin timed without with adds <<<"$(grep '^osg-row ' <<<"$osg_out")"
renderer=$(sed -n 's/^renderer: //p' <<<"$osg_out")
demo_sss=$(awk '$1 == "close" { for (i = 1; i < NF; ++i) if ($i == "sss") print $(i + 1) }' <<<"$demo_out")
demo_total=$(awk '$1 == "close" { for (i = 1; i < NF; ++i) if ($i == "total") print $(i + 1) }' <<<"$demo_out")
demo_skin=$(sed -n 's/.*touched [0-9]* of \([0-9]*\) marked pixels.*/\1/p' <<<"$demo_out")
per_mpx() { awk -v ms="$1" -v px="$2" 'BEGIN { printf "%.1f", ms / (px / 1e6) }'; }
{
  echo "# The library inside OpenSceneGraph: what it adds to the engine's frame"
  echo
  echo "Written by \`scripts/update-osg-docs.sh $frames\`; a benchmark, not a test (timing). Renderer:"
  echo "\`$renderer\`, $(nproc) cores. Medians of $frames frames."
  echo
  echo "The OpenSceneGraph host (\`examples/osg\`, [integration.md §22](../integration.md#22-inside-openscenegraph-an-engine-that-caches-gl-state))"
  echo "times whole \`viewer.frame()\` calls, single-threaded, with its read-backs: without the module (its"
  echo "composite reads the diffuse), with it, and without it again (the two averaged). The demo times its"
  echo "\`sss_apply_frame\` alone (glFinish around it) on its close-up. Skin pixels are those with strength"
  echo "above 0; the pass's cost follows them, not the frame's size."
  echo
  echo "| host | size | skin pixels | frame without the module (ms) | frame with it (ms) | the module adds (ms) | per million skin pixels (ms) |"
  echo "|---|---|---|---|---|---|---|"
  echo "| OpenSceneGraph 3.6 (\`sss_osg_host --bench\`) | $size | $skin | $without | $with | $adds | $(per_mpx "$adds" "$skin") |"
  echo "| the demo (\`sss_demo --headless --preset close\`) | 1280x720 | $demo_skin | $demo_total (all passes) | | $demo_sss | $(per_mpx "$demo_sss" "$demo_skin") |"
} >docs/benchmarks/osg-host.md
cat docs/benchmarks/osg-host.md
mkdir -p docs/osg build/osg-pictures
xvfb=$(command -v xvfb-run || true)
examples/osg/run_with_display.sh "$xvfb" "$host" --width 960 --height 540 --out docs/osg
examples/osg/run_with_display.sh "$xvfb" "$host" --width 960 --height 540 --no-sss --out build/osg-pictures
cp build/osg-pictures/final.png docs/osg/final-without.png
