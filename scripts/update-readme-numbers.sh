#!/usr/bin/env bash
# Rewrites the README's headline table (between "<!-- headline: begin" and "<!-- headline: end -->")
# from the committed benchmark results: docs/benchmarks/results.csv and results.json, and
# docs/benchmarks-gpu/ when present (tools/docs/sss_docs.cpp makes the table). The ctest
# docs.readme_headline_numbers fails until this has run after the results change;
# scripts/run-benchmark.sh runs it at its end. Builds sss_docs in build/release (configuring it if
# needed); installs what is missing first.
#
#   scripts/update-readme-numbers.sh [--check]     (--check: only compare, exit 1 when they differ)
set -euo pipefail
cd "$(dirname "$0")/.."

mode=--write
for arg in "$@"; do
  case "$arg" in
    --check) mode= ;;
    *) echo "update-readme-numbers.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

scripts/install-deps.sh test
[[ -f build/release/build.ninja ]] || cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --target sss_docs
build/release/tools/docs/sss_docs headline . README.md $mode
