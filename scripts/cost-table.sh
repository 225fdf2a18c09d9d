#!/usr/bin/env bash
# A Markdown table of the instructions one in-place frame executes (scripts/cost-probe.sh, callgrind
# on llvmpipe) for each scene and path, for this build's probe and, optionally, a baseline build's:
# the repeatable counterpart of the benchmark's llvmpipe times.
#
#   scripts/cost-table.sh [--size WxH] [--scenes a,b,...] [--baseline PROBE --baseline-name NAME] > FILE.md
#   scripts/cost-table.sh [--size WxH] [--scenes a,b,...] --baseline-counts OLD.md > FILE.md
#
# --baseline-counts: the baseline column of an earlier table of this script (same size, scenes and
# paths), carried over instead of counted again; the counts repeat, so this skips a second build of
# an old release (0.1's probe needs its sources patched) and half of the time. The header names the
# table it came from.
# PROBE: another checkout's build/release/tests/bench/sss_cost_probe (tests/bench/cost_probe.cpp
# builds against sss 0.1 too: copy it and its CMake lines there). Default size 640x360 (about 15 s
# a count; 1920x1080 about 2.5 min); default scenes head-close, head-mid, head-far and empty. The
# paths: each build's default (sss_default_settings: 0.1 the plain passes, SSS_PATH_AUTO since),
# the plain fragment passes and the masked ones.
set -euo pipefail
cd "$(dirname "$0")/.."

size=640x360
scenes=head-close,head-mid,head-far,empty
baseline_counts=""
source scripts/cost-options.sh
cost_options cost-table.sh "$@"
if [[ -n $baseline_counts ]]; then
  [[ -z $baseline ]] || { echo "cost-table.sh: --baseline and --baseline-counts exclude each other" >&2; exit 2; }
  grep -q "^# Instructions per frame on llvmpipe ($size," "$baseline_counts" ||
    { echo "cost-table.sh: $baseline_counts is not a table at $size" >&2; exit 2; }
  # Its header row's third column is the baseline's name.
  baseline_name=$(awk -F' [|] ' '/^[|] scene [|] path [|]/ { print $3; exit }' "$baseline_counts")
  [[ -n $baseline_name ]] || { echo "cost-table.sh: $baseline_counts has no baseline column" >&2; exit 2; }
fi
count() {  # probe, scene, path
  scripts/cost-probe.sh "$1" -- --scene "$2" --size "$size" --path "$3" | awk '{print $NF}'
}
baseline_count() {  # scene, path: counted with the baseline's probe, or carried over from $baseline_counts
  if [[ -n $baseline ]]; then
    count "$baseline" "$1" "$2"
    return
  fi
  local n
  n=$(awk -F' *[|] *' -v s="$1" -v p="$2" '$2 == s && $3 == p { print $4; exit }' "$baseline_counts")
  [[ -n $n ]] || { echo "cost-table.sh: $baseline_counts has no row for $1 $2" >&2; exit 2; }
  echo "$n"
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
if [[ -n $baseline_counts ]]; then
  written=$(grep -o 'cost-table.sh` at [0-9a-f]* on [0-9-]* [0-9:]* UTC' "$baseline_counts" | head -1 | cut -d' ' -f2-)
  echo "The $baseline_name counts are carried over from the table this one replaces (written $written;"
  echo "\`--baseline-counts\`): a count repeats, so they were not counted again."
fi
echo
if [[ -n $baseline || -n $baseline_counts ]]; then
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
    if [[ -n $baseline || -n $baseline_counts ]]; then
      before=$(baseline_count "$scene" "$path")
      ratio=$(awk -v a="$now" -v b="$before" 'BEGIN { printf "%.3f", a / b }')
      echo "| $scene | $path | $before | $now | $ratio | $over_copy |"
    else
      echo "| $scene | $path | $now | $over_copy |"
    fi
  done
done
