#!/usr/bin/env bash
# Here, before a run on a lent GPU machine (../shared/docs/gpu.md): builds the benchmark, the GL
# test suites and sss_headless_info in Release into build-gpu/, and gathers in .gpu/ what that
# machine lacks: the shared libraries they link beyond glibc, libstdc++ and GL (.gpu/lib), the
# head scan (.gpu/assets), and the GL loader packages (.gl/, amd64 .deb files unpacked there).
# Then one device run with carry [".gl", ".gpu", "build-gpu"] calls scripts/gpu/on-device.sh.
set -euo pipefail
cd "$(dirname "$0")/../.."

scripts/install-deps.sh test
for ignored in /.gl/ /.gpu/; do
  grep -qxF "$ignored" .git/info/exclude || echo "$ignored" >>.git/info/exclude
done

cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build-gpu --parallel "$(nproc)" --target sss_bench sss_headless_info sss_gl_tests sss_gl_state_tests sss_gl_stress_tests

rm -rf .gpu
mkdir -p .gpu/lib
# Every library the programs load from the system that the GPU machine's image may not have: all
# but the C and C++ runtimes (there, newer) and GL (the driver's and the .gl packages').
for program in build-gpu/tests/bench/sss_bench build-gpu/tests/sss_gl_tests build-gpu/tests/sss_gl_state_tests build-gpu/tests/sss_gl_stress_tests; do
  ldd "$program" | awk '$3 ~ /^\// {print $3}'
done | sort -u | grep -Ev '/(libc|libm|libstdc\+\+|libgcc_s|libGL|libEGL|libOpenGL|libGLX|libGLdispatch)\.' |
  while read -r lib; do cp -L "$lib" .gpu/lib/; done

if ! ls .gl/libegl1_*.deb >/dev/null 2>&1; then
  mkdir -p .gl /tmp/amd64/partial
  o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
  # shellcheck disable=SC2086
  apt-get $o update >/dev/null
  # shellcheck disable=SC2086
  (cd .gl && apt-get $o download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
fi
echo "prepare.sh: ready; carry .gl .gpu build-gpu and run scripts/gpu/on-device.sh" \
  "($(du -sh build-gpu .gpu .gl | awk '{print $2 " " $1}' | paste -sd' '))"
