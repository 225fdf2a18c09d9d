# Sourced by scripts/cost-table.sh and scripts/cost-times.sh: their shared options. The caller sets
# the defaults first (size, scenes; reps and frames only where it takes them), then calls
# `cost_options NAME "$@"`; sets baseline, baseline_name and probe (this build's sss_cost_probe).
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
      --reps | --frames)
        local variable=${1#--}
        [[ -v $variable ]] || { echo "$name: unknown argument '$1'" >&2; exit 2; }
        printf -v "$variable" '%s' "$2"
        shift 2 ;;
      *) echo "$name: unknown argument '$1'" >&2; exit 2 ;;
    esac
  done
  probe=build/release/tests/bench/sss_cost_probe
}
