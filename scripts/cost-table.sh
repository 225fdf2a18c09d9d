#!/usr/bin/env bash
# A Markdown table of the instructions one in-place frame executes (scripts/cost-probe.sh, callgrind
# on llvmpipe) for each scene and path, for this build's probe and, optionally, a baseline build's:
# the repeatable counterpart of the benchmark's llvmpipe times.
#
#   scripts/cost-table.sh [--size WxH] [--scenes a,b,...] [--baseline PROBE --baseline-name NAME] > FILE.md
#
# PROBE: another checkout's build/release/tests/bench/sss_cost_probe (tests/bench/cost_probe.cpp
# builds against sss 0.1 too: copy it and its CMake lines there). Default size 640x360 (about 15 s
# a count; 1920x1080 about 2.5 min); default scenes head-close, head-mid, head-far and empty. The
# paths: each build's default (sss_default_settings: 0.1 the plain passes, SSS_PATH_AUTO since),
# the plain fragment passes and the masked ones.
set -euo pipefail
cd "$(dirname "$0")/.."

size=640x360
scenes=head-close,head-mid,head-far,empty
source scripts/cost-options.sh
cost_options cost-table.sh "$@"
count() {  # probe, scene, path
  scripts/cost-probe.sh "$1" -- --scene "$2" --size "$size" --path "$3" | awk '{print $NF}'
}

rev=$(git rev-parse --short HEAD)
echo "# Instructions per frame on llvmpipe ($size, in place, 17 taps, default settings but the path)"
echo
echo "Counted by callgrind over one steady \`sss_apply_frame\` + \`glFinish\` (\`scripts/cost-probe.sh\`:"
echo "the JIT-compiled shaders and the rasteriser included, in one thread); written by"
echo "\`scripts/cost-table.sh\` at $rev on $(date -u '+%Y-%m-%d %H:%M UTC'). Counts repeat to about 1e-7;"
echo "they measure work, not time (no cache or memory effects). Path \`default\`: what sss_default_settings"
echo "asks for (0.1: the plain fragment passes; since: \`SSS_PATH_AUTO\`, which takes the masked passes here)."
copy=$(count "$probe" head-close copy)
echo "\`× copy\`: this build's count over the benchmark's two-pass full-screen copy (\`--path copy\`, $copy"
echo "instructions here): the benchmark's \`× copy\` in work, not time (the copy is bound by memory, which a"
echo "count does not see, so it reads higher than the times' ratio)."
echo
if [[ -n $baseline ]]; then
  echo "| scene | path | $baseline_name | this build ($rev) | ratio | × copy |"
  echo "|---|---|---:|---:|---:|---:|"
else
  echo "| scene | path | this build ($rev) | × copy |"
  echo "|---|---|---:|---:|"
fi
for path in default fragment masked; do
  for scene in ${scenes//,/ }; do
    now=$(count "$probe" "$scene" "$path")
    over_copy=$(awk -v a="$now" -v b="$copy" 'BEGIN { printf "%.2f", a / b }')
    if [[ -n $baseline ]]; then
      before=$(count "$baseline" "$scene" "$path")
      ratio=$(awk -v a="$now" -v b="$before" 'BEGIN { printf "%.3f", a / b }')
      echo "| $scene | $path | $before | $now | $ratio | $over_copy |"
    else
      echo "| $scene | $path | $now | $over_copy |"
    fi
  done
done
