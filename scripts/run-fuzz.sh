#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, with ASan + UBSan) and runs each for a bounded time from the
# committed seed corpus (tests/fuzz/corpus/<target>, copied: the committed files never change).
# Skipped, with a message and exit status 0, when clang is not installed.
#
#   scripts/run-fuzz.sh [--seconds N] [--build-dir DIR]     (default 20 s per target, build/fuzz)
#
# Targets: validation (sss_set_settings / sss_set_camera / sss_kernel_separable argument bytes),
# kernel (the kernel generator), cpu_model (the CPU model of the passes and the exact reference).
# Writes DIR/summary.txt ("target executions seconds corpus_files"); a crash, sanitizer report or
# invariant failure leaves its input in DIR/artifacts/ and makes the exit status 1.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=20
build=build/fuzz
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    --build-dir) build=$2; shift 2 ;;
    *) echo "run-fuzz.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

if ! command -v clang++ >/dev/null 2>&1 || ! command -v clang >/dev/null 2>&1; then
  echo "run-fuzz.sh: clang is not installed: fuzzing skipped (scripts/install-deps.sh test installs it)"
  exit 0
fi

echo "== fuzz: configure and build ($build)"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DSSS_BUILD_FUZZERS=ON -DSSS_BUILD_DEMO=OFF -DSSS_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build "$build" --target sss_fuzzers --parallel "$(nproc)"

mkdir -p "$build/artifacts"
: >"$build/summary.txt"
# Each target runs on one core (libFuzzer without -jobs is one process), so as many run side by side
# as the machine has cores, each for the whole $seconds.
fuzz_one() {  # target
  local target=$1 corpus="$build/corpus/$1" log="$build/$1.log" rc=0
  rm -rf "$corpus"
  mkdir -p "$corpus"
  cp tests/fuzz/corpus/"$target"/* "$corpus"/
  "$build/tests/fuzz/sss_fuzz_$target" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="$build/artifacts/$target-" "$corpus" >"$log" 2>&1 || rc=$?
  local execs files
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  files=$(find "$corpus" -type f | wc -l)
  echo "fuzz $target: exit $rc, ${execs:-0} executions in $seconds s, corpus $files inputs ($log)"
  echo "$target ${execs:-0} $seconds $files $rc" >>"$build/summary.txt"
  if [[ $rc -ne 0 ]]; then
    grep -E 'invariant violated|ERROR|runtime error|SUMMARY' "$log" | head -5 >&2 || true
  fi
}
for target in validation kernel cpu_model; do
  while [[ $(jobs -rp | wc -l) -ge $(nproc) ]]; do wait -n || true; done
  fuzz_one "$target" &
done
wait
status=0
while read -r _ _ _ _ rc; do
  if [[ $rc -ne 0 ]]; then status=1; fi
done <"$build/summary.txt"
exit $status
