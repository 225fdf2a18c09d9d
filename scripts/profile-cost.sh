#!/usr/bin/env bash
# What per-pixel profiles cost on llvmpipe (issue 23: "at most 10 % above a single profile on the
# benchmark's head close-up"): the same in-place frame of a benchmark scene with one profile and no
# profile texture, and with N profiles set (sss_set_profiles) and an R8UI index texture given
# (sss_cost_probe --profiles N), as callgrind's instruction counts (scripts/cost-probe.sh; they repeat
# to about 1e-7) and as wall time (the two runs in turn, `--reps` rounds, each the median of
# `--frames` frames; on a shared machine read the ratio, not the times). Prints Markdown.
#
#   scripts/profile-cost.sh [--size WxH] [--scenes a,b,...] [--reps N] [--frames N] [--profiles N]
#                           > docs/benchmarks/profile-cost.md
set -euo pipefail
cd "$(dirname "$0")/.."

size=1920x1080
scenes=head-close,head-mid,head-far
reps=5
frames=7
profiles=4
source scripts/cost-options.sh
cost_options profile-cost.sh "$@"
[[ -x $probe ]] || { echo "profile-cost.sh: $probe not built" >&2; exit 2; }
count() {  # scene, profiles
  scripts/cost-probe.sh "$probe" -- --scene "$1" --size "$size" --profiles "$2" | awk '{print $NF}'
}
time_of() {  # scene, profiles: the median of one run's frames, in ms
  "$probe" --scene "$1" --size "$size" --profiles "$2" --frames "$frames" | sed -n 's/.*median \([0-9.]*\) ms.*/\1/p'
}

declare -A runs
for ((r = 0; r < reps; ++r)); do
  for scene in ${scenes//,/ }; do
    runs[one,$scene]+="$(time_of "$scene" 0) "
    runs[many,$scene]+="$(time_of "$scene" "$profiles") "
  done
done

rev=$(git rev-parse --short HEAD)
renderer=$(build/release/integration/sss_headless_info egl 2>/dev/null | sed -n 's/^GL_RENDERER: *//p' | head -1)
echo "# Per-pixel profiles against one profile on llvmpipe ($size, in place, 17 taps)"
echo
echo "The same frame of each benchmark scene (the default settings at the scene's scale, the default"
echo "path: \`SSS_PATH_AUTO\`, the culled fragment passes here): once with one profile and no \`profile_texture\`,"
echo "once with $profiles profiles set (\`sss_set_profiles\`; the others of other strength, falloff and"
echo "scale) and an \`R8UI\` index texture (\`sss_cost_probe --profiles $profiles\`). Written by"
echo "\`scripts/profile-cost.sh\` at $rev on $(date -u '+%Y-%m-%d %H:%M UTC'). Renderer: \`$renderer\`."
echo
echo "Instructions: callgrind over one steady frame (\`scripts/cost-probe.sh\`, one thread; they repeat"
echo "to about 1e-7 and measure work, not time). Time: milliseconds around \`sss_apply_frame\` +"
echo "\`glFinish\` with llvmpipe's own threads, the median over $reps rounds of each run's median of $frames"
echo "frames, the two runs in turn, on a machine shared with other work (read the ratio)."
echo
echo "| scene | instructions, one profile | $profiles profiles | ratio | ms, one profile | $profiles profiles | ratio |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for scene in ${scenes//,/ }; do
  one=$(count "$scene" 0)
  many=$(count "$scene" "$profiles")
  t1=$(tr ' ' '\n' <<<"${runs[one,$scene]}" | grep . | median)
  tn=$(tr ' ' '\n' <<<"${runs[many,$scene]}" | grep . | median)
  echo "| $scene | $one | $many | $(awk -v a="$many" -v b="$one" 'BEGIN { printf "%.3f", a / b }') |" \
       "$t1 | $tn | $(awk -v a="$tn" -v b="$t1" 'BEGIN { printf "%.2f", a / b }') |"
done
