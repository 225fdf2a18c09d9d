#!/usr/bin/env bash
# There, on the lent GPU machine, in the repository root (see prepare.sh): unpacks the GL loaders,
# points libglvnd at the NVIDIA EGL driver, prints the GPU and the GL_RENDERER string, then runs
# the steps asked for, each under its own time limit, writing into $OUT:
#
#   scripts/gpu/on-device.sh [tests SECONDS] [bench NAME SECONDS -- SSS_BENCH_ARGS...]...
#
#   tests   the GL suites on the NVIDIA EGL device (egl-device): $OUT/gl-tests.log (failures in full,
#           passing tests not listed: --gtest_brief)
#   bench   sss_bench --backend egl-device with the given arguments; its output folder and
#           results document (docs/NAME.md, docs/NAME/) packed into $OUT/NAME.tar.gz, its log
#           in $OUT/NAME.log
#
# Issue 24's compute limit (the compute path at 1080p on the close-up at most 1.3 x the two-pass
# compute copy: the row "close-up on the compute path ... over the two-pass compute copy" of
# docs/NAME.md, with the renderer and date at its top) in a few minutes of device time:
#   m=copy,copy-compute,no-scattering,separable-in-place,separable-region,separable-masked
#   m=$m,separable-masked-region,separable-half,separable-compute,separable-compute-region,separable-auto-region
#   scripts/gpu/on-device.sh bench benchmarks-h100 420 -- --size 1920x1080:head-close,head-mid,head-far,empty \
#     --taps 17 --methods "$m" --warmup 30 --reps 61 --no-heat-maps
set -uo pipefail
cd "$(dirname "$0")/../.."
out=${OUT:-out}
mkdir -p "$out"

for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
export LD_LIBRARY_PATH=$PWD/.gpu/lib SSS_ASSET_DIR=$PWD/assets

{
  date -u
  nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,memory.total --format=csv
  build-gpu/integration/sss_headless_info egl-device
} 2>&1 | tee "$out/info.txt"

status=0
while [[ $# -gt 0 ]]; do
  step=$1
  shift
  if [[ $step == bench ]]; then
    name=$1
    shift
  fi
  limit=$1
  shift
  case "$step" in
    tests)
      for suite in sss_gl_tests sss_gl_state_tests sss_gl_stress_tests; do
        timeout "$limit" "build-gpu/tests/$suite" --sss-backend=egl-device --gtest_brief=1 2>&1 | tail -n 2000 >>"$out/gl-tests.log"
        rc=${PIPESTATUS[0]}
        echo "$suite: exit $rc" | tee -a "$out/gl-tests.log"
        [[ $rc -eq 0 ]] || status=1
      done
      ;;
    bench)
      [[ ${1:-} == -- ]] && shift
      args=()
      while [[ $# -gt 0 && $1 != tests && $1 != bench ]]; do args+=("$1"); shift; done
      rm -rf "docs/$name" "docs/$name.md"
      mkdir -p "docs/$name"
      timeout "$limit" build-gpu/tests/bench/sss_bench --backend egl-device --out "docs/$name" \
        --doc "docs/$name.md" "${args[@]}" 2>&1 | tee "$out/$name.log" | grep -v '^\['
      rc=${PIPESTATUS[0]}
      echo "sss_bench: exit $rc" | tee -a "$out/$name.log"
      [[ $rc -eq 0 ]] || status=1
      tar czf "$out/$name.tar.gz" "docs/$name" "docs/$name.md"
      ;;
    *) echo "on-device.sh: unknown step $step" >&2; exit 2 ;;
  esac
done
exit $status
