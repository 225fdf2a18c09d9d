#!/usr/bin/env bash
# Valgrind memcheck over a bounded selection, on OSMesa (llvmpipe under valgrind is slow: a few GL
# tests at small sizes, the unit and property suites, a short soak): no invalid access, no use of
# uninitialised memory, no leak (definite or indirect) from sss code. Reports from inside Mesa,
# LLVM and ld.so are suppressed by tests/valgrind.supp, which says why for each.
#
#   scripts/run-valgrind.sh [BUILD_DIR]     (default build/release, built by run-tests.sh)
#
# Logs: BUILD_DIR/valgrind/*.log; one line per run and a summary on stdout. Exit status 0 when
# every run passed with zero errors. Valgrind runs a program's threads one at a time, so the runs go
# side by side, as many at once as the machine has cores, the longest first.
#
# Most of a GL run's time under valgrind was llvmpipe compiling shaders (LLVM, instrumented). So the
# GL programs first run natively, a few seconds, into a Mesa shader cache of their own
# (BUILD_DIR/valgrind/mesa-shader-cache, emptied each time), and their valgrind runs then load every
# shader from it: each run builds the same programs as its native run. On the 2-core machine here
# the GL selection took 440 s with the cache off and 182 s with it warm, the soak 167 s and 146 s,
# the stress selection 56 s and 19 s; the whole script 7.3 minutes and 4.3 (with the quadrature
# below left out of the unit run).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
tests="$build/tests"
logs="$build/valgrind"
mkdir -p "$logs"
if ! command -v valgrind >/dev/null 2>&1; then
  echo "run-valgrind.sh: valgrind is not installed (scripts/install-deps.sh test)" >&2
  exit 1
fi

vg=(valgrind --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect
  --show-leak-kinds=definite,indirect --suppressions="$PWD/tests/valgrind.supp" --num-callers=40
  --smc-check=all-non-file --gen-suppressions=all)
# The slowest exact-reference tests (multithreaded, ~1 s each natively, ~50x under valgrind) are
# left out; the rest of the unit suite runs.
slow_unit='ExactReference.MaskedPixelsNeitherReceiveNorContribute:ExactReference.SeriesEvaluationAgreesWithClosedForm'
slow_unit+=':ExactReference.FlatPlaneFacingCameraIsUnchangedFinePixels:ExactReference.ScreenBoundAndThreadsDoNotChangeTheResult'
# And a quadrature of plain doubles on the stack, 39 s under valgrind (the sanitizer suite runs it).
slow_unit+=':Burley.RectangleIntegralsMatchDuffysQuadrature'
gl_filter='Faults.*:ContextLoss.*:Invariants.AFlatImageStaysFlat:Invariants.NonFinitePixelsDoNotSpread'
gl_filter+=':BadInput.*:StateRestore.FailedCallsLeaveNoErrorAndNoStateBehind'

results="$logs/results.txt"
: >"$results"
run() {  # name, command...: one run in the background; its result line goes to $results
  local name=$1
  shift
  while [[ $(jobs -rp | wc -l) -ge $(nproc) ]]; do wait -n || true; done
  (
    log="$logs/$name.log"
    rc=0
    start=$(date +%s)
    # The shader cache warmed below. (Should a run miss it, Mesa's writer thread compresses the new
    # entry with zstd, whose uninitialised hash tables tests/valgrind.supp suppresses.)
    env LSAN_OPTIONS= MESA_SHADER_CACHE_DIR="$shader_cache" "${vg[@]}" "$@" >"$log" 2>&1 || rc=$?
    errors=$(sed -n 's/.*ERROR SUMMARY: \([0-9]*\) errors.*/\1/p' "$log" | tail -1)
    lost=$(sed -n 's/.*definitely lost: \([0-9,]*\) bytes.*/\1/p' "$log" | tail -1)
    echo "valgrind $name: exit $rc, ${errors:-?} errors, definitely lost ${lost:-0} bytes, $(($(date +%s) - start)) s ($log)"
    echo "$name $rc ${errors:-1}" >>"$results"
  ) &
}

gl_run=("$tests/sss_gl_tests" --sss-backend=osmesa "--gtest_filter=$gl_filter")
# (Resident memory means nothing under valgrind, which tracks leaks itself: not judged there.)
soak_run=("$tests/sss_soak" --backend osmesa --frames 24 --max-size 12 --resize-every 4 --recreate-every 12
  --rss-slack-kib 100000000)
stress_run=("$tests/sss_gl_stress_tests" --sss-backend=osmesa
  "--gtest_filter=NonFiniteStress.UnusableDepthNeverSpreads:CameraStress.SingularAndUnsupportedMatricesAreRejectedAndTheOldCameraStays")

# The GL runs natively, once, to fill the shader cache (their results are the valgrind runs').
shader_cache="$(cd "$logs" && pwd)/mesa-shader-cache"
rm -rf "$shader_cache"
warm() {  # name, command...
  local name=$1
  shift
  MESA_SHADER_CACHE_DIR="$shader_cache" "$@" >"$logs/warm-$name.log" 2>&1 || true
}
warm gl "${gl_run[@]}"
warm soak "${soak_run[@]}"
warm stress "${stress_run[@]}"

# The longest first, so the shorter ones fill whichever core frees up first.
run gl-osmesa "${gl_run[@]}"
run soak-osmesa "${soak_run[@]}"
run unit "$tests/sss_unit_tests" "--gtest_filter=-$slow_unit"
run stress-osmesa "${stress_run[@]}"
if [[ -x "$tests/sss_property_tests" ]]; then
  RC_PARAMS="seed=20261121 max_success=100" run property "$tests/sss_property_tests"
fi
wait

failed=0
total_errors=0
while read -r name rc errors; do
  total_errors=$((total_errors + errors))
  if [[ $rc -ne 0 ]]; then failed=1; fi
done <"$results"
echo "valgrind: $total_errors errors in all"
exit $failed
