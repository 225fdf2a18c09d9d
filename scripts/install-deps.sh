#!/usr/bin/env bash
# Installs the Debian 12 packages this project needs, only those that are missing.
#
#   scripts/install-deps.sh [--check] [build|test|demo|web|all ...]
#
#   build   compiler, CMake/Ninja, OpenGL headers, OSMesa/EGL (llvmpipe), GLM, stb, Eigen, NLopt
#   test    build + GoogleTest/GoogleMock, Google Benchmark, glslangValidator, and the benchmark's
#           tinygltf (head scenes), nlohmann-json (results) and gnuplot (plots); RapidCheck
#           (property tests), valgrind (memcheck run), clang + its runtime (libFuzzer targets),
#           clang-tidy (the code.shape test), Emscripten and Chromium (the web.browser test), npm
#           (the web.three test: three, lil-gui and TypeScript from web/three/dev/package-lock.json),
#           OpenSceneGraph 3.6 with Xvfb (the osg.engine_cache tests of examples/osg)
#   demo    build + GLFW, tinygltf, Dear ImGui, and Xvfb (the demo's window test)
#   web     build + Emscripten, Chromium, tinygltf, nlohmann-json (scripts/run-web-demo.sh), npm
#           (the three.js package: scripts/build-three-package.sh, scripts/run-three-demo.sh)
#   all     everything above
#   --check only report what is missing; exit 1 if something is, install nothing
#
# Without a set, "build" is used. Several sets may be given. Runs apt-get through sudo when not
# root. When everything is present it only queries dpkg (no apt-get update) and exits 0.
set -euo pipefail

readonly BUILD_PKGS=(cmake ninja-build g++ pkg-config libosmesa6-dev libegl-dev libegl-mesa0
  libgl1-mesa-dri libgles-dev libglm-dev libstb-dev libeigen3-dev libnlopt-dev)
readonly TEST_PKGS=(libgtest-dev libgmock-dev libbenchmark-dev glslang-tools libtinygltf-dev
  nlohmann-json3-dev gnuplot-nox librapidcheck-dev valgrind clang libclang-rt-14-dev clang-tidy emscripten
  chromium npm libopenscenegraph-dev xvfb xauth)
readonly DEMO_PKGS=(libglfw3-dev libtinygltf-dev libimgui-dev xvfb xauth)
# The web demo: emcc compiles tinygltf, nlohmann-json, stb_image and glm from their Debian headers.
# The three.js package: npm packs it and installs three, lil-gui and TypeScript from the registry.
readonly WEB_PKGS=(emscripten chromium libtinygltf-dev nlohmann-json3-dev npm)

usage() {
  sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'
}

check_only=0
sets=()
for arg in "$@"; do
  case "$arg" in
    build | test | demo | web | all) sets+=("$arg") ;;
    --check) check_only=1 ;;
    -h | --help)
      usage
      exit 0
      ;;
    *)
      echo "install-deps.sh: unknown argument '$arg'" >&2
      usage >&2
      exit 2
      ;;
  esac
done
[[ ${#sets[@]} -gt 0 ]] || sets=(build)

wanted=()
for s in "${sets[@]}"; do
  case "$s" in
    build) wanted+=("${BUILD_PKGS[@]}") ;;
    test) wanted+=("${BUILD_PKGS[@]}" "${TEST_PKGS[@]}") ;;
    demo) wanted+=("${BUILD_PKGS[@]}" "${DEMO_PKGS[@]}") ;;
    web) wanted+=("${BUILD_PKGS[@]}" "${WEB_PKGS[@]}") ;;
    all) wanted+=("${BUILD_PKGS[@]}" "${TEST_PKGS[@]}" "${DEMO_PKGS[@]}" "${WEB_PKGS[@]}") ;;
  esac
done

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps.sh: dpkg-query/apt-get not found; this script is for Debian 12 (or a" \
    "derivative). Install the equivalents of: ${wanted[*]}" >&2
  exit 1
fi

# A package counts as present when dpkg reports "install ok installed" for it (for any
# architecture: dpkg-query prints one status per installed architecture).
is_installed() {
  local status
  # npm: any npm on the PATH serves (Node's own release bundles it, outside dpkg); Debian's
  # package only where there is none, since it brings Debian's nodejs with it.
  if [[ $1 == npm ]] && command -v npm >/dev/null 2>&1; then
    return 0
  fi
  status=$(dpkg-query -W -f='${Status}\n' "$1" 2>/dev/null) || return 1
  grep -qx 'install ok installed' <<<"$status"
}

missing=()
declare -A seen=()
for p in "${wanted[@]}"; do
  [[ -z ${seen[$p]:-} ]] || continue
  seen[$p]=1
  is_installed "$p" || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps.sh: all ${#seen[@]} packages for '${sets[*]}' are installed"
  exit 0
fi

if [[ $check_only -eq 1 ]]; then
  echo "install-deps.sh: missing for '${sets[*]}': ${missing[*]}"
  exit 1
fi

as_root=()
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    echo "install-deps.sh: need root to install ${missing[*]} (not root and no sudo)" >&2
    exit 1
  fi
fi

echo "install-deps.sh: installing ${missing[*]}"
${as_root[@]+"${as_root[@]}"} env DEBIAN_FRONTEND=noninteractive apt-get update
${as_root[@]+"${as_root[@]}"} env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
