#!/usr/bin/env bash
# The half-resolution path's work against the masked fragment passes' on the same frames: the
# instructions one steady in-place frame executes on llvmpipe (scripts/cost-probe.sh, callgrind,
# the JIT-compiled shaders and the rasteriser included), per scene, and the path that ran.
#
#   scripts/half-cost.sh [--size WxH] [--scenes a,b,...] > docs/benchmarks/half-resolution-cost.md
#
# Default 1920x1080 (about 2.5 minutes a count on two cores) on head-close, head-mid, head-far and
# empty. Uses this build's probe (build/release, or SSS_BUILD_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."

size=1920x1080
scenes=head-close,head-mid,head-far,empty
source scripts/cost-options.sh
cost_options half-cost.sh "$@"
count() {  # scene, path
  scripts/cost-probe.sh "$probe" -- --scene "$1" --size "$size" --path "$2" | awk '{print $NF}'
}
ran() {  # scene, path: the sss_path the frame took (sss_stats.last_frame_path)
  "$probe" --scene "$1" --size "$size" --path "$2" | sed -n 's/.*, \([0-9]*\) ran,.*/\1/p'
}

rev=$(git rev-parse --short HEAD)
threshold=$(sed -n 's/.*kHalfResolutionMinReachPixels = \([0-9.]*\)f;.*/\1/p' module/src/math/half_resolution_threshold.hpp)
echo "# The half-resolution path's cost on llvmpipe ($size, in place, 17 taps)"
echo
echo "Instructions of one steady \`sss_apply_frame\` + \`glFinish\`, counted by callgrind"
echo "(\`scripts/cost-probe.sh\`: the JIT-compiled shaders and the rasteriser included, in one thread;"
echo "they measure work, not time), \`SSS_PATH_HALF_RESOLUTION\` (\`--path half\`, threshold $threshold pixels:"
echo "[half-resolution.md](half-resolution.md)) against the masked fragment passes (\`--path masked\`) on"
echo "the same frame; \`ran\`: the sss_path the frame took (3 masked, 4 half resolution). Written by"
echo "\`scripts/half-cost.sh\` at $rev on $(date -u '+%Y-%m-%d %H:%M UTC')."
echo
echo "| scene | masked | half resolution | half / masked | ran |"
echo "|---|---:|---:|---:|---:|"
for scene in ${scenes//,/ }; do
  masked=$(count "$scene" masked)
  half=$(count "$scene" half)
  ratio=$(awk -v a="$half" -v b="$masked" 'BEGIN { printf "%.3f", a / b }')
  echo "| $scene | $masked | $half | $ratio | $(ran "$scene" half) |"
done
