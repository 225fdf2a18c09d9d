#!/usr/bin/env bash
# The whole test suite from a clean checkout: installs the missing Debian packages, builds with
# warnings as errors, runs every ctest suite (GL tests once on OSMesa and once on EGL surfaceless),
# builds and runs the consumer projects against static and shared installs (check-consumers.sh),
# runs a bounded selection under valgrind memcheck (run-valgrind.sh), then builds again with
# AddressSanitizer + UndefinedBehaviorSanitizer and runs the suite again (at -O1 -g1,
# cmake/SssSanitizers.cmake; its benchmark run reduced, its report checks, the shader validation, the
# offline tools and the programs no test runs left to the release suite: tests/bench/CMakeLists.txt,
# tests/CMakeLists.txt), and runs each libFuzzer target for 20 s (run-fuzz.sh; needs clang).
# --no-sanitizers skips the last three. Valgrind's runs and the fuzz targets go side by side, one
# per core.
#
#   scripts/run-tests.sh [--no-sanitizers]
#
# Build folders: build/release and build/sanitize (ignored by git). Exit status: 0 when every
# suite passed.
set -euo pipefail
cd "$(dirname "$0")/.."

sanitizers=1
for arg in "$@"; do
  case "$arg" in
    --no-sanitizers) sanitizers=0 ;;
    *) echo "run-tests.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

scripts/install-deps.sh test demo  # the demo is part of the default build and has tests
jobs=$(nproc)

run_suite() {  # name, build dir, extra cmake arguments...
  local name=$1 dir=$2
  shift 2
  echo "== $name: configure and build ($dir)"
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSS_WARNINGS_AS_ERRORS=ON "$@"
  cmake --build "$dir" --parallel "$jobs"
  echo "== $name: ctest"
  ctest --test-dir "$dir" --output-on-failure --parallel "$jobs"
}

run_suite "release" build/release
scripts/check-consumers.sh
if [[ $sanitizers -eq 1 ]]; then
  echo "== valgrind memcheck (OSMesa; a bounded selection)"
  scripts/run-valgrind.sh build/release
  # halt_on_error: UBSan is built without recovery; ASan stops at the first report anyway.
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  run_suite "asan+ubsan" build/sanitize -DSSS_SANITIZE=ON -DSSS_BUILD_DEMO=OFF -DSSS_BUILD_TOOLS=OFF
  echo "== libFuzzer targets, 20 s each (skipped without clang)"
  scripts/run-fuzz.sh --seconds 20
fi
