#!/usr/bin/env bash
# The wall-clock counterpart of scripts/cost-table.sh: one steady in-place frame's time on llvmpipe
# for this build's probe and a baseline build's, run in turn (baseline, then this build, per scene
# and path, `--reps` rounds) so that both see the same machine; each run times `--frames` frames
# after a warm-up one (sss_cost_probe --frames) and gives its median. Prints a Markdown table of
# the median over the rounds and the ratio. On a shared machine single runs move by tens of per
# cent; the interleaving and medians keep the comparison fair, not the times exact.
#
#   scripts/cost-times.sh --baseline PROBE [--baseline-name NAME] [--size WxH] [--scenes a,b,...]
#                         [--reps N] [--frames N] > FILE.md
set -euo pipefail
cd "$(dirname "$0")/.."

size=1920x1080
scenes=head-close,head-mid,head-far
reps=5
frames=7
source scripts/cost-options.sh
cost_options cost-times.sh "$@"
[[ -n $baseline ]] || { echo "cost-times.sh: --baseline PROBE is needed" >&2; exit 2; }
for p in "$probe" "$baseline"; do
  [[ -x $p ]] || { echo "cost-times.sh: $p not built" >&2; exit 2; }
done
time_of() {  # probe, scene, path: the median of one run's frames, in ms
  "$1" --scene "$2" --size "$size" --path "$3" --frames "$frames" | sed -n 's/.*median \([0-9.]*\) ms.*/\1/p'
}

declare -A runs
for ((r = 0; r < reps; ++r)); do
  for scene in ${scenes//,/ }; do
    for path in default fragment masked; do
      runs[b,$scene,$path]+="$(time_of "$baseline" "$scene" "$path") "
      runs[n,$scene,$path]+="$(time_of "$probe" "$scene" "$path") "
    done
  done
done

rev=$(git rev-parse --short HEAD)
echo "## Wall time per frame on llvmpipe ($size, in place, 17 taps)"
echo
echo "Milliseconds around \`sss_apply_frame\` + \`glFinish\` (llvmpipe's own threads, as a host runs it),"
echo "the median over $reps rounds of each run's median of $frames frames, the two builds in turn;"
echo "written by \`scripts/cost-times.sh\` at $rev on $(date -u '+%Y-%m-%d %H:%M UTC') on a machine shared with other"
echo "work (read the ratios, not the times). Renderer: \`$(build/release/integration/sss_headless_info egl 2>/dev/null | sed -n 's/^GL_RENDERER: *//p' | head -1)\`."
echo
echo "| scene | path | $baseline_name | this build ($rev) | ratio |"
echo "|---|---|---:|---:|---:|"
for path in default fragment masked; do
  for scene in ${scenes//,/ }; do
    before=$(tr ' ' '\n' <<<"${runs[b,$scene,$path]}" | grep . | median)
    now=$(tr ' ' '\n' <<<"${runs[n,$scene,$path]}" | grep . | median)
    ratio=$(awk -v a="$now" -v b="$before" 'BEGIN { printf "%.2f", a / b }')
    echo "| $scene | $path | $before | $now | $ratio |"
  done
done
