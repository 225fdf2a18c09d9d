# Sourced by scripts/cost-table.sh, scripts/cost-times.sh and scripts/profile-cost.sh: their shared
# options. The caller sets the defaults first (size, scenes; reps, frames, profiles and
# baseline_counts only where it takes them), then calls `cost_options NAME "$@"`; sets baseline, baseline_name and probe (this
# build's sss_cost_probe, under build/release or SSS_BUILD_DIR). Also `median` (stdin: one number a
# line) for the wall-time scripts.
cost_options() {
  local name=$1
  shift
  baseline=""
  baseline_name=baseline
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --size) size=$2; shift 2 ;;
      --scenes) scenes=$2; shift 2 ;;
      --baseline) baseline=$2; shift 2 ;;
      --baseline-name) baseline_name=$2; shift 2 ;;
      --reps | --frames | --profiles | --baseline-counts)
        local variable=${1#--}
        variable=${variable//-/_}
        [[ -v $variable ]] || { echo "$name: unknown argument '$1'" >&2; exit 2; }
        printf -v "$variable" '%s' "$2"
        shift 2 ;;
      *) echo "$name: unknown argument '$1'" >&2; exit 2 ;;
    esac
  done
  probe=${SSS_BUILD_DIR:-build/release}/tests/bench/sss_cost_probe
}

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
